#include "evolve/parallel/scaling_model.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace robozoo {
namespace {

TEST(ListScheduleMakespan, HandsJobsToTheFirstFreeWorkerInOrder) {
  EXPECT_DOUBLE_EQ(list_schedule_makespan({}, 3), 0.0);
  EXPECT_DOUBLE_EQ(list_schedule_makespan({1, 2, 3}, 1), 6.0);        // one worker: the sum
  EXPECT_DOUBLE_EQ(list_schedule_makespan({1, 1, 1, 1}, 2), 2.0);     // even split
  EXPECT_DOUBLE_EQ(list_schedule_makespan({4, 1, 1, 1, 1}, 2), 4.0);  // the short ones go to the other
  EXPECT_DOUBLE_EQ(list_schedule_makespan({1, 1, 1, 1, 4}, 2), 6.0);  // a long job last: in order, not LPT
  EXPECT_DOUBLE_EQ(list_schedule_makespan({2, 5, 1}, 8), 5.0);        // more workers than jobs: the longest
}

TEST(ListScheduleMakespan, RefusesBadInput) {
  EXPECT_THROW(list_schedule_makespan({1}, 0), std::invalid_argument);
  EXPECT_THROW(list_schedule_makespan({-1}, 1), std::invalid_argument);
  EXPECT_THROW(list_schedule_makespan({std::numeric_limits<double>::infinity()}, 1), std::invalid_argument);
}

TEST(ProjectGeneration, AddsLatencyBytesAndTheSerialPart) {
  GenerationCost c;
  c.job_seconds = {1.0, 1.0, 1.0, 1.0};
  c.job_bytes = {1000, 1000, 1000, 1000};
  c.serial_seconds = 0.5;
  c.root_seconds_per_job = 0.001;
  ClusterParams k;
  k.latency_s = 0.01;
  k.bandwidth_bytes_per_s = 1e5;  // 10 ms per job's bytes
  k.core_speed = 2.0;             // jobs take 0.5 s
  const GenerationProjection p = project_generation(c, 2, k);
  EXPECT_DOUBLE_EQ(p.workers, 2 * (0.5 + 0.02 + 0.01));
  EXPECT_DOUBLE_EQ(p.root_link, 4 * 0.001 + 4000 / 1e5);
  EXPECT_DOUBLE_EQ(p.serial, 0.5);
  EXPECT_DOUBLE_EQ(p.seconds, 0.5 + p.workers);
  EXPECT_EQ(p.bound, "evaluations");
}

TEST(ProjectGeneration, NamesWhatBoundsIt) {
  GenerationCost c;
  c.job_seconds.assign(100, 0.01);
  c.job_bytes.assign(100, 5000);
  ClusterParams k;
  c.root_seconds_per_job = 0.002;                                      // rank 0 needs 0.2 s for 100 jobs
  EXPECT_EQ(project_generation(c, 1, k).bound, "evaluations");         // 1 s of work on one worker
  EXPECT_EQ(project_generation(c, 100, k).bound, "rank 0 messaging");  // 10 ms of work each
  c.serial_seconds = 1.0;
  EXPECT_EQ(project_generation(c, 100, k).bound, "rank 0 serial");
  // More workers never make it slower here.
  c.serial_seconds = 0.0;
  c.root_seconds_per_job = 0.0;
  double last = project_generation(c, 1, k).seconds;
  for (int w = 2; w <= 128; w *= 2) {
    const double t = project_generation(c, w, k).seconds;
    EXPECT_LE(t, last + 1e-12) << w;
    last = t;
  }
}

TEST(ProjectGeneration, RefusesBadInput) {
  GenerationCost c;
  c.job_seconds = {1.0};
  c.job_bytes = {};
  EXPECT_THROW(project_generation(c, 1, {}), std::invalid_argument);
  c.job_bytes = {1.0};
  ClusterParams k;
  k.bandwidth_bytes_per_s = 0;
  EXPECT_THROW(project_generation(c, 1, k), std::invalid_argument);
  EXPECT_THROW(project_generation(c, 0, {}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
