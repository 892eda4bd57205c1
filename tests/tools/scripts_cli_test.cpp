// Every script under tools/ answers --help (exit 0, its usage, which
// names the script) and refuses an unknown option with one line and exit 2, before
// it installs, builds or runs anything. The scripts are found in the source tree, so
// a new script is checked without a change here.
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

std::vector<fs::path> scripts() {
  std::vector<fs::path> found;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(ROBOZOO_SOURCE_DIR) / "tools")) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".sh" || ext == ".sbatch")) found.push_back(e.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

// The sbatch script checks the flags it passes on with this build's robozoo-evolve.
Outcome run_script(const fs::path& script, const std::string& args) {
  return run_shell("env ROBOZOO_BIN='" + std::string(ROBOZOO_BIN_DIR) + "' timeout 60 bash '" + script.string() + "' " +
                   args + " </dev/null");
}

}  // namespace

TEST(ScriptsCli, TheScriptsAreFound) {
  const auto all = scripts();
  const auto has = [&](const std::string& rel) {
    return std::find(all.begin(), all.end(), fs::path(ROBOZOO_SOURCE_DIR) / rel) != all.end();
  };
  EXPECT_TRUE(has("tools/demo.sh"));
  EXPECT_TRUE(has("tools/test.sh"));
  EXPECT_TRUE(has("tools/experiment/slurm/robozoo-trials.sbatch"));
  EXPECT_TRUE(has("tools/experiment/paper_experiment.sh"));
  EXPECT_TRUE(has("tools/measure/bus_loss_study.sh"));
  EXPECT_GE(all.size(), 10u);
}

TEST(ScriptsCli, EveryScriptAnswersHelp) {
  for (const auto& s : scripts()) {
    const Outcome o = run_script(s, "--help");
    EXPECT_EQ(o.status, 0) << s << ":\n" << o.output;
    EXPECT_NE(o.output.find(s.filename().string()), std::string::npos) << s << ": usage does not name it:\n"
                                                                       << o.output;
  }
}

TEST(ScriptsCli, EveryScriptRefusesAnUnknownOptionInOneLine) {
  for (const auto& s : scripts()) {
    const Outcome o = run_script(s, "--bogus");
    EXPECT_EQ(o.status, 2) << s << ":\n" << o.output;
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << s << ":\n" << o.output;
    EXPECT_NE(o.output.find("--bogus"), std::string::npos) << s << ":\n" << o.output;
  }
}
