// robozoo-stats DIR --sensitivity REFERENCE on a small real study: a reference
// experiment, a factor that changes one key on its seeds, and a factor still
// without results; the report's own command makes the same files again, and
// what cannot be compared is refused with exit status 2.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

// A small experiment in `out`: two trials per arm (seeds 1, 5 and 2, 6), with unit bias so
// that feed-forward robots reach the simulator, plus `extra`.
void small_experiment(const std::string& out, const std::string& generations, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {bin("robozoo-experiment"),
                                   "--out",
                                   out,
                                   "--trials",
                                   "2",
                                   "--population",
                                   "12",
                                   "--generations",
                                   generations,
                                   "--steps",
                                   "300",
                                   "--workers",
                                   "1",
                                   "--progress-interval",
                                   "0",
                                   "--set",
                                   "growth.bias_input=1.0"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_shell(join(args));
  ASSERT_EQ(r.status, 0) << r.output;
}

TEST(StatsSensitivityCli, ComparesAFactorWithTheReferenceAndMakesItsReportAgain) {
  TempDir t;
  small_experiment(t / "ref", "4", {});
  small_experiment(t / "runs", "3", {"--set", "growth.weight_mapping=proportional"});
  fs::create_directories(t / "study/proportional/results");
  fs::create_directories(t / "study/waiting/results");
  for (const auto& e : fs::directory_iterator(t / "runs/results"))
    fs::copy_file(e.path(), t / ("study/proportional/results/" + e.path().filename().string()));

  const std::string cd = "cd '" + t.path + "' && ";
  const auto r = run_shell(cd + bin("robozoo-stats") + " study --sensitivity ref/results --note 'A note.'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 factors compared at generation 3, 1 without results yet"), std::string::npos) << r.output;
  const std::string report = read_file(t / "study/report.md");
  EXPECT_NE(report.find("| proportional | `growth.weight_mapping` \"rescaled\" → \"proportional\" |"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("after 3 generations (generation record 2, counted from 0)"), std::string::npos);
  EXPECT_NE(report.find("- proportional: seeds feedforward 1 5; recurrent 2 6."), std::string::npos) << report;
  EXPECT_NE(report.find("- Factors without results yet: waiting."), std::string::npos);
  const std::string command = "build/bin/robozoo-stats study --sensitivity ref/results --generation 3 --note 'A note.'";
  ASSERT_NE(report.find(command), std::string::npos) << report;
  const std::string csv = read_file(t / "study/sensitivity.csv");
  EXPECT_NE(csv.find("\nproportional,\"growth.weight_mapping \"\"rescaled\"\" -> \"\"proportional\"\"\",3,"),
            std::string::npos)
      << csv;

  // The report's command, run again into another folder, writes the same files.
  const auto again = run_shell(cd + bin("robozoo-stats") +
                               command.substr(std::string("build/bin/robozoo-stats").size()) + " --out again");
  ASSERT_EQ(again.status, 0) << again.output;
  for (const std::string f : {"sensitivity.csv", "sensitivity_outcomes.csv", "sensitivity.gp"})
    EXPECT_EQ(read_file(t / ("again/" + f)), read_file(t / ("study/" + f))) << f;
  // The figure: gnuplot drew it, and the report shows it.
  const std::string png = read_file(t / "study/sensitivity.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_NE(report.find("](sensitivity.png)"), std::string::npos) << report;
  EXPECT_NE(r.output.find("sensitivity.gp report.md sensitivity.png"), std::string::npos) << r.output;
  // The reports differ only in the command (its --out).
  std::string made = read_file(t / "again/report.md");
  const std::string with_out =
      "build/bin/robozoo-stats study --sensitivity ref/results --generation 3 --out again --note 'A note.'";
  ASSERT_NE(made.find(with_out), std::string::npos);
  made.replace(made.find(with_out), with_out.size(), command);
  EXPECT_EQ(made, report);

  // A factor with fewer runs than the others (one still running) is compared on the seeds it
  // has, and named on the terminal and in the report.
  fs::create_directories(t / "partial");
  fs::copy(t / "study/proportional", t / "partial/complete", fs::copy_options::recursive);
  fs::copy(t / "study/proportional", t / "partial/running", fs::copy_options::recursive);
  ASSERT_TRUE(fs::remove(t / "partial/running/results/feedforward-s5.results.json"));
  const auto p = run_shell(cd + bin("robozoo-stats") + " partial --sensitivity ref/results --no-plots");
  ASSERT_EQ(p.status, 0) << p.output;
  EXPECT_NE(p.output.find("2 factors compared at generation 3; fewer runs: running (1 feedforward and 2 recurrent "
                          "runs, against 2 and 2)\n"),
            std::string::npos)
      << p.output;
  EXPECT_NE(read_file(t / "partial/report.md").find("**Fewer runs than the other factors**"), std::string::npos);
}

TEST(StatsSensitivityCli, RefusesWhatItCannotCompare) {
  TempDir t;
  small_experiment(t / "ref", "3", {});
  const std::string cd = "cd '" + t.path + "' && ";
  const std::string stats = bin("robozoo-stats");
  // A factor that changes nothing.
  fs::create_directories(t / "same/nothing");
  fs::copy(t / "ref/results", t / "same/nothing/results");
  auto r = run_shell(cd + stats + " same --sensitivity ref/results");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("has the reference's configuration: nothing was changed"), std::string::npos) << r.output;
  // A generation the runs did not reach.
  r = run_shell(cd + stats + " same --sensitivity ref/results --generation 9");
  EXPECT_EQ(r.status, 2) << r.output;
  // No factor with results; no folder at all.
  fs::create_directories(t / "empty/f/results");
  r = run_shell(cd + stats + " empty --sensitivity ref/results");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no factor in empty has compact results"), std::string::npos) << r.output;
  r = run_shell(cd + stats + " nowhere --sensitivity ref/results");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("nowhere is not a folder"), std::string::npos) << r.output;
  // --generation belongs to --sensitivity; --sensitivity excludes --same-as.
  r = run_shell(cd + stats + " ref/results --generation 2");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--generation belongs to --sensitivity"), std::string::npos) << r.output;
  r = run_shell(cd + stats + " same --sensitivity ref/results --same-as ref/results");
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(t / "same/report.md"));
}

}  // namespace
}  // namespace robozoo
