#include "evolve/parallel/pipe_transport.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <set>
#include <thread>

#include "tests/evolve/parallel/process_checks.hpp"

namespace robozoo {
namespace {

Bytes reverse(const Bytes& in) { return Bytes(in.rbegin(), in.rend()); }

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }
std::string text(const Bytes& b) { return std::string(b.begin(), b.end()); }

/// Waits (up to 10 s) for the next event; fails the test on timeout.
WorkerEvent next_event(PipeTransport& t) {
  auto e = t.receive(10.0);
  if (!e) throw std::runtime_error("no event within 10 s");
  return std::move(*e);
}

TEST(PipeTransport, RoundTripOnEveryWorker) {
  PipeTransport t(3, reverse);
  ASSERT_EQ(t.size(), 3);
  std::set<pid_t> pids;
  for (int w = 0; w < 3; ++w) {
    EXPECT_GT(t.pid(w), 0);
    EXPECT_NE(t.pid(w), ::getpid());
    pids.insert(t.pid(w));
    ASSERT_TRUE(t.send(w, Job{static_cast<uint64_t>(10 + w), {1, 2, static_cast<uint8_t>(w)}}));
  }
  EXPECT_EQ(pids.size(), 3u);
  std::set<int> answered;
  for (int k = 0; k < 3; ++k) {
    const WorkerEvent e = next_event(t);
    ASSERT_EQ(e.kind, WorkerEvent::Kind::Result);
    EXPECT_TRUE(e.result.ok);
    EXPECT_EQ(e.result.index, static_cast<uint64_t>(10 + e.worker));
    EXPECT_EQ(e.result.payload, (Bytes{static_cast<uint8_t>(e.worker), 2, 1}));
    answered.insert(e.worker);
  }
  EXPECT_EQ(answered.size(), 3u);
  EXPECT_FALSE(t.receive(0.0).has_value());  // nothing else pending
}

TEST(PipeTransport, LargePayloadsBothWays) {
  PipeTransport t(1, reverse);
  Bytes big(8u << 20);
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(i * 2654435761u >> 13);
  ASSERT_TRUE(t.send(0, Job{1, big}));
  const WorkerEvent e = next_event(t);
  ASSERT_EQ(e.kind, WorkerEvent::Kind::Result);
  EXPECT_EQ(e.result.payload, reverse(big));
}

TEST(PipeTransport, ExceptionComesBackAsAFailedResult) {
  PipeTransport t(1, [](const Bytes& in) -> Bytes {
    if (in.empty()) throw std::invalid_argument("empty genome");
    return in;
  });
  ASSERT_TRUE(t.send(0, Job{4, {}}));
  const WorkerEvent e = next_event(t);
  ASSERT_EQ(e.kind, WorkerEvent::Kind::Result);
  EXPECT_EQ(e.result.index, 4u);
  EXPECT_FALSE(e.result.ok);
  EXPECT_EQ(e.result.error, "empty genome");
  ASSERT_TRUE(t.send(0, Job{5, {9}}));  // the worker lives on
  EXPECT_EQ(next_event(t).result.payload, Bytes{9});
}

TEST(PipeTransport, KilledIdleWorkerIsReportedOnceAndRestarts) {
  PipeTransport t(2, reverse);
  const pid_t victim = t.pid(1);
  ASSERT_GT(victim, 1);
  ASSERT_EQ(::kill(victim, SIGKILL), 0);
  const WorkerEvent e = next_event(t);
  EXPECT_EQ(e.kind, WorkerEvent::Kind::Died);
  EXPECT_EQ(e.worker, 1);
  EXPECT_NE(e.reason.find("signal 9"), std::string::npos) << e.reason;
  EXPECT_EQ(t.pid(1), -1);
  EXPECT_FALSE(t.send(1, Job{1, {1}}));       // known dead: nothing delivered
  EXPECT_FALSE(t.receive(0.05).has_value());  // reported once only
  EXPECT_FALSE(test::has_zombie_child());
  t.restart(1);
  EXPECT_GT(t.pid(1), 0);
  EXPECT_NE(t.pid(1), victim);
  ASSERT_TRUE(t.send(1, Job{2, {1, 2}}));
  const WorkerEvent r = next_event(t);
  EXPECT_EQ(r.worker, 1);
  EXPECT_EQ(r.result.payload, (Bytes{2, 1}));
}

TEST(PipeTransport, SendingToADeadWorkerDoesNotRaiseSigpipe) {
  // SIGPIPE's default action would end this test process.
  ASSERT_NE(::signal(SIGPIPE, SIG_DFL), SIG_ERR);
  PipeTransport t(1, reverse);
  ASSERT_GT(t.pid(0), 1);
  ASSERT_EQ(::kill(t.pid(0), SIGKILL), 0);
  // Let the kernel finish the child (its socket closes), without reaping it here.
  siginfo_t info{};
  ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(t.pid(0)), &info, WEXITED | WNOWAIT), 0);
  const bool delivered = t.send(0, Job{1, Bytes(1 << 20, 7)});
  EXPECT_FALSE(delivered);
  const WorkerEvent e = next_event(t);
  EXPECT_EQ(e.kind, WorkerEvent::Kind::Died);
  EXPECT_FALSE(test::has_zombie_child());
}

