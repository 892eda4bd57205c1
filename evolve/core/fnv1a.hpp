#pragma once
// FNV-1a, 64 bit: the hash robozoo prints to name a genome or a grown robot by
// its bytes (genome_hash, robot_hash). Not for security; stable across builds.
#include <cstddef>
#include <cstdint>

namespace robozoo {

struct Fnv1a {
  uint64_t h = 1469598103934665603ull;  ///< the offset basis; the hash so far
  void bytes(const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  }
  /// The object representation of a value (integers and doubles: no padding).
  template <class T>
  void add(T v) {
    bytes(&v, sizeof v);
  }
};

}  // namespace robozoo
