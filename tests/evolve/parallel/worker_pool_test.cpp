#include "evolve/parallel/worker_pool.hpp"

#include <signal.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <thread>

#include "tests/evolve/parallel/process_checks.hpp"

namespace robozoo {
namespace {

// A job: 8 bytes of seed, then 4 bytes of cost (iterations). The work: a splitmix64
// chain of `cost` steps, answered with the final value and a seed-dependent number
// of derived bytes, so results differ in content and length.
Bytes make_job(uint64_t seed, uint32_t cost) {
  Bytes b(12);
  for (int i = 0; i < 8; ++i) b[i] = static_cast<uint8_t>(seed >> (8 * i));
  for (int i = 0; i < 4; ++i) b[8 + i] = static_cast<uint8_t>(cost >> (8 * i));
  return b;
}
uint64_t job_seed(const Bytes& b) {
  uint64_t s = 0;
  for (int i = 0; i < 8; ++i) s |= static_cast<uint64_t>(b.at(i)) << (8 * i);
  return s;
}
uint32_t job_cost(const Bytes& b) {
  uint32_t c = 0;
  for (int i = 0; i < 4; ++i) c |= static_cast<uint32_t>(b.at(8 + i)) << (8 * i);
  return c;
}

Bytes chain(const Bytes& job) {
  uint64_t x = job_seed(job);
  for (uint32_t k = 0; k < job_cost(job); ++k) {
    x += 0x9E3779B97F4A7C15ull;
    uint64_t z = x;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    x = z ^ (z >> 31);
  }
  Bytes out(8 + job_seed(job) % 41);
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<uint8_t>((x >> (8 * (i % 8))) + i);
  return out;
}

/// Jobs of very uneven cost (0 to ~300k iterations, a few ms at most).
std::vector<Bytes> uneven_jobs(size_t n) {
  std::vector<Bytes> jobs;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t c = static_cast<uint32_t>((i * 7919) % 13);
    jobs.push_back(make_job(1000 + i * 31, c * c * c * 140));
  }
  return jobs;
}

std::vector<Bytes> in_process(const std::vector<Bytes>& jobs) {
  std::vector<Bytes> out;
  for (const auto& j : jobs) out.push_back(chain(j));
  return out;
}

PoolParams quick() {
  PoolParams p;
  p.job_timeout_s = 1.0;
  p.max_attempts = 3;
  p.pipe.shutdown_grace_s = 0.5;
  return p;
}

TEST(WorkerPool, SameResultsInJobOrderForAnyWorkerCount) {
  const auto jobs = uneven_jobs(60);
  const auto expected = in_process(jobs);
  std::set<Bytes> distinct(expected.begin(), expected.end());
  ASSERT_GT(distinct.size(), 50u);  // results tell jobs apart, so order matters
  for (int workers : {1, 2, 4}) {
    WorkerPool pool(workers, chain, quick());
    EXPECT_EQ(pool.workers(), workers);
    EXPECT_EQ(pool.map(jobs), expected) << workers << " workers";
    EXPECT_EQ(pool.map(jobs), expected) << workers << " workers, second map";
    EXPECT_EQ(pool.stats().maps, 2u);
    EXPECT_EQ(pool.stats().jobs_completed, 120u);
    EXPECT_EQ(pool.stats().restarts, 0u);
  }
}

TEST(WorkerPool, EmptyMapAndLargePayloads) {
  WorkerPool pool(
      2, [](const Bytes& in) { return Bytes(in.rbegin(), in.rend()); }, quick());
  EXPECT_TRUE(pool.map({}).empty());
  std::vector<Bytes> jobs;
  for (size_t i = 0; i < 4; ++i) {
    Bytes b((1u << 20) + i * 12345);
    for (size_t k = 0; k < b.size(); ++k) b[k] = static_cast<uint8_t>(k * (i + 3) >> 3);
    jobs.push_back(std::move(b));
  }
  const auto out = pool.map(jobs);
  ASSERT_EQ(out.size(), jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) EXPECT_EQ(out[i], Bytes(jobs[i].rbegin(), jobs[i].rend()));
}

TEST(WorkerPool, JobsAreHandedOutDynamically) {
  // Job 0 is slow; while one worker runs it, the other should take the short jobs.
  const auto fn = [](const Bytes& in) -> Bytes {
    if (in.at(0) == 0) std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const pid_t p = ::getpid();
    return Bytes{static_cast<uint8_t>(p), static_cast<uint8_t>(p >> 8), static_cast<uint8_t>(p >> 16)};
  };
  WorkerPool pool(2, fn, quick());
  std::vector<Bytes> jobs;
  for (uint8_t i = 0; i < 21; ++i) jobs.push_back(Bytes{i});
  const auto out = pool.map(jobs);
  int elsewhere = 0;
  for (size_t i = 1; i < out.size(); ++i) elsewhere += out[i] != out[0];
  EXPECT_GE(elsewhere, 10) << "short jobs waited behind the slow one";
}

TEST(WorkerPool, WorkerKilledOnPurposeIsReplacedAndNothingIsLost) {
  test::TempDir dir;
  const auto jobs = uneven_jobs(30);
  const auto expected = in_process(jobs);
  const std::string marks = dir.path();
  // Job 7 kills its worker on its first attempt only (the marker file remembers).
  const auto fn = [marks](const Bytes& in) -> Bytes {
    if (job_seed(in) == 1000 + 7 * 31 && test::TempDir::first_time(marks, "job7")) ::raise(SIGKILL);
    return chain(in);
  };
  for (int workers : {1, 2, 4}) {
    std::filesystem::remove(marks + "/job7");
    WorkerPool pool(workers, fn, quick());
    EXPECT_EQ(pool.map(jobs), expected) << workers << " workers";
    EXPECT_EQ(pool.stats().worker_deaths, 1u);
    EXPECT_EQ(pool.stats().restarts, 1u);
    EXPECT_EQ(pool.stats().jobs_reissued, 1u);
    EXPECT_EQ(pool.stats().job_timeouts, 0u);
    EXPECT_FALSE(test::has_zombie_child());
  }
}

TEST(WorkerPool, HungJobIsKilledAndReissued) {
  test::TempDir dir;
  const auto jobs = uneven_jobs(12);
  const auto expected = in_process(jobs);
  const std::string marks = dir.path();
  const auto fn = [marks](const Bytes& in) -> Bytes {
    if (job_seed(in) == 1000 + 3 * 31 && test::TempDir::first_time(marks, "job3"))
      std::this_thread::sleep_for(std::chrono::seconds(60));
    return chain(in);
  };
  WorkerPool pool(2, fn, quick());
  EXPECT_EQ(pool.map(jobs), expected);
  EXPECT_EQ(pool.stats().job_timeouts, 1u);
  EXPECT_EQ(pool.stats().restarts, 1u);
  EXPECT_EQ(pool.stats().jobs_reissued, 1u);
  EXPECT_EQ(pool.stats().worker_deaths, 0u);
  EXPECT_FALSE(test::has_zombie_child());
}

TEST(WorkerPool, JobThatAlwaysCrashesFailsTheMapNamingIt) {
  const auto fn = [](const Bytes& in) -> Bytes {
    if (in.at(0) == 2) ::raise(SIGKILL);
    return in;
  };
  WorkerPool pool(2, fn, quick());
  std::vector<Bytes> jobs;
  for (uint8_t i = 0; i < 6; ++i) jobs.push_back(Bytes{i});
  try {
    pool.map(jobs);
    FAIL() << "map() should have failed";
  } catch (const PoolError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("job 2 "), std::string::npos) << what;
    EXPECT_NE(what.find("3 times"), std::string::npos) << what;
    EXPECT_NE(what.find("signal 9"), std::string::npos) << what;
  }
  EXPECT_EQ(pool.stats().worker_deaths, 3u);
  EXPECT_EQ(pool.stats().jobs_reissued, 2u);
  EXPECT_EQ(pool.stats().maps, 0u);
  // The pool is still usable.
  jobs.erase(jobs.begin() + 2);
  EXPECT_EQ(pool.map(jobs), jobs);
  EXPECT_FALSE(test::has_zombie_child());
}

