#pragma once
// A robot's motion as render and view need it: the world centre of every sphere
// at increasing simulated times, from a logged ROBOZOO_POSE stream or, when a
// genome has none, from re-simulating it with the shared simulation code
// (grow_genome + Simulation: nothing here re-implements either).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"
#include "runlog/read/run_record.hpp"

namespace robozoo {

struct Trajectory {
  std::vector<int> step;                              ///< physics step of each sample (count)
  std::vector<double> time;                           ///< simulated time of each sample (s), increasing
  std::vector<std::vector<Eigen::Vector3d>> centers;  ///< per sample, per sphere (m)
  std::vector<std::vector<double>> neurons;           ///< per sample, CTRNN outputs (dimensionless)
  std::vector<std::vector<double>> sensors;           ///< per sample, sensor values in morphology order (dimensionless)
  bool resimulated = false;                           ///< made by re-simulation rather than read from poses

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

/// The genome whose logged poses show `genome` moving: itself when it has
/// poses, else another genome of the run with the same genes and poses;
/// nullptr when none (it must be re-simulated).
const GenomeRecord* logged_pose_source(const RunRecord& run, const GenomeRecord& genome);

/// The trajectory of a genome of `run`: its logged pose stream; else the
/// stream of another genome of the run with the same genes (NEAT copies
/// champions under fresh ids, and evolve logs a trajectory once per change of
/// genes); else re-simulation keeping every `every`-th step. Throws
/// std::invalid_argument when the genome has no morphology,
/// std::runtime_error when re-simulation cannot reproduce it. `resimulate`:
/// ignore logged poses.
Trajectory genome_trajectory(const RunRecord& run, const GenomeRecord& genome, bool resimulate = false, int every = 1);

/// The target position of a run (sim.target_x/y/z of run_t.config_json).
/// Throws std::invalid_argument when the configuration does not parse.
Eigen::Vector3d run_target(const run_t& run);

}  // namespace robozoo
