// grow() over 1,000 random CPPNs of both regimes: every rule of docs/method.md
// section 2 checked on every robot, re-deriving what can be re-derived from
// fresh CPPN queries, independently of the growth code.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Geometry>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/random_genome.hpp"
#include "evolve/growth/growth.hpp"
#include "tests/evolve/growth/cppn_builders.hpp"

namespace robozoo {
namespace {

using CppnOutputsArray = std::array<double, 11>;

using Out = CppnOutputsArray;

class Checker {
 public:
  /// check_maximal: also re-cast every cloud to prove no admissible point was
  /// skipped (as costly as growing again, so not done for every genome).
  Checker(Network& net, const Robot& robot, const GrowthParams& p, bool check_maximal)
      : net_(net), r_(robot), p_(p), n_(static_cast<int>(robot.spheres.size())), check_maximal_(check_maximal) {}

  Out query(const Eigen::Vector3d& x, double r_parent, int one_hot = -1) {
    double in[9] = {x.x(), x.y(), x.z(), r_parent, p_.bias_input, 0, 0, 0, 0};
    if (one_hot >= 0) in[kInSensorDistance + one_hot] = 1.0;
    Out out;
    net_.query(in, out.data());
    return out;
  }

  void run() {
    ASSERT_GE(n_, 1);
    ASSERT_LE(n_, p_.max_spheres);
    structure();
    if (::testing::Test::HasFatalFailure()) return;
    spheres_from_queries();
    placement_rules();
    queue_order();
    if (check_maximal_) maximal_growth();
    bodies_joints_neurons();
    sensors();
    weights();
    r_term();
    vertical_shift();
  }

 private:
  // Pre-shift centre (growth frame).
  Eigen::Vector3d c(int i) const { return r_.spheres[i].center - Eigen::Vector3d(0, 0, r_.vertical_shift); }
  bool grown_joint(int i) const { return r_.spheres[i].has_joint || r_.spheres[i].joint_pruned; }

  void structure() {
    children_.assign(n_, {});
    for (int i = 0; i < n_; ++i) {
      const Sphere& s = r_.spheres[i];
      ASSERT_EQ(s.index, i);
      ASSERT_EQ(c(i).z(), 0.0) << "all centres share one height";
      if (i == 0) {
        ASSERT_EQ(s.parent, -1);
        continue;
      }
      ASSERT_GE(s.parent, 0);
      ASSERT_LT(s.parent, i);
      children_[s.parent].push_back(i);
    }
    // Growth-time components: a grown joint starts one, named by its first sphere.
    comp_.assign(n_, 0);
    comp_parent_.assign(n_, -1);
    for (int i = 1; i < n_; ++i) {
      const int parent = r_.spheres[i].parent;
      if (grown_joint(i)) {
        comp_[i] = i;
        comp_parent_[i] = comp_[parent];
      } else {
        comp_[i] = comp_[parent];
      }
    }
  }

  static double density(double m, const GrowthParams& p) {
    return p.rho_min + (p.rho_max - p.rho_min) * (std::max(m, p.t_matter) - p.t_matter) / (1 - p.t_matter);
  }

  uint8_t mask(const Out& o, bool joint) const {
    uint8_t m = 0;
    if (o[kOutSensorDistance] > p_.t_sensor) m |= kSensorDistance;
    if (o[kOutSensorTouch] > p_.t_sensor) m |= kSensorTouch;
    if (joint && o[kOutSensorProprio] > p_.t_sensor) m |= kSensorProprio;
    if (o[kOutSensorTime] > p_.t_sensor) m |= kSensorTime;
    return m;
  }

