#include "replay/compare/morphology_compare.hpp"

#include <algorithm>

namespace robozoo::replay {

bool compare_morphology(const morphology_t& a, const morphology_t& b, ValueComparer& cmp) {
  const int64_t before = cmp.mismatch_count();
  cmp.set_context("morphology");
  cmp.text({"run_id"}, a.run_id, b.run_id);
  cmp.integer({"generation"}, a.generation, b.generation);
  cmp.integer({"genome_id"}, a.genome_id, b.genome_id);
  if (cmp.count({"num_spheres"}, a.num_spheres, b.num_spheres) && sizes_agree(a.spheres, b.spheres, a.num_spheres)) {
    for (int s = 0; s < a.num_spheres; ++s) {
      const sphere_t &x = a.spheres[s], &y = b.spheres[s];
      cmp.integer({"spheres[%d].index", s, -1, "sphere"}, x.index, y.index);
      cmp.integer({"spheres[%d].parent", s, -1, "sphere"}, x.parent, y.parent);
      for (int k = 0; k < 3; ++k) cmp.real({"spheres[%d].center[%d]", s, k, "sphere"}, x.center[k], y.center[k]);
      cmp.real({"spheres[%d].radius", s, -1, "sphere"}, x.radius, y.radius);
      cmp.real({"spheres[%d].density", s, -1, "sphere"}, x.density, y.density);
      cmp.integer({"spheres[%d].body", s, -1, "sphere"}, x.body, y.body);
      cmp.integer({"spheres[%d].has_joint", s, -1, "sphere"}, x.has_joint, y.has_joint);
      for (int k = 0; k < 3; ++k)
        cmp.real({"spheres[%d].joint_axis[%d]", s, k, "sphere"}, x.joint_axis[k], y.joint_axis[k]);
      cmp.real({"spheres[%d].joint_range", s, -1, "sphere"}, x.joint_range, y.joint_range);
      cmp.integer({"spheres[%d].motor_neuron", s, -1, "sphere"}, x.motor_neuron, y.motor_neuron);
      cmp.integer({"spheres[%d].sensors", s, -1, "sphere"}, x.sensors, y.sensors);
    }
  }
  cmp.integer({"num_bodies"}, a.num_bodies, b.num_bodies);
  const bool neurons = cmp.count({"num_neurons"}, a.num_neurons, b.num_neurons) &&
                       sizes_agree(a.tau, b.tau, a.num_neurons) && sizes_agree(a.omega, b.omega, a.num_neurons);
  if (neurons) {
    for (int i = 0; i < a.num_neurons; ++i) {
      cmp.real({"tau[%d]", i, -1, "neuron"}, a.tau[i], b.tau[i]);
      cmp.real({"omega[%d]", i, -1, "neuron"}, a.omega[i], b.omega[i]);
    }
  }
  const bool sensors = cmp.count({"num_sensors"}, a.num_sensors, b.num_sensors) &&
                       sizes_agree(a.sensor_sphere, b.sensor_sphere, a.num_sensors) &&
                       sizes_agree(a.sensor_type, b.sensor_type, a.num_sensors);
  if (sensors) {
    for (int k = 0; k < a.num_sensors; ++k) {
      cmp.integer({"sensor_sphere[%d]", k, -1, "sensor"}, a.sensor_sphere[k], b.sensor_sphere[k]);
      cmp.integer({"sensor_type[%d]", k, -1, "sensor"}, a.sensor_type[k], b.sensor_type[k]);
    }
  }
  if (neurons && sensors && sizes_agree(a.w_sensor_neuron, b.w_sensor_neuron, a.num_sensors)) {
    for (int k = 0; k < a.num_sensors; ++k) {
      if (!sizes_agree(a.w_sensor_neuron[k], b.w_sensor_neuron[k], a.num_neurons)) continue;
      for (int i = 0; i < a.num_neurons; ++i)
        cmp.real({"w_sensor_neuron[%d][%d]", k, i, "sensor"}, a.w_sensor_neuron[k][i], b.w_sensor_neuron[k][i]);
    }
  }
  if (neurons && sizes_agree(a.w_neuron_neuron, b.w_neuron_neuron, a.num_neurons)) {
    for (int j = 0; j < a.num_neurons; ++j) {
      if (!sizes_agree(a.w_neuron_neuron[j], b.w_neuron_neuron[j], a.num_neurons)) continue;
      for (int i = 0; i < a.num_neurons; ++i)
        cmp.real({"w_neuron_neuron[%d][%d]", j, i, "neuron"}, a.w_neuron_neuron[j][i], b.w_neuron_neuron[j][i]);
    }
  }
  cmp.real({"r_term"}, a.r_term, b.r_term);
  return cmp.mismatch_count() == before;
}

}  // namespace robozoo::replay
