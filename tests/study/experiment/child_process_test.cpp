#include "study/experiment/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

// Gone, or a zombie waiting for init to reap it.
bool ended(pid_t pid) {
  const std::string stat = read_file("/proc/" + std::to_string(pid) + "/stat");
  if (stat.empty()) return true;
  const size_t close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'Z';
}

TEST(ChildProcess, ExitStatusAndOutputAppended) {
  TempDir dir;
  SignalBlock block;
  for (int i = 0; i < 2; ++i) {
    const pid_t pid = spawn_child({"/bin/sh", "-c", "echo run; exit 3"}, dir / "out.txt");
    ChildEvent ev;
    do ev = wait_child(block, pid, 5.0);
    while (ev.kind == ChildEvent::Timeout);
    EXPECT_EQ(ev.kind, ChildEvent::Exited);
    EXPECT_EQ(ev.status, 3);
  }
  EXPECT_EQ(read_file(dir / "out.txt"), "run\nrun\n");
}

TEST(ChildProcess, AStopSignalToTheDriverIsReportedAndTheChildGroupStopped) {
  TempDir dir;
  SignalBlock block;
  // The child starts a grandchild in its group; both must end.
  const pid_t pid = spawn_child({"/bin/sh", "-c", "sleep 30 & echo $! > " + (dir / "gc") + "; wait"}, dir / "out");
  while (read_file(dir / "gc").empty()) ::usleep(2000);
  const pid_t grandchild = std::stoi(read_file(dir / "gc"));
  EXPECT_EQ(wait_child(block, pid, 0.05).kind, ChildEvent::Timeout);
  ::kill(::getpid(), SIGINT);  // blocked: taken by wait_child, not fatal
  const ChildEvent ev = wait_child(block, pid, 5.0);
  EXPECT_EQ(ev.kind, ChildEvent::Signalled);
  EXPECT_EQ(ev.signal, SIGINT);
  EXPECT_EQ(stop_child(pid), 128 + SIGTERM);
  for (int i = 0; i < 500 && !ended(grandchild); ++i) ::usleep(2000);
  EXPECT_TRUE(ended(grandchild)) << "the grandchild outlived the stop";
}

TEST(ChildProcess, AProgramThatCannotRunIsAnError) {
  TempDir dir;
  SignalBlock block;
  EXPECT_THROW(spawn_child({"/nonexistent/robozoo-evolve"}, dir / "out"), std::runtime_error);
  EXPECT_THROW(spawn_child({"/bin/true"}, dir / "no/such/folder/out"), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
