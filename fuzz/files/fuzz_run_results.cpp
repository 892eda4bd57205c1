// libFuzzer target: a compact result (<run>.results.json, robozoo-stats DIR of
// results, robozoo-evolve champion RESULT): run_results_from_text. Every
// refusal is a std::invalid_argument naming the file; an accepted result
// writes and reads back to the same text, and its summary is consistent
// (one champion per generation at most, each naming its generation's champion).
#include <stdexcept>
#include <string>

#include "evolve/record/run_results.hpp"
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace robozoo;
  const std::string text(reinterpret_cast<const char*>(data), size);
  RunResults r;
  try {
    r = run_results_from_text(text, "dir/fuzz.results.json");
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).rfind("dir/fuzz.results.json: ", 0) != 0)
      fuzz::violated(std::string("a refusal does not name the file: ") + e.what());
    return 0;
  }
  if (r.run.champions.size() > r.run.generations.size()) fuzz::violated("more champions than generations");
  for (const auto& c : r.run.champions)
    if (c.has_morphology && c.morphology.spheres.empty()) fuzz::violated("a champion robot without spheres");
  const std::string once = run_results_to_json(r).dump();
  const RunResults back = run_results_from_text(once, "dir/fuzz.results.json");
  if (run_results_to_json(back).dump() != once) fuzz::violated("an accepted result does not read back to itself");
  return 0;
}
