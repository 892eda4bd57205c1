// The MPI transport and the worker ranks' loop (mpi_transport, mpi_worker,
// mpi_setup, mpi_session), on real MPI jobs. Each test starts mpirun on this very
// executable with ROBOZOO_MPI_PLAY set: main() then plays a rank instead of running
// GoogleTest. Rank 0 runs the scenarios and prints "scenario NAME ok" or
// "scenario NAME FAILED: why"; the other ranks serve one session per scenario.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>
#include <thread>

#include "evolve/parallel/mpi/mpi_error.hpp"
#include "evolve/parallel/mpi/mpi_session.hpp"
#include "evolve/parallel/mpi/mpi_transport.hpp"
#include "evolve/parallel/mpi/mpi_worker.hpp"
#include "evolve/parallel/worker_pool.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/mpirun.hpp"

namespace robozoo {
namespace {

// ---------------------------------------------------------------- the ranks

struct Check : std::runtime_error {
  using std::runtime_error::runtime_error;
};
#define REQUIRE(cond, what)                                                \
  do {                                                                     \
    if (!(cond)) {                                                         \
      std::ostringstream why_;                                             \
      why_ << "line " << __LINE__ << ": " << #cond << " (" << what << ")"; \
      throw Check(why_.str());                                             \
    }                                                                      \
  } while (0)

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }
std::string text(const Bytes& b) { return std::string(b.begin(), b.end()); }

int my_rank() {
  int r = -1;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

/// The work functions the scenarios ask for by name.
WorkFn make_work(const std::string& setup) {
  if (setup == "reverse") return [](const Bytes& in) { return Bytes(in.rbegin(), in.rend()); };
  if (setup == "throw-on-empty")
    return [](const Bytes& in) -> Bytes {
      if (in.empty()) throw std::invalid_argument("empty payload");
      return in;
    };
  if (setup == "sleep")  // payload: milliseconds (one byte, times 10); answer: payload + rank
    return [](const Bytes& in) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10 * in.at(0)));
      Bytes out = in;
      out.push_back(static_cast<uint8_t>(my_rank()));
      return out;
    };
  if (setup.rfind("garbage-from-rank-2 in session ", 0) == 0) {
    if (my_rank() == 2) {  // a rank that breaks the protocol: bytes that are no frame
      const uint32_t session = static_cast<uint32_t>(std::stoul(setup.substr(setup.rfind(' ') + 1)));
      const char junk[] = "not a frame";
      MPI_Send(junk, sizeof junk, MPI_CHAR, 0, mpi_detail::result_tag(session), MPI_COMM_WORLD);
    }
    return [](const Bytes& in) { return in; };
  }
  throw std::invalid_argument("unknown scenario setup '" + setup + "'");
}

WorkerEvent next_event(MpiTransport& t) {
  auto e = t.receive(20.0);
  REQUIRE(e.has_value(), "no event within 20 s");
  return std::move(*e);
}

MpiTransportParams in_session(uint32_t session) {
  MpiTransportParams p;
  p.session = session;
  return p;
}

void round_trip(uint32_t session) {
  MpiTransport t(in_session(session));
  REQUIRE(t.size() == 2, t.size());
  REQUIRE(!t.started(), "");
  t.start("reverse");
  REQUIRE(t.started(), "");
  uint64_t bytes = 0;
  for (int w = 0; w < 2; ++w) {
    const Job job{static_cast<uint64_t>(10 + w), text("abc" + std::to_string(w))};
    bytes += encode_job(job).size();
    REQUIRE(t.send(w, job), "send to worker " << w);
  }
  for (int k = 0; k < 2; ++k) {
    const WorkerEvent e = next_event(t);
    REQUIRE(e.kind == WorkerEvent::Kind::Result, e.reason);
    REQUIRE(e.result.ok, e.result.error);
    REQUIRE(e.result.index == static_cast<uint64_t>(10 + e.worker), e.result.index);
    REQUIRE(text(e.result.payload) == std::to_string(e.worker) + "cba", text(e.result.payload));
  }
  REQUIRE(!t.receive(0.0).has_value(), "nothing else is pending");
  const MpiTransportStats& s = t.stats();
  REQUIRE(s.messages_sent == 2 && s.messages_received == 2, s.messages_sent << " " << s.messages_received);
  REQUIRE(s.bytes_sent == bytes, s.bytes_sent << " vs " << bytes);
  REQUIRE(s.bytes_received == bytes, s.bytes_received);  // results are as long as the jobs
  REQUIRE(s.jobs.size() == 2 && s.jobs[0] == 1 && s.jobs[1] == 1, "");
  REQUIRE(s.setup_bytes == 7, s.setup_bytes);
  bool threw = false;
  try {
    t.start("reverse");
  } catch (const std::logic_error&) {
    threw = true;
  }
  REQUIRE(threw, "a second start() is refused");
}

