#include <cstring>

#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {
namespace {

// FNV-1a over the exact bytes of each double (little-endian bit patterns).
void mix(uint64_t& h, double x) {
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  for (int i = 0; i < 8; ++i) {
    h ^= (bits >> (8 * i)) & 0xffu;
    h *= 0x100000001b3ull;
  }
}

}  // namespace

uint64_t pose_hash(const SimState& s) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (const auto& p : s.body_position)
    for (int i = 0; i < 3; ++i) mix(h, p[i]);
  for (const auto& q : s.body_quaternion)
    for (int i = 0; i < 4; ++i) mix(h, q[i]);
  return h;
}

}  // namespace robozoo
