// robozoo-log cppn: a logged genome drawn by Graphviz, from a tiny run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::testing {
namespace {

namespace fs = std::filesystem;

class LogCppn : public ::testing::Test {
 public:
  static inline fs::path dir, log;
  static void SetUpTestSuite() {
    dir = fs::temp_directory_path() / ("robozoo_log_cppn_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    log = dir / "run.lcmlog";
    const Outcome o = run_shell(
        join(evolve_args(log.string(), 2, {"--regime", "recurrent"},
                         {"--seed", "3", "--population", "10", "--generations", "2", "--steps", "200", "--quiet"})));
    ASSERT_EQ(o.status, 0) << o.output;
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }
  static std::string cppn(const std::string& args) {
    return "'" + bin("robozoo-log") + "' cppn '" + log.string() + "' " + args;
  }
};

/// The champion of the last generation, from robozoo-log cat.
int64_t last_champion() {
  const Outcome o =
      run_shell("'" + bin("robozoo-log") + "' cat '" + LogCppn::log.string() + "' --channel generation | tail -n 1");
  const size_t at = o.output.find("\"champion_id\":");
  EXPECT_NE(at, std::string::npos) << o.output;
  return std::stoll(o.output.substr(at + 14));
}

TEST_F(LogCppn, DefaultIsTheLastChampionAsDot) {
  const Outcome o = run_shell(cppn(""));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.output.rfind("digraph cppn {", 0), 0u) << o.output;
  EXPECT_NE(o.output.find("label=\"genome " + std::to_string(last_champion()) + ", generation 1"), std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("label=\"bias\""), std::string::npos);
  EXPECT_EQ(run_shell(cppn("--genome " + std::to_string(last_champion()))).output, o.output);
}

TEST_F(LogCppn, SvgToAFile) {
  const fs::path out = dir / "cppn.svg";
  const Outcome o = run_shell(cppn("--format svg -o '" + out.string() + "'"));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(o.output.empty()) << o.output;
  std::ifstream in(out);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

TEST_F(LogCppn, UnknownGenomeIsOneClearLine) {
  const Outcome o = run_shell(cppn("--genome 987654321"));
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.output.find("no genome 987654321 in the log"), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
}

TEST_F(LogCppn, BadOptionsAreRefused) {
  EXPECT_NE(run_shell(cppn("--format png")).status, 0);
  EXPECT_NE(run_shell(cppn("--bogus")).status, 0);
  const Outcome help = run_shell("'" + bin("robozoo-log") + "' cppn --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--genome"), std::string::npos);
}

}  // namespace
}  // namespace robozoo::testing
