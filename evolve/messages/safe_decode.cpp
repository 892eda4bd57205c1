#include "evolve/messages/safe_decode.hpp"

#include <cstring>
#include <vector>

namespace robozoo {

namespace {

// Sizes on the wire (LCM: big-endian, nested structs without their hash).
constexpr int64_t kNodeBytes = 4 + 1 + 1 + 8;                                  // cppn_node_t
constexpr int64_t kLinkBytes = 8 + 4 + 4 + 8 + 1;                              // link_t
constexpr int64_t kSphereBytes = 4 + 4 + 24 + 8 + 8 + 4 + 1 + 24 + 8 + 4 + 1;  // sphere_t

class Walker {
 public:
  Walker(const uint8_t* d, size_t len, std::string* why) : d_(d), len_(static_cast<int64_t>(len)), why_(why) {}

  bool hash(int64_t expected) {
    if (!need(8, "fingerprint")) return false;
    uint64_t h = 0;
    for (int i = 0; i < 8; ++i) h = (h << 8) | d_[pos_ + i];
    pos_ += 8;
    if (static_cast<int64_t>(h) != expected) return fail("wrong fingerprint (not this message type)");
    return true;
  }
  bool skip(int64_t n, const char* what) {
    if (!need(n, what)) return false;
    pos_ += n;
    return true;
  }
  // An LCM string: its length with the terminating zero byte, its bytes, the
  // zero. LCM's decoder keeps any bytes (it never looks at the terminator) but
  // its encoder writes the string up to its first zero byte, so a string with
  // a zero inside or without its terminator would not survive re-encoding:
  // two different messages would normalise to the same bytes.
  bool str(const char* what) {
    int32_t n;
    if (!i32(n, what)) return false;
    if (n < 1) return fail(std::string(what) + ": bad string length");
    if (!need(n, what)) return false;
    if (d_[pos_ + n - 1] != 0) return fail(std::string(what) + ": string without its terminating zero byte");
    if (std::memchr(d_ + pos_, 0, static_cast<size_t>(n - 1)))
      return fail(std::string(what) + ": zero byte inside the string");
    pos_ += n;
    return true;
  }
  bool count(int32_t& n, const char* what) {
    if (!i32(n, what)) return false;
    if (n < 0) return fail(std::string(what) + ": negative count " + std::to_string(n));
    return true;
  }
  bool array(int64_t n, int64_t elem, const char* what) {
    if (n != 0 && elem > (len_ - pos_) / n) return fail(std::string(what) + ": array larger than the message");
    return skip(n * elem, what);
  }
  int64_t end() {
    if (pos_ != len_) {
      fail(std::to_string(len_ - pos_) + " bytes after the end of the message");
      return -1;
    }
    return pos_;
  }
  bool ok() const { return ok_; }

 private:
  bool i32(int32_t& v, const char* what) {
    if (!need(4, what)) return false;
    v = static_cast<int32_t>((uint32_t(d_[pos_]) << 24) | (uint32_t(d_[pos_ + 1]) << 16) |
                             (uint32_t(d_[pos_ + 2]) << 8) | uint32_t(d_[pos_ + 3]));
    pos_ += 4;
    return true;
  }
  bool need(int64_t n, const char* what) {
    if (n < 0 || n > len_ - pos_) return fail(std::string("truncated at ") + what);
    return true;
  }
  bool fail(const std::string& m) {
    if (why_ && ok_) *why_ = m;
    ok_ = false;
    return false;
  }
  const uint8_t* d_;
  int64_t len_;
  int64_t pos_ = 0;
  std::string* why_;
  bool ok_ = true;
};

template <class T>
int64_t fingerprint() {
  return T::getHash();
}

}  // namespace

int64_t wire_size(const run_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  if (w.hash(fingerprint<run_t>()) && w.skip(8, "utime") && w.str("run_id") && w.str("software_version") &&
      w.skip(8 + 1 + 4 + 4 + 4 + 8, "run fields") && w.str("config_json"))
    return w.end();
  return -1;
}

int64_t wire_size(const generation_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  if (w.hash(fingerprint<generation_t>()) && w.skip(8, "utime") && w.str("run_id") &&
      w.skip(4 + 8 + 4 * 8 + 8 + 4 + 8 + 6 * 4 + 2 * 8, "generation fields"))
    return w.end();
  return -1;
}

int64_t wire_size(const cppn_genome_t*, const uint8_t* data, size_t len, std::string* why) {
  if (len >= 8) {
    uint64_t h = 0;
    for (int i = 0; i < 8; ++i) h = (h << 8) | data[i];
    if (static_cast<int64_t>(h) == fingerprint<genome_t>()) {
      if (why)
        *why =
            "a genome_t of an older robozoo (its nodes have no drawing positions, written before the "
            "HyperNEAT topology rules); this robozoo reads cppn_genome_t: run the evolution again";
      return -1;
    }
  }
  Walker w(data, len, why);
  int32_t nodes = 0, links = 0;
  if (w.hash(fingerprint<cppn_genome_t>()) && w.skip(8, "utime") && w.str("run_id") &&
      w.skip(4 + 8 + 4 + 3 * 8 + 1, "genome fields") && w.count(nodes, "num_nodes") &&
      w.array(nodes, kNodeBytes, "nodes") && w.count(links, "num_links") && w.array(links, kLinkBytes, "links"))
    return w.end();
  return -1;
}

int64_t wire_size(const morphology_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  int32_t spheres = 0, neurons = 0, sensors = 0;
  if (w.hash(fingerprint<morphology_t>()) && w.skip(8, "utime") && w.str("run_id") &&
      w.skip(4 + 8, "morphology fields") && w.count(spheres, "num_spheres") &&
      w.array(spheres, kSphereBytes, "spheres") && w.skip(4, "num_bodies") && w.count(neurons, "num_neurons") &&
      w.array(neurons, 8, "tau") && w.array(neurons, 8, "omega") && w.count(sensors, "num_sensors") &&
      w.array(sensors, 4, "sensor_sphere") && w.array(sensors, 1, "sensor_type") &&
      w.array(int64_t(sensors) * neurons, 8, "w_sensor_neuron") &&
      w.array(int64_t(neurons) * neurons, 8, "w_neuron_neuron") && w.skip(8, "r_term"))
    return w.end();
  return -1;
}

int64_t wire_size(const pose_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  int32_t bodies = 0, spheres = 0, neurons = 0, sensors = 0;
  if (w.hash(fingerprint<pose_t>()) && w.skip(8, "utime") && w.str("run_id") && w.skip(4 + 8 + 4 + 8, "pose fields") &&
      w.count(bodies, "num_bodies") && w.array(bodies, 24, "body_position") && w.array(bodies, 32, "body_quaternion") &&
      w.count(spheres, "num_spheres") && w.array(spheres, 24, "sphere_center") && w.count(neurons, "num_neurons") &&
      w.array(neurons, 8, "neuron_output") && w.count(sensors, "num_sensors") && w.array(sensors, 8, "sensor_value"))
    return w.end();
  return -1;
}

int64_t wire_size(const eval_result_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  if (w.hash(fingerprint<eval_result_t>()) && w.skip(8 + 3 * 8 + 1 + 5 * 4, "result fields")) return w.end();
  return -1;
}

int64_t wire_size(const bus_status_t*, const uint8_t* data, size_t len, std::string* why) {
  Walker w(data, len, why);
  if (w.hash(fingerprint<bus_status_t>()) && w.skip(8, "utime") && w.str("run_id") &&
      w.skip(4 + 3 * 8, "bus status fields"))
    return w.end();
  return -1;
}

}  // namespace robozoo
