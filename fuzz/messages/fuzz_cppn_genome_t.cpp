// libFuzzer target: safe_decode of a cppn_genome_t from untrusted bytes, then
// genome_from_message, which must refuse any genome that breaks the robot
// layout or carries a non-finite weight or position.
#include <stdexcept>

#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  robozoo::cppn_genome_t m;
  if (!robozoo::fuzz::decode_and_check(data, size, m)) return 0;
  try {
    const robozoo::Genome g = robozoo::genome_from_message(m, robozoo::robot_layout());
    for (const auto& l : g.links)
      if (!std::isfinite(l.weight)) robozoo::fuzz::violated("a genome with a non-finite weight was accepted");
    for (const auto& n : g.nodes)
      if (!std::isfinite(n.position)) robozoo::fuzz::violated("a genome with a non-finite position was accepted");
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).empty()) robozoo::fuzz::violated("genome refused without a message");
  }
  return 0;
}