TEST(WorkerPool, MaxAttemptsOfOneFailsOnTheFirstCrash) {
  PoolParams p = quick();
  p.max_attempts = 1;
  WorkerPool pool(
      1, [](const Bytes&) -> Bytes { ::_exit(3); }, p);
  try {
    pool.map({Bytes{1}});
    FAIL() << "map() should have failed";
  } catch (const PoolError& e) {
    EXPECT_NE(std::string(e.what()).find("1 time "), std::string::npos) << e.what();
  }
}

TEST(WorkerPool, ThrowingWorkFunctionFailsTheMapWithItsMessage) {
  const auto fn = [](const Bytes& in) -> Bytes {
    if (in.at(0) == 4) throw std::runtime_error("robot has no root sphere");
    if (in.at(0) == 5) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    return in;
  };
  WorkerPool pool(3, fn, quick());
  std::vector<Bytes> jobs;
  for (uint8_t i = 0; i < 8; ++i) jobs.push_back(Bytes{i});
  try {
    pool.map(jobs);
    FAIL() << "map() should have failed";
  } catch (const PoolError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("job 4 "), std::string::npos) << what;
    EXPECT_NE(what.find("robot has no root sphere"), std::string::npos) << what;
  }
  EXPECT_EQ(pool.stats().worker_deaths, 0u);  // an exception is not a crash: no retries
  // Workers left busy with the abandoned map were replaced: the next map is clean.
  jobs.erase(jobs.begin() + 4);
  EXPECT_EQ(pool.map(jobs), jobs);
  EXPECT_EQ(pool.map(jobs), jobs);
}

