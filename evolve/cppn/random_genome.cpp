#include "evolve/cppn/random_genome.hpp"

#include <set>
#include <stdexcept>
#include <utility>

namespace robozoo {

Genome random_cppn(const GenomeLayout& layout, bool recurrent, int hidden_nodes, int extra_links, Rng& rng) {
  if (hidden_nodes < 0) throw std::invalid_argument("random_cppn: hidden_nodes must not be negative");
  if (extra_links < 0) throw std::invalid_argument("random_cppn: extra_links must not be negative");
  const int ni = layout.num_inputs, no = layout.num_outputs, h0 = layout.first_hidden();

  Genome g;
  for (int i = 0; i < ni; ++i)
    g.nodes.push_back(
        {i, i == layout.bias_input ? NodeKind::Bias : NodeKind::Input, Activation::Linear, kInputPosition});
  for (int o = 0; o < no; ++o) g.nodes.push_back({ni + o, NodeKind::Output, layout.output_activation, kOutputPosition});
  for (int h = 0; h < hidden_nodes; ++h)
    g.nodes.push_back(
        {h0 + h, NodeKind::Hidden, static_cast<Activation>(rng.uniform_int(0, 2)), (h + 1.0) / (hidden_nodes + 1.0)});

  std::set<std::pair<int32_t, int32_t>> linked;
  int64_t innovation = 0;
  auto add = [&](int32_t from, int32_t to) {
    g.links.push_back({innovation++, from, to, rng.uniform(-3.0, 3.0), true, 0});
    linked.emplace(from, to);
  };
  for (int i = 0; i < ni; ++i)
    for (int o = 0; o < no; ++o) add(i, ni + o);

  // Each hidden node sits on a path input/earlier hidden -> node -> output.
  for (int h = 0; h < hidden_nodes; ++h) {
    const int id = h0 + h;
    const int64_t src = rng.uniform_int(0, ni + h - 1);  // an input, or one of the h earlier hidden nodes
    add(src < ni ? static_cast<int32_t>(src) : static_cast<int32_t>(h0 + (src - ni)), id);
    add(id, static_cast<int32_t>(ni + rng.uniform_int(0, no - 1)));
  }

  // Rank for the feed-forward order: inputs 0, hidden node h at 1 + h, outputs last.
  auto rank = [&](int32_t id) {
    if (id < ni) return 0;
    if (id < h0) return 1 + hidden_nodes;
    return 1 + (id - h0);
  };
  const int n = static_cast<int>(g.nodes.size());
  std::vector<std::pair<int32_t, int32_t>> free_pairs;
  for (int a = 0; a < n; ++a)
    for (int b = ni; b < n; ++b) {  // never into an input
      const int32_t from = g.nodes[a].id, to = g.nodes[b].id;
      if (linked.count({from, to})) continue;
      if (!recurrent && !(rank(from) < rank(to))) continue;
      free_pairs.emplace_back(from, to);
    }
  for (int e = 0; e < extra_links && !free_pairs.empty(); ++e) {
    const size_t k = rng.index(free_pairs.size());
    const auto [from, to] = free_pairs[k];
    free_pairs.erase(free_pairs.begin() + static_cast<std::ptrdiff_t>(k));  // keep the order: deterministic
    add(from, to);
  }

  validate_genome(g, layout);
  if (!recurrent && has_cycle(g)) throw std::logic_error("random_cppn: feed-forward genome has a cycle");
  return g;
}

}  // namespace robozoo
