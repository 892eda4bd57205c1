#pragma once
// A robot's motion as the renderer needs it: the world centre of every sphere
// at increasing simulated times, from a logged ROBOZOO_POSE stream or, when a
// genome has none, from re-simulating it with the shared simulation code
// (grow_genome + Simulation: the renderer re-implements neither).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo::render {

struct Trajectory {
  std::vector<int> step;        ///< physics step of each sample (count)
  std::vector<double> time;     ///< simulated time of each sample (s), increasing
  std::vector<std::vector<Eigen::Vector3d>> centers;  ///< per sample, per sphere (m)
  bool resimulated = false;     ///< made by re-simulation rather than read from poses

  bool empty() const { return time.empty(); }
  double start_time() const { return time.front(); }
  double end_time() const { return time.back(); }
  /// Sphere centres at time t, linear between samples, clamped at the ends.
  std::vector<Eigen::Vector3d> sample(double t) const;
};

/// From a logged pose stream (steps increasing). Throws std::invalid_argument
/// when it is empty, when a pose has another number of spheres than
/// `num_spheres`, or when times do not increase.
Trajectory trajectory_from_poses(const std::vector<pose_t>& poses, size_t num_spheres);

/// Re-grows `genome` with the run's configuration (run_t.config_json) and
/// simulates it, keeping every `every`-th step, the first and the last. The
/// re-grown robot must be the logged `morphology` (same spheres, same centres);
/// throws std::runtime_error when it is not (another software version or
/// configuration), std::invalid_argument for a bad configuration or genome.
Trajectory simulate_trajectory(const run_t& run, const cppn_genome_t& genome, const morphology_t& morphology,
                               int every = 1);

}  // namespace robozoo::render
