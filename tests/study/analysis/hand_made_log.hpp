#pragma once
// Hand-made run logs with known champions, written with robozoo's own log
// writer and message types, for the statistics tests.
#include <optional>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "tests/study/analysis/builders.hpp"

namespace robozoo::testing {

struct HandGeneration {
  double best_fitness = 0;  ///< the champion's fitness
  double best_so_far = 0;
  int8_t outcome = 1;  ///< the champion's outcome (0: not simulated)
  int64_t champion_id = 0;
  std::vector<int32_t> parents;  ///< the champion's sphere tree
  std::vector<double> radii;     ///< its radii (default 0.1)
  std::vector<NodeSpec> nodes;   ///< its CPPN
  std::vector<LinkSpec> links;
  /// Lowest centre heights of a pose stream published for the champion (none: no poses).
  std::optional<std::vector<double>> pose_min_z;
};

struct HandRun {
  int8_t regime = 0;
  int64_t seed = 1;
  int32_t population = 10;
  int32_t generations_requested = 0;  ///< 0: as many as given
  std::vector<HandGeneration> generations;
};

inline void write_hand_log(const std::string& path, const HandRun& run) {
  EventLogWriter log = EventLogWriter::create(path);
  const std::string run_id =
      std::string(run.regime == 0 ? "feedforward" : "recurrent") + "-s" + std::to_string(run.seed);
  int64_t t = 1000;
  for (size_t g = 0; g < run.generations.size(); ++g) {
    const HandGeneration& h = run.generations[g];
    const auto gen = static_cast<int32_t>(g);
    run_t r{};
    r.utime = t;
    r.run_id = run_id;
    r.software_version = "test";
    r.seed = run.seed;
    r.regime = run.regime;
    r.population = run.population;
    r.generations =
        run.generations_requested > 0 ? run.generations_requested : static_cast<int32_t>(run.generations.size());
    r.steps = 2500;
    r.dt = 0.01;
    r.config_json = "{}";
    log.write(kChannelRun, encode_message(r), t++);
    generation_t m{};
    m.utime = t;
    m.run_id = run_id;
    m.generation = gen;
    m.best_fitness = h.best_fitness;
    m.mean_fitness = h.best_fitness / 2;
    m.best_so_far_fitness = h.best_so_far;
    m.champion_id = h.champion_id;
    log.write(kChannelGeneration, encode_message(m), t++);
    // Another genome of the same generation (as with --publish-all): not the champion.
    cppn_genome_t other = make_genome({{0, 0, 0}}, {}, h.champion_id + 1000, gen, 1.0, 0);
    other.run_id = run_id;
    log.write(kChannelGenome, encode_message(other), t++);
    cppn_genome_t champ = make_genome(h.nodes, h.links, h.champion_id, gen, h.best_fitness, h.outcome);
    champ.run_id = run_id;
    log.write(kChannelGenome, encode_message(champ), t++);
    morphology_t morph = make_morphology(h.parents, h.radii, {}, {}, h.champion_id, gen);
    morph.run_id = run_id;
    log.write(kChannelMorphology, encode_message(morph), t++);
    if (h.pose_min_z) {
      std::vector<double> high = *h.pose_min_z;
      for (double& z : high) z += 0.5;
      for (const auto& z : {high, *h.pose_min_z, high}) {
        pose_t p = make_pose(h.champion_id, gen, 0, z);
        p.run_id = run_id;
        log.write(kChannelPose, encode_message(p), t++);
      }
    }
  }
  log.sync();
}

}  // namespace robozoo::testing
