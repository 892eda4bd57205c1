#pragma once
// Hand-made robozoo messages for the analysis tests.
#include <cstdint>
#include <vector>

#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"

namespace robozoo::testing {

/// A morphology with the given parents (growth order), radii (default 0.1),
/// joints and sensor masks (default none); centres on a line at z = radius.
inline morphology_t make_morphology(const std::vector<int32_t>& parents, std::vector<double> radii = {},
                                    std::vector<bool> joints = {}, std::vector<int8_t> sensors = {},
                                    int64_t genome_id = 1, int32_t generation = 0) {
  const size_t n = parents.size();
  if (radii.empty()) radii.assign(n, 0.1);
  if (joints.empty()) joints.assign(n, false);
  if (sensors.empty()) sensors.assign(n, 0);
  morphology_t m{};
  m.run_id = "test";
  m.generation = generation;
  m.genome_id = genome_id;
  m.num_spheres = static_cast<int32_t>(n);
  for (size_t i = 0; i < n; ++i) {
    sphere_t s{};
    s.index = static_cast<int32_t>(i);
    s.parent = parents[i];
    s.center[0] = 0.3 * static_cast<double>(i);
    s.center[1] = 0;
    s.center[2] = radii[i];
    s.radius = radii[i];
    s.density = 1;
    s.body = 0;
    s.has_joint = joints[i];
    s.motor_neuron = -1;
    s.sensors = sensors[i];
    m.spheres.push_back(s);
  }
  m.num_bodies = 1;
  m.num_neurons = 0;
  m.num_sensors = 0;
  return m;
}

struct NodeSpec {
  int32_t id;
  int8_t kind;           ///< 0 input, 1 bias, 2 output, 3 hidden
  int8_t activation;     ///< 0 sigmoid, 1 cosine, 2 Gaussian
  double position = -1;  ///< drawing position; < 0: 0 for inputs, 1 for outputs, 0.5 for hidden nodes
};
struct LinkSpec {
  int32_t from, to;
  bool enabled = true;
};

inline cppn_genome_t make_genome(const std::vector<NodeSpec>& nodes, const std::vector<LinkSpec>& links,
                                 int64_t genome_id = 1, int32_t generation = 0, double fitness = 0,
                                 int8_t outcome = 1) {
  cppn_genome_t g{};
  g.run_id = "test";
  g.generation = generation;
  g.genome_id = genome_id;
  g.fitness = fitness;
  g.outcome = outcome;
  for (const auto& n : nodes) {
    cppn_node_t x{};
    x.id = n.id;
    x.kind = n.kind;
    x.activation = n.activation;
    x.position = n.position >= 0 ? n.position : n.kind == 2 ? 1.0 : n.kind == 3 ? 0.5 : 0.0;
    g.nodes.push_back(x);
  }
  g.num_nodes = static_cast<int32_t>(g.nodes.size());
  int64_t innov = 0;
  for (const auto& l : links) {
    link_t x{};
    x.innovation = innov++;
    x.from_node = l.from;
    x.to_node = l.to;
    x.weight = 1.0;
    x.enabled = l.enabled;
    g.links.push_back(x);
  }
  g.num_links = static_cast<int32_t>(g.links.size());
  return g;
}

/// A pose of a robot whose sphere centres are at the given heights.
inline pose_t make_pose(int64_t genome_id, int32_t generation, int32_t step, const std::vector<double>& z) {
  pose_t p{};
  p.run_id = "test";
  p.generation = generation;
  p.genome_id = genome_id;
  p.step = step;
  p.sim_time = 0.01 * step;
  p.num_bodies = 0;
  p.num_spheres = static_cast<int32_t>(z.size());
  for (size_t i = 0; i < z.size(); ++i) p.sphere_center.push_back({0.3 * static_cast<double>(i), 0.0, z[i]});
  p.num_neurons = 0;
  p.num_sensors = 0;
  return p;
}

}  // namespace robozoo::testing
