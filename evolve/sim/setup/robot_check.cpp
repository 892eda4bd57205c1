#include "evolve/sim/setup/robot_check.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace robozoo {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("robot model: " + what); }
std::string str(int i) { return std::to_string(i); }

int find_root(std::vector<int>& up, int a) {
  while (up[a] != a) a = up[a] = up[up[a]];
  return a;
}

}  // namespace

void check_robot(const Robot& robot) {
  const auto& sp = robot.spheres;
  const int n = static_cast<int>(sp.size());
  if (n == 0) fail("no spheres");
  if (robot.num_bodies < 1) fail("num_bodies must be >= 1, got " + str(robot.num_bodies));
  std::vector<int> body_used(robot.num_bodies, 0);
  for (int i = 0; i < n; ++i) {
    const Sphere& s = sp[i];
    const std::string name = "sphere " + str(i);
    if (s.index != i) fail(name + " has index " + str(s.index));
    if (i == 0 ? s.parent != -1 : (s.parent < 0 || s.parent >= i))
      fail(name + " has parent " + str(s.parent) + " (the root has -1, others an earlier sphere)");
    if (!s.center.allFinite()) fail(name + " has a non-finite centre");
    if (!(s.radius > 0) || !std::isfinite(s.radius)) fail(name + " needs a positive finite radius");
    if (!(s.density > 0) || !std::isfinite(s.density)) fail(name + " needs a positive finite density");
    if (s.body < 0 || s.body >= robot.num_bodies) fail(name + " has body " + str(s.body));
    body_used[s.body] = 1;
    if (i > 0 && !s.has_joint && s.body != sp[s.parent].body)
      fail(name + " is fused to its parent but lies in another body");
  }
  for (int b = 0; b < robot.num_bodies; ++b)
    if (!body_used[b]) fail("body " + str(b) + " has no sphere");

  // Joints: one per jointed sphere, in growth order, forming a tree over the bodies.
  std::vector<int> joint_of(n, -1);
  std::vector<int> up(robot.num_bodies);
  std::iota(up.begin(), up.end(), 0);
  const int nn = static_cast<int>(robot.neurons.size());
  for (size_t k = 0; k < robot.joints.size(); ++k) {
    const Joint& j = robot.joints[k];
    const std::string name = "joint " + str(static_cast<int>(k));
    if (j.sphere <= 0 || j.sphere >= n) fail(name + " has sphere " + str(j.sphere));
    const Sphere& s = sp[j.sphere];
    if (!s.has_joint) fail(name + " sits on sphere " + str(j.sphere) + ", which has no joint");
    if (joint_of[j.sphere] >= 0) fail(name + " duplicates a joint on sphere " + str(j.sphere));
    joint_of[j.sphere] = static_cast<int>(k);
    if (j.child_body != s.body || j.parent_body != sp[s.parent].body || j.child_body == j.parent_body)
      fail(name + " must join its parent sphere's body to its own, different body");
    if (!j.axis.allFinite() || std::abs(j.axis.norm() - 1.0) > 1e-9) fail(name + " needs a unit axis");
    if (!(j.range >= 0) || !std::isfinite(j.range)) fail(name + " needs a finite range >= 0");
    if (j.neuron < 0 || j.neuron >= nn || robot.neurons[j.neuron].sphere != j.sphere)
      fail(name + " has motor neuron " + str(j.neuron) + ", which does not sit on its sphere");
    const int a = find_root(up, j.parent_body), b = find_root(up, j.child_body);
    if (a == b) fail(name + " closes a loop of joints");
    up[a] = b;
  }
  for (int i = 0; i < n; ++i)
    if (sp[i].has_joint && joint_of[i] < 0) fail("sphere " + str(i) + " has a joint flag but no joint");
  if (static_cast<int>(robot.joints.size()) != robot.num_bodies - 1)
    fail("joints must connect all " + str(robot.num_bodies) + " bodies (got " +
         str(static_cast<int>(robot.joints.size())) + " joints)");
  for (int i = 0; i < nn; ++i) {
    const Neuron& ne = robot.neurons[i];
    if (ne.sphere < 0 || ne.sphere >= n || joint_of[ne.sphere] < 0)
      fail("neuron " + str(i) + " is not on a jointed sphere");
    if (!(ne.tau > 0) || !std::isfinite(ne.tau) || !std::isfinite(ne.omega))
      fail("neuron " + str(i) + " needs tau > 0 and a finite omega");
  }
  for (size_t k = 0; k < robot.sensors.size(); ++k) {
    const Sensor& s = robot.sensors[k];
    if (s.sphere < 0 || s.sphere >= n) fail("sensor " + str(static_cast<int>(k)) + " has sphere " + str(s.sphere));
    if (s.type == SensorType::Proprio && joint_of[s.sphere] < 0)
      fail("proprioceptive sensor " + str(static_cast<int>(k)) + " sits on unjointed sphere " + str(s.sphere));
  }
  const int ns = static_cast<int>(robot.sensors.size());
  if (robot.w_sensor_neuron.rows() != ns || robot.w_sensor_neuron.cols() != nn)
    fail("w_sensor_neuron must be " + str(ns) + "x" + str(nn));
  if (robot.w_neuron_neuron.rows() != nn || robot.w_neuron_neuron.cols() != nn)
    fail("w_neuron_neuron must be " + str(nn) + "x" + str(nn));
  if (!robot.w_sensor_neuron.allFinite() || !robot.w_neuron_neuron.allFinite()) fail("non-finite CTRNN weight");
}

}  // namespace robozoo
