#include "evolve/experiment/trial_status.hpp"

#include <gtest/gtest.h>

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
  void checkpoint(int32_t population_generation, bool finished, int population = 12, int64_t seed = 2) {
    RunConfig c;
    c.regime = Regime::Recurrent;
    c.seed = seed;
    c.generations = 5;
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
  f.checkpoint(4, true);   // the last generation (4) done: no advance
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

TEST(TrialStatus, AnUnreadableCheckpointIsAnError) {
  Fixture f;
  std::ofstream(f.trial.log_path + ".checkpoint") << "{ not json";
  EXPECT_THROW(trial_status(f.trial, f.p), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
