#pragma once
// The single source of randomness of a run. Seeded once from the run's seed
// and passed explicitly to every function that draws (docs/method.md section 4).
//
// Distributions are implemented here rather than taken from <random>: the
// standard fixes mt19937_64's output sequence but not the algorithms of
// uniform_real_distribution and friends, so results would differ between
// standard libraries. These conversions are exact and portable.
#include <cstdint>
#include <random>
#include <string>

namespace robozoo {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0) : engine_(seed) {}

  /// 64 random bits.
  uint64_t next_u64() { return engine_(); }
  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [lo, hi] (inclusive), unbiased (rejection sampling).
  int64_t uniform_int(int64_t lo, int64_t hi);
  /// True with probability p.
  bool bernoulli(double p) { return uniform() < p; }
  /// Uniform index in [0, n), n > 0.
  size_t index(size_t n) { return static_cast<size_t>(uniform_int(0, static_cast<int64_t>(n) - 1)); }

  /// Full generator state as text (for checkpoints); restore with set_state.
  std::string state() const;
  /// Restores a state produced by state(); throws std::invalid_argument on bad text.
  void set_state(const std::string& text);

  bool operator==(const Rng& o) const { return engine_ == o.engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace robozoo
