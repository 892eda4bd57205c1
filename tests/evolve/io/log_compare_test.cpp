// first_log_difference is the oracle of the determinism, resume, worker-count
// and MPI tests: each test here builds two logs that differ in one known way
// and checks that the oracle finds it (or, for the clock fields it leaves out,
// that it does not).
#include "evolve/io/log_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "evolve/messages/build.hpp"

namespace robozoo {
namespace {

template <class T>
LogRecord record(const std::string& channel, const T& m) {
  LogRecord r;
  r.channel = channel;
  r.data = encode_message(m);
  return r;
}

run_t run_message() {
  run_t m{};
  m.utime = 1000;
  m.run_id = "run-1";
  m.software_version = "abc123";
  m.seed = 7;
  m.regime = 1;
  m.population = 10;
  m.generations = 2;
  m.steps = 100;
  m.dt = 0.01;
  m.config_json = "{\"seed\":7}";
  return m;
}

generation_t generation_message() {
  generation_t m{};
  m.utime = 2000;
  m.run_id = "run-1";
  m.generation = 0;
  m.evaluations = 10;
  m.best_fitness = 3.25;
  m.mean_fitness = 1.5;
  m.stderr_fitness = 0.125;
  m.best_so_far_fitness = 3.25;
  m.champion_id = 4;
  m.num_species = 2;
  m.compatibility_threshold = 3.0;
  m.n_not_simulated = 6;
  m.n_completed = 4;
  m.eval_seconds = 1.75;
  m.generation_seconds = 2.5;
  return m;
}

cppn_genome_t genome_message() {
  cppn_genome_t m{};
  m.utime = 3000;
  m.run_id = "run-1";
  m.genome_id = 4;
  m.species_id = 1;
  m.fitness = 3.25;
  m.r_term = 1;
  m.d_term = 2.25;
  m.outcome = 1;
  m.nodes.resize(2);
  m.nodes[0].id = 0;
  m.nodes[0].kind = 0;
  m.nodes[0].position = 0.0;
  m.nodes[1].id = 9;
  m.nodes[1].kind = 2;
  m.nodes[1].position = 1.0;
  m.num_nodes = 2;
  m.links.resize(1);
  m.links[0].innovation = 1;
  m.links[0].from_node = 0;
  m.links[0].to_node = 9;
  m.links[0].weight = 0.5;
  m.links[0].enabled = true;
  m.num_links = 1;
  return m;
}

morphology_t morphology_message() {
  morphology_t m{};
  m.utime = 4000;
  m.run_id = "run-1";
  m.genome_id = 4;
  m.spheres.resize(1);
  m.spheres[0].parent = -1;
  m.spheres[0].center[2] = 0.1;
  m.spheres[0].radius = 0.1;
  m.spheres[0].density = 1000;
  m.spheres[0].motor_neuron = -1;
  m.num_spheres = 1;
  m.num_bodies = 1;
  m.num_neurons = 1;
  m.tau = {0.5};
  m.omega = {0.25};
  m.num_sensors = 1;
  m.sensor_sphere = {0};
  m.sensor_type = {3};
  m.w_sensor_neuron = {{0.75}};
  m.w_neuron_neuron = {{-0.5}};
  m.r_term = 1;
  return m;
}

pose_t pose_message(int32_t step) {
  pose_t m{};
  m.utime = 5000 + step;
  m.run_id = "run-1";
  m.genome_id = 4;
  m.step = step;
  m.sim_time = 0.01 * step;
  m.num_bodies = 1;
  m.body_position = {{0.0, 0.0, 0.1 + step}};
  m.body_quaternion = {{1.0, 0.0, 0.0, 0.0}};
  m.num_spheres = 1;
  m.sphere_center = {{0.0, 0.0, 0.1 + step}};
  m.num_neurons = 1;
  m.neuron_output = {0.5};
  m.num_sensors = 1;
  m.sensor_value = {0.25};
  return m;
}

// A small log with every channel, poses of steps 0, 10 and 20, and an LCM
// self-test message.
struct Messages {
  run_t run = run_message();
  generation_t generation = generation_message();
  cppn_genome_t genome = genome_message();
  morphology_t morphology = morphology_message();
  std::vector<pose_t> poses = {pose_message(0), pose_message(10), pose_message(20)};
};

LogContents log_of(const Messages& m) {
  LogContents c;
  c.records.push_back(record(kChannelRun, m.run));
  LogRecord self_test;
  self_test.channel = "LCM_SELF_TEST";
  self_test.data = {1, 2, 3};
  c.records.push_back(self_test);
  c.records.push_back(record(kChannelGeneration, m.generation));
  c.records.push_back(record(kChannelGenome, m.genome));
  c.records.push_back(record(kChannelMorphology, m.morphology));
  for (const auto& p : m.poses) c.records.push_back(record(kChannelPose, p));
  for (size_t i = 0; i < c.records.size(); ++i) c.records[i].eventnum = static_cast<int64_t>(i);
  return c;
}

// The oracle must report a difference that names `channel`.
void expect_difference(const Messages& changed, const std::string& channel) {
  const std::string d = first_log_difference(log_of(Messages{}), log_of(changed));
  EXPECT_NE(d, "") << "a change on " << channel << " went unnoticed";
  EXPECT_NE(d.find(channel), std::string::npos) << d;
  // The oracle is symmetric in what it finds.
  EXPECT_NE(first_log_difference(log_of(changed), log_of(Messages{})), "");
}

double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

double nan_with_payload(uint64_t payload) {
  uint64_t bits = 0x7ff8000000000000ull | payload;
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

TEST(LogCompare, EqualLogsAreEqual) { EXPECT_EQ(first_log_difference(log_of(Messages{}), log_of(Messages{})), ""); }

TEST(LogCompare, LeavesOutOnlyUtimeAndTheGenerationTimings) {
  Messages m;
  m.run.utime += 1;
  m.generation.utime += 1;
  m.generation.eval_seconds = 99;
  m.generation.generation_seconds = 123;
  m.genome.utime += 1;
  m.morphology.utime += 1;
  for (auto& p : m.poses) p.utime += 1;
  LogContents b = log_of(m);
  for (auto& r : b.records) {
    r.timestamp += 17;  // the event's own time stamp is not a message field
    r.eventnum += 3;    // nor is its number (a resumed log continues numbering)
  }
  EXPECT_EQ(first_log_difference(log_of(Messages{}), b), "");
}

TEST(LogCompare, SkipsChannelsRobozooDoesNotOwn) {
  LogContents b = log_of(Messages{});
  LogRecord other;
  other.channel = "SOMEONE_ELSE";
  other.data = {9, 9};
  b.records.insert(b.records.begin() + 3, other);
  EXPECT_EQ(first_log_difference(log_of(Messages{}), b), "");
}

// One difference per channel.
TEST(LogCompare, FindsADifferenceOnEveryChannel) {
  {
    Messages m;
    m.run.seed = 8;
    expect_difference(m, kChannelRun);
  }
  {
    Messages m;
    m.generation.num_species = 3;
    expect_difference(m, kChannelGeneration);
  }
  {
    Messages m;
    m.genome.species_id = 2;
    expect_difference(m, kChannelGenome);
  }
  {
    Messages m;
    m.morphology.num_bodies = 2;
    expect_difference(m, kChannelMorphology);
  }
  {
    Messages m;
    m.poses[1].sim_time = 0.2;
    expect_difference(m, kChannelPose);
  }
}

// One difference per kind of field.
TEST(LogCompare, FindsAnIntegerDifference) {
  Messages m;
  m.generation.n_completed += 1;
  expect_difference(m, kChannelGeneration);
  Messages big;
  big.genome.genome_id += int64_t(1) << 40;  // only the high bytes of an int64 differ
  expect_difference(big, kChannelGenome);
  Messages byte;
  byte.genome.outcome = 2;  // an int8
  expect_difference(byte, kChannelGenome);
  Messages boolean;
  boolean.genome.links[0].enabled = false;
  expect_difference(boolean, kChannelGenome);
}

TEST(LogCompare, FindsADoubleThatDiffersByOneUlp) {
  Messages m;
  m.generation.best_fitness = next_up(m.generation.best_fitness);
  expect_difference(m, kChannelGeneration);
  Messages tiny;
  tiny.poses[2].body_position[0][0] = std::numeric_limits<double>::denorm_min();  // vs +0.0
  expect_difference(tiny, kChannelPose);
  Messages zero;
  zero.poses[2].body_position[0][0] = -0.0;  // equal as numbers, not as bits
  expect_difference(zero, kChannelPose);
}

TEST(LogCompare, NanEqualsOnlyTheSameNan) {
  Messages a, b;
  a.generation.stderr_fitness = nan_with_payload(0);
  b.generation.stderr_fitness = nan_with_payload(0);
  EXPECT_EQ(first_log_difference(log_of(a), log_of(b)), "") << "a NaN logged twice is bit-identical";
  b.generation.stderr_fitness = nan_with_payload(1);
  EXPECT_NE(first_log_difference(log_of(a), log_of(b)), "") << "NaNs with different bits";
  b.generation.stderr_fitness = -nan_with_payload(0);
  EXPECT_NE(first_log_difference(log_of(a), log_of(b)), "") << "NaNs with different signs";
  b.generation.stderr_fitness = 0.125;
  EXPECT_NE(first_log_difference(log_of(a), log_of(b)), "") << "NaN vs a number";
  b.generation.stderr_fitness = std::numeric_limits<double>::infinity();
  EXPECT_NE(first_log_difference(log_of(a), log_of(b)), "") << "NaN vs infinity";
}

TEST(LogCompare, FindsAStringDifference) {
  Messages m;
  m.run.config_json = "{\"seed\":8}";
  expect_difference(m, kChannelRun);
  Messages longer;
  longer.run.software_version += "-dirty";
  expect_difference(longer, kChannelRun);
  Messages id;
  id.poses[0].run_id = "run-2";
  expect_difference(id, kChannelPose);
}

TEST(LogCompare, FindsAnArrayLengthDifference) {
  Messages m;
  m.poses[1].num_neurons = 2;
  m.poses[1].neuron_output = {0.5, 0.5};
  expect_difference(m, kChannelPose);
  Messages empty;
  empty.genome.num_links = 0;
  empty.genome.links.clear();
  expect_difference(empty, kChannelGenome);
  Messages two_d;
  two_d.morphology.num_neurons = 2;
  two_d.morphology.tau = {0.5, 0.5};
  two_d.morphology.omega = {0.25, 0.25};
  two_d.morphology.w_sensor_neuron = {{0.75, 0.0}};
  two_d.morphology.w_neuron_neuron = {{-0.5, 0.0}, {0.0, 0.0}};
  expect_difference(two_d, kChannelMorphology);
}

TEST(LogCompare, FindsAnArrayElementDifference) {
  Messages m;
  m.poses[2].sensor_value[0] = next_up(0.25);
  expect_difference(m, kChannelPose);
  Messages quat;
  quat.poses[0].body_quaternion[0][3] = 1e-300;
  expect_difference(quat, kChannelPose);
  Messages matrix;
  matrix.morphology.w_neuron_neuron[0][0] = -0.25;
  expect_difference(matrix, kChannelMorphology);
  Messages int8s;
  int8s.morphology.sensor_type[0] = 2;
  expect_difference(int8s, kChannelMorphology);
}

TEST(LogCompare, FindsANestedStructElementDifference) {
  Messages m;
  m.genome.links[0].weight = next_up(0.5);
  expect_difference(m, kChannelGenome);
  Messages node;
  node.genome.nodes[1].position = 0.5;
  expect_difference(node, kChannelGenome);
  Messages activation;
  activation.genome.nodes[1].activation = 1;
  expect_difference(activation, kChannelGenome);
  Messages sphere;
  sphere.morphology.spheres[0].radius = next_up(0.1);
  expect_difference(sphere, kChannelMorphology);
  Messages axis;
  axis.morphology.spheres[0].joint_axis[1] = 1.0;
  expect_difference(axis, kChannelMorphology);
}

TEST(LogCompare, FindsAnExtraEvent) {
  LogContents b = log_of(Messages{});
  b.records.push_back(record(kChannelPose, pose_message(30)));
  const std::string d = first_log_difference(log_of(Messages{}), b);
  EXPECT_NE(d.find("robozoo events: 7 vs 8"), std::string::npos) << d;
  EXPECT_NE(d.find(kChannelPose), std::string::npos) << d;
  // A duplicated event in the middle.
  LogContents dup = log_of(Messages{});
  dup.records.insert(dup.records.begin() + 6, dup.records[6]);
  EXPECT_NE(first_log_difference(log_of(Messages{}), dup), "");
}

TEST(LogCompare, FindsAMissingEvent) {
  for (size_t k : {0u, 2u, 3u, 4u, 5u, 6u, 7u}) {  // every robozoo event in turn (1 is the self-test)
    LogContents b = log_of(Messages{});
    const std::string channel = b.records[k].channel;
    b.records.erase(b.records.begin() + static_cast<long>(k));
    EXPECT_NE(first_log_difference(log_of(Messages{}), b), "") << "removed " << channel;
    EXPECT_NE(first_log_difference(b, log_of(Messages{})), "") << "removed " << channel;
  }
}

TEST(LogCompare, FindsReorderedEvents) {
  LogContents poses = log_of(Messages{});
  std::swap(poses.records[5], poses.records[6]);  // two poses of the same genome
  const std::string d = first_log_difference(log_of(Messages{}), poses);
  EXPECT_NE(d.find("event 4"), std::string::npos) << d;
  EXPECT_NE(d.find(kChannelPose), std::string::npos) << d;
  LogContents channels = log_of(Messages{});
  std::swap(channels.records[3], channels.records[4]);  // genome and morphology
  const std::string c = first_log_difference(log_of(Messages{}), channels);
  EXPECT_NE(c.find("channel ROBOZOO_GENOME vs ROBOZOO_MORPHOLOGY"), std::string::npos) << c;
}

// A record that does not decode never compares equal, not even to itself.
TEST(LogCompare, AnUndecodableRecordEqualsNothing) {
  const std::vector<std::vector<uint8_t>> bad = {
      {},                               // empty
      {0xde, 0xad},                     // garbage
      encode_message(pose_message(0)),  // a pose on the genome channel (wrong fingerprint)
  };
  for (const auto& data : bad) {
    LogContents a = log_of(Messages{});
    a.records[3].data = data;  // ROBOZOO_GENOME
    LogContents b = a;
    const std::string d = first_log_difference(a, b);
    EXPECT_NE(d.find("does not decode"), std::string::npos) << d;
    EXPECT_NE(d.find(kChannelGenome), std::string::npos) << d;
    EXPECT_NE(first_log_difference(log_of(Messages{}), a), "");
  }
  // A genome cut short by one byte, and one with a byte after its end.
  auto cut = encode_message(genome_message());
  cut.pop_back();
  auto longer = encode_message(genome_message());
  longer.push_back(0);
  for (const auto& data : {cut, longer}) {
    LogContents a = log_of(Messages{});
    a.records[3].data = data;
    EXPECT_NE(first_log_difference(a, a).find("does not decode"), std::string::npos);
  }
  // A count that claims more elements than the bytes hold.
  auto pose = encode_message(pose_message(0));
  const size_t num_neurons_at = pose.size() - (4 + 8 + 4 + 8);  // before neuron_output, num_sensors, sensor_value
  pose[num_neurons_at] = 0x7f;
  LogContents a = log_of(Messages{});
  a.records[5].data = pose;
  const std::string d = first_log_difference(a, a);
  EXPECT_NE(d.find("does not decode"), std::string::npos) << d;
  EXPECT_NE(d.find("neuron_output"), std::string::npos) << d;
}

TEST(LogCompare, NormalizeMessageSaysWhyItRefuses) {
  std::vector<uint8_t> out;
  std::string why;
  EXPECT_FALSE(normalize_message(kChannelRun, {1, 2, 3}, out, &why));
  EXPECT_NE(why, "");
  EXPECT_FALSE(normalize_message("LCM_SELF_TEST", {1, 2, 3}, out, &why));
  EXPECT_EQ(why, "not a robozoo channel");
  EXPECT_TRUE(normalize_message(kChannelRun, encode_message(run_message()), out, &why));
  run_t decoded;
  ASSERT_EQ(decoded.decode(out.data(), 0, static_cast<int>(out.size())), static_cast<int>(out.size()));
  EXPECT_EQ(decoded.utime, 0);
  EXPECT_EQ(decoded.seed, 7);
}

TEST(LogCompare, ComparesAnUnknownRobozooChannelAsRawBytes) {
  LogContents a = log_of(Messages{});
  LogRecord status;
  status.channel = "ROBOZOO_SOMETHING_NEW";
  status.data = {1, 2, 3};
  a.records.push_back(status);
  LogContents b = a;
  EXPECT_EQ(first_log_difference(a, b), "");
  b.records.back().data[2] = 4;
  const std::string d = first_log_difference(a, b);
  EXPECT_NE(d.find("ROBOZOO_SOMETHING_NEW"), std::string::npos) << d;
}

TEST(LogCompare, NamesTheFirstDifferingByte) {
  Messages m;
  m.run.seed = 8;
  const std::string d = first_log_difference(log_of(Messages{}), log_of(m));
  EXPECT_NE(d.find("event 0"), std::string::npos) << d;
  EXPECT_NE(d.find("0x07 vs 0x08"), std::string::npos) << d;
}

}  // namespace
}  // namespace robozoo

namespace robozoo {
namespace {

// A bus recording: missing events are loss (counted, not a defect); anything
// changed, extra, repeated or reordered is a defect, named at once.
TEST(BusRecording, TheSameEventsAreComplete) {
  const BusRecording r = compare_bus_recording(log_of(Messages{}), log_of(Messages{}));
  EXPECT_EQ(r.defect, "");
  EXPECT_EQ(r.missing, 0u);
  EXPECT_EQ(r.sent, 7u);
  EXPECT_EQ(r.received, 7u);
}

TEST(BusRecording, MissingEventsAreCountedNotDefects) {
  LogContents b = log_of(Messages{});
  b.records.erase(b.records.begin() + 5);  // a pose
  b.records.erase(b.records.begin() + 2);  // the generation
  b.records.pop_back();                    // the last pose
  const BusRecording r = compare_bus_recording(log_of(Messages{}), b);
  EXPECT_EQ(r.defect, "");
  EXPECT_EQ(r.missing, 3u);
}

TEST(BusRecording, ChangedExtraRepeatedOrReorderedEventsAreDefects) {
  Messages changed;
  changed.poses[1].body_position[0][0] += 1e-9;
  EXPECT_NE(compare_bus_recording(log_of(Messages{}), log_of(changed)).defect, "");
  LogContents extra = log_of(Messages{});
  extra.records.push_back(record(kChannelPose, pose_message(30)));
  EXPECT_NE(compare_bus_recording(log_of(Messages{}), extra).defect.find("equals no event"), std::string::npos);
  LogContents repeated = log_of(Messages{});
  repeated.records.insert(repeated.records.begin() + 6, repeated.records[6]);
  EXPECT_NE(compare_bus_recording(log_of(Messages{}), repeated).defect.find("repeats or reorders"), std::string::npos);
  LogContents swapped = log_of(Messages{});
  std::swap(swapped.records[5], swapped.records[6]);
  EXPECT_NE(compare_bus_recording(log_of(Messages{}), swapped).defect, "");
  LogContents undecodable = log_of(Messages{});
  undecodable.records[3].data[0] ^= 0x40;
  EXPECT_NE(compare_bus_recording(log_of(Messages{}), undecodable).defect.find("does not decode"), std::string::npos);
}

TEST(BusRecording, BusStatusMessagesAreNeverCompared) {
  LogContents b = log_of(Messages{});
  bus_status_t s{};
  s.run_id = "run-1";
  s.messages_published = 7;
  b.records.push_back(record(kChannelBus, s));
  EXPECT_EQ(first_log_difference(log_of(Messages{}), b), "");
  EXPECT_EQ(compare_bus_recording(log_of(Messages{}), b).defect, "");
}

}  // namespace
}  // namespace robozoo
