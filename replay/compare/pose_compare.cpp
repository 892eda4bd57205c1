#include "replay/compare/pose_compare.hpp"

namespace robozoo::replay {

bool compare_pose(const pose_t& a, const pose_t& b, ValueComparer& cmp) {
  const int64_t before = cmp.mismatch_count();
  cmp.set_context("pose", a.step);
  cmp.text({"run_id"}, a.run_id, b.run_id);
  cmp.integer({"generation"}, a.generation, b.generation);
  cmp.integer({"genome_id"}, a.genome_id, b.genome_id);
  cmp.integer({"step"}, a.step, b.step);
  cmp.real({"sim_time"}, a.sim_time, b.sim_time);
  if (cmp.count({"num_bodies"}, a.num_bodies, b.num_bodies) &&
      sizes_agree(a.body_position, b.body_position, a.num_bodies) &&
      sizes_agree(a.body_quaternion, b.body_quaternion, a.num_bodies)) {
    for (int i = 0; i < a.num_bodies; ++i) {
      for (int k = 0; k < 3; ++k)
        cmp.real({"body_position[%d][%d]", i, k, "body"}, a.body_position[i][k], b.body_position[i][k]);
      for (int k = 0; k < 4; ++k)
        cmp.real({"body_quaternion[%d][%d]", i, k, "body"}, a.body_quaternion[i][k], b.body_quaternion[i][k]);
    }
  }
  if (cmp.count({"num_spheres"}, a.num_spheres, b.num_spheres) &&
      sizes_agree(a.sphere_center, b.sphere_center, a.num_spheres)) {
    for (int s = 0; s < a.num_spheres; ++s)
      for (int k = 0; k < 3; ++k)
        cmp.real({"sphere_center[%d][%d]", s, k, "sphere"}, a.sphere_center[s][k], b.sphere_center[s][k]);
  }
  if (cmp.count({"num_neurons"}, a.num_neurons, b.num_neurons) &&
      sizes_agree(a.neuron_output, b.neuron_output, a.num_neurons)) {
    for (int i = 0; i < a.num_neurons; ++i)
      cmp.real({"neuron_output[%d]", i, -1, "neuron"}, a.neuron_output[i], b.neuron_output[i]);
  }
  if (cmp.count({"num_sensors"}, a.num_sensors, b.num_sensors) &&
      sizes_agree(a.sensor_value, b.sensor_value, a.num_sensors)) {
    for (int k = 0; k < a.num_sensors; ++k)
      cmp.real({"sensor_value[%d]", k, -1, "sensor"}, a.sensor_value[k], b.sensor_value[k]);
  }
  return cmp.mismatch_count() == before;
}

}  // namespace robozoo::replay
