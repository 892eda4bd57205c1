// Every robozoo message type round-trips through encode/decode, and through an
// LCM log file written and read back with lcm::LogFile.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "robozoo/generation_t.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"

namespace {

robozoo::run_t make_run() {
  robozoo::run_t m;
  m.utime = 1234567;
  m.run_id = "run-42";
  m.software_version = "0.1.0";
  m.seed = -9000000000LL;
  m.regime = 1;
  m.population = 150;
  m.generations = 500;
  m.steps = 2500;
  m.dt = 0.01;
  m.config_json = "{\"a\": [1, 2, 3]}";
  return m;
}

robozoo::generation_t make_generation() {
  robozoo::generation_t m{};
  m.utime = 7;
  m.run_id = "run-42";
  m.generation = 3;
  m.evaluations = 600;
  m.best_fitness = 15.25;
  m.mean_fitness = 3.5;
  m.stderr_fitness = 0.125;
  m.best_so_far_fitness = 16.0;
  m.champion_id = 451;
  m.num_species = 8;
  m.compatibility_threshold = 6.3;
  m.n_not_simulated = 100;
  m.n_completed = 20;
  m.n_stopped_early = 10;
  m.n_accel_fault = 5;
  m.n_rolling_contact = 10;
  m.n_rolling_spin = 5;
  m.eval_seconds = 1.5;
  m.generation_seconds = 1.75;
  return m;
}

robozoo::cppn_genome_t make_genome() {
  robozoo::cppn_genome_t m{};
  m.utime = 8;
  m.run_id = "run-42";
  m.generation = 3;
  m.genome_id = 451;
  m.species_id = 2;
  m.fitness = 15.25;
  m.r_term = 15;
  m.d_term = 0.25;
  m.outcome = 1;
  for (int i = 0; i < 3; ++i) {
    robozoo::cppn_node_t n;
    n.id = i == 2 ? 20 : i;
    n.kind = static_cast<int8_t>(i == 2 ? 3 : 0);
    n.activation = static_cast<int8_t>(i);
    m.nodes.push_back(n);
  }
  m.num_nodes = static_cast<int32_t>(m.nodes.size());
  for (int i = 0; i < 2; ++i) {
    robozoo::link_t l;
    l.innovation = 100 + i;
    l.from_node = i;
    l.to_node = 20;
    l.weight = -1.0 / 3.0 + i;
    l.enabled = i == 0;
    m.links.push_back(l);
  }
  m.num_links = static_cast<int32_t>(m.links.size());
  return m;
}

robozoo::morphology_t make_morphology() {
  robozoo::morphology_t m{};
  m.utime = 9;
  m.run_id = "run-42";
  m.generation = 3;
  m.genome_id = 451;
  for (int i = 0; i < 2; ++i) {
    robozoo::sphere_t s{};
    s.index = i;
    s.parent = i - 1;
    s.center[0] = 0.1 * i;
    s.center[1] = 0.2;
    s.center[2] = 0.3;
    s.radius = 0.1;
    s.density = 1.5;
    s.body = i;
    s.has_joint = i == 1;
    s.joint_axis[1] = i;
    s.joint_range = 0.5 * i;
    s.motor_neuron = i - 1;
    s.sensors = static_cast<int8_t>(1 | 8);
    m.spheres.push_back(s);
  }
  m.num_spheres = 2;
  m.num_bodies = 2;
  m.num_neurons = 1;
  m.tau = {0.5};
  m.omega = {-1.25};
  m.num_sensors = 3;
  m.sensor_sphere = {0, 0, 1};
  m.sensor_type = {0, 3, 2};
  m.w_sensor_neuron = {{0.5}, {0.0}, {-2.5}};
  m.w_neuron_neuron = {{1.75}};
  m.r_term = 15;
  return m;
}

robozoo::pose_t make_pose() {
  robozoo::pose_t m{};
  m.utime = 10;
  m.run_id = "run-42";
  m.generation = 3;
  m.genome_id = 451;
  m.step = 40;
  m.sim_time = 0.4;
  m.num_bodies = 2;
  m.body_position = {{0, 1, 2}, {3, 4, 5}};
  m.body_quaternion = {{1, 0, 0, 0}, {0.5, 0.5, 0.5, 0.5}};
  m.num_spheres = 1;
  m.sphere_center = {{0.1, 0.2, 0.3}};
  m.num_neurons = 2;
  m.neuron_output = {0.25, -0.75};
  m.num_sensors = 1;
  m.sensor_value = {0.5};
  return m;
}

template <class T>
T round_trip(const T& in) {
  const int size = in.getEncodedSize();
  std::vector<uint8_t> buf(static_cast<size_t>(size));
  EXPECT_EQ(in.encode(buf.data(), 0, size), size);
  T out;
  EXPECT_EQ(out.decode(buf.data(), 0, size), size);
  // Byte-exact: re-encoding what was decoded gives the same bytes.
  std::vector<uint8_t> again(static_cast<size_t>(out.getEncodedSize()));
  out.encode(again.data(), 0, static_cast<int>(again.size()));
  EXPECT_EQ(buf, again);
  return out;
}

template <class T>
std::vector<uint8_t> encode(const T& m) {
  std::vector<uint8_t> buf(static_cast<size_t>(m.getEncodedSize()));
  m.encode(buf.data(), 0, static_cast<int>(buf.size()));
  return buf;
}

TEST(LcmTypes, RunRoundTrip) {
  auto in = make_run();
  auto out = round_trip(in);
  EXPECT_EQ(out.run_id, in.run_id);
  EXPECT_EQ(out.seed, in.seed);
  EXPECT_EQ(out.regime, in.regime);
  EXPECT_EQ(out.config_json, in.config_json);
  EXPECT_EQ(out.dt, in.dt);
}

TEST(LcmTypes, GenerationRoundTrip) {
  auto in = make_generation();
  auto out = round_trip(in);
  EXPECT_EQ(out.evaluations, in.evaluations);
  EXPECT_EQ(out.best_so_far_fitness, in.best_so_far_fitness);
  EXPECT_EQ(out.n_rolling_spin, in.n_rolling_spin);
  EXPECT_EQ(out.compatibility_threshold, in.compatibility_threshold);
}

TEST(LcmTypes, GenomeRoundTrip) {
  auto in = make_genome();
  auto out = round_trip(in);
  ASSERT_EQ(out.num_nodes, 3);
  ASSERT_EQ(out.num_links, 2);
  EXPECT_EQ(out.nodes[2].id, 20);
  EXPECT_EQ(out.nodes[2].kind, 3);
  EXPECT_EQ(out.links[0].weight, -1.0 / 3.0);
  EXPECT_TRUE(out.links[0].enabled);
  EXPECT_FALSE(out.links[1].enabled);
}

TEST(LcmTypes, MorphologyRoundTrip) {
  auto in = make_morphology();
  auto out = round_trip(in);
  ASSERT_EQ(out.spheres.size(), 2u);
  EXPECT_EQ(out.spheres[1].parent, 0);
  EXPECT_EQ(out.spheres[1].joint_range, 0.5);
  EXPECT_EQ(out.w_sensor_neuron, in.w_sensor_neuron);
  EXPECT_EQ(out.w_neuron_neuron, in.w_neuron_neuron);
  EXPECT_EQ(out.sensor_type, in.sensor_type);
}

TEST(LcmTypes, PoseRoundTrip) {
  auto in = make_pose();
  auto out = round_trip(in);
  EXPECT_EQ(out.body_quaternion, in.body_quaternion);
  EXPECT_EQ(out.sphere_center, in.sphere_center);
  EXPECT_EQ(out.neuron_output, in.neuron_output);
}

TEST(LcmTypes, DecodeRejectsTruncatedBuffer) {
  auto buf = encode(make_morphology());
  robozoo::morphology_t out;
  EXPECT_LT(out.decode(buf.data(), 0, static_cast<int>(buf.size()) - 5), 0);
}

TEST(LcmTypes, DecodeRejectsWrongType) {
  auto buf = encode(make_pose());
  robozoo::cppn_genome_t out;  // different fingerprint
  EXPECT_LT(out.decode(buf.data(), 0, static_cast<int>(buf.size())), 0);
}

TEST(LcmTypes, LogFileRoundTrip) {
  char path[] = "/tmp/robozoo_lcmtypes_test_XXXXXX";
  int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  const std::vector<std::pair<std::string, std::vector<uint8_t>>> events = {
      {"ROBOZOO_RUN", encode(make_run())},       {"ROBOZOO_GENERATION", encode(make_generation())},
      {"ROBOZOO_GENOME", encode(make_genome())}, {"ROBOZOO_MORPHOLOGY", encode(make_morphology())},
      {"ROBOZOO_POSE", encode(make_pose())},
  };
  {
    lcm::LogFile log(path, "w");
    ASSERT_TRUE(log.good());
    int64_t t = 1000;
    for (const auto& [channel, data] : events) {
      lcm::LogEvent ev{};
      ev.eventnum = 0;
      ev.timestamp = t++;
      ev.channel = channel;
      ev.datalen = static_cast<int32_t>(data.size());
      ev.data = const_cast<uint8_t*>(data.data());
      ASSERT_EQ(log.writeEvent(&ev), 0);
    }
  }
  lcm::LogFile log(path, "r");
  ASSERT_TRUE(log.good());
  size_t i = 0;
  for (const lcm::LogEvent* ev = log.readNextEvent(); ev; ev = log.readNextEvent(), ++i) {
    ASSERT_LT(i, events.size());
    EXPECT_EQ(ev->channel, events[i].first);
    ASSERT_EQ(ev->datalen, static_cast<int32_t>(events[i].second.size()));
    std::vector<uint8_t> data(static_cast<const uint8_t*>(ev->data),
                              static_cast<const uint8_t*>(ev->data) + ev->datalen);
    EXPECT_EQ(data, events[i].second);
  }
  EXPECT_EQ(i, events.size());
  // Decode one back through the generated type.
  lcm::LogFile again(path, "r");
  const lcm::LogEvent* ev = nullptr;
  for (int k = 0; k < 4; ++k) ev = again.readNextEvent();
  ASSERT_NE(ev, nullptr);
  robozoo::morphology_t m;
  ASSERT_EQ(m.decode(ev->data, 0, ev->datalen), ev->datalen);
  EXPECT_EQ(m.w_sensor_neuron, make_morphology().w_sensor_neuron);
  std::remove(path);
}

}  // namespace
