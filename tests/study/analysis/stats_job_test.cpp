#include "study/analysis/stats_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

TEST(StatsJob, ListLogsPutsSeedsInNumericOrder) {
  TempDir d;
  for (const char* name : {"recurrent-s10.lcmlog", "recurrent-s2.lcmlog", "feedforward-s1.lcmlog",
                           "recurrent-s1.lcmlog", "feedforward-s10.lcmlog", "feedforward-s9.lcmlog",
                           "recurrent-s02.lcmlog", "notes.txt", "recurrent-s1.lcmlog.checkpoint"})
    std::ofstream(d / name) << "x";
  std::filesystem::create_directory(d / "sub.lcmlog");  // a folder, not a log
  std::vector<std::string> names;
  for (const auto& p : list_logs(d.path)) names.push_back(std::filesystem::path(p).filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"feedforward-s1.lcmlog", "feedforward-s9.lcmlog", "feedforward-s10.lcmlog",
                                             "recurrent-s1.lcmlog", "recurrent-s2.lcmlog", "recurrent-s02.lcmlog",
                                             "recurrent-s10.lcmlog"}));
}

TEST(StatsJob, ListResultsTakesOnlyCompactResultsInNumericOrder) {
  TempDir d;
  for (const char* name : {"recurrent-s10.results.json", "recurrent-s2.results.json", "feedforward-s1.results.json",
                           "recurrent-s2.lcmlog", ".results.json", "notes.json", "x.results.json.tmp"})
    std::ofstream(d / name) << "x";
  std::vector<std::string> names;
  for (const auto& p : list_results(d.path)) names.push_back(std::filesystem::path(p).filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"feedforward-s1.results.json", "recurrent-s2.results.json",
                                             "recurrent-s10.results.json"}));
  EXPECT_EQ(results_file_name("/runs/paper/recurrent-sparse-s3.lcmlog"), "recurrent-sparse-s3.results.json");
}

TEST(StatsJob, ListLogsRefusesWhatIsNotAFolder) {
  TempDir d;
  std::ofstream(d / "file") << "x";
  EXPECT_THROW(list_logs(d / "file"), std::invalid_argument);
  EXPECT_THROW(list_logs(d / "absent"), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
