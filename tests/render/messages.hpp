#pragma once
// Hand-built ROBOZOO_* messages for the collector's tests.
#include <string>
#include <vector>

#include "evolve/messages/build.hpp"
#include "tests/render/fixtures.hpp"

namespace robozoo::render::testing {

inline run_t run_message(const std::string& id, int32_t steps = 100) {
  run_t m{};
  m.run_id = id;
  m.software_version = "test";
  m.seed = 1;
  m.regime = 1;
  m.population = 10;
  m.generations = 5;
  m.steps = steps;
  m.dt = 0.01;
  m.config_json = config_to_json(RunConfig{}).dump();
  return m;
}

inline generation_t generation_message(const std::string& id, int32_t g, int64_t champion) {
  generation_t m{};
  m.run_id = id;
  m.generation = g;
  m.champion_id = champion;
  m.best_fitness = 15.0 + g;
  return m;
}

inline cppn_genome_t genome_message(const std::string& id, int32_t g, int64_t genome_id, double fitness) {
  cppn_genome_t m{};
  m.run_id = id;
  m.generation = g;
  m.genome_id = genome_id;
  m.fitness = fitness;
  return m;
}

inline morphology_t morphology_message(const std::string& id, int32_t g, int64_t genome_id) {
  morphology_t m = known_robot(id, genome_id);
  m.generation = g;
  return m;
}

/// A pose of the known robot moved by `dx` along x.
inline pose_t pose_message(const std::string& id, int32_t g, int64_t genome_id, int32_t step, double dx = 0.0,
                           int spheres = 4) {
  pose_t m{};
  m.run_id = id;
  m.generation = g;
  m.genome_id = genome_id;
  m.step = step;
  m.sim_time = 0.01 * step;
  m.num_bodies = 1;
  m.body_position = {{0, 0, 0.2}};
  m.body_quaternion = {{1, 0, 0, 0}};
  const morphology_t k = known_robot();
  m.num_spheres = spheres;
  for (int i = 0; i < spheres; ++i)
    m.sphere_center.push_back(
        {k.spheres[static_cast<size_t>(i % 4)].center[0] + dx, 0.0, k.spheres[static_cast<size_t>(i % 4)].center[2]});
  return m;
}

}  // namespace robozoo::render::testing
