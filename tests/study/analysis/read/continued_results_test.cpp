// A run's compact result from the log that continues it and its earlier
// result: the same JSON as the uninterrupted run's (wall time aside), and a
// pair that is not one run is refused, naming the first break.
#include "study/analysis/read/continued_results.hpp"

#include <gtest/gtest.h>

#include "study/analysis/read/log_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "tests/support/continued_run.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

std::string refusal(const RunResults& earlier, const RunResults& later) {
  try {
    merge_run_results(earlier, later, "E and L");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

nlohmann::json without_wall_time(const RunResults& r) {
  nlohmann::json j = run_results_to_json(r);
  j.erase("evolve_seconds");
  return j;
}

TEST(ContinuedResults, AContinuedLogWithItsEarlierResultIsTheUninterruptedRun) {
  TempDir dir;
  // The log moves away after 3 generations; the portable checkpoint goes on in another folder.
  evolve_whole_and_continued(small_run_config(5), "r", dir / "whole/r.lcmlog", dir / "a/r.lcmlog", dir / "b/r.lcmlog",
                             3);

  const RunResults whole = results_from_log(dir / "whole/r.lcmlog");
  const RunResults merged = run_results_of_log(dir / "b/r.lcmlog");
  EXPECT_EQ(without_wall_time(merged).dump(), without_wall_time(whole).dump());
  EXPECT_TRUE(merged.run.complete());

  const RunResults earlier = read_run_results(earlier_results_path_for(dir / "b/r.lcmlog"));
  const RunResults later = results_from_log(dir / "b/r.lcmlog");
  ASSERT_TRUE(later.run.continues.has_value());
  EXPECT_EQ(later.run.continues->from_generation, 3);
  EXPECT_EQ(later.run.generations.front().generation, 3);

  RunResults gap = earlier;
  gap.run.generations.pop_back();
  EXPECT_NE(refusal(gap, later)
                .find("E and L: not one run: the later log continues from generation 3, the earlier "
                      "result has 2 generations"),
            std::string::npos);
  RunResults other = earlier;
  other.run.run_id = "s";
  EXPECT_NE(refusal(other, later).find("not one run: run/run_id: \"s\" != \"r\""), std::string::npos)
      << refusal(other, later);
  RunResults seed = earlier;
  seed.run.seed = 8;
  EXPECT_NE(refusal(seed, later).find("not one run: run/seed: 8 != 7"), std::string::npos) << refusal(seed, later);
  RunResults best = earlier;
  best.run.generations.back().best_so_far_fitness += 1;
  EXPECT_NE(refusal(best, later).find("best-so-far fitness does not go on"), std::string::npos);
  EXPECT_NE(refusal(earlier, whole).find("the later log does not say it continues a run"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
