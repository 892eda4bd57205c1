#include "evolve/neat/variation/mutation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "evolve/neat/start/initial_genome.hpp"

namespace robozoo {
namespace {

// Index of node `id` in g.nodes (sorted by id), or -1.
int node_index(const Genome& g, int32_t id) {
  const auto it =
      std::lower_bound(g.nodes.begin(), g.nodes.end(), id, [](const NodeGene& n, int32_t v) { return n.id < v; });
  return it != g.nodes.end() && it->id == id ? static_cast<int>(it - g.nodes.begin()) : -1;
}

bool has_link(const Genome& g, int32_t from, int32_t to) {
  for (const auto& l : g.links)
    if (l.from == from && l.to == to) return true;
  return false;
}

bool has_innovation(const Genome& g, int64_t innovation) {
  const auto it = std::lower_bound(g.links.begin(), g.links.end(), innovation,
                                   [](const LinkGene& x, int64_t v) { return x.innovation < v; });
  return it != g.links.end() && it->innovation == innovation;
}

// True if `dst` can be reached from `src` along link genes, enabled or not.
bool reaches(const Genome& g, int32_t src, int32_t dst) {
  const size_t n = g.nodes.size();
  std::vector<std::vector<int>> out(n);
  for (const auto& l : g.links) {
    const int a = node_index(g, l.from), b = node_index(g, l.to);
    if (a < 0 || b < 0) throw std::logic_error("genome " + std::to_string(g.id) + ": link to a missing node");
    out[static_cast<size_t>(a)].push_back(b);
  }
  const int s = node_index(g, src), d = node_index(g, dst);
  if (s < 0 || d < 0)
    throw std::logic_error("genome " + std::to_string(g.id) + ": no node " + std::to_string(s < 0 ? src : dst));
  std::vector<char> seen(n, 0);
  std::vector<int> stack{s};
  seen[static_cast<size_t>(s)] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if (v == d) return true;
    for (int w : out[static_cast<size_t>(v)])
      if (!seen[static_cast<size_t>(w)]) {
        seen[static_cast<size_t>(w)] = 1;
        stack.push_back(w);
      }
  }
  return false;
}

void insert_link(Genome& g, const LinkGene& l) {
  const auto it = std::lower_bound(g.links.begin(), g.links.end(), l.innovation,
                                   [](const LinkGene& x, int64_t v) { return x.innovation < v; });
  g.links.insert(it, l);
}

void insert_node(Genome& g, const NodeGene& n) {
  const auto it =
      std::lower_bound(g.nodes.begin(), g.nodes.end(), n.id, [](const NodeGene& x, int32_t v) { return x.id < v; });
  g.nodes.insert(it, n);
}

std::vector<Activation> allowed_activations(uint32_t mask) {
  std::vector<Activation> v;
  for (int c = 0; c < kNumActivations; ++c)
    if (mask & (1u << c)) v.push_back(static_cast<Activation>(c));
  if (v.empty())
    throw std::invalid_argument("neat.hidden_activations: the mask " + std::to_string(mask) +
                                " names no activation function (bits 0.." + std::to_string(kNumActivations - 1) + ")");
  return v;
}

NodeKind node_kind_of(const Genome& g, int32_t id) {
  const int i = node_index(g, id);
  if (i < 0) throw std::logic_error("genome " + std::to_string(g.id) + ": no node " + std::to_string(id));
  return g.nodes[static_cast<size_t>(i)].kind;
}

}  // namespace

bool link_allowed(const Genome& g, const NodeGene& from, const NodeGene& to, Regime regime, const NeatParams& p) {
  if (regime == Regime::FeedForward && p.link_rule == LinkRule::CycleTest) {
    if (to.kind == NodeKind::Input || to.kind == NodeKind::Bias || from.id == to.id) return false;
    return !reaches(g, to.id, from.id);
  }
  return link_allowed_by_positions(from, to, regime, p);
}

bool mutate_add_link(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p,
                     InnovationTracker& innov, int32_t generation, Rng& rng) {
  if (g.nodes.empty()) return false;
  int32_t from = -1, to = -1;
  if (p.add_link == AddLinkRule::Uniform) {
    // Every allowed pair not linked yet, in (from, to) node order; one uniform draw.
    std::vector<std::pair<int32_t, int32_t>> free;
    for (const auto& a : g.nodes)
      for (const auto& b : g.nodes) {
        if (b.id < layout.num_inputs) continue;
        if (has_link(g, a.id, b.id) || !link_allowed(g, a, b, regime, p)) continue;
        free.emplace_back(a.id, b.id);
      }
    if (free.empty()) return false;
    std::tie(from, to) = free[rng.index(free.size())];
  } else {
    // Candidate targets: every node that is not an input.
    std::vector<size_t> targets;
    for (size_t i = 0; i < g.nodes.size(); ++i)
      if (g.nodes[i].id >= layout.num_inputs && g.nodes[i].kind != NodeKind::Input && g.nodes[i].kind != NodeKind::Bias)
        targets.push_back(i);
    if (targets.empty()) return false;
    for (int t = 0; t < p.add_link_tries && from < 0; ++t) {
      const NodeGene& a = g.nodes[rng.index(g.nodes.size())];
      const NodeGene& b = g.nodes[targets[rng.index(targets.size())]];
      if (has_link(g, a.id, b.id) || !link_allowed(g, a, b, regime, p)) continue;
      from = a.id;
      to = b.id;
    }
    if (from < 0) return false;
  }
  LinkGene l;
  l.innovation = innov.link(from, to);
  l.from = from;
  l.to = to;
  l.weight = rng.uniform(-p.initial_weight_range, p.initial_weight_range);
  l.enabled = true;
  l.born = generation;
  if (has_innovation(g, l.innovation))
    throw std::logic_error("mutate_add_link: innovation " + std::to_string(l.innovation) + " already in genome " +
                           std::to_string(g.id));
  insert_link(g, l);
  return true;
}