  void spheres_from_queries() {
    const Sphere& root = r_.spheres[0];
    EXPECT_EQ(c(0), Eigen::Vector3d::Zero());
    EXPECT_EQ(root.radius, p_.r_init);
    EXPECT_EQ(root.cloud_angle_index, -1);
    EXPECT_FALSE(root.has_joint || root.joint_pruned);
    const Out o0 = query(Eigen::Vector3d::Zero(), p_.r_init);
    EXPECT_EQ(root.matter, o0[kOutMatter]);
    EXPECT_EQ(root.density, density(o0[kOutMatter], p_));
    EXPECT_EQ(root.sensors, mask(o0, false));
    for (int i = 1; i < n_; ++i) {
      const Sphere& s = r_.spheres[i];
      const Sphere& par = r_.spheres[s.parent];
      const int k = s.cloud_angle_index;
      ASSERT_GE(k, 0);
      ASSERT_LT(k, p_.cloud_points);
      // On the parent's circle, at angle k * step.
      const double a = k * p_.cloud_step;
      const Eigen::Vector3d want = c(s.parent) + par.radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
      EXPECT_NEAR((c(i) - want).norm(), 0.0, 1e-12) << "sphere " << i;
      const Out o = query(c(i), par.radius);
      EXPECT_GT(o[kOutMatter], p_.t_matter);  // rule (a)
      EXPECT_EQ(s.matter, o[kOutMatter]);
      EXPECT_GE(s.radius, p_.r_min);
      EXPECT_LE(s.radius, p_.r_max);
      EXPECT_EQ(s.radius, std::clamp(par.radius * (1 + o[kOutRadius]), p_.r_min, p_.r_max));
      EXPECT_EQ(s.density, density(o[kOutMatter], p_));
      EXPECT_EQ(grown_joint(i), o[kOutJoint] > p_.t_joint) << "sphere " << i;
      if (s.has_joint) {
        const Eigen::Vector3d ax = (c(i) - c(s.parent)).normalized();
        const Eigen::Vector3d n0 = ax.cross(Eigen::Vector3d::UnitZ()).normalized();
        const Eigen::Vector3d want_axis = Eigen::AngleAxisd(M_PI * o[kOutTheta], ax) * n0;
        EXPECT_NEAR((s.joint_axis - want_axis).norm(), 0.0, 1e-12);
        EXPECT_NEAR(s.joint_axis.norm(), 1.0, 1e-12);
        EXPECT_NEAR(s.joint_axis.dot(ax), 0.0, 1e-12);
        EXPECT_DOUBLE_EQ(s.joint_range, (o[kOutJoint] - p_.t_joint) / (1 - p_.t_joint) * p_.max_joint_range);
        const Neuron& nn = r_.neurons.at(s.motor_neuron);
        EXPECT_DOUBLE_EQ(nn.tau, p_.tau_min + (p_.tau_max - p_.tau_min) * (o[kOutTau] + 1) / 2);
        EXPECT_DOUBLE_EQ(nn.omega, o[kOutOmega] * p_.bias_max);
      } else {
        EXPECT_EQ(s.joint_axis, Eigen::Vector3d::Zero());
        EXPECT_EQ(s.joint_range, 0.0);
        EXPECT_EQ(s.motor_neuron, -1);
      }
      EXPECT_EQ(s.sensors, mask(o, s.has_joint)) << "sphere " << i;
    }
  }

  // Rules (b), (c), (d) for a sphere of radius r at x attached to `parent`
  // (jointed or fused), against the spheres in `existing`: written from
  // docs/method.md's text, independently of evolve/growth/body/placement.cpp.
  bool admissible(const Eigen::Vector3d& x, double r, int parent, bool jointed,
                  const std::vector<int>& existing) const {
    // Touching is decided with the relative tolerance e (docs/method.md section 2.3),
    // written here with distances rather than squared distances.
    const double e = p_.touch_tolerance;
    const double edge = (1 + e) * p_.bound;
    if (!(std::abs(x.x()) <= edge && std::abs(x.y()) <= edge)) return false;  // (d)
    const int pc = comp_[parent];
    for (int q : existing) {
      const Eigen::Vector3d d = x - c(q);
      const double dist = std::hypot(d.x(), d.y(), d.z());
      if (q != parent && dist < (1 - e) * r) return false;  // (b)
      const int qc = comp_[q];
      bool joined;
      if (jointed)
        joined = qc == pc;  // the new component is joined to the parent's only
      else
        joined = qc == pc || comp_parent_[qc] == pc || comp_parent_[pc] == qc;
      const double reach = r + r_.spheres[q].radius;
      if (!joined && dist < (1 - e) * reach) return false;  // (c)
    }
    return true;
  }

  void placement_rules() {
    for (int i = 1; i < n_; ++i) {
      std::vector<int> before(i);
      for (int q = 0; q < i; ++q) before[q] = q;
      const Sphere& s = r_.spheres[i];
      EXPECT_TRUE(admissible(c(i), s.radius, s.parent, grown_joint(i), before))
          << "sphere " << i << " breaks rule (b), (c) or (d)";
    }
  }

