#include "evolve/run/eval_job.hpp"

#include <gtest/gtest.h>

#include "evolve/neat/start/random_genome.hpp"

namespace robozoo {
namespace {

TEST(EvalJob, GenomeTravelsExactly) {
  Rng rng(8);
  const Genome g =
      random_evolved_genome(robot_layout(), Regime::Recurrent, NeatParams{}, RandomGenomeParams{}, rng, 77);
  const Genome back = decode_eval_job(encode_eval_job(g), robot_layout());
  EXPECT_EQ(back.id, g.id);
  EXPECT_EQ(back.nodes, g.nodes);
  ASSERT_EQ(back.links.size(), g.links.size());
  for (size_t i = 0; i < g.links.size(); ++i) {
    EXPECT_EQ(back.links[i].weight, g.links[i].weight);  // bit-exact doubles
    EXPECT_EQ(back.links[i].innovation, g.links[i].innovation);
    EXPECT_EQ(back.links[i].enabled, g.links[i].enabled);
  }
}

TEST(EvalJob, ResultTravelsExactly) {
  EvalSummary s;
  s.genome_id = 42;
  s.fitness = 15.0 + 1.0 / 3.0;
  s.r = 15;
  s.d = 1.0 / 3.0;
  s.outcome = Outcome::RollingSpin;
  s.num_spheres = 7;
  s.num_bodies = 3;
  s.num_joints = 2;
  s.num_sensors = 4;
  s.steps_run = 1234;
  EXPECT_TRUE(decode_eval_result(encode_eval_result(s)) == s);
}

TEST(EvalJob, WorkerResultEqualsInProcessEvaluation) {
  Rng rng(9);
  EvalParams p;
  p.sim.steps = 300;
  for (int i = 0; i < 10; ++i) {
    RandomGenomeParams rp;
    rp.rounds = 20;
    const Genome g = random_evolved_genome(robot_layout(), Regime::FeedForward, NeatParams{}, rp, rng, i);
    const EvalSummary via_bytes = decode_eval_result(run_eval_job(encode_eval_job(g), p));
    EXPECT_TRUE(via_bytes == summarize(g.id, evaluate(g, p)));
    EXPECT_GE(via_bytes.r, 1.0);
  }
}

TEST(EvalJob, RejectsBytesThatAreNotMessages) {
  std::vector<uint8_t> junk(40, 0x5a);
  EXPECT_THROW(decode_eval_job(junk, robot_layout()), std::invalid_argument);
  EXPECT_THROW(decode_eval_result(junk), std::invalid_argument);
  auto job = encode_eval_job(Genome{});
  EXPECT_THROW(decode_eval_job(job, robot_layout()), std::invalid_argument);  // no nodes at all
}

}  // namespace
}  // namespace robozoo
