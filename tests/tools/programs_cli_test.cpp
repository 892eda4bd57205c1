// Every program robozoo builds (robozoo-* in the build's bin folder) answers
// --help and --version with exit 0, and refuses an unknown option with one
// line, "PROGRAM: what (see --help)", and exit 2, before it does anything.
// The programs are found in the bin folder, so a new one is checked without a
// change here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/subprocess.hpp"

namespace fs = std::filesystem;
using robozoo::testing::Outcome;
using robozoo::testing::run_shell;

namespace {

std::vector<fs::path> programs() {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(ROBOZOO_BIN_DIR))
    if (e.is_regular_file() && e.path().filename().string().rfind("robozoo-", 0) == 0) found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

Outcome run(const fs::path& program, const std::string& args) {
  return run_shell("timeout 60 '" + program.string() + "' " + args + " </dev/null");
}

}  // namespace

TEST(ProgramsCli, TheProgramsAreFound) {
  const auto all = programs();
  for (const char* name : {"robozoo-evolve", "robozoo-replay", "robozoo-render", "robozoo-view", "robozoo-experiment",
                           "robozoo-stats", "robozoo-log"})
    EXPECT_NE(std::find(all.begin(), all.end(), fs::path(ROBOZOO_BIN_DIR) / name), all.end()) << name;
}

TEST(ProgramsCli, EveryProgramAnswersHelpAndVersion) {
  for (const auto& p : programs()) {
    const Outcome help = run(p, "--help");
    EXPECT_EQ(help.status, 0) << p << ":\n" << help.output;
    EXPECT_NE(help.output.find(p.filename().string()), std::string::npos) << p << ": help does not name it:\n"
                                                                          << help.output;
    const Outcome version = run(p, "--version");
    EXPECT_EQ(version.status, 0) << p << ":\n" << version.output;
    EXPECT_NE(version.output.find("robozoo"), std::string::npos) << p << ":\n" << version.output;
  }
}

TEST(ProgramsCli, EveryProgramRefusesAnUnknownOptionInOneLine) {
  for (const auto& p : programs()) {
    const Outcome o = run(p, "--bogus");
    EXPECT_EQ(o.status, 2) << p << ":\n" << o.output;
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << p << ":\n" << o.output;
    EXPECT_EQ(o.output.rfind(p.filename().string() + ": ", 0), 0u) << p << ":\n" << o.output;
    // Named even where a required argument or subcommand is missing too (CLI11 checks those first).
    EXPECT_NE(o.output.find("not expected: --bogus"), std::string::npos) << p << ":\n" << o.output;
    EXPECT_NE(o.output.find("(see --help)"), std::string::npos) << p << ":\n" << o.output;
  }
}
