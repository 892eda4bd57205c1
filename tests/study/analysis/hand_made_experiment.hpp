#pragma once
// Four hand-made runs with known champions (two per regime, three generations
// each) and the statistics they must give, worked out by hand below.
//
// feed-forward s1: g0 A 4.0 (not simulated, root only); g1 B 15.5 chain (-1,0,1);
//                  g2 C 16.0 chain with other radii: same topology, +0.5.
//                  Best C: 3 spheres, 1 leaf, depth 2, poses: all 3 on the ground.
//                  CPPN: nodes 0, 9, 20 (sigmoid); links 0->20, 20->9: 2 forward.
// feed-forward s2: g0 D 15.0 (-1,0); g1 D again 15.0 (no change); g2 E 17.0
//                  (-1,0,0): topology changed, +2.0. Best E: 3 spheres, 2 leaves,
//                  depth 1, no pose stream (ground 0). CPPN: nodes 0, 9; link 0->9.
// recurrent s1:    g0 F 15.0 (-1,0); g1 G 16.0 (-1,0,1) changed +1.0; g2 H 18.0
//                  (-1,0,0,1) changed +2.0. Best H: 4 spheres, 2 leaves, depth 2,
//                  poses: only the root on the ground. CPPN: nodes 0, 9, 20 (cosine);
//                  links 0->20, 20->9, 9->20: 2 forward (by position), 1 recurrent, 2 on a cycle.
// recurrent s2:    g0 I 15.0 (-1,0,1); g1 J 15.5 (-1,0,0) changed +0.5; g2 K 16.5
//                  (-1,0,0) other radii, same +1.0. Best K: 3 spheres, 2 leaves,
//                  depth 1, poses: all 3 on the ground. CPPN: nodes 0, 9; links
//                  0->9, 9->9: 1 forward, 1 self-loop.
#include <string>

#include "tests/study/analysis/hand_made_log.hpp"

namespace robozoo::testing {

inline std::vector<HandRun> hand_made_experiment() {
  const std::vector<NodeSpec> io = {{0, 0, 0}, {9, 2, 0}};
  const std::vector<NodeSpec> io_sig = {{0, 0, 0}, {9, 2, 0}, {20, 3, 0}};
  const std::vector<NodeSpec> io_cos = {{0, 0, 0}, {9, 2, 0}, {20, 3, 1}};
  HandRun f1{0, 1, 10, 3, {}}, f2{0, 2, 10, 3, {}}, r1{1, 1, 10, 3, {}}, r2{1, 2, 10, 3, {}};
  f1.generations = {
      {4.0, 4.0, 0, 10, {-1}, {}, io, {{0, 9}}, std::nullopt},
      {15.5, 15.5, 1, 11, {-1, 0, 1}, {0.1, 0.2, 0.2}, io, {{0, 9}}, std::vector<double>{0.1, 0.2, 0.2}},
      {16.0, 16.0, 1, 12, {-1, 0, 1}, {0.1, 0.3, 0.2}, io_sig, {{0, 20}, {20, 9}}, std::vector<double>{0.1, 0.3, 0.2}},
  };
  f2.generations = {
      {15.0, 15.0, 1, 20, {-1, 0}, {}, io, {{0, 9}}, std::vector<double>{0.1, 0.1}},
      {15.0, 15.0, 1, 21, {-1, 0}, {}, io, {{0, 9}}, std::nullopt},
      {17.0, 17.0, 1, 22, {-1, 0, 0}, {}, io, {{0, 9}}, std::nullopt},
  };
  r1.generations = {
      {15.0, 15.0, 1, 30, {-1, 0}, {}, io, {{0, 9}}, std::vector<double>{0.1, 0.1}},
      {16.0, 16.0, 1, 31, {-1, 0, 1}, {}, io, {{0, 9}}, std::vector<double>{0.1, 0.1, 0.1}},
      {18.0,
       18.0,
       1,
       32,
       {-1, 0, 0, 1},
       {},
       io_cos,
       {{0, 20}, {20, 9}, {9, 20}},
       std::vector<double>{0.1, 0.2, 0.2, 0.2}},
  };
  r2.generations = {
      {15.0, 15.0, 1, 40, {-1, 0, 1}, {}, io, {{0, 9}}, std::vector<double>{0.1, 0.1, 0.1}},
      {15.5, 15.5, 1, 41, {-1, 0, 0}, {}, io, {{0, 9}}, std::vector<double>{0.1, 0.1, 0.1}},
      {16.5, 16.5, 1, 42, {-1, 0, 0}, {0.1, 0.2, 0.3}, io, {{0, 9}, {9, 9}}, std::vector<double>{0.1, 0.2, 0.3}},
  };
  return {f1, f2, r1, r2};
}

/// Writes the four logs into `dir` as <regime>-s<seed>.lcmlog.
inline void write_hand_made_experiment(const std::string& dir) {
  for (const auto& run : hand_made_experiment())
    write_hand_log(
        dir + "/" + (run.regime == 0 ? "feedforward" : "recurrent") + "-s" + std::to_string(run.seed) + ".lcmlog", run);
}

}  // namespace robozoo::testing
