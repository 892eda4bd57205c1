#include "runlog/text/logged_genome.hpp"

#include <stdexcept>
#include <string>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo {

cppn_genome_t find_logged_genome(const ScannedLog& log, std::optional<int64_t> id) {
  std::string run_id;
  if (!id) {
    for (const LogRecord& r : log.contents.records) {
      generation_t g{};
      if (r.channel == kChannelGeneration && safe_decode(r.data.data(), r.data.size(), g, nullptr)) {
        id = g.champion_id;
        run_id = g.run_id;
      }
    }
    if (!id) throw std::invalid_argument("no generation in the log, so no champion: name one with --genome");
  }
  std::optional<cppn_genome_t> found;
  for (const LogRecord& r : log.contents.records) {
    cppn_genome_t g{};
    if (r.channel == kChannelGenome && safe_decode(r.data.data(), r.data.size(), g, nullptr) && g.genome_id == *id &&
        (run_id.empty() || g.run_id == run_id))
      found = std::move(g);
  }
  if (!found)
    throw std::invalid_argument((run_id.empty() ? "no genome " : "the last champion, genome ") + std::to_string(*id) +
                                (run_id.empty() ? " in the log" : ", was not logged"));
  return *found;
}

}  // namespace robozoo
