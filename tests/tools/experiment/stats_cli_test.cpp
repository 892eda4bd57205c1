// robozoo-stats on hand-made logs with known champions: the tables come out as
// worked out by hand (tests/study/analysis/hand_made_experiment.hpp), gnuplot
// makes the PNGs, robozoo-render is called for the zoo sheets when it exists
// and the report says so when it does not.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "study/analysis/compare/ttest.hpp"
#include "tests/study/analysis/hand_made_experiment.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

// A CSV file as rows of fields (quoted fields allowed), keyed by the first column.
std::map<std::string, std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::istringstream in(read_file(path));
  std::string line;
  std::vector<std::string> header;
  std::map<std::string, std::map<std::string, std::string>> rows;
  auto split = [](const std::string& l) {
    std::vector<std::string> f(1);
    bool q = false;
    for (size_t i = 0; i < l.size(); ++i) {
      const char c = l[i];
      if (q && c == '"' && i + 1 < l.size() && l[i + 1] == '"') {
        f.back() += '"';
        ++i;
      } else if (c == '"') {
        q = !q;
      } else if (c == ',' && !q) {
        f.emplace_back();
      } else {
        f.back() += c;
      }
    }
    return f;
  };
  while (std::getline(in, line)) {
    const auto f = split(line);
    if (header.empty()) {
      header = f;
      continue;
    }
    for (size_t i = 0; i < f.size() && i < header.size(); ++i) rows[f[0]][header[i]] = f[i];
  }
  return rows;
}

double num(const std::string& s) { return std::stod(s); }

std::string stats(const std::string& args) { return bin("robozoo-stats") + " " + args; }

