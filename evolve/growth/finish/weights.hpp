#pragma once
// Growth step 6 (paper 2.3; docs/method.md section 2): the CTRNN weights.
#include "evolve/growth/body/cppn_probe.hpp"
#include "evolve/growth/params.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo {

/// Sets robot.w_sensor_neuron(k, i) and robot.w_neuron_neuron(j, i) from CPPN
/// queries at the midpoint of the two spheres' centres, r_parent input 0:
/// sensor k -> neuron i with sensor k's type one-hot input set; neuron j -> neuron
/// i (self-loops included) with no one-hot. The weight is expressed_weight() of
/// the output: 0 (no link) when |output_w| <= weight_threshold. The midpoint is
/// symmetric, so w(j, i) = w(i, j) and each neuron pair is queried once.
/// Uses the centres as they are: call before the vertical shift (growth frame).
void set_ctrnn_weights(Robot& robot, CppnProbe& probe, const GrowthParams& params);

/// The weight a CPPN weight output w expresses, with T = weight_threshold: exactly 0 when
/// |w| <= T; otherwise, with weight_mapping rescaled (HyperNEAT's),
/// sign(w) (|w| - T) / (1 - T) weight_max, and with proportional w weight_max.
double expressed_weight(double output_w, const GrowthParams& params);

}  // namespace robozoo
