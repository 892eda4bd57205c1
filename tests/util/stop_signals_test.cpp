// StopWatcher in child processes (signals and their masks are per process): a
// stop signal writes the one-line message and ends the process with 128 + signal.
#include "util/stop_signals.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <thread>

namespace robozoo {
namespace {

struct Ended {
  int wait_status = 0;
  std::string err;  ///< what the child wrote to stderr
};

/// Runs `body` in a child whose stderr is captured; waits for it.
Ended in_child(const std::function<void()>& body) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fds[1], 2);
    ::close(fds[0]);
    ::close(fds[1]);
    body();
    ::_exit(0);
  }
  ::close(fds[1]);
  Ended e;
  char buf[512];
  ssize_t n;
  while ((n = ::read(fds[0], buf, sizeof buf)) > 0) e.err.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  ::waitpid(pid, &e.wait_status, 0);
  return e;
}

TEST(StopWatcher, SignalWritesTheMessageAndEndsTheProcess) {
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
    const Ended e = in_child([sig] {
      block_stop_signals();
      StopWatcher watcher("prog");
      watcher.set_message("first");
      std::atomic<int> done{1};
      watcher.set_message_source([&done] { return "after " + std::to_string(done.load()) + " generations"; });
      done = 3;  // read when the signal comes
      watcher.set_message("checkpoint intact after " + std::to_string(done.load()) + "; resume with: prog --resume");
      ::kill(::getpid(), sig);
      std::this_thread::sleep_for(std::chrono::seconds(10));  // the watcher ends us first
      ::_exit(0);
    });
    ASSERT_TRUE(WIFEXITED(e.wait_status)) << sig;
    EXPECT_EQ(WEXITSTATUS(e.wait_status), 128 + sig);
    EXPECT_EQ(e.err, "prog: stopped by signal " + std::to_string(sig) + " (" + strsignal(sig) +
                         "): checkpoint intact after 3; resume with: prog --resume\n");
  }
}

TEST(StopWatcher, MessageMadeWhenTheSignalComes) {
  const Ended e = in_child([] {
    block_stop_signals();
    StopWatcher watcher("prog");
    std::atomic<int> done{1};
    watcher.set_message_source([&done] { return "after " + std::to_string(done.load()) + " generations"; });
    done = 4;
    ::kill(::getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::seconds(10));
    ::_exit(0);
  });
  ASSERT_TRUE(WIFEXITED(e.wait_status));
  EXPECT_EQ(e.err, std::string("prog: stopped by signal 15 (") + strsignal(SIGTERM) + "): after 4 generations\n");
}

TEST(StopWatcher, WithADelayEndsSilentlyNoSoonerThanTheDelay) {
  constexpr std::chrono::milliseconds delay{300};
  const auto start = std::chrono::steady_clock::now();
  const Ended e = in_child([delay] {
    block_stop_signals();
    StopWatcher watcher("", delay);
    ::kill(::getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::seconds(10));  // the watcher ends us first
    ::_exit(0);
  });
  const auto lived = std::chrono::steady_clock::now() - start;
  ASSERT_TRUE(WIFEXITED(e.wait_status));
  EXPECT_EQ(WEXITSTATUS(e.wait_status), 128 + SIGTERM);
  EXPECT_EQ(e.err, "");  // an empty program name: no line
  EXPECT_GE(lived, delay);
}

TEST(StopWatcher, DestroyedDuringTheDelayTheProcessGoesOn) {
  const Ended e = in_child([] {
    block_stop_signals();
    {
      StopWatcher watcher("prog", std::chrono::seconds(10));
      ::kill(::getpid(), SIGTERM);
      sigset_t pending;
      do {  // until the watcher has taken the signal (and waits out its delay)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        sigpending(&pending);
      } while (sigismember(&pending, SIGTERM) == 1);
    }  // the program ends as it would have: the watcher does not end it
    ::_exit(5);
  });
  ASSERT_TRUE(WIFEXITED(e.wait_status));
  EXPECT_EQ(WEXITSTATUS(e.wait_status), 5);
  EXPECT_EQ(e.err, "");
}

TEST(StopWatcher, AfterTheWatcherASignalHasItsDefaultAction) {
  const Ended e = in_child([] {
    block_stop_signals();
    { StopWatcher watcher("prog"); }
    ::kill(::getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::seconds(10));
    ::_exit(0);
  });
  ASSERT_TRUE(WIFSIGNALED(e.wait_status));
  EXPECT_EQ(WTERMSIG(e.wait_status), SIGTERM);
  EXPECT_EQ(e.err, "");
}

TEST(StopWatcher, RefusesToStartWithTheSignalsUnblocked) {
  const Ended e = in_child([] {
    unblock_stop_signals();
    try {
      StopWatcher watcher("prog");
    } catch (const std::logic_error&) {
      ::_exit(7);
    }
    ::_exit(0);
  });
  ASSERT_TRUE(WIFEXITED(e.wait_status));
  EXPECT_EQ(WEXITSTATUS(e.wait_status), 7);
}

}  // namespace
}  // namespace robozoo
