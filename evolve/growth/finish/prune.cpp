#include "evolve/growth/finish/prune.hpp"

namespace robozoo {

int prune_leaf_joints(GrownBody& body) {
  int pruned = 0;
  for (Sphere& s : body.spheres) {
    if (!s.has_joint || s.num_children > 0) continue;
    s.has_joint = false;
    s.joint_pruned = true;
    s.joint_axis = Eigen::Vector3d::Zero();
    s.joint_range = 0.0;
    s.motor_neuron = -1;
    s.sensors = static_cast<uint8_t>(s.sensors & ~kSensorProprio);
    body.motors[s.index] = Neuron{s.index, 0.0, 0.0};
    ++pruned;
  }
  return pruned;
}

}  // namespace robozoo
