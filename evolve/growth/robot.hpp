#pragma once
// A grown robot: a constant model (docs/method.md section 6: model apart from state).
// Positions are in the growth frame after the vertical shift unless noted.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace robozoo {

enum SensorBit : uint8_t {
  kSensorDistance = 1,
  kSensorTouch = 2,
  kSensorProprio = 4,
  kSensorTime = 8,
};
/// Sensor types in CPPN one-hot order and in morphology_t.sensor_type.
enum class SensorType : int8_t { Distance = 0, Touch = 1, Proprio = 2, Time = 3 };

struct Sphere {
  int index = 0;                        ///< growth order, 0 = root
  int parent = -1;                      ///< parent sphere index, -1 for the root
  Eigen::Vector3d center{0, 0, 0};      ///< centre after the vertical shift (m)
  double radius = 0.1;                  ///< (m)
  double density = 1.0;                 ///< (mass per m^3)
  double matter = 0.0;                  ///< CPPN output m at this sphere's point (queue priority)
  int body = 0;                         ///< rigid component index
  bool has_joint = false;               ///< hinge to the parent's body at this sphere's centre
  Eigen::Vector3d joint_axis{0, 0, 0};  ///< unit hinge axis (zero without a joint)
  double joint_range = 0.0;             ///< half range of motion (rad)
  int motor_neuron = -1;                ///< neuron driving the joint, -1 if none
  int cloud_angle_index = -1;           ///< k of the parent's cloud point (angle k * cloud_step); -1 for the root
  uint8_t sensors = 0;                  ///< SensorBit mask
  int num_children = 0;                 ///< spheres attached to this one
  bool joint_pruned = false;            ///< grew a joint that pruning made rigid (a leaf; paper 2.3)
};

struct Joint {
  int sphere = 0;                 ///< the child sphere (anchor at its centre)
  int parent_body = 0;            ///< body of the parent sphere
  int child_body = 0;             ///< body of the child sphere
  Eigen::Vector3d axis{1, 0, 0};  ///< unit hinge axis
  double range = 0.0;             ///< half range (rad): limits are [-range, +range]
  int neuron = 0;                 ///< motor neuron index
};

struct Sensor {
  int sphere = 0;
  SensorType type = SensorType::Distance;
};

struct Neuron {
  int sphere = 0;      ///< the jointed sphere carrying it
  double tau = 1.0;    ///< time constant (s)
  double omega = 0.0;  ///< bias (dimensionless)
};

struct Robot {
  std::vector<Sphere> spheres;  ///< growth order
  int num_bodies = 0;           ///< rigid components after pruning; bodies are numbered
                                ///< by their first sphere in growth order
  std::vector<Joint> joints;    ///< in growth order of their child spheres
  std::vector<Neuron> neurons;  ///< motor neurons, in growth order of their spheres
  std::vector<Sensor> sensors;  ///< by sphere, then by type (Distance, Touch, Proprio, Time)
  /// w_sensor_neuron(k, i): weight from sensor k to neuron i (0 = no link).
  Eigen::MatrixXd w_sensor_neuron;
  /// w_neuron_neuron(j, i): weight from neuron j to neuron i; diagonal = self-loops (0 = no link).
  Eigen::MatrixXd w_neuron_neuron;
  double r_term = 1.0;          ///< the fitness's r term (paper 2.4), +10 included when simulated
  bool simulate = false;        ///< all four r rewards earned and a distance sensor present
  double vertical_shift = 0.0;  ///< dz added to every centre so the largest sphere rests on z = 0 (m)
};

}  // namespace robozoo
