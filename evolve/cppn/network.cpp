#include "evolve/cppn/network.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

namespace robozoo {

namespace {
/// Bitwise inequality: +0.0 and -0.0 differ, a NaN equals its own bits.
inline char bits_differ(double a, double b) {
  uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x != y;
}
}  // namespace

Network::Network(const Genome& g, const GenomeLayout& layout, int updates)
    : num_inputs_(layout.num_inputs), num_outputs_(layout.num_outputs), updates_(updates) {
  if (updates < 1) throw std::invalid_argument("CPPN updates must be at least 1");
  validate_genome(g, layout);
  const int n = static_cast<int>(g.nodes.size());
  std::unordered_map<int32_t, int> index;
  for (int i = 0; i < n; ++i) index[g.nodes[i].id] = i;
  act_.resize(n);
  for (int i = 0; i < n; ++i) act_[i] = static_cast<int>(g.nodes[i].activation);

  // CSR of incoming enabled links, in innovation order (the summation order).
  std::vector<std::vector<std::pair<int, double>>> incoming(n);
  for (const auto& l : g.links)
    if (l.enabled) incoming[index.at(l.to)].emplace_back(index.at(l.from), l.weight);
  in_begin_.assign(n + 1, 0);
  for (int v = 0; v < n; ++v) {
    in_begin_[v + 1] = in_begin_[v] + static_cast<int>(incoming[v].size());
    for (const auto& [from, w] : incoming[v]) {
      in_from_.push_back(from);
      in_weight_.push_back(w);
    }
  }

  // Longest-path depth by Kahn's algorithm over non-input nodes; a node left
  // unvisited lies on or behind a cycle.
  std::vector<int> indeg(n, 0), depth(n, 0);
  std::vector<std::vector<int>> out(n);
  for (int v = num_inputs_; v < n; ++v)
    for (int k = in_begin_[v]; k < in_begin_[v + 1]; ++k) {
      const int u = in_from_[k];
      if (u >= num_inputs_) { ++indeg[v]; out[u].push_back(v); }
    }
  std::vector<int> ready;
  for (int v = num_inputs_; v < n; ++v)
    if (indeg[v] == 0) ready.push_back(v);
  int max_depth = 0;
  for (size_t head = 0; head < ready.size(); ++head) {
    const int v = ready[head];
    int d = 1;
    for (int k = in_begin_[v]; k < in_begin_[v + 1]; ++k)
      d = std::max(d, in_from_[k] < num_inputs_ ? 1 : depth[in_from_[k]] + 1);
    depth[v] = d;
    max_depth = std::max(max_depth, d);
    order_.push_back(v);
    for (int w : out[v])
      if (--indeg[w] == 0) ready.push_back(w);
  }
  single_pass_ = static_cast<int>(order_.size()) == n - num_inputs_ && max_depth <= updates_;
  cur_.assign(n, 0.0);
  prev_.assign(n, 0.0);
  changed_cur_.assign(n, 0);
  changed_prev_.assign(n, 0);
}

int Network::num_inputs() const { return num_inputs_; }
int Network::num_outputs() const { return num_outputs_; }

void Network::query(const double* inputs, double* outputs) {
  ++queries_;
  if (!single_pass_) {
    --queries_;  // counted by query_synchronous
    query_synchronous(inputs, outputs);
    return;
  }
  double* v = cur_.data();
  for (int i = 0; i < num_inputs_; ++i) v[i] = inputs[i];
  const int* from = in_from_.data();
  const double* w = in_weight_.data();
  for (int node : order_) {
    double s = 0.0;
    for (int k = in_begin_[node]; k < in_begin_[node + 1]; ++k) s += w[k] * v[from[k]];
    v[node] = activate(static_cast<Activation>(act_[node]), s);
  }
  for (int o = 0; o < num_outputs_; ++o) outputs[o] = v[num_inputs_ + o];
}

void Network::query_synchronous(const double* inputs, double* outputs) {
  ++queries_;
  const int n = static_cast<int>(act_.size());
  std::fill(prev_.begin(), prev_.end(), 0.0);
  for (int i = 0; i < num_inputs_; ++i) prev_[i] = cur_[i] = inputs[i];
  const int* from = in_from_.data();
  const double* w = in_weight_.data();
  // Update 1 computes every node from the zero state.
  for (int node = num_inputs_; node < n; ++node) {
    double s = 0.0;
    for (int k = in_begin_[node]; k < in_begin_[node + 1]; ++k) s += w[k] * prev_[from[k]];
    cur_[node] = activate(static_cast<Activation>(act_[node]), s);
    changed_cur_[node] = bits_differ(cur_[node], prev_[node]);
  }
  // Inputs changed from 0 to their value before update 1, and never again.
  for (int i = 0; i < num_inputs_; ++i) changed_cur_[i] = 0;
  std::swap(cur_, prev_);
  std::swap(changed_cur_, changed_prev_);
  for (int u = 1; u < updates_; ++u) {
    bool any = false;
    for (int node = num_inputs_; node < n; ++node) {
      bool dirty = false;
      for (int k = in_begin_[node]; k < in_begin_[node + 1] && !dirty; ++k) dirty = changed_prev_[from[k]];
      if (!dirty) {
        cur_[node] = prev_[node];
        changed_cur_[node] = 0;
        continue;
      }
      double s = 0.0;
      for (int k = in_begin_[node]; k < in_begin_[node + 1]; ++k) s += w[k] * prev_[from[k]];
      cur_[node] = activate(static_cast<Activation>(act_[node]), s);
      changed_cur_[node] = bits_differ(cur_[node], prev_[node]);
      any |= changed_cur_[node] != 0;
    }
    std::swap(cur_, prev_);
    std::swap(changed_cur_, changed_prev_);
    if (!any) break;  // a fixed point: every later update repeats these values
  }
  // prev_ holds the newest values.
  for (int o = 0; o < num_outputs_; ++o) outputs[o] = prev_[num_inputs_ + o];
}

void Network::query_reference(const double* inputs, double* outputs) {
  const int n = static_cast<int>(act_.size());
  std::fill(prev_.begin(), prev_.end(), 0.0);
  for (int i = 0; i < num_inputs_; ++i) prev_[i] = cur_[i] = inputs[i];
  const int* from = in_from_.data();
  const double* w = in_weight_.data();
  for (int u = 0; u < updates_; ++u) {
    for (int node = num_inputs_; node < n; ++node) {
      double s = 0.0;
      for (int k = in_begin_[node]; k < in_begin_[node + 1]; ++k) s += w[k] * prev_[from[k]];
      cur_[node] = activate(static_cast<Activation>(act_[node]), s);
    }
    std::swap(cur_, prev_);
  }
  // After the last swap, prev_ holds the newest values.
  for (int o = 0; o < num_outputs_; ++o) outputs[o] = prev_[num_inputs_ + o];
}

std::vector<double> Network::query(const std::vector<double>& inputs) {
  if (static_cast<int>(inputs.size()) != num_inputs_)
    throw std::invalid_argument("CPPN query with " + std::to_string(inputs.size()) +
                                " inputs, expected " + std::to_string(num_inputs_));
  std::vector<double> out(static_cast<size_t>(num_outputs_));
  query(inputs.data(), out.data());
  return out;
}

}  // namespace robozoo
