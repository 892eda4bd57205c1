// robozoo-stats from compact results: a small real experiment's logs give
// report A; the compact results robozoo-experiment left give report B; every
// file of A and B is the same byte for byte (the zoo sheets, drawn from logs in
// one and re-simulated from results in the other, left out of both with
// --no-zoo). robozoo-stats --export-results writes the same compact results
// from the logs as robozoo-experiment did.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(StatsResultsCli, CompactResultsGiveTheReportOfTheLogsByteForByte) {
  TempDir logs_home, results_home, reports;
  const std::string exp = logs_home / "exp";
  const auto run =
      run_shell(join({bin("robozoo-experiment"), "--out", exp, "--trials", "2", "--population", "12", "--generations",
                      "4", "--steps", "300", "--workers", "1", "--progress-interval", "0"}));
  ASSERT_EQ(run.status, 0) << run.output;
  // One compact result per trial, in OUT/results.
  const std::vector<std::string> results = files_in(exp + "/results");
  ASSERT_EQ(results, (std::vector<std::string>{"feedforward-s1.results.json", "feedforward-s5.results.json",
                                               "recurrent-s2.results.json", "recurrent-s6.results.json"}));
  // The same folder name elsewhere, holding only the compact results: the report names its source folder.
  fs::create_directories(results_home / "exp");
  for (const auto& f : results) fs::copy_file(exp + "/results/" + f, results_home / "exp/" + f);

  const std::string flags = " --no-zoo --note 'a note'";
  // Each into a folder "stats" beside its input: the report's robozoo-stats command (with --out) is the same.
  const auto a = run_shell("cd '" + logs_home.path + "' && " + bin("robozoo-stats") + " exp --out stats" + flags);
  ASSERT_EQ(a.status, 0) << a.output;
  const auto b = run_shell("cd '" + results_home.path + "' && " + bin("robozoo-stats") + " exp --out stats" + flags);
  ASSERT_EQ(b.status, 0) << b.output;
  const std::string A = logs_home / "stats", B = results_home / "stats";
  const auto fa = files_in(A), fb = files_in(B);
  ASSERT_EQ(fa, fb);
  EXPECT_NE(std::find(fa.begin(), fa.end(), "report.md"), fa.end());
  EXPECT_NE(std::find(fa.begin(), fa.end(), "fig1_fitness.png"), fa.end());
  EXPECT_GE(fa.size(), 15u);
  for (const auto& f : fa) EXPECT_EQ(read_file(A + "/" + f), read_file(B + "/" + f)) << f;
  // The report has what only the checkpoints (next to the logs) know: robozoo-evolve's time.
  EXPECT_NE(read_file(B + "/report.md").find("of wall time on the 4 runs with a checkpoint"), std::string::npos);
  // Its reproduce command is the command that ran, options that shape the files included.
  EXPECT_NE(
      read_file(B + "/report.md")
          .find("build/bin/robozoo-stats exp --compare feedforward,recurrent --out stats --no-zoo --note 'a note'"),
      std::string::npos)
      << read_file(B + "/report.md");

  // With zoo sheets asked for, a folder of compact results gets them too: each arm's best-of-run
  // robots re-grown and re-simulated from the results (robozoo-render zoo checks their fitness).
  const auto zoo = run_shell("cd '" + results_home.path + "' && " + bin("robozoo-stats") + " exp --no-plots --out '" +
                             (reports / "C") + "'");
  ASSERT_EQ(zoo.status, 0) << zoo.output;
  const std::string with_zoo = read_file(reports / "C/report.md");
  EXPECT_NE(with_zoo.find("best-of-run robots of the 2 runs (robozoo-render zoo RESULTS..."), std::string::npos)
      << with_zoo;
  for (const char* png : {"zoo-feedforward.png", "zoo-recurrent.png"}) {
    EXPECT_GT(fs::file_size(reports / (std::string("C/") + png)), 10000u) << png;
    EXPECT_NE(with_zoo.find(std::string("](") + png + ")"), std::string::npos) << png;
  }

  // --export-results: the same files robozoo-experiment wrote.
  const auto ex = run_shell(bin("robozoo-stats") + " '" + exp + "' --export-results '" + (reports / "R") + "'");
  ASSERT_EQ(ex.status, 0) << ex.output;
  ASSERT_EQ(files_in(reports / "R"), results);
  for (const auto& f : results) EXPECT_EQ(read_file(reports / "R/" + f), read_file(exp + "/results/" + f)) << f;
}

TEST(StatsResultsCli, AFolderWithoutLogsOrResultsIsAnError) {
  TempDir d;
  const auto r = run_shell(bin("robozoo-stats") + " '" + d.path + "' --no-plots --no-zoo");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("(nor compact results, *.results.json)"), std::string::npos) << r.output;
  std::ofstream(d / "x.results.json") << "{\"format\": \"robozoo-run-results\", \"version\": 1}";
  const auto bad = run_shell(bin("robozoo-stats") + " '" + d.path + "' --no-plots --no-zoo");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find(d.path + "/x.results.json: results.run: missing"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace robozoo