void failure_comes_back(uint32_t session) {
  MpiTransport t(in_session(session));
  t.start("throw-on-empty");
  REQUIRE(t.send(1, Job{4, {}}), "");
  WorkerEvent e = next_event(t);
  REQUIRE(e.kind == WorkerEvent::Kind::Result && e.worker == 1, e.reason);
  REQUIRE(!e.result.ok && e.result.index == 4, "");
  REQUIRE(e.result.error == "empty payload", e.result.error);
  REQUIRE(t.send(1, Job{5, {9}}), "the rank lives on");
  e = next_event(t);
  REQUIRE(e.result.ok && e.result.payload == Bytes{9}, "");
}

void pool_hands_out_dynamically(uint32_t session) {
  MpiTransportParams tp = in_session(session);
  tp.record_jobs = true;
  auto owned = std::make_unique<MpiTransport>(tp);
  MpiTransport& t = *owned;
  t.start("sleep");
  WorkerPool pool(std::move(owned));
  REQUIRE(pool.workers() == 2, "");
  std::vector<Bytes> jobs = {Bytes{40}};                  // 400 ms
  for (int i = 1; i < 30; ++i) jobs.push_back(Bytes{1});  // 10 ms each
  const std::vector<Bytes> results = pool.map(jobs);
  REQUIRE(results.size() == jobs.size(), "");
  int slow_rank = 0;
  for (size_t i = 0; i < jobs.size(); ++i) {
    REQUIRE(results[i].size() == 2 && results[i][0] == jobs[i][0], "result " << i << " answers job " << i);
    if (i == 0) slow_rank = results[i][1];
  }
  // The rank busy with the long job took few others: the other took the rest.
  const MpiTransportStats& s = t.stats();
  const int slow = slow_rank - 1, fast = 1 - slow;
  REQUIRE(s.jobs[static_cast<size_t>(slow)] <= 5 && s.jobs[static_cast<size_t>(fast)] >= 25,
          "jobs " << s.jobs[0] << " / " << s.jobs[1]);
  REQUIRE(s.timings.size() == jobs.size(), s.timings.size());
  REQUIRE(s.busy_seconds[static_cast<size_t>(slow)] >= 0.39, s.busy_seconds[static_cast<size_t>(slow)]);
  // Results come back in job order whatever rank answered, map after map.
  const std::vector<Bytes> again = pool.map(jobs);
  for (size_t i = 0; i < jobs.size(); ++i) REQUIRE(again[i][0] == jobs[i][0], i);
}

void hung_rank_fails_the_map(uint32_t session) {
  auto owned = std::make_unique<MpiTransport>(in_session(session));
  owned->start("sleep");
  PoolParams pp;
  pp.job_timeout_s = 0.2;
  WorkerPool pool(std::move(owned), pp);
  std::string message;
  try {
    pool.map({Bytes{80}});  // 800 ms
  } catch (const PoolError& e) {
    message = e.what();
  }
  REQUIRE(message.find("did not answer its job in time") != std::string::npos, message);
  REQUIRE(message.find("cannot replace a rank") != std::string::npos, message);
  REQUIRE(message.find("rank 1 (worker 0)") != std::string::npos, message);
}

/// Follows hung_rank_fails_the_map: that session's late result must not show up here.
void garbage_is_a_death(uint32_t session) {
  MpiTransport t(in_session(session));
  t.start("garbage-from-rank-2 in session " + std::to_string(session));
  const WorkerEvent e = next_event(t);
  REQUIRE(e.kind == WorkerEvent::Kind::Died && e.worker == 1, "kind " << static_cast<int>(e.kind));
  REQUIRE(e.reason.find("rank 2 (worker 1) broke the protocol") != std::string::npos, e.reason);
  REQUIRE(!t.send(1, Job{1, {1}}), "a dead rank takes no job");
  std::string message;
  try {
    t.restart(1);
  } catch (const std::runtime_error& err) {
    message = err.what();
  }
  REQUIRE(message.find("broke the protocol") != std::string::npos, message);
  REQUIRE(t.send(0, Job{2, {7}}), "the other rank still works");
  const WorkerEvent r = next_event(t);
  REQUIRE(r.kind == WorkerEvent::Kind::Result && r.result.payload == Bytes{7}, r.reason);
}

