#pragma once
// Test fixtures for robozoo-render: a real log written in this process by the
// same Evolution that robozoo-evolve runs, a hand-made robot whose leaves are
// known, and helpers to write logs message by message.
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "render/gl/image.hpp"
#include "runlog/read/run_record.hpp"
#include "tests/support/small_run.hpp"

namespace robozoo::render::testing {

/// The configuration of the small run: 4 generations of 24, 400 steps, seed 7
/// (robots reach the simulator from generation 1 on).
inline RunConfig small_config() { return robozoo::testing::small_run_config(); }

/// Writes the small run's log to `path` (about a second, in this process).
inline void write_small_run(const std::string& path) {
  const RunConfig c = small_config();
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = path;
  Evolution evo(c, o, evaluator);
  evo.run();
}

/// Appends one message to a log.
template <class T>
void append(EventLogWriter& w, const char* channel, const T& m, int64_t t = 0) {
  w.write(channel, encode_message(m), t);
}

/// A robot of four separate spheres in a row along x, all resting on the
/// ground: 0 (root, r 0.25) -- 1 (r 0.2) -- 2 (leaf, r 0.15), and 3 (leaf,
/// r 0.2) on the root's other side. Leaves 2 and 3 are red, 0 and 1 blue.
inline morphology_t known_robot(const std::string& run_id = "known", int64_t genome_id = 1) {
  morphology_t m{};
  m.run_id = run_id;
  m.genome_id = genome_id;
  const double x[4] = {0.0, 0.9, 1.6, -0.9};
  const double r[4] = {0.25, 0.2, 0.15, 0.2};
  const int parent[4] = {-1, 0, 1, 0};
  for (int i = 0; i < 4; ++i) {
    sphere_t s{};
    s.index = i;
    s.parent = parent[i];
    s.center[0] = x[i];
    s.center[1] = 0.0;
    s.center[2] = r[i];
    s.radius = r[i];
    s.density = 1.0;
    s.body = 0;
    m.spheres.push_back(s);
  }
  m.num_spheres = 4;
  m.num_bodies = 1;
  m.r_term = 1.0;
  return m;
}

inline bool is_red(uint8_t r, uint8_t g, uint8_t b) { return r > 90 && r > 2 * g && r > 2 * b; }
inline bool is_blue(uint8_t r, uint8_t g, uint8_t b) { return b > 90 && b > 2 * r && b > g + 40; }

/// How many pixels of a picture are a sphere's red and blue.
struct Pixels {
  int red = 0, blue = 0;
};

inline Pixels count_colours(const Image& img) {
  Pixels p;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const Rgb c = img.at(x, y);
      p.red += is_red(c.r, c.g, c.b);
      p.blue += is_blue(c.r, c.g, c.b);
    }
  return p;
}

}  // namespace robozoo::render::testing
