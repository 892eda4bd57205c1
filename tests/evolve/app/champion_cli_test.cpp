// robozoo-evolve champion: a compact result's best-of-run champion becomes a
// log that robozoo-replay check proves (morphology, pose stream, fitness
// against this build) and robozoo-render films, holding the same genome,
// morphology and pose stream as the run's own log; a result whose fitness this
// build does not reproduce is refused.
#include <gtest/gtest.h>

#include <fstream>

#include "evolve/record/run_results.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "study/analysis/read/log_results.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

template <class T>
std::vector<T> messages(const LogContents& log, const std::string& channel, int64_t genome_id) {
  std::vector<T> out;
  for (const auto& r : log.records) {
    if (r.channel != channel) continue;
    T m;
    if (safe_decode(r.data.data(), r.data.size(), m) && m.genome_id == genome_id) out.push_back(m);
  }
  return out;
}

template <class T>
std::vector<uint8_t> as_generation_0(T m) {
  m.utime = 0;
  m.generation = 0;
  return encode_message(m);
}

TEST(ChampionCli, ACompactResultsChampionBecomesALogThatReplayCheckProves) {
  TempDir dir;
  const auto run = run_shell(join(evolve_args(dir / "run.lcmlog", 1, {"--regime", "recurrent"})));
  ASSERT_EQ(run.status, 0) << run.output;
  const RunResults r = results_from_log(dir / "run.lcmlog");
  write_run_results(dir / "run.results.json", r);
  const ChampionRecord* best = best_of_run(r.run);
  ASSERT_NE(best, nullptr);
  ASSERT_NE(best->genome.outcome, 0) << "the small run's best robot was never simulated";

  const auto champ =
      run_shell(join({bin("robozoo-evolve"), "champion", dir / "run.results.json", "--log", dir / "champion.lcmlog"}));
  ASSERT_EQ(champ.status, 0) << champ.output;
  const LogContents original = read_event_log(dir / "run.lcmlog"), written = read_event_log(dir / "champion.lcmlog");
  const int64_t id = best->genome.genome_id;
  // The same genome, robot and pose stream as the run logged (as generation 0 of a one-generation run).
  const auto g0 = messages<cppn_genome_t>(original, kChannelGenome, id);
  const auto g1 = messages<cppn_genome_t>(written, kChannelGenome, id);
  ASSERT_EQ(g0.size(), 1u);
  ASSERT_EQ(g1.size(), 1u);
  EXPECT_EQ(as_generation_0(g0[0]), as_generation_0(g1[0]));
  const auto m0 = messages<morphology_t>(original, kChannelMorphology, id);
  const auto m1 = messages<morphology_t>(written, kChannelMorphology, id);
  ASSERT_EQ(m0.size(), 1u);
  ASSERT_EQ(m1.size(), 1u);
  EXPECT_EQ(as_generation_0(m0[0]), as_generation_0(m1[0]));
  const auto p0 = messages<pose_t>(original, kChannelPose, id), p1 = messages<pose_t>(written, kChannelPose, id);
  ASSERT_GT(p0.size(), 1u);
  ASSERT_EQ(p0.size(), p1.size());
  for (size_t i = 0; i < p0.size(); ++i) EXPECT_EQ(as_generation_0(p0[i]), as_generation_0(p1[i])) << "pose " << i;
  EXPECT_EQ(count_channel(written, kChannelRun), 1u);
  EXPECT_EQ(count_channel(written, kChannelGeneration), 1u);

  // robozoo-replay check proves the log: structure, morphology, poses, fitness.
  const auto check = run_shell(bin("robozoo-replay") + " check '" + (dir / "champion.lcmlog") + "' --no-progress");
  EXPECT_EQ(check.status, 0) << check.output;

  // robozoo-render films it: an MP4 of its pose stream (5 simulated seconds per second, 10 frames per second).
  const auto film = run_shell(bin("robozoo-render") + " video '" + (dir / "champion.lcmlog") + "' -o '" +
                              (dir / "champion.mp4") + "' -q --size 160x120 --fps 10 --speed 5 --samples 0");
  EXPECT_EQ(film.status, 0) << film.output;
  EXPECT_GT(read_file(dir / "champion.mp4").size(), 1000u);

  // A committed fitness this build does not give: refused, nothing claimed.
  nlohmann::json j = run_results_to_json(r);
  for (auto& c : j["champions"])
    if (c["genome_id"] == id) c["fitness"] = c["fitness"].get<double>() + 1.0;
  std::ofstream(dir / "edited.results.json") << j.dump();
  const auto refused =
      run_shell(join({bin("robozoo-evolve"), "champion", dir / "edited.results.json", "--log", dir / "edited.lcmlog"}));
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("evaluates to fitness"), std::string::npos) << refused.output;

  const auto missing =
      run_shell(join({bin("robozoo-evolve"), "champion", dir / "absent.results.json", "--log", dir / "x.lcmlog"}));
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find("absent.results.json: cannot read the compact result"), std::string::npos)
      << missing.output;
}

}  // namespace
}  // namespace robozoo