  // The visible part of the queue's history: a parent's children are placed
  // consecutively (a cloud is finished before the next pop), in m-descending
  // order (ties: cloud order), and a parent was popped before any older
  // sphere of lower priority whose cloud bore children later.
  void queue_order() {
    std::vector<int> parents;
    for (int i = 0; i < n_; ++i) {
      const auto& ch = children_[i];
      if (ch.empty()) continue;
      parents.push_back(i);
      for (size_t a = 1; a < ch.size(); ++a) {
        EXPECT_EQ(ch[a], ch[a - 1] + 1) << "children of " << i << " not consecutive";
        const Sphere &x = r_.spheres[ch[a - 1]], &y = r_.spheres[ch[a]];
        EXPECT_TRUE(x.matter > y.matter || (x.matter == y.matter && x.cloud_angle_index < y.cloud_angle_index));
      }
    }
    std::sort(parents.begin(), parents.end(),
              [&](int a, int b) { return children_[a][0] < children_[b][0]; });  // pop order
    for (size_t a = 0; a < parents.size(); ++a)
      for (size_t b = a + 1; b < parents.size(); ++b) {
        const int P = parents[a], Q = parents[b];
        if (Q >= children_[P][0]) continue;  // Q did not exist when P was popped
        const double mp = r_.spheres[P].matter, mq = r_.spheres[Q].matter;
        EXPECT_TRUE(mp > mq || (mp == mq && P < Q)) << "popped " << P << " before " << Q;
      }
  }

  // Growth places every admissible point: for each cloud that bore children,
  // every point with m > T that did not become a child must have been
  // inadmissible given the spheres present when it was visited (unless growth
  // stopped at max_spheres first). When the queue emptied (n < max), every
  // sphere's cloud was cast; for childless ones (pop time unknown) a point
  // inadmissible then is inadmissible against all final spheres, by monotony.
  void maximal_growth() {
    const bool stopped_at_max = n_ == p_.max_spheres;
    for (int P = 0; P < n_; ++P) {
      const auto& ch = children_[P];
      if (ch.empty() && stopped_at_max) continue;
      const Eigen::Vector3d cp = c(P);
      const double rp = r_.spheres[P].radius;
      struct Point {
        int k;
        double m;
        Out o;
      };
      std::vector<Point> pts;
      for (int k = 0; k < p_.cloud_points; ++k) {
        const double a = k * p_.cloud_step;
        const Eigen::Vector3d x = cp + rp * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
        Out o = query(x, rp);
        if (o[kOutMatter] > p_.t_matter) pts.push_back({k, o[kOutMatter], o});
      }
      std::stable_sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.m > b.m; });
      // Spheres present when the cloud was cast: all older than its first child,
      // or (pop time unknown) all of them.
      std::vector<int> existing;
      const int first = ch.empty() ? n_ : ch[0];
      for (int q = 0; q < first; ++q) existing.push_back(q);
      size_t next_child = 0;
      for (const Point& pt : pts) {
        if (next_child < ch.size() && r_.spheres[ch[next_child]].cloud_angle_index == pt.k) {
          existing.push_back(ch[next_child++]);
          continue;
        }
        if (stopped_at_max && next_child == ch.size() && !ch.empty() && ch.back() == n_ - 1) break;
        const double a = pt.k * p_.cloud_step;
        const Eigen::Vector3d x = cp + rp * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
        const double r = std::clamp(rp * (1 + pt.o[kOutRadius]), p_.r_min, p_.r_max);
        if (admissible(x, r, P, pt.o[kOutJoint] > p_.t_joint, existing))
          ADD_FAILURE() << "point " << pt.k << " of sphere " << P << "'s cloud was admissible but skipped";
      }
      EXPECT_EQ(next_child, ch.size()) << "children of " << P << " out of visiting order";
    }
  }

  void bodies_joints_neurons() {
    int bodies = 0, joints = 0;
    for (int i = 0; i < n_; ++i) {
      const Sphere& s = r_.spheres[i];
      EXPECT_EQ(s.num_children, static_cast<int>(children_[i].size()));
      if (s.num_children == 0) {
        EXPECT_FALSE(s.has_joint) << "leaf " << i << " kept its joint";
      }
      if (s.joint_pruned) {
        EXPECT_EQ(s.num_children, 0);
      }
      if (i == 0 || s.has_joint) {
        EXPECT_EQ(s.body, bodies++) << "bodies numbered by first sphere";
      } else {
        EXPECT_EQ(s.body, r_.spheres[s.parent].body);
      }
      if (s.has_joint) {
        ASSERT_LT(joints, static_cast<int>(r_.joints.size()));
        const Joint& j = r_.joints[joints];
        EXPECT_EQ(j.sphere, i);
        EXPECT_EQ(j.neuron, joints);
        EXPECT_EQ(s.motor_neuron, joints);
        EXPECT_EQ(j.parent_body, r_.spheres[s.parent].body);
        EXPECT_EQ(j.child_body, s.body);
        EXPECT_EQ(j.axis, s.joint_axis);
        EXPECT_EQ(j.range, s.joint_range);
        EXPECT_EQ(r_.neurons.at(joints).sphere, i);
        ++joints;
      }
    }
    EXPECT_EQ(r_.num_bodies, bodies);
    EXPECT_EQ(static_cast<int>(r_.joints.size()), joints);
    EXPECT_EQ(r_.neurons.size(), r_.joints.size());
  }