bool mutate_add_node(Genome& g, const NeatParams& p, InnovationTracker& innov, int32_t generation, Rng& rng) {
  const std::vector<Activation> acts = allowed_activations(p.hidden_activations);
  // Splittable links: enabled ones; with HyperNEAT's rule, forward ones only.
  std::vector<size_t> splittable;
  for (size_t i = 0; i < g.links.size(); ++i) {
    const LinkGene& l = g.links[i];
    if (!l.enabled || l.from == l.to) continue;
    if (p.add_node == AddNodeRule::HyperNeat && !is_forward_link(g, l)) continue;
    if (!p.split_bias_links && node_kind_of(g, l.from) == NodeKind::Bias) continue;
    splittable.push_back(i);
  }
  if (splittable.empty()) return false;
  const size_t k = splittable[rng.index(splittable.size())];
  const Activation drawn = acts[rng.index(acts.size())];
  const LinkGene old = g.links[k];
  const InnovationTracker::Split s = p.add_node_innovations == AddNodeInnovations::Fresh
                                         ? innov.fresh_split(old.from, old.to, drawn)
                                         : innov.split(old.innovation, old.from, old.to, drawn);
  // The same split twice in one genome (possible only if a link is split again
  // within the generation that split it): leave the genome alone.
  if (node_index(g, s.node) >= 0 || has_innovation(g, s.in_link) || has_innovation(g, s.out_link)) return false;
  const double position = (node_position(g, old.from) + node_position(g, old.to)) / 2.0;
  double out_weight = old.weight;
  if (p.add_node == AddNodeRule::HyperNeat) {
    // HyperNEAT keeps the split link, halves its weight and makes it young
    // again; the new path carries half of what is left: w/2 * 1/2 = w/4.
    g.links[k].weight = old.weight / 2.0;
    g.links[k].born = generation;
    out_weight = g.links[k].weight / 2.0;
  } else {
    g.links[k].enabled = false;
  }
  insert_node(g, {s.node, NodeKind::Hidden, s.activation, position});
  insert_link(g, {s.in_link, old.from, s.node, 1.0, true, generation});
  insert_link(g, {s.out_link, s.node, old.to, out_weight, true, generation});
  return true;
}

void mutate_weights(Genome& g, const NeatParams& p, int32_t generation, Rng& rng) {
  if (p.weight_mutation == WeightMutationRule::Stanley) {
    // Stanley's mutate_link_weights(power, rate 1, GAUSSIAN). One draw u per link: perturbed
    // when u > perturb_above, replaced when perturb_above >= u > replace_above, else kept.
    const bool severe = rng.bernoulli(kStanleySevereProbability);
    const size_t n = g.links.size();
    const double tail_start = 0.8 * static_cast<double>(n);  // links past it are the newest
    const double power = p.weight_perturbation;
    for (size_t i = 0; i < n; ++i) {
      LinkGene& l = g.links[i];
      const bool tail = n >= 10 && static_cast<double>(i) > tail_start;
      const double delta = rng.uniform(-power, power);
      if (severe || tail) {
        const double perturb_above = severe ? 0.3 : 0.5;  // severe: 70 % perturbed; tail: 50 %
        const double replace_above = severe ? 0.1 : 0.3;  // both: 20 % replaced
        const double u = rng.uniform();
        if (u > perturb_above)
          l.weight += delta;
        else if (u > replace_above)
          l.weight = delta;
      } else {
        l.weight += delta;  // rate 1: every other link is perturbed
      }
      l.weight = std::clamp(l.weight, -p.weight_limit, p.weight_limit);
    }
    return;
  }
  for (auto& l : g.links) {
    if (p.weight_mutation == WeightMutationRule::Classic) {
      if (rng.bernoulli(p.weight_replace_probability))
        l.weight = rng.uniform(-p.initial_weight_range, p.initial_weight_range);
      else
        l.weight += rng.uniform(-p.weight_perturbation, p.weight_perturbation);
      l.weight = std::clamp(l.weight, -p.weight_limit, p.weight_limit);
      continue;
    }
    const bool young = generation - l.born < p.young_link_age;
    if (young || rng.bernoulli(p.old_link_perturb_probability)) {
      l.weight += rng.uniform(-p.weight_perturbation, p.weight_perturbation);
      l.weight = std::clamp(l.weight, -p.weight_limit, p.weight_limit);
    }
  }
}

void mutate(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p, InnovationTracker& innov,
            int32_t generation, Rng& rng) {
  if (p.mutation_order == MutationOrder::Independent) {
    // HyperNEAT's testMutate: three independent draws; a failed structural mutation changes nothing.
    if (rng.bernoulli(p.add_node_probability)) mutate_add_node(g, p, innov, generation, rng);
    if (rng.bernoulli(p.add_link_probability)) mutate_add_link(g, regime, layout, p, innov, generation, rng);
    if (rng.bernoulli(p.mutate_weights_probability)) mutate_weights(g, p, generation, rng);
    return;
  }
  if (rng.bernoulli(p.add_node_probability) &&
      (mutate_add_node(g, p, innov, generation, rng) || p.structural_draw_decides))
    return;
  if (rng.bernoulli(p.add_link_probability) &&
      (mutate_add_link(g, regime, layout, p, innov, generation, rng) || p.structural_draw_decides))
    return;
  if (rng.bernoulli(p.mutate_weights_probability)) mutate_weights(g, p, generation, rng);
}

}  // namespace robozoo
