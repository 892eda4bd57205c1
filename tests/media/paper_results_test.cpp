// The committed paper-size experiment (media/experiment/paper): every compact
// result is a finished trial of its milestone's plan, made by the milestone's pinned
// software version with the milestone's configuration;
// robozoo-stats, run as each committed report's own reproduce command says (a milestone's
// report, and the full comparison of each other arm with the control beside it), gives
// that report, its tables and its plot scripts byte for byte (the PNGs exist; their
// bytes depend on gnuplot's and cairo's builds); and a later milestone's results
// repeat the milestone's they continue field for field (runs are deterministic, even
// when a trial ran again from generation 0 on another machine). Every committed portable
// checkpoint is a trial of its milestone's plan still in progress, made by the pinned version
// with the milestone's configuration, and one that continues a trial the earlier milestone
// finished carries that trial's committed result.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/experiment/portable_checkpoint.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

const std::string kPaper = "media/experiment/paper";

struct Milestone {
  std::string folder;      ///< relative to the repository
  int generations;         ///< the milestone's end
  std::string version;     ///< the file (under kPaper) that names its software version
  int trials = 30;         ///< trials per arm (count)
  bool four_arms = false;  ///< also recurrent-sparse and recurrent-zero
  std::string continues;   ///< the folder of the milestone whose trials it continues ("" for none)
  /// Configuration values every result must hold (JSON pointer -> value).
  std::map<std::string, nlohmann::json> config;
};

/// Every milestone of tools/experiment/paper_experiment.sh, in order.
std::vector<Milestone> all_milestones() {
  const std::map<std::string, nlohmann::json> m3 = {
      {"/growth/bias_input", 0.3}, {"/growth/weight_mapping", "rescaled"}, {"/neat/add_node_innovations", "fresh"}};
  std::vector<Milestone> out = {
      {kPaper, 30, "VERSION", 30, true, "", {{"/growth/bias_input", 1.0}}},
      {kPaper + "/m2", 60, "VERSION", 30, false, kPaper, {{"/growth/bias_input", 1.0}}},
      {kPaper + "/m3", 60, "m3/VERSION", 30, false, "", m3},
  };
  const std::map<std::string, std::pair<std::string, nlohmann::json>> factors = {
      {"bias-1.0", {"/growth/bias_input", 1.0}},
      {"proportional-weights", {"/growth/weight_mapping", "proportional"}},
      {"shared-add-node", {"/neat/add_node_innovations", "shared"}},
      {"no-contact-rule", {"/sim/rolling_contact_rule", false}},
      {"cap-100", {"/growth/max_spheres", 100}}};
  for (const auto& [name, change] : factors) {
    std::map<std::string, nlohmann::json> config = m3;
    config[change.first] = change.second;
    config["/sim/rolling_spin_rule"] = true;
    out.push_back({kPaper + "/sensitivity/" + name, 30, "m3/VERSION", 10, false, "", config});
  }
  out.push_back({kPaper + "/m3/g100", 100, "m3/VERSION", 30, false, kPaper + "/m3", m3});
  out.push_back({kPaper + "/m3/g150", 150, "m3/VERSION", 30, false, kPaper + "/m3/g100", m3});
  out.push_back({kPaper + "/m3/g500", 500, "m3/VERSION", 30, false, kPaper + "/m3/g150", m3});
  return out;
}

/// The milestones whose results are committed, in order.
std::vector<Milestone> committed_milestones() {
  std::vector<Milestone> out;
  const std::string root = ROBOZOO_SOURCE_DIR;
  for (const Milestone& m : all_milestones())
    if (fs::is_directory(root + "/" + m.folder + "/results")) out.push_back(m);
  return out;
}

std::vector<std::string> result_files(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(std::string(ROBOZOO_SOURCE_DIR) + "/" + folder + "/results"))
    out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// The pinned version's 12-character commit, from the milestone's version file.
std::string pinned_version(const Milestone& m) {
  std::string version = read_file(std::string(ROBOZOO_SOURCE_DIR) + "/" + kPaper + "/" + m.version);
  version = version.substr(0, version.find_first_of("\n "));
  EXPECT_GE(version.size(), 12u) << m.version << ": " << version;
  return version.substr(0, 12);
}

/// A compact result's run is trial `arm`-s`seed` of the milestone's plan, made by its pinned
/// version with its configuration (the generations asked for aside).
void expect_trial_of(const Milestone& m, const std::string& version, const std::string& arm, long seed,
                     const nlohmann::json& run) {
  const std::map<std::string, int> arm_index = {
      {"feedforward", 0}, {"recurrent", 1}, {"recurrent-sparse", 2}, {"recurrent-zero", 3}};
  ASSERT_TRUE(arm_index.count(arm)) << arm;
  // Trial k of arm a has seed 4(k - 1) + a + 1 (docs/experiment.md), k from 1 to the milestone's trials.
  EXPECT_EQ((seed - 1) % 4, arm_index.at(arm));
  EXPECT_LE((seed - 1) / 4 + 1, m.trials);
  EXPECT_EQ(run.at("software_version").get<std::string>(), version);
  EXPECT_EQ(run.at("arm").get<std::string>(), arm);
  EXPECT_EQ(run.at("seed").get<long>(), seed);
  EXPECT_EQ(run.at("population").get<int>(), 150);
  EXPECT_EQ(run.at("steps").get<int>(), 2500);
  for (const auto& [pointer, value] : m.config) {
    const nlohmann::json::json_pointer at(pointer);
    ASSERT_TRUE(run.at("config").contains(at)) << pointer;
    EXPECT_EQ(run.at("config").at(at), value) << pointer;
  }
}

