#include "runlog/robots/selection.hpp"

#include <algorithm>
#include <cstring>
#include <set>

namespace robozoo {

namespace {
void mix(uint64_t& h, uint64_t v) {
  // FNV-1a over the 8 bytes of v.
  for (int i = 0; i < 8; ++i) {
    h ^= (v >> (8 * i)) & 0xff;
    h *= 1099511628211ull;
  }
}
}  // namespace

uint64_t gene_hash(const cppn_genome_t& g) {
  uint64_t h = 1469598103934665603ull;
  for (const auto& n : g.nodes) {
    mix(h, static_cast<uint64_t>(n.id));
    mix(h, static_cast<uint64_t>(n.kind) << 8 | static_cast<uint8_t>(n.activation));
  }
  mix(h, 0xffffffffffffffffull);
  for (const auto& l : g.links) {
    uint64_t w;
    std::memcpy(&w, &l.weight, sizeof w);
    mix(h, static_cast<uint64_t>(l.innovation));
    mix(h, static_cast<uint64_t>(static_cast<uint32_t>(l.from_node)) << 32 | static_cast<uint32_t>(l.to_node));
    mix(h, w);
    mix(h, l.enabled ? 1 : 0);
  }
  return h;
}

std::vector<Pick> champions(const RunRecord& run) {
  std::vector<Pick> out;
  for (const auto& g : run.genomes)
    if (g->champion && g->has_morphology) out.push_back({&run, g.get()});
  std::stable_sort(out.begin(), out.end(), [](const Pick& a, const Pick& b) {
    return a.genome->genome.generation < b.genome->genome.generation;
  });
  return out;
}

std::vector<Pick> best_of_run(const std::vector<const RunRecord*>& runs) {
  std::vector<Pick> out;
  for (const RunRecord* r : runs) {
    const std::vector<Pick> c = champions(*r);
    if (c.empty()) continue;
    Pick best = c.front();
    for (const Pick& p : c)
      if (p.genome->genome.fitness > best.genome->genome.fitness) best = p;
    out.push_back(best);
  }
  return out;
}

std::vector<Pick> top_champions(const std::vector<const RunRecord*>& runs, int n) {
  std::vector<Pick> all;
  for (const RunRecord* r : runs) {
    std::set<uint64_t> seen;
    for (const Pick& p : champions(*r))
      if (seen.insert(gene_hash(p.genome->genome)).second) all.push_back(p);
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const Pick& a, const Pick& b) { return a.genome->genome.fitness > b.genome->genome.fitness; });
  if (n >= 0 && static_cast<size_t>(n) < all.size()) all.resize(static_cast<size_t>(n));
  return all;
}

std::vector<Pick> generation_champions(const std::vector<const RunRecord*>& runs, int32_t g) {
  std::vector<Pick> out;
  for (const RunRecord* r : runs)
    for (const Pick& p : champions(*r))
      if (p.genome->genome.generation == g) {
        out.push_back(p);
        break;
      }
  return out;
}

std::vector<Pick> genome_by_id(const std::vector<const RunRecord*>& runs, int64_t genome_id) {
  std::vector<Pick> out;
  for (const RunRecord* r : runs) {
    const GenomeRecord* g = r->find(genome_id);
    if (g && g->has_morphology) out.push_back({r, g});
  }
  return out;
}

}  // namespace robozoo