TEST(WorkerPool, NoZombiesOrLeakedDescriptorsAfterManyRestarts) {
  test::TempDir dir;
  const std::string marks = dir.path();
  const auto jobs = uneven_jobs(40);
  const auto expected = in_process(jobs);
  // Every job kills its worker on its first attempt: 40 restarts.
  const auto fn = [marks](const Bytes& in) -> Bytes {
    if (test::TempDir::first_time(marks, std::to_string(job_seed(in)))) ::raise(SIGKILL);
    return chain(in);
  };
  const int fds_before = test::open_fd_count();
  {
    WorkerPool pool(2, fn, quick());
    const int fds_running = test::open_fd_count();
    EXPECT_EQ(fds_running, fds_before + 2);  // one socket per worker
    EXPECT_EQ(pool.map(jobs), expected);
    EXPECT_EQ(pool.stats().restarts, 40u);
    EXPECT_EQ(pool.stats().jobs_reissued, 40u);
    EXPECT_EQ(test::open_fd_count(), fds_running);
    EXPECT_FALSE(test::has_zombie_child());
    EXPECT_TRUE(test::has_any_child());
  }
  EXPECT_EQ(test::open_fd_count(), fds_before);
  EXPECT_FALSE(test::has_any_child());
}

TEST(WorkerPool, RejectsBadArguments) {
  EXPECT_THROW(WorkerPool(0, chain), std::invalid_argument);
  PoolParams p;
  p.max_attempts = 0;
  EXPECT_THROW(WorkerPool(1, chain, p), std::invalid_argument);
  p = PoolParams{};
  p.job_timeout_s = 0.0;
  EXPECT_THROW(WorkerPool(1, chain, p), std::invalid_argument);
  p.job_timeout_s = std::nan("");
  EXPECT_THROW(WorkerPool(1, chain, p), std::invalid_argument);
  p.job_timeout_s = std::numeric_limits<double>::infinity();  // no limit: allowed
  WorkerPool pool(1, chain, p);
  EXPECT_EQ(pool.map({make_job(5, 10)}), std::vector<Bytes>{chain(make_job(5, 10))});
  EXPECT_THROW(WorkerPool(std::unique_ptr<Transport>{}), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
