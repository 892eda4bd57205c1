#include "study/analysis/measure/genotype_stats.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace robozoo {

GenotypeStats genotype_stats(const cppn_genome_t& g) {
  GenotypeStats s;
  std::map<int32_t, size_t> index;
  std::vector<double> position;
  for (const auto& nd : g.nodes) {
    position.push_back(nd.position);
    if (!index.emplace(nd.id, index.size()).second)
      throw std::invalid_argument("genome " + std::to_string(g.genome_id) + " has node " + std::to_string(nd.id) +
                                  " twice");
    s.nodes += 1;
    if (nd.kind != 3) continue;
    s.hidden += 1;
    switch (nd.activation) {
      case 0: s.hidden_sigmoid += 1; break;
      case 1: s.hidden_cosine += 1; break;
      case 2: s.hidden_gaussian += 1; break;
      default: s.hidden_other += 1; break;
    }
  }
  const size_t n = index.size();
  std::vector<std::vector<size_t>> out(n);
  std::vector<std::pair<size_t, size_t>> enabled;
  for (const auto& l : g.links) {
    const auto from = index.find(l.from_node), to = index.find(l.to_node);
    if (from == index.end() || to == index.end())
      throw std::invalid_argument("genome " + std::to_string(g.genome_id) + ": link " + std::to_string(l.innovation) +
                                  " joins node " + std::to_string(l.from_node) + " to node " +
                                  std::to_string(l.to_node) + ", which the genome does not have");
    s.link_genes += 1;
    if (!l.enabled) continue;
    s.links += 1;
    out[from->second].push_back(to->second);
    enabled.emplace_back(from->second, to->second);
  }
  // reach[v][u]: u is reachable from v along expressed links (one search per node).
  std::vector<std::vector<bool>> reach(n, std::vector<bool>(n, false));
  for (size_t v = 0; v < n; ++v) {
    std::vector<size_t> stack = out[v];
    while (!stack.empty()) {
      const size_t u = stack.back();
      stack.pop_back();
      if (reach[v][u]) continue;
      reach[v][u] = true;
      for (size_t w : out[u]) stack.push_back(w);
    }
  }
  for (const auto& [from, to] : enabled) {
    if (position[from] < position[to])
      s.forward_links += 1;
    else
      s.recurrent_links += 1;
    // from -> to lies on a cycle exactly when `from` is reachable from `to` (or from == to).
    if (from == to || reach[to][from]) s.cycle_links += 1;
  }
  return s;
}

}  // namespace robozoo
