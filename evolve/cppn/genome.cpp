#include "evolve/cppn/genome.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include "evolve/core/fnv1a.hpp"

namespace robozoo {

GenomeLayout robot_layout() { return GenomeLayout{}; }

void validate_genome(const Genome& g, const GenomeLayout& layout) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("genome " + std::to_string(g.id) + ": " + what);
  };
  const int fixed = layout.num_inputs + layout.num_outputs;
  if (static_cast<int>(g.nodes.size()) < fixed)
    fail("has " + std::to_string(g.nodes.size()) + " nodes, fewer than the " + std::to_string(fixed) +
         " inputs and outputs");
  std::unordered_map<int32_t, NodeKind> kind;
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const NodeGene& n = g.nodes[i];
    if (i > 0 && n.id <= g.nodes[i - 1].id) fail("node ids not strictly increasing at node " + std::to_string(n.id));
    if (!valid_activation(static_cast<int>(n.activation)))
      fail("node " + std::to_string(n.id) + " has unknown activation code " +
           std::to_string(static_cast<int>(n.activation)));
    NodeKind want;
    if (n.id < 0) fail("negative node id " + std::to_string(n.id));
    if (n.id < layout.num_inputs) {
      want = n.id == layout.bias_input ? NodeKind::Bias : NodeKind::Input;
      if (static_cast<int>(i) != n.id) fail("input node " + std::to_string(i) + " missing");
    } else if (n.id < fixed) {
      want = NodeKind::Output;
      if (static_cast<int>(i) != n.id) fail("output node " + std::to_string(i) + " missing");
    } else {
      want = NodeKind::Hidden;
    }
    if (n.kind != want)
      fail("node " + std::to_string(n.id) + " has kind " + std::to_string(static_cast<int>(n.kind)) + ", expected " +
           std::to_string(static_cast<int>(want)));
    const bool fixed_position = want != NodeKind::Hidden;
    const double want_position = want == NodeKind::Output ? kOutputPosition : kInputPosition;
    if (fixed_position ? n.position != want_position : !(n.position >= kInputPosition && n.position <= kOutputPosition))
      fail("node " + std::to_string(n.id) + " has drawing position " + std::to_string(n.position) +
           (fixed_position ? ", expected " + std::to_string(want_position) : ", expected one in [0, 1]"));
    kind[n.id] = n.kind;
  }
  for (size_t i = 0; i < g.links.size(); ++i) {
    const LinkGene& l = g.links[i];
    if (i > 0 && l.innovation <= g.links[i - 1].innovation)
      fail("link innovations not strictly increasing at innovation " + std::to_string(l.innovation));
    auto from = kind.find(l.from), to = kind.find(l.to);
    if (from == kind.end())
      fail("link " + std::to_string(l.innovation) + " comes from missing node " + std::to_string(l.from));
    if (to == kind.end())
      fail("link " + std::to_string(l.innovation) + " goes to missing node " + std::to_string(l.to));
    if (to->second == NodeKind::Input || to->second == NodeKind::Bias)
      fail("link " + std::to_string(l.innovation) + " goes into input node " + std::to_string(l.to));
    if (!std::isfinite(l.weight)) fail("link " + std::to_string(l.innovation) + " has a non-finite weight");
  }
}

bool has_cycle(const Genome& g) {
  // Iterative three-colour DFS over enabled links.
  std::unordered_map<int32_t, std::vector<int32_t>> out;
  for (const auto& l : g.links)
    if (l.enabled) out[l.from].push_back(l.to);
  std::unordered_map<int32_t, int> colour;  // 0 white, 1 grey, 2 black
  for (const auto& n : g.nodes) {
    if (colour[n.id] != 0) continue;
    std::vector<std::pair<int32_t, size_t>> stack{{n.id, 0}};
    colour[n.id] = 1;
    while (!stack.empty()) {
      auto& [v, next] = stack.back();
      const auto& succ = out[v];
      if (next < succ.size()) {
        const int32_t w = succ[next++];
        const int c = colour[w];
        if (c == 1) return true;
        if (c == 0) {
          colour[w] = 1;
          stack.emplace_back(w, 0);
        }
      } else {
        colour[v] = 2;
        stack.pop_back();
      }
    }
  }
  return false;
}

uint64_t genome_hash(const Genome& g) {
  Fnv1a f;
  f.add(g.id);
  f.add(static_cast<uint64_t>(g.nodes.size()));
  for (const auto& n : g.nodes) {
    f.add(n.id);
    f.add(static_cast<int8_t>(n.kind));
    f.add(static_cast<int8_t>(n.activation));
    uint64_t pos;
    std::memcpy(&pos, &n.position, sizeof pos);
    f.add(pos);
  }
  f.add(static_cast<uint64_t>(g.links.size()));
  for (const auto& l : g.links) {
    f.add(l.innovation);
    f.add(l.from);
    f.add(l.to);
    uint64_t bits;
    std::memcpy(&bits, &l.weight, sizeof bits);
    f.add(bits);
    f.add(static_cast<uint8_t>(l.enabled));
    f.add(l.born);
  }
  return f.h;
}

double node_position(const Genome& g, int32_t id) {
  const auto it =
      std::lower_bound(g.nodes.begin(), g.nodes.end(), id, [](const NodeGene& n, int32_t v) { return n.id < v; });
  if (it == g.nodes.end() || it->id != id)
    throw std::invalid_argument("genome " + std::to_string(g.id) + " has no node " + std::to_string(id));
  return it->position;
}

bool is_forward_link(const Genome& g, const LinkGene& l) { return node_position(g, l.from) < node_position(g, l.to); }

int count_recurrent_links(const Genome& g) {
  int n = 0;
  for (const auto& l : g.links) n += !is_forward_link(g, l);
  return n;
}

int count_hidden(const Genome& g) {
  int n = 0;
  for (const auto& x : g.nodes) n += x.kind == NodeKind::Hidden;
  return n;
}

int count_enabled_links(const Genome& g) {
  int n = 0;
  for (const auto& l : g.links) n += l.enabled;
  return n;
}

}  // namespace robozoo