TEST(PaperResults, EveryCommittedResultIsAFinishedTrialOfThePlanMadeByThePinnedVersion) {
  const auto milestones = committed_milestones();
  ASSERT_FALSE(milestones.empty()) << "no " << kPaper << "/results";
  const std::regex name_rule("([a-z-]+)-s([0-9]+)\\.results\\.json");
  for (const Milestone& m : milestones) {
    const std::string version = pinned_version(m);
    std::map<std::string, int> per_arm;
    for (const auto& f : result_files(m.folder)) {
      SCOPED_TRACE(m.folder + "/results/" + f);
      std::smatch match;
      ASSERT_TRUE(std::regex_match(f, match, name_rule));
      const std::string arm = match[1];
      ++per_arm[arm];
      const nlohmann::json j =
          nlohmann::json::parse(read_file(std::string(ROBOZOO_SOURCE_DIR) + "/" + m.folder + "/results/" + f));
      const nlohmann::json& run = j.at("run");
      expect_trial_of(m, version, arm, std::stol(match[2]), run);
      EXPECT_EQ(run.at("generations").get<int>(), m.generations);
      EXPECT_EQ(j.at("generations").at("generation").size(), static_cast<size_t>(m.generations));  // finished
      EXPECT_FALSE(j.at("truncated").get<bool>());
      EXPECT_EQ(j.at("undecodable").get<int>(), 0);
    }
    for (const auto& [arm, n] : per_arm) EXPECT_LE(n, m.trials) << m.folder << " " << arm;
    if (!m.four_arms) {  // only M1 has the recurrent-sparse and recurrent-zero arms
      EXPECT_EQ(per_arm.count("recurrent-sparse") + per_arm.count("recurrent-zero"), 0u) << m.folder;
    }
  }
}

/// The robozoo-stats command of a committed report's Reproduce section ("" when none).
std::string stats_command_of(const std::string& report) {
  std::istringstream in(report);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("build/bin/robozoo-stats ", 0) == 0) return line;
  return "";
}

/// Every committed report under kPaper (a milestone's, and the full comparisons of other
/// arms in folders beside it): its folder, relative to the repository, in order.
std::vector<std::string> committed_reports() {
  std::vector<std::string> out;
  const fs::path root = ROBOZOO_SOURCE_DIR;
  for (const auto& e : fs::recursive_directory_iterator(root / kPaper))
    if (e.is_regular_file() && e.path().filename() == "report.md")
      out.push_back(fs::relative(e.path().parent_path(), root).string());
  std::sort(out.begin(), out.end());
  return out;
}

/// A temporary copy of every milestone's committed results at the same relative paths, so
/// that a report's command runs as it ran.
void copy_results(const TempDir& t) {
  for (const Milestone& m : committed_milestones()) {
    fs::create_directories(t / (m.folder + "/results"));
    for (const auto& f : result_files(m.folder))
      fs::copy_file(std::string(ROBOZOO_SOURCE_DIR) + "/" + m.folder + "/results/" + f,
                    t / (m.folder + "/results/" + f));
  }
}

