#include "util/program_path.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

void write_program(const std::string& path, bool executable) {
  std::ofstream(path) << "#!/bin/sh\n";
  ::chmod(path.c_str(), executable ? 0755 : 0644);
}

TEST(ProgramPath, FindsTheFirstExecutableOnThePath) {
  TempDir a, b, c;
  write_program(a / "launcher", false);  // there, but not executable
  write_program(b / "launcher", true);
  write_program(c / "launcher", true);
  EXPECT_EQ(find_program("launcher", a.path + ":" + b.path + ":" + c.path), b / "launcher");
  EXPECT_EQ(find_program("launcher", c.path + ":" + b.path), c / "launcher");
  EXPECT_EQ(find_program("launcher", a.path), "");
  EXPECT_EQ(find_program("missing", a.path + ":" + b.path), "");
  EXPECT_EQ(find_program("", b.path), "");
}

TEST(ProgramPath, APathIsTakenAsGiven) {
  EXPECT_EQ(find_program("/opt/mpi/bin/mpirun", "/usr/bin"), "/opt/mpi/bin/mpirun");
  EXPECT_EQ(find_program("./mpirun", "/usr/bin"), "./mpirun");
}

TEST(ProgramPath, IsExecutableWantsARegularExecutableFile) {
  TempDir d;
  write_program(d / "yes", true);
  write_program(d / "no", false);
  EXPECT_TRUE(is_executable(d / "yes"));
  EXPECT_FALSE(is_executable(d / "no"));
  EXPECT_FALSE(is_executable(d.path));  // a folder
  EXPECT_FALSE(is_executable(d / "absent"));
}

}  // namespace
}  // namespace robozoo
