#pragma once
// Parameters of growing a robot from a CPPN (paper 2.3, docs/method.md section 2).
// Lengths in ODE length units (m), angles in rad.
#include <cmath>
#include <cstdint>
#include <string>

namespace robozoo {

/// How a CPPN weight output w beyond weight_threshold T becomes a CTRNN weight.
enum class WeightMapping : int8_t {
  /// HyperNEAT's substrate code (its experiments' populateSubstrate / convertOutputToWeight):
  /// sign(w) (|w| - T) / (1 - T) weight_max, so weights start at 0 at the threshold
  Rescaled = 0,
  /// robozoo's earlier mapping: w weight_max, which jumps from 0 to T weight_max at the threshold
  Proportional = 1,
};
std::string weight_mapping_name(WeightMapping m);              ///< "rescaled" / "proportional"
WeightMapping weight_mapping_from_name(const std::string& s);  ///< throws std::invalid_argument listing the names

struct GrowthParams {
  double r_init = 0.1;                ///< root radius (m)
  double r_min = 0.05;                ///< smallest sphere radius (m)
  double r_max = 0.5;                 ///< largest sphere radius (m)
  double t_matter = 0.7;              ///< matter threshold on output m
  double t_joint = 0.7;               ///< joint threshold on output j
  double t_sensor = 0.7;              ///< sensor-present threshold on the four sensor outputs
  double weight_threshold = 0.2;      ///< |w| at or below this expresses no CTRNN link
  double rho_min = 1.0;               ///< density at m = t_matter (mass per m^3)
  double rho_max = 3.0;               ///< density at m = 1 (mass per m^3)
  double max_joint_range = M_PI / 2;  ///< half range of motion at j = 1 (rad)
  double tau_min = 0.05;              ///< motor neuron time constant at tau = -1 (s)
  double tau_max = 1.0;               ///< motor neuron time constant at tau = +1 (s)
  double bias_max = 3.0;              ///< motor neuron bias at omega = 1 (dimensionless)
  double weight_max = 3.0;            ///< CTRNN weight at w = 1 (dimensionless)
  /// How an expressed weight output becomes a CTRNN weight (HyperNEAT's rescaling by default).
  WeightMapping weight_mapping = WeightMapping::Rescaled;
  /// Value of the CPPN's constant bias input (dimensionless): 0.3, the value HyperNEAT's
  /// experiments and the first author's CPPN growth code feed (docs/method.md section 2.1).
  double bias_input = 0.3;
  int cloud_points = 629;    ///< points per cloud (count), at angles k * cloud_step
  double cloud_step = 0.01;  ///< angle between cloud points (rad)
  double bound = 2.0;        ///< sphere centres must have |x|, |y| <= bound (m)
  /// Growth stops at this many spheres (count). The paper sets no cap; it binds for about
  /// half the robots that grow at all, at 50, 100 or 200 alike, so the counts of a robot at
  /// the cap are censored (docs/method.md section 2.3 step 4, docs/performance.md).
  int max_spheres = 50;
  /// Relative tolerance of placement rules (b), (c), (d) (dimensionless): a distance
  /// within touch_tolerance * limit of its limit counts as exactly at the limit, so
  /// spheres that touch in exact geometry touch whatever the last bit of rounding says
  /// (docs/method.md section 2.3).
  double touch_tolerance = 1e-9;
};

/// Checks that growth can run with these parameters (positive radii with
/// r_min <= r_init <= r_max, thresholds below 1, ordered density and time-constant
/// ranges, at least one cloud point and one sphere, finite values). Throws
/// std::invalid_argument naming the first offending field.
void validate_growth_params(const GrowthParams& p);

}  // namespace robozoo