  void sensors() {
    std::vector<Sensor> want;
    for (int i = 0; i < n_; ++i) {
      const uint8_t m = r_.spheres[i].sensors;
      if (m & kSensorProprio) {
        EXPECT_TRUE(r_.spheres[i].has_joint) << "proprioception off a joint";
      }
      for (int t = 0; t < 4; ++t)
        if (m & (1 << t)) want.push_back({i, static_cast<SensorType>(t)});
    }
    ASSERT_EQ(r_.sensors.size(), want.size());
    for (size_t k = 0; k < want.size(); ++k) {
      EXPECT_EQ(r_.sensors[k].sphere, want[k].sphere);
      EXPECT_EQ(r_.sensors[k].type, want[k].type);
    }
  }

  double expressed(double w) const {
    const double t = p_.weight_threshold;
    if (!(std::abs(w) > t)) return 0.0;
    if (p_.weight_mapping == WeightMapping::Proportional) return w * p_.weight_max;
    return (w > 0 ? w - t : w + t) / (1 - t) * p_.weight_max;
  }

  void weights() {
    const auto ns = static_cast<Eigen::Index>(r_.sensors.size());
    const auto nn = static_cast<Eigen::Index>(r_.neurons.size());
    ASSERT_EQ(r_.w_sensor_neuron.rows(), ns);
    ASSERT_EQ(r_.w_sensor_neuron.cols(), nn);
    ASSERT_EQ(r_.w_neuron_neuron.rows(), nn);
    ASSERT_EQ(r_.w_neuron_neuron.cols(), nn);
    // The smallest magnitude a link may have: above threshold * weight_max when proportional, above 0 when rescaled.
    const double floor = p_.weight_mapping == WeightMapping::Proportional ? p_.weight_threshold * p_.weight_max : 0.0;
    for (Eigen::Index k = 0; k < ns; ++k)
      for (Eigen::Index i = 0; i < nn; ++i) {
        const double w = r_.w_sensor_neuron(k, i);
        EXPECT_TRUE(w == 0.0 || std::abs(w) > floor);
        const Eigen::Vector3d mid = (c(r_.sensors[k].sphere) + c(r_.neurons[i].sphere)) / 2.0;
        const Out o = query(mid, 0.0, static_cast<int>(r_.sensors[k].type));
        EXPECT_EQ(w, expressed(o[kOutWeight]));
      }
    for (Eigen::Index j = 0; j < nn; ++j)
      for (Eigen::Index i = 0; i < nn; ++i) {
        const double w = r_.w_neuron_neuron(j, i);
        EXPECT_TRUE(w == 0.0 || std::abs(w) > floor);
        const Eigen::Vector3d mid = (c(r_.neurons[j].sphere) + c(r_.neurons[i].sphere)) / 2.0;
        EXPECT_EQ(w, expressed(query(mid, 0.0)[kOutWeight]));
      }
  }

  void r_term() {
    const bool s = !r_.sensors.empty(), j = !r_.joints.empty();
    const bool nn = (r_.w_neuron_neuron.array() != 0).any(), sn = (r_.w_sensor_neuron.array() != 0).any();
    bool dist = false;
    for (const Sensor& x : r_.sensors) dist |= x.type == SensorType::Distance;
    const bool sim = s && j && nn && sn && dist;
    EXPECT_EQ(r_.r_term, 1.0 + s + j + nn + sn + (sim ? 10.0 : 0.0));
    EXPECT_EQ(r_.simulate, sim);
  }

  void vertical_shift() {
    int largest = 0;
    for (int i = 1; i < n_; ++i)
      if (r_.spheres[i].radius > r_.spheres[largest].radius) largest = i;
    const Sphere& l = r_.spheres[largest];
    EXPECT_EQ(l.center.z() - l.radius, 0.0) << "largest sphere rests on the ground";
    EXPECT_EQ(r_.vertical_shift, l.radius);
    for (const Sphere& s : r_.spheres) EXPECT_GE(s.center.z() - s.radius, 0.0);
  }

