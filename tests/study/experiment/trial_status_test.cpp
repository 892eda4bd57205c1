#include "study/experiment/trial_status.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "evolve/config/run_config.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

struct Fixture {
  TempDir dir;
  ExperimentParams p;
  Trial trial;
  Fixture() {
    p.trials = 1;
    p.generations = 5;
    p.population = 12;
    p.out_dir = dir.path;
    trial = plan_trials(p)[1];  // recurrent-s2
  }
  void checkpoint(int32_t population_generation, bool finished, int population = 12, int64_t seed = 2,
                  int generations = 5) {
    RunConfig c;
    c.regime = Regime::Recurrent;
    c.seed = seed;
    c.generations = generations;
    c.neat.population = population;
    Checkpoint cp;
    cp.run_id = "recurrent-s2";
    cp.config = config_to_json(c);
    cp.population.generation = population_generation;
    cp.elapsed_seconds = 12.5;
    cp.finished = finished;
    write_checkpoint(trial.log_path + ".checkpoint", cp);
  }
};

TEST(TrialStatus, NotStartedPartialFinished) {
  Fixture f;
  EXPECT_EQ(trial_status(f.trial, f.p).state, TrialState::NotStarted);
  f.checkpoint(0, false);  // written at the start, before generation 0
  EXPECT_EQ(trial_status(f.trial, f.p).state, TrialState::Partial);
  EXPECT_EQ(trial_status(f.trial, f.p).generations_done, 0);
  f.checkpoint(3, false);  // generations 0-2 done, population holds generation 3
  EXPECT_EQ(trial_status(f.trial, f.p).generations_done, 3);
  EXPECT_EQ(trial_status(f.trial, f.p).elapsed_seconds, 12.5);
  f.checkpoint(4, true);  // the last generation (4) done: no advance
  const TrialStatus s = trial_status(f.trial, f.p);
  EXPECT_EQ(s.state, TrialState::Finished);
  EXPECT_EQ(s.generations_done, 5);
  EXPECT_EQ(state_name(s.state), "finished");
}

TEST(TrialStatus, ACheckpointOfAnotherExperimentIsRefused) {
  Fixture f;
  f.checkpoint(2, false, 60, 7);
  try {
    trial_status(f.trial, f.p);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("seed 7, not 2"), std::string::npos) << what;
    EXPECT_NE(what.find("population 60, not 12"), std::string::npos) << what;
  }
  ExperimentParams steps = f.p;
  steps.steps = 300;  // the checkpoint has the default 2,500
  f.checkpoint(2, false);
  EXPECT_THROW(trial_status(f.trial, steps), std::invalid_argument);
}

TEST(TrialStatus, ACheckpointWithoutTheExperimentsSetsIsRefused) {
  Fixture f;
  f.checkpoint(2, false);  // the defaults: bias input 0.3, rescaled weights
  ExperimentParams bias = f.p;
  bias.sets = {"growth.bias_input=1.0", "growth.weight_mapping=rescaled"};
  try {
    trial_status(f.trial, bias);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("growth.bias_input 0.3, not 1.0"), std::string::npos) << what;
    EXPECT_EQ(what.find("weight_mapping"), std::string::npos) << what;
  }
  ExperimentParams same = f.p;
  same.sets = {"growth.bias_input=0.3"};
  EXPECT_EQ(trial_status(f.trial, same).state, TrialState::Partial);
  // A recorded configuration without a newer key ran with its old behaviour.
  nlohmann::json old = config_to_json(RunConfig{});
  old["growth"].erase("weight_mapping");
  EXPECT_EQ(sets_mismatch(old, {"growth.weight_mapping=proportional"}), "");
  EXPECT_EQ(sets_mismatch(old, {"growth.weight_mapping=rescaled"}),
            "growth.weight_mapping \"proportional\", not \"rescaled\"");
}

TEST(TrialStatus, MoreGenerationsThanATrialWasStartedForExtendIt) {
  Fixture f;
  f.checkpoint(4, true, 12, 2, 5);  // finished at 5
  ExperimentParams more = f.p;
  more.generations = 8;
  TrialStatus s = trial_status(f.trial, more);
  EXPECT_EQ(s.state, TrialState::Partial);  // resumed with --generations 8
  EXPECT_EQ(s.generations_done, 5);
  f.checkpoint(3, false, 12, 2, 5);  // stopped after generation 2 of 5
  s = trial_status(f.trial, more);
  EXPECT_EQ(s.state, TrialState::Partial);
  EXPECT_EQ(s.generations_done, 3);
}

TEST(TrialStatus, ATrialStartedForMoreGenerationsIsDoneOnceItHasThem) {
  Fixture f;
  ExperimentParams fewer = f.p;
  fewer.generations = 3;
  f.checkpoint(4, true, 12, 2, 5);  // finished at 5
  TrialStatus s = trial_status(f.trial, fewer);
  EXPECT_EQ(s.state, TrialState::Finished);
  EXPECT_EQ(s.generations_done, 3);  // counted as the experiment's 3
  f.checkpoint(3, false, 12, 2, 5);  // 3 of 5 done
  EXPECT_EQ(trial_status(f.trial, fewer).state, TrialState::Finished);
  f.checkpoint(2, false, 12, 2, 5);  // 2 of 5 done: it cannot stop at 3
  try {
    trial_status(f.trial, fewer);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("was started for 5 generations and has 2; continue it with --generations 5"),
              std::string::npos)
        << e.what();
  }
}

TEST(TrialStatus, ALogWithoutItsCheckpointIsAnError) {
  Fixture f;
  std::ofstream(f.trial.log_path) << "log";
  try {
    trial_status(f.trial, f.p);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has no checkpoint"), std::string::npos) << e.what();
  }
}

TEST(TrialStatus, AnUnreadableCheckpointIsAnError) {
  Fixture f;
  std::ofstream(f.trial.log_path + ".checkpoint") << "{ not json";
  EXPECT_THROW(trial_status(f.trial, f.p), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
