#include "evolve/cppn/network.hpp"

#include <algorithm>
#include <ctime>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "evolve/cppn/activation_libm.hpp"
#include "evolve/core/cpu_time.hpp"

namespace robozoo {

namespace {

/// Marks the points where rows a and b differ bitwise (+0.0 and -0.0 differ, a
/// NaN equals its own bits) in `point_changed`; returns whether any point differs.
char mark_changes(const double* a, const double* b, int m, char* point_changed) {
  char any = 0;
  for (int p = 0; p < m; ++p) {
    uint64_t x, y;
    std::memcpy(&x, a + p, sizeof x);
    std::memcpy(&y, b + p, sizeof y);
    const char d = x != y;
    point_changed[p] |= d;
    any |= d;
  }
  return any;
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
  prefix_end_.assign(n, 0);
  for (int v = 0; v < n; ++v) {
    in_begin_[v + 1] = in_begin_[v] + static_cast<int>(incoming[v].size());
    prefix_end_[v] = in_begin_[v];
    bool leading_inputs = true;
    for (const auto& [from, w] : incoming[v]) {
      in_from_.push_back(from);
      in_weight_.push_back(w);
      leading_inputs = leading_inputs && from < num_inputs_;
      if (leading_inputs) ++prefix_end_[v];
    }
  }

  // Longest-path depth by Kahn's algorithm over non-input nodes; a node left
  // unvisited lies on or behind a cycle.
  std::vector<int> indeg(n, 0), depth(n, 0);
  std::vector<std::vector<int>> out(n);
  for (int v = num_inputs_; v < n; ++v)
    for (int k = in_begin_[v]; k < in_begin_[v + 1]; ++k) {
      const int u = in_from_[k];
      if (u >= num_inputs_) {
        ++indeg[v];
        out[u].push_back(v);
      }
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

  in_.setZero(num_inputs_, kBlockPoints);
  base_.setZero(n, kBlockPoints);
  val_[0].setZero(n, kBlockPoints);
  val_[1].setZero(n, kBlockPoints);
  in_zero_.assign(num_inputs_, 0);
  changed_[0].assign(n, 0);
  changed_[1].assign(n, 0);
  point_changed_.assign(kBlockPoints, 0);
  point_.assign(kBlockPoints, 0);
  rows_.assign(n, nullptr);
  one_in_.setZero(num_inputs_, 1);
  one_out_.setZero(num_outputs_, 1);
  ref_cur_.assign(n, 0.0);
  ref_prev_.assign(n, 0.0);
}

int Network::num_inputs() const { return num_inputs_; }
int Network::num_outputs() const { return num_outputs_; }

void Network::query_batch(const QueryInputs& inputs, QueryOutputs outputs) { run(inputs, outputs, false); }

void Network::query_batch_synchronous(const QueryInputs& inputs, QueryOutputs outputs) { run(inputs, outputs, true); }

void Network::run(const QueryInputs& inputs, QueryOutputs& outputs, bool synchronous) {
  if (inputs.rows() != num_inputs_ || outputs.rows() != num_outputs_ || outputs.cols() != inputs.cols())
    throw std::invalid_argument(
        "CPPN batch of " + std::to_string(inputs.rows()) + " x " + std::to_string(inputs.cols()) + " inputs and " +
        std::to_string(outputs.rows()) + " x " + std::to_string(outputs.cols()) + " outputs, expected " +
        std::to_string(num_inputs_) + " and " + std::to_string(num_outputs_) + " rows of equal length");
  const double t0 = timing_ ? thread_cpu_seconds() : 0.0;
  const int total = static_cast<int>(inputs.cols());
  for (int first = 0; first < total; first += kBlockPoints) {
    const int m = std::min(kBlockPoints, total - first);
    load_block(inputs, first, m);
    if (single_pass_ && !synchronous) {
      single_pass_block(m);
      for (int o = 0; o < num_outputs_; ++o) outputs.row(o).segment(first, m) = val_[0].row(num_inputs_ + o).head(m);
    } else {
      synchronous_block(outputs, first, m);
    }
  }
  queries_ += total;
  if (timing_) query_seconds_ += thread_cpu_seconds() - t0;
}

void Network::load_block(const QueryInputs& inputs, int first, int m) {
  const int n = static_cast<int>(act_.size());
  in_.leftCols(m) = inputs.middleCols(first, m);
  for (int i = 0; i < num_inputs_; ++i) {
    in_zero_[i] = (in_.row(i).head(m) == 0.0).all();
    rows_[i] = &in_(i, 0);
  }
  // The leading input links of every node, summed once: inputs hold their value
  // through all updates.
  for (int v = num_inputs_; v < n; ++v) {
    double* b = &base_(v, 0);
    std::fill(b, b + m, 0.0);
    add_terms(b, in_begin_[v], prefix_end_[v], rows_.data(), false, m);
  }
}

void Network::add_terms(double* s, int k0, int k1, const double* const* rows, bool skip_nodes, int m) const {
  // Up to four terms per pass over s, each point summing them in link order:
  // ((s + w0 a) + w1 b) + ... is exactly the per-point sequence of additions.
  double w[4];
  const double* src[4];
  int c = 0;
  auto flush = [&]() {
    double* __restrict d = s;
    const double* __restrict a = src[0];
    const double* __restrict b = src[1];
    const double* __restrict e = src[2];
    const double* __restrict f = src[3];
    switch (c) {
      case 1:
        for (int p = 0; p < m; ++p) d[p] = d[p] + w[0] * a[p];
        break;
      case 2:
        for (int p = 0; p < m; ++p) d[p] = (d[p] + w[0] * a[p]) + w[1] * b[p];
        break;
      case 3:
        for (int p = 0; p < m; ++p) d[p] = ((d[p] + w[0] * a[p]) + w[1] * b[p]) + w[2] * e[p];
        break;
      case 4:
        for (int p = 0; p < m; ++p) d[p] = (((d[p] + w[0] * a[p]) + w[1] * b[p]) + w[2] * e[p]) + w[3] * f[p];
        break;
      default: break;
    }
    c = 0;
  };
  for (int k = k0; k < k1; ++k) {
    const int from = in_from_[k];
    if (from < num_inputs_ ? in_zero_[from] != 0 : skip_nodes) continue;  // a +-0 term: no change
    w[c] = in_weight_[k];
    src[c] = rows[from];
    if (++c == 4) flush();
  }
  flush();
}

void Network::activate_node_row(int v, double* s, int m) const {
  const auto a = static_cast<Activation>(act_[v]);
  if (libm_)
    activate_row_libm(a, s, s, m);
  else
    activate_row(a, s, s, m);
}

void Network::single_pass_block(int m) {
  const int n = static_cast<int>(act_.size());
  for (int v = num_inputs_; v < n; ++v) rows_[v] = &val_[0](v, 0);
  for (int v : order_) {
    double* s = &val_[0](v, 0);
    std::copy(&base_(v, 0), &base_(v, 0) + m, s);
    add_terms(s, prefix_end_[v], in_begin_[v + 1], rows_.data(), false, m);
    activate_node_row(v, s, m);
  }
}

void Network::synchronous_block(QueryOutputs& outputs, int first, int m) {
  const int n = static_cast<int>(act_.size());
  for (int p = 0; p < m; ++p) point_[p] = first + p;
  int prev = 0, cur = 1;
  // Update 1 from the reset state: every node reads zeros, which add nothing.
  std::fill(point_changed_.begin(), point_changed_.begin() + m, 0);
  for (int v = num_inputs_; v < n; ++v) {
    double* z = &val_[prev](v, 0);
    std::fill(z, z + m, 0.0);
    double* s = &val_[cur](v, 0);
    std::copy(&base_(v, 0), &base_(v, 0) + m, s);
    add_terms(s, prefix_end_[v], in_begin_[v + 1], rows_.data(), true, m);
    activate_node_row(v, s, m);
    changed_[cur][v] = mark_changes(s, z, m, point_changed_.data());
  }
  std::swap(prev, cur);
  for (int u = 1; u < updates_; ++u) {
    // val_[prev] holds the newest values; points where nothing changed are at a
    // fixed point: every further update repeats them.
    settle_points(outputs, prev, m);
    if (m == 0) return;
    for (int v = num_inputs_; v < n; ++v) rows_[v] = &val_[prev](v, 0);
    std::fill(point_changed_.begin(), point_changed_.begin() + m, 0);
    for (int v = num_inputs_; v < n; ++v) {
      bool dirty = false;
      for (int k = in_begin_[v]; k < in_begin_[v + 1] && !dirty; ++k)
        dirty = in_from_[k] >= num_inputs_ && changed_[prev][in_from_[k]];
      double* s = &val_[cur](v, 0);
      const double* old = &val_[prev](v, 0);
      if (!dirty) {  // its sources hold their bits, so does it
        std::copy(old, old + m, s);
        changed_[cur][v] = 0;
        continue;
      }
      std::copy(&base_(v, 0), &base_(v, 0) + m, s);
      add_terms(s, prefix_end_[v], in_begin_[v + 1], rows_.data(), false, m);
      activate_node_row(v, s, m);
      changed_[cur][v] = mark_changes(s, old, m, point_changed_.data());
    }
    std::swap(prev, cur);
  }
  std::fill(point_changed_.begin(), point_changed_.begin() + m, 0);  // all final
  settle_points(outputs, prev, m);
}

void Network::settle_points(QueryOutputs& outputs, int newest, int& m) {
  const int n = static_cast<int>(act_.size());
  const QueryArray& val = val_[newest];
  int kept = 0;
  for (int p = 0; p < m; ++p) {
    if (!point_changed_[p]) {
      for (int o = 0; o < num_outputs_; ++o) outputs(o, point_[p]) = val(num_inputs_ + o, p);
      continue;
    }
    if (kept != p) {  // close the gap: the block's columns stay contiguous
      for (int i = 0; i < num_inputs_; ++i) in_(i, kept) = in_(i, p);
      for (int v = num_inputs_; v < n; ++v) {
        val_[newest](v, kept) = val(v, p);
        base_(v, kept) = base_(v, p);
      }
      point_[kept] = point_[p];
    }
    ++kept;
  }
  m = kept;
}

void Network::query(const double* inputs, double* outputs) {
  for (int i = 0; i < num_inputs_; ++i) one_in_(i, 0) = inputs[i];
  QueryOutputs out(one_out_);
  run(QueryInputs(one_in_), out, false);
  for (int o = 0; o < num_outputs_; ++o) outputs[o] = one_out_(o, 0);
}

void Network::query_reference(const double* inputs, double* outputs) {
  const int n = static_cast<int>(act_.size());
  std::fill(ref_prev_.begin(), ref_prev_.end(), 0.0);
  for (int i = 0; i < num_inputs_; ++i) ref_prev_[i] = ref_cur_[i] = inputs[i];
  const int* from = in_from_.data();
  const double* w = in_weight_.data();
  for (int u = 0; u < updates_; ++u) {
    for (int node = num_inputs_; node < n; ++node) {
      double s = 0.0;
      for (int k = in_begin_[node]; k < in_begin_[node + 1]; ++k) s += w[k] * ref_prev_[from[k]];
      const auto a = static_cast<Activation>(act_[node]);
      ref_cur_[node] = libm_ ? activate_libm(a, s) : activate(a, s);
    }
    std::swap(ref_cur_, ref_prev_);
  }
  // After the last swap, ref_prev_ holds the newest values.
  for (int o = 0; o < num_outputs_; ++o) outputs[o] = ref_prev_[num_inputs_ + o];
}

std::vector<double> Network::query(const std::vector<double>& inputs) {
  if (static_cast<int>(inputs.size()) != num_inputs_)
    throw std::invalid_argument("CPPN query with " + std::to_string(inputs.size()) + " inputs, expected " +
                                std::to_string(num_inputs_));
  std::vector<double> out(static_cast<size_t>(num_outputs_));
  query(inputs.data(), out.data());
  return out;
}

}  // namespace robozoo
