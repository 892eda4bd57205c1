#include "evolve/sim/episode/episode_rules.hpp"

#include <algorithm>
#include <cmath>

namespace robozoo {

bool acceleration_fault(double lin, double ang, const SimParams& p) {
  return !(lin <= p.max_linear_acceleration) || !(ang <= p.max_angular_acceleration);
}

bool at_rest(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>& w,
             const std::vector<double>& output_change, const SimParams& p) {
  for (const auto& x : v)
    if (!(x.norm() < p.rest_linear_speed)) return false;
  for (const auto& x : w)
    if (!(x.norm() < p.rest_angular_speed)) return false;
  for (double d : output_change)
    if (!(std::abs(d) < p.rest_output_rate * p.dt)) return false;
  return true;
}

SimResult apply_rules(const EpisodeRecord& rec, double d_init, double d_final, const SimParams& p) {
  SimResult r;
  r.steps_run = rec.steps_run;
  r.stopped_early = rec.stopped_early;
  r.d_init = d_init;
  r.d_raw = d_init - d_final;
  r.max_linear_acceleration = rec.max_linear_acceleration;
  r.max_angular_acceleration = rec.max_angular_acceleration;
  const double n = std::max(1, rec.steps_run);
  for (int g : rec.ground_steps) r.ground_contact_fraction.push_back(rec.steps_run ? g / n : 0.0);
  for (const auto& w : rec.angular_velocity_sum) r.mean_angular_speed.push_back(rec.steps_run ? (w / n).norm() : 0.0);
  const auto over = [](const std::vector<double>& xs, double t) {
    return std::any_of(xs.begin(), xs.end(), [t](double x) { return x > t; });
  };
  if (rec.fault)
    r.outcome = Outcome::AccelFault;
  else if (p.rolling_contact_rule && over(r.ground_contact_fraction, p.rolling_contact_fraction))
    r.outcome = Outcome::RollingContact;
  else if (p.rolling_spin_rule && over(r.mean_angular_speed, p.rolling_spin_threshold))
    r.outcome = Outcome::RollingSpin;
  else
    r.outcome = rec.stopped_early ? Outcome::StoppedEarly : Outcome::Completed;
  const bool valid = r.outcome == Outcome::Completed || r.outcome == Outcome::StoppedEarly;
  r.d_final = valid ? d_final : d_init;
  r.d = valid ? r.d_raw : 0.0;
  return r;
}

}  // namespace robozoo