TEST(PaperResults, RobozooStatsReproducesEachCommittedReportByteForByte) {
  const auto reports = committed_reports();
  for (const std::string& folder : reports) {
    SCOPED_TRACE(folder);
    const std::string committed = std::string(ROBOZOO_SOURCE_DIR) + "/" + folder;
    std::string command = stats_command_of(read_file(committed + "/report.md"));
    ASSERT_FALSE(command.empty()) << "the committed report names no robozoo-stats command";
    // The report's command writes into the report's folder (the committed files' place).
    ASSERT_TRUE(std::regex_search(command, std::regex(" --out " + folder + "( |$)"))) << command;
    command.replace(0, std::string("build/bin/robozoo-stats").size(), bin("robozoo-stats"));
    TempDir t;
    copy_results(t);
    const Outcome run = run_shell("cd '" + t.path + "' && " + command);
    ASSERT_EQ(run.status, 0) << command << "\n" << run.output;
    const std::string made = t / folder;
    size_t compared = 0;
    for (const auto& e : fs::directory_iterator(made)) {
      if (!e.is_regular_file()) continue;
      const std::string name = e.path().filename().string();
      SCOPED_TRACE(name);
      ASSERT_TRUE(fs::exists(committed + "/" + name)) << "made but not committed";
      if (e.path().extension() == ".png") continue;
      EXPECT_EQ(read_file(made + "/" + name), read_file(committed + "/" + name));
      ++compared;
    }
    // A milestone's report: report.md, its tables and plot scripts; the sensitivity report:
    // report.md and its two tables.
    EXPECT_GE(compared, command.find(" --sensitivity ") != std::string::npos ? 3u : 10u);
  }
  // A milestone with no report yet (it is running): the command that will make it works on
  // what is there, once each of its two arms has two runs (a t-test needs them).
  for (const Milestone& m : committed_milestones()) {
    if (std::find(reports.begin(), reports.end(), m.folder) != reports.end()) continue;
    SCOPED_TRACE(m.folder);
    const auto files = result_files(m.folder);
    auto runs_of = [&files](const std::string& arm) {
      return std::count_if(files.begin(), files.end(),
                           [&arm](const std::string& f) { return f.rfind(arm + "-s", 0) == 0; });
    };
    if (runs_of("feedforward") < 2 || runs_of("recurrent") < 2) continue;
    TempDir t;
    copy_results(t);
    const std::string command = bin("robozoo-stats") + " " + m.folder + "/results --out " + m.folder;
    const Outcome run = run_shell("cd '" + t.path + "' && " + command);
    ASSERT_EQ(run.status, 0) << command << "\n" << run.output;
    EXPECT_NE(read_file(t / (m.folder + "/report.md")).find(m.folder + "/results"), std::string::npos);
  }
}

TEST(PaperResults, ContinuedMilestonesRepeatTheGenerationsOfTheOnesTheyContinue) {
  const auto milestones = committed_milestones();
  for (const Milestone& m : milestones) {
    if (m.continues.empty() || !fs::is_directory(std::string(ROBOZOO_SOURCE_DIR) + "/" + m.continues + "/results"))
      continue;
    const std::string later = m.folder + "/results", earlier = m.continues + "/results";
    const Outcome same = run_shell("cd '" + std::string(ROBOZOO_SOURCE_DIR) + "' && " + bin("robozoo-stats") + " " +
                                   later + " --same-as " + earlier);
    EXPECT_EQ(same.status, 0) << same.output;
    EXPECT_NE(same.output.find("trials in both folders agree over the generations both hold"), std::string::npos)
        << same.output;
  }
}

TEST(PaperResults, EveryCommittedPortableCheckpointIsATrialInProgressOfItsMilestone) {
  const std::string root = ROBOZOO_SOURCE_DIR;
  const std::regex name_rule("([a-z-]+)-s([0-9]+)\\.portable-checkpoint");
  size_t checked = 0;
  const std::vector<Milestone> milestones = all_milestones();
  for (const Milestone& m : milestones) {
    const std::string folder = root + "/" + m.folder + "/checkpoints";
    if (!fs::is_directory(folder)) continue;
    const std::string version = pinned_version(m);
    TempDir carried;  // the compact results the files carry, as <trial>.results.json
    fs::create_directories(carried / "results");
    size_t continuing = 0;
    for (const auto& e : fs::directory_iterator(folder)) {
      const std::string f = e.path().filename().string();
      SCOPED_TRACE(m.folder + "/checkpoints/" + f);
      std::smatch match;
      ASSERT_TRUE(std::regex_match(f, match, name_rule));
      // Read as a run would read it: header, sizes, CRC-32s, one run at generation k.
      const PortableCheckpoint pc = read_portable_checkpoint(e.path().string());
      expect_trial_of(m, version, match[1], std::stol(match[2]), nlohmann::json::parse(pc.results_text).at("run"));
      EXPECT_GE(pc.generation, 1);
      EXPECT_LT(pc.generation, m.generations);  // in progress
      const std::string trial = f.substr(0, f.size() - std::string(kPortableCheckpointExtension).size());
      if (!m.continues.empty() && fs::exists(root + "/" + m.continues + "/results/" + trial + ".results.json")) {
        // A trial the earlier milestone finished: at least that milestone's generations.
        const auto earlier = std::find_if(milestones.begin(), milestones.end(),
                                          [&](const Milestone& x) { return x.folder == m.continues; });
        ASSERT_NE(earlier, milestones.end());
        EXPECT_GE(pc.generation, earlier->generations);
        std::ofstream(carried / ("results/" + trial + ".results.json")) << pc.results_text;
        ++continuing;
      }
      ++checked;
    }
    if (continuing == 0) continue;
    const Outcome same = run_shell(bin("robozoo-stats") + " '" + carried / "results" + "' --same-as '" + root + "/" +
                                   m.continues + "/results'");
    EXPECT_EQ(same.status, 0) << m.folder << "\n" << same.output;
    EXPECT_NE(same.output.find(std::to_string(continuing) + " trials in both folders agree"), std::string::npos)
        << same.output;
  }
  std::cout << checked << " portable checkpoints checked\n";
}

}  // namespace
}  // namespace robozoo
