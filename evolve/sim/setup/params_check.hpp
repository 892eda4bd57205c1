#pragma once
// Validates SimParams before a simulation is built.
#include "evolve/sim/params.hpp"

namespace robozoo {

/// Throws std::invalid_argument naming the first field out of its range
/// (steps >= 0, dt > 0, iterations >= 1, ERPs in [0, 1], CFMs, friction, gains,
/// strengths >= 0, sensor range > 0, rest and fault thresholds > 0, contact
/// fraction in [0, 1], ...). NaN is out of every range.
void check_sim_params(const SimParams& params);

}  // namespace robozoo