  Network& net_;
  const Robot& r_;
  const GrowthParams& p_;
  int n_;
  bool check_maximal_;
  std::vector<std::vector<int>> children_;
  std::vector<int> comp_, comp_parent_;
};

// A saturated CPPN: every output constant, m = 0.9 (every point is matter, all
// equal, so clouds are visited in angle order), r_scale = -0.9 (every child gets
// r_min), j = 0.9 (every child hinged). Its chains of r_min spheres along one
// cloud angle touch their grandparents exactly, which rounding alone used to
// decide. Growth must place every admissible point (checked independently,
// with hypot distances): it fills max_spheres, 50 or 200. Deciding touches by
// the last bit (touch_tolerance 0) refuses some exact touches and stops at 29.
TEST(GrowInvariants, SaturatedCppnGrowsEveryTouchingSphere) {
  Genome g = testing::bare_robot_genome();
  testing::constant(g, kOutMatter, 0.9);
  testing::constant(g, kOutRadius, -0.9);
  testing::constant(g, kOutJoint, 0.9);
  for (int cap : {50, 200}) {
    SCOPED_TRACE("max_spheres " + std::to_string(cap));
    GrowthParams p = testing::unit_bias_growth();
    p.max_spheres = cap;
    Network net(g, robot_layout());
    const Robot robot = grow(net, p);
    Checker(net, robot, p, /*check_maximal=*/true).run();
    const int n = static_cast<int>(robot.spheres.size());
    GrowthParams exact = p;
    exact.touch_tolerance = 0;
    const int n_exact = static_cast<int>(grow(net, exact).spheres.size());
    std::printf("saturated CPPN, max_spheres %d: %d spheres (%d with touch_tolerance 0)\n", cap, n, n_exact);
    EXPECT_EQ(n, cap);
    EXPECT_EQ(n_exact, 29);
  }
}

TEST(GrowInvariants, HoldForRandomCppnsOfBothRegimes) {
  const GrowthParams p = testing::unit_bias_growth();  // the bias -> m shift below assumes a bias input of 1
  Rng rng(20240611);
  const int kGenomes = 1000;
  int grew = 0, joint = 0, pruned = 0, distance = 0, simulate = 0, full = 0, partial = 0;
  std::vector<int> counts;
  for (int g = 0; g < kGenomes; ++g) {
    SCOPED_TRACE("genome " + std::to_string(g));
    const bool recurrent = g % 2 == 1;
    const int hidden = static_cast<int>(rng.uniform_int(0, 3));  // sequenced: argument order is unspecified
    const int extra = static_cast<int>(rng.uniform_int(0, 6));
    Genome genome = random_cppn(robot_layout(), recurrent, hidden, extra, rng);
    // Bias the bias -> m link up so that about half grow beyond the root.
    for (auto& l : genome.links)
      if (l.from == kInBias && l.to == robot_layout().num_inputs + kOutMatter) l.weight += 1.5;
    Network net(genome, robot_layout());
    const Robot robot = grow(net, p);
    Checker(net, robot, p, /*check_maximal=*/g % 4 < 2).run();
    if (HasFailure()) return;  // one genome's report is enough
    const int n = static_cast<int>(robot.spheres.size());
    counts.push_back(n);
    grew += n > 1;
    full += n == p.max_spheres;
    partial += n > 1 && n < p.max_spheres;
    joint += !robot.joints.empty();
    for (const Sphere& s : robot.spheres)
      if (s.joint_pruned) {
        ++pruned;
        break;
      }
    for (const Sensor& s : robot.sensors)
      if (s.type == SensorType::Distance) {
        ++distance;
        break;
      }
    simulate += robot.simulate;
  }
  std::sort(counts.begin(), counts.end());
  std::printf(
      "%d genomes: %d grew beyond the root (%d reached max_spheres, %d stopped between), "
      "%d with a joint, %d with a pruned joint, %d with a distance sensor, %d simulated; "
      "spheres median %d, 90th percentile %d\n",
      kGenomes, grew, full, partial, joint, pruned, distance, simulate, counts[counts.size() / 2],
      counts[counts.size() * 9 / 10]);
  // The checks above covered real morphologies of every kind.
  EXPECT_GT(grew, kGenomes / 4);
  EXPECT_GT(partial, 20);
  EXPECT_GT(full, 20);
  EXPECT_GT(joint, 20);
  EXPECT_GT(pruned, 20);
  EXPECT_GT(simulate, 5);
}

}  // namespace
}  // namespace robozoo