int play_root(const MpiSession& mpi) {
  const std::vector<std::pair<std::string, std::function<void(uint32_t)>>> scenarios = {
      {"round_trip", round_trip},
      {"failure_comes_back", failure_comes_back},
      {"pool_hands_out_dynamically", pool_hands_out_dynamically},
      {"hung_rank_fails_the_map", hung_rank_fails_the_map},
      {"garbage_is_a_death", garbage_is_a_death},
  };
  if (mpi.size() == 1) {  // a job of one rank: nothing to evaluate on
    std::string message;
    try {
      MpiTransport t;
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    const bool ok = message.find("needs at least 2 ranks") != std::string::npos;
    std::cout << "scenario single_rank " << (ok ? "ok" : "FAILED: " + message) << std::endl;
    return ok ? 0 : 1;
  }
  int failed = 0;
  uint32_t session = 0;
  for (const auto& [name, run] : scenarios) {
    try {
      run(session++);
      std::cout << "scenario " << name << " ok" << std::endl;
    } catch (const std::exception& e) {
      ++failed;
      std::cout << "scenario " << name << " FAILED: " << e.what() << std::endl;
    }
  }
  { MpiTransport last(in_session(session)); }  // never started: tells the worker ranks that no session follows
  // The worker ranks' own count: 2 + 2 + 60 + 1 (abandoned, still answered) + 1 jobs.
  const std::vector<MpiWorkerStats> stats = gather_worker_stats(MpiWorkerStats{});
  uint64_t jobs = 0;
  double busy = 0.0;
  for (const auto& st : stats) {
    jobs += st.jobs;
    busy += st.busy_seconds;
  }
  const bool counted = stats.size() == 3 && stats[0].jobs == 0 && jobs == 66 && busy >= 1.2;
  std::cout << "scenario worker_stats "
            << (counted ? std::string("ok")
                        : "FAILED: " + std::to_string(jobs) + " jobs, " + std::to_string(busy) + " s")
            << std::endl;
  return failed || !counted ? 1 : 0;
}

int play_worker(const MpiSession& session) {
  std::string message;
  try {
    MpiTransport t;  // only rank 0 may own the pool
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  if (message.find("belongs on rank 0, this is rank " + std::to_string(session.rank())) == std::string::npos)
    std::cout << "scenario transport_off_rank_0 FAILED on rank " << session.rank() << ": " << message << std::endl;
  MpiWorkerStats stats;
  int sessions = 0;
  while (serve_mpi_session(make_work, &stats)) ++sessions;
  if (sessions != 5)
    std::cout << "scenario sessions FAILED on rank " << session.rank() << ": " << sessions << std::endl;
  gather_worker_stats(stats);
  return 0;
}

int play(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  return session.rank() == 0 ? play_root(session) : play_worker(session);
}

// ---------------------------------------------------------------- the tests

using namespace robozoo::testing;

std::string self() {
  char path[4096];
  const ssize_t n = ::readlink("/proc/self/exe", path, sizeof path - 1);
  return n > 0 ? std::string(path, static_cast<size_t>(n)) : "";
}

Outcome play_under_mpirun(int np) {
  std::vector<std::string> argv = under_mpirun(np, {self()});
  return run_shell("ROBOZOO_MPI_PLAY=1 timeout 120 " + join(argv));
}

TEST(MpiTransport, ScenariosOnThreeRanks) {
  const Outcome o = play_under_mpirun(3);
  EXPECT_EQ(o.status, 0) << o.output;
  for (const char* name : {"round_trip", "failure_comes_back", "pool_hands_out_dynamically", "hung_rank_fails_the_map",
                           "garbage_is_a_death", "worker_stats"})
    EXPECT_NE(o.output.find(std::string("scenario ") + name + " ok"), std::string::npos) << name << "\n" << o.output;
  EXPECT_EQ(o.output.find("FAILED"), std::string::npos) << o.output;
}

TEST(MpiTransport, RefusesAJobOfOneRank) {
  const Outcome o = play_under_mpirun(1);
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("scenario single_rank ok"), std::string::npos) << o.output;
}

}  // namespace
}  // namespace robozoo

int main(int argc, char** argv) {
  if (std::getenv("ROBOZOO_MPI_PLAY")) {
    try {
      return robozoo::play(argc, argv);
    } catch (const std::exception& e) {
      std::cout << "scenario setup FAILED: " << e.what() << std::endl;
      return 1;
    }
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
