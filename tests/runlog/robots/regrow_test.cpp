// Re-growing logged genomes: the robot grown again is the logged one, and a
// robot that is not is refused with the reason.
#include "runlog/robots/regrow.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "runlog/read/log_source.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

std::string error_of(const Robot& robot, const morphology_t& m, int64_t id) {
  try {
    require_logged_morphology(robot, m, id);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(Regrow, EveryLoggedGenomeGrowsIntoItsLoggedMorphology) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  const RunRecord& run = *log.runs()[0];
  const RunConfig config = config_from_json(nlohmann::json::parse(run.run.config_json));
  int checked = 0;
  for (const auto& g : run.genomes) {
    if (!g->has_morphology) continue;
    const RegrownGenome r = regrow_genome(g->genome, config);
    EXPECT_EQ(r.genes.id, g->genome.genome_id);
    EXPECT_EQ(r.genes.nodes.size(), g->genome.nodes.size());
    EXPECT_EQ(r.robot.spheres.size(), g->morphology.spheres.size());
    EXPECT_EQ(error_of(r.robot, g->morphology, g->genome.genome_id), "");
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

TEST(Regrow, AnotherRobotOrABadGenomeIsRefused) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  const RunRecord& run = *log.runs()[0];
  const GenomeRecord& g = *run.genomes.back();
  ASSERT_TRUE(g.has_morphology);
  const RunConfig config = config_from_json(nlohmann::json::parse(run.run.config_json));
  const Robot robot = regrow_genome(g.genome, config).robot;
  const int64_t id = g.genome.genome_id;

  morphology_t moved = g.morphology;
  moved.spheres[0].center[2] += 0.01;
  EXPECT_EQ(error_of(robot, moved, id),
            "re-growing genome " + std::to_string(id) + " moved sphere 0 from where the log has it");

  morphology_t fewer = g.morphology;
  fewer.spheres.pop_back();
  EXPECT_EQ(error_of(robot, fewer, id), "re-growing genome " + std::to_string(id) + " gave " +
                                            std::to_string(robot.spheres.size()) + " spheres, the log has " +
                                            std::to_string(robot.spheres.size() - 1) +
                                            " (another version or configuration?)");

  cppn_genome_t broken = g.genome;
  broken.num_nodes += 1;  // counts that disagree with the arrays
  EXPECT_THROW(logged_genes(broken), std::invalid_argument);
  EXPECT_THROW(regrow_genome(broken, config), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