TEST(PipeTransport, WorkerThatExitsOrBreaksTheProtocolIsReported) {
  PipeTransport t(1, [](const Bytes& in) -> Bytes {
    if (text(in) == "exit") ::_exit(7);
    if (text(in) == "garbage") {  // write around the protocol on the worker's socket
      // The worker's socket is its only socket (inherited descriptors are closed),
      // but its number depends on what the test runner had open: find it.
      const char junk[] = "this is not a frame, not at all";
      bool wrote = false;
      for (int fd = 3; fd < 256 && !wrote; ++fd) {
        struct stat st {};
        if (::fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode)) wrote = ::write(fd, junk, sizeof junk) > 0;
      }
      if (!wrote) ::_exit(8);
    }
    return in;
  });
  ASSERT_TRUE(t.send(0, Job{1, text("exit")}));
  WorkerEvent e = next_event(t);
  EXPECT_EQ(e.kind, WorkerEvent::Kind::Died);
  EXPECT_NE(e.reason.find("exited with status 7"), std::string::npos) << e.reason;
  t.restart(0);
  ASSERT_TRUE(t.send(0, Job{2, text("garbage")}));
  e = next_event(t);
  EXPECT_EQ(e.kind, WorkerEvent::Kind::Died);
  EXPECT_NE(e.reason.find("broke the protocol"), std::string::npos) << e.reason;
  EXPECT_NE(e.reason.find("signal 9"), std::string::npos) << e.reason;
  t.restart(0);
  ASSERT_TRUE(t.send(0, Job{3, text("fine")}));
  EXPECT_EQ(text(next_event(t).result.payload), "fine");
  EXPECT_FALSE(test::has_zombie_child());
}

TEST(PipeTransport, HungWorkerTimesOutAndIsReplaced) {
  PipeTransport t(1, [](const Bytes& in) -> Bytes {
    if (text(in) == "hang") std::this_thread::sleep_for(std::chrono::seconds(60));
    return in;
  });
  const pid_t hung = t.pid(0);
  ASSERT_TRUE(t.send(0, Job{1, text("hang")}));
  EXPECT_FALSE(t.receive(0.2).has_value());
  t.restart(0);
  EXPECT_NE(t.pid(0), hung);
  EXPECT_NE(::kill(hung, 0), 0);  // the hung process is gone (killed and reaped)
  ASSERT_TRUE(t.send(0, Job{2, text("ok")}));
  EXPECT_EQ(text(next_event(t).result.payload), "ok");
}

TEST(PipeTransport, ChildrenHoldOnlyTheirOwnSocket) {
  // Parent-side descriptors a child must not hold: a file and other workers' sockets.
  const int file = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  ASSERT_GE(file, 0);
  const auto list_fds = [](const Bytes&) -> Bytes {
    std::string all;
    for (const auto& t : test::open_fd_targets()) all += t + "\n";
    return Bytes(all.begin(), all.end());
  };
  for (const bool close_all : {true, false}) {
    PipeTransportParams p;
    p.close_inherited_fds = close_all;
    PipeTransport t(3, list_fds, p);
    for (int w = 0; w < 3; ++w) {
      ASSERT_TRUE(t.send(w, Job{0, {}}));
      const std::string fds = text(next_event(t).result.payload);
      size_t sockets = 0;
      for (size_t at = fds.find("socket:"); at != std::string::npos; at = fds.find("socket:", at + 1)) ++sockets;
      EXPECT_EQ(sockets, 1u) << "close_inherited_fds=" << close_all << "\n" << fds;
      const bool has_file = fds.find(std::to_string(file) + " -> /dev/null") != std::string::npos;
      EXPECT_EQ(has_file, !close_all) << fds;
    }
  }
  ::close(file);
}

TEST(PipeTransport, DestructorKillsStragglersAndLeavesNoChildren) {
  const int fds_before = test::open_fd_count();
  {
    PipeTransportParams p;
    p.shutdown_grace_s = 0.1;
    PipeTransport t(
        2,
        [](const Bytes& in) -> Bytes {
          std::this_thread::sleep_for(std::chrono::seconds(60));
          return in;
        },
        p);
    ASSERT_TRUE(t.send(0, Job{1, {}}));
    EXPECT_TRUE(test::has_any_child());
  }
  EXPECT_FALSE(test::has_any_child());
  EXPECT_EQ(test::open_fd_count(), fds_before);
}

TEST(PipeTransport, RejectsBadArguments) {
  EXPECT_THROW(PipeTransport(0, reverse), std::invalid_argument);
  EXPECT_THROW(PipeTransport(1, WorkFn{}), std::invalid_argument);
  PipeTransportParams p;
  p.shutdown_grace_s = -1;
  EXPECT_THROW(PipeTransport(1, reverse, p), std::invalid_argument);
  PipeTransport t(1, reverse);
  EXPECT_THROW(t.send(1, Job{}), std::out_of_range);
  EXPECT_THROW(t.restart(-1), std::out_of_range);
}

}  // namespace
}  // namespace robozoo
