#include "evolve/core/rng.hpp"

#include <sstream>
#include <stdexcept>

namespace robozoo {

int64_t Rng::uniform_int(int64_t lo, int64_t hi) {
  if (hi < lo) throw std::invalid_argument("Rng::uniform_int: empty range");
  const uint64_t span = static_cast<uint64_t>(hi - lo) + 1u;  // 0 means the full 2^64 range
  if (span == 0) return static_cast<int64_t>(engine_());
  const uint64_t limit = UINT64_MAX - (UINT64_MAX % span);  // reject the biased tail
  uint64_t x;
  do {
    x = engine_();
  } while (x >= limit);
  return lo + static_cast<int64_t>(x % span);
}

std::string Rng::state() const {
  std::ostringstream os;
  os << engine_;
  return os.str();
}

void Rng::set_state(const std::string& text) {
  std::istringstream is(text);
  std::mt19937_64 e;
  is >> e;
  if (is.fail()) throw std::invalid_argument("Rng::set_state: not a generator state");
  engine_ = e;
}

}  // namespace robozoo