TEST(StatsCli, HandMadeLogsGiveTheStatisticsWorkedOutByHand) {
  TempDir dir;
  write_hand_made_experiment(dir.path);
  const auto o = run_shell(stats("'" + dir.path + "' --render /nonexistent/robozoo-render"));
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string out = dir / "stats";

  const auto curve = read_csv(out + "/fitness_curve.csv");
  EXPECT_DOUBLE_EQ(num(curve.at("0").at("feedforward_mean")), 9.5);
  EXPECT_DOUBLE_EQ(num(curve.at("0").at("feedforward_se")), 5.5);
  EXPECT_DOUBLE_EQ(num(curve.at("2").at("recurrent_mean")), 17.25);
  EXPECT_EQ(curve.at("2").at("recurrent_n"), "2");

  const auto morph = read_csv(out + "/morphology.csv");
  EXPECT_DOUBLE_EQ(num(morph.at("spheres").at("feedforward_mean")), 3.0);
  EXPECT_DOUBLE_EQ(num(morph.at("spheres").at("recurrent_mean")), 3.5);
  EXPECT_DOUBLE_EQ(num(morph.at("leaves").at("feedforward_mean")), 1.5);
  EXPECT_DOUBLE_EQ(num(morph.at("ground_fraction").at("recurrent_mean")), 0.625);

  const auto geno = read_csv(out + "/genotype.csv");
  EXPECT_DOUBLE_EQ(num(geno.at("forward_links").at("feedforward_mean")), 1.5);
  // By drawing position: recurrent s1 has 0 -> 20 -> 9 forward and 9 -> 20 not; s2 0 -> 9 forward, 9 -> 9 not.
  EXPECT_DOUBLE_EQ(num(geno.at("forward_links").at("recurrent_mean")), 1.5);
  EXPECT_DOUBLE_EQ(num(geno.at("cycle_links").at("recurrent_mean")), 1.5);
  EXPECT_DOUBLE_EQ(num(geno.at("links").at("recurrent_mean")), 2.5);

  const auto champ = read_csv(out + "/champion_changes.csv");
  // Pooled events: described ({0, 1} and {1, 1, 1, 0}), not tested.
  const auto& pooled = champ.at("topology_changed");
  EXPECT_EQ(pooled.at("samples"), "pooled_events");
  EXPECT_DOUBLE_EQ(num(pooled.at("feedforward_mean")), 0.5);
  EXPECT_DOUBLE_EQ(num(pooled.at("recurrent_mean")), 0.75);
  EXPECT_EQ(pooled.at("student_p"), "nan");
  EXPECT_NEAR(num(champ.at("improvement_changed").at("recurrent_mean")), 3.5 / 3.0, 1e-9);
  // Per run, tested: each run's share, feed-forward {0, 1}, recurrent {1, 0.5}.
  const auto& share = champ.at("topology_changed_per_run");
  EXPECT_EQ(share.at("samples"), "runs");
  EXPECT_EQ(share.at("student_df"), "2");
  EXPECT_NEAR(num(share.at("student_p")), ttest_ind({1, 0.5}, {0, 1}).p, 1e-9);
  EXPECT_NEAR(num(share.at("welch_p")), welch_ttest({1, 0.5}, {0, 1}).p, 1e-9);
  EXPECT_EQ(champ.at("improvement_same_per_run").at("student_p"), "nan");  // one run each

  const auto claims = read_csv(out + "/claims.csv");
  EXPECT_EQ(claims.at("best_fitness").at("role"), "primary");
  EXPECT_EQ(claims.at("recurrent_links").at("role"), "by_construction");
  EXPECT_EQ(claims.at("topology_changed").at("role"), "descriptive");
  EXPECT_EQ(claims.at("joints").at("role"), "secondary");

  const auto runs = read_csv(out + "/runs.csv");
  ASSERT_EQ(runs.size(), 4u);
  const auto events = read_file(out + "/champion_change_events.csv");
  EXPECT_EQ(std::count(events.begin(), events.end(), '\n'), 1 + 2 + 4);  // header, 2 + 4 new champions

  for (const char* png : {"fig1_fitness.png", "fig2_morphology.png", "fig3_genotype.png", "champion_changes.png"}) {
    struct stat st {};
    EXPECT_EQ(::stat((out + "/" + png).c_str(), &st), 0) << png;
    EXPECT_GT(st.st_size, 5000) << png;
  }
  const std::string report = read_file(out + "/report.md");
  EXPECT_NE(report.find("96.99 % (recurrent) vs 59.92 % (feed-forward)"), std::string::npos);
  EXPECT_NE(report.find("| 50.00 ± 50.00 % (2) | 75.00 ± 25.00 % (2) |"), std::string::npos) << report;
  EXPECT_EQ(report.rfind("# robozoo: recurrent vs feed-forward CPPNs\n\nThe paper's fitness result (recurrent CPPNs "
                         "fitter) is **inconclusive** at generation 2 (the last) with 2 feed-forward and 2 recurrent "
                         "runs",
                         0),
            0u)
      << report;
  EXPECT_NE(report.find("robozoo-render is missing (looked for /nonexistent/robozoo-render)"), std::string::npos);
  EXPECT_NE(report.find("![Figure 2](fig2_morphology.png)"), std::string::npos);
  EXPECT_NE(report.find("1 feed-forward, 0 recurrent"), std::string::npos);  // best-of-run without poses
  // The hand-made seeds (1 and 2 in both arms) are not robozoo-experiment's: one robozoo-evolve per run.
  EXPECT_NE(report.find("--regime feedforward --seed 2 --population 10 --generations 3 --run-id feedforward-s2"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("build/bin/robozoo-stats " + dir.path + " --compare feedforward,recurrent\n"),
            std::string::npos);
}

TEST(StatsCli, CallsRobozooRenderForEachRegimesZooSheet) {
  TempDir dir;
  write_hand_made_experiment(dir.path);
  // A stand-in robozoo-render that records its arguments and writes the -o file.
  const std::string render = dir / "fake-render";
  std::ofstream(render) << "#!/bin/sh\necho \"$@\" >> '" << (dir / "render-calls") << "'\n"
                        << "while [ $# -gt 0 ]; do if [ \"$1\" = -o ]; then echo png > \"$2\"; fi; shift; done\n";
  ::chmod(render.c_str(), 0755);
  const auto o = run_shell(stats("'" + dir.path + "' -o '" + (dir / "out") + "' --no-plots --render '" + render + "'"));
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string calls = read_file(dir / "render-calls");
  EXPECT_NE(calls.find("zoo " + dir.path + "/feedforward-s1.lcmlog " + dir.path + "/feedforward-s2.lcmlog -o " +
                       (dir / "out/zoo-feedforward.png") + " --best-of-run"),
            std::string::npos)
      << calls;
  EXPECT_NE(calls.find("recurrent-s2.lcmlog -o " + (dir / "out/zoo-recurrent.png") + " --best-of-run"),
            std::string::npos);
  const std::string report = read_file(dir / "out/report.md");
  EXPECT_NE(report.find("![recurrent zoo](zoo-recurrent.png)"), std::string::npos);
  EXPECT_FALSE(file_exists(dir / "out/fig1_fitness.png"));  // --no-plots
}

TEST(StatsCli, UnfinishedRunsAreLeftOutUnlessAskedFor) {
  TempDir dir;
  write_hand_made_experiment(dir.path);
  HandRun unfinished = hand_made_experiment()[2];
  unfinished.seed = 9;
  unfinished.generations_requested = 10;
  write_hand_log(dir / "recurrent-s9.lcmlog", unfinished);
  std::ofstream(dir / "notes.txt") << "not a log";
  std::ofstream(dir / "broken.lcmlog") << "garbage";

  auto o = run_shell(stats("'" + dir.path + "' --no-plots --no-zoo"));
  ASSERT_EQ(o.status, 0) << o.output;
  auto runs = read_csv(dir / "stats/runs.csv");
  EXPECT_EQ(runs.size(), 4u);
  std::string report = read_file(dir / "stats/report.md");
  EXPECT_NE(report.find("Left out: recurrent-s9.lcmlog: unfinished (3 of 10 generations)"), std::string::npos)
      << report;
  EXPECT_NE(report.find("Left out: broken.lcmlog"), std::string::npos);

  o = run_shell(stats("'" + dir.path + "' --no-plots --no-zoo --include-unfinished"));
  ASSERT_EQ(o.status, 0) << o.output;
  runs = read_csv(dir / "stats/runs.csv");
  EXPECT_EQ(runs.size(), 5u);
}

TEST(StatsCli, CompareAndAlphaReachTheReport) {
  TempDir dir;
  write_hand_made_experiment(dir.path);
  // Recurrent as the control, feed-forward as the experimental arm, at alpha 0.5:
  // feed-forward {16, 17} against recurrent {18, 16.5}, t = -0.83, p = 0.49 < 0.5,
  // recurrent fitter as the paper says: reproduced at this (silly) level.
  const auto o = run_shell(stats("'" + dir.path + "' --no-plots --no-zoo --compare recurrent,feedforward --alpha 0.5"));
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string report = read_file(dir / "stats/report.md");
  EXPECT_NE(report.find("is **reproduced** at generation 2 (the last) with 2 recurrent and 2 feed-forward runs"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("at α = 0.50"), std::string::npos);
  // The command that ran, with the options that shape its files.
  EXPECT_NE(report.find(" --compare recurrent,feedforward --alpha 0.5 --no-plots --no-zoo\n"), std::string::npos)
      << report;
  const auto curve = read_csv(dir / "stats/fitness_curve.csv");
  EXPECT_EQ(curve.at("2").at("recurrent_n"), "2");
  // Feed-forward minus recurrent at generation 2.
  EXPECT_NEAR(num(curve.at("2").at("student_t")), ttest_ind({16, 17}, {18, 16.5}).t, 1e-9);
  EXPECT_NE(run_shell(stats("'" + dir.path + "' --compare recurrent,recurrent")).status, 0);
  EXPECT_NE(run_shell(stats("'" + dir.path + "' --compare feedforward,nonsense")).status, 0);
  EXPECT_NE(run_shell(stats("'" + dir.path + "' --alpha 0.9")).status, 0);
}

TEST(StatsCli, NoLogsIsAnError) {
  TempDir dir;
  const auto o = run_shell(stats("'" + dir.path + "'"));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.output.find("no *.lcmlog in"), std::string::npos);
  EXPECT_EQ(run_shell(stats("/nonexistent/folder")).status, 2);
}

}  // namespace
}  // namespace robozoo
