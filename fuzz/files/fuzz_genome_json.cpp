// libFuzzer target: a genome JSON file (robozoo-evolve eval --genome FILE):
// genome_from_json, then validate_genome as the program does. A genome that
// passes must be finite and write and read back to itself.
#include <stdexcept>

#include "evolve/neat/population_json.hpp"
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace robozoo;
  const auto j = nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return 0;
  Genome g;
  try {
    g = genome_from_json(j, "fuzz.json");
    validate_genome(g, robot_layout());
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).empty()) fuzz::violated("genome refused without a message");
    return 0;
  }
  for (const auto& l : g.links)
    if (!std::isfinite(l.weight)) fuzz::violated("a genome with a non-finite weight was accepted");
  if (!(genome_from_json(genome_to_json(g)) == g)) fuzz::violated("an accepted genome does not read back");
  return 0;
}
