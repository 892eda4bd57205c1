#pragma once
// A decoded CPPN, queried as docs/method.md section 2 says: reset all node values, run
// `updates` synchronous updates (every node reads the previous update's values;
// input nodes hold their input), read the outputs.
//
// Queries are answered in batches (growth asks for a whole cloud of 629 points,
// or all of a robot's weight queries, at once): node values are held as
// nodes x points arrays and every update is a few array operations per node, in
// blocks of kBlockPoints points that stay in the first-level cache. Each point
// gets exactly the operations of the plain per-point procedure (query_reference),
// in the same order, so the results are the same bits:
// - a node's sum adds its incoming links in innovation order, starting from +0.0;
// - the leading run of links that come from inputs is summed once per query
//   (inputs never change during a query), the rest in every update;
// - a term whose source row is exactly zero at every point of the block (an
//   input such as z or an unset sensor one-hot; every node in the first update)
//   is skipped: a sum that starts from +0.0 is never -0.0, and adding +-0 to
//   anything else leaves its bits unchanged;
// - activations apply the same operations element by element (activate_row);
// - a node none of whose sources changed in the previous update keeps its values
//   (a pure function of unchanged bits gives the same bits), and a point at which
//   no node changed has reached a fixed point: its outputs are final and it
//   leaves the batch;
// - an acyclic network no deeper than `updates` is evaluated in one pass in
//   topological order, which the synchronous updates reproduce exactly.
//
// Querying allocates nothing once the network has answered its first batch.
#include <vector>

#include <Eigen/Core>

#include "evolve/cppn/genome.hpp"

namespace robozoo {

/// Inputs or outputs of a batch of queries: row i holds value i of every point,
/// column p is point p.
using QueryArray = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using QueryInputs = Eigen::Ref<const QueryArray, 0, Eigen::OuterStride<>>;
using QueryOutputs = Eigen::Ref<QueryArray, 0, Eigen::OuterStride<>>;

class Network {
 public:
  /// Points evaluated together (nodes x kBlockPoints values stay in the first-level cache).
  static constexpr int kBlockPoints = 64;

  /// Decodes the enabled links of g. Throws std::invalid_argument if g does not
  /// fit the layout (see validate_genome).
  Network(const Genome& g, const GenomeLayout& layout, int updates = 10);

  int num_inputs() const;
  int num_outputs() const;
  /// True when the enabled links are acyclic and no path is longer than the
  /// number of updates: then one pass in topological order gives exactly (bit
  /// for bit) what the synchronous updates give, and queries take that path.
  bool single_pass() const { return single_pass_; }

  /// Queries every column of `inputs` (num_inputs() rows, the bias read like any
  /// other input) and writes num_outputs() rows of the same number of columns to
  /// `outputs`. Throws std::invalid_argument when the shapes do not fit.
  void query_batch(const QueryInputs& inputs, QueryOutputs outputs);
  /// The synchronous updates, always (for tests of the single-pass path).
  void query_batch_synchronous(const QueryInputs& inputs, QueryOutputs outputs);

  /// One point: a batch of one. inputs: num_inputs() values in node order;
  /// outputs: num_outputs() values written.
  void query(const double* inputs, double* outputs);
  /// Convenience wrapper (allocates the result).
  std::vector<double> query(const std::vector<double>& inputs);

  /// The plain per-point procedure: every node recomputed in every update, no
  /// shortcut. The reference the tests hold the batched path to, bit for bit.
  void query_reference(const double* inputs, double* outputs);

  /// Points queried so far (for benchmarks: growth's CPPN share).
  long long queries() const { return queries_; }
  /// With timing on, query_batch adds its thread CPU time to query_seconds() (benchmarks).
  void enable_timing(bool on) { timing_ = on; }
  double query_seconds() const { return query_seconds_; }
  /// With this on, activations use the C library's exp/cos/sin
  /// (activation_libm.hpp) instead of robozoo's own: for tests and robozoo-bench's
  /// baseline only, never for results.
  void use_libm_activations(bool on) { libm_ = on; }

 private:
  void run(const QueryInputs& inputs, QueryOutputs& outputs, bool synchronous);
  void load_block(const QueryInputs& inputs, int first, int m);
  void single_pass_block(int m);
  void synchronous_block(QueryOutputs& outputs, int first, int m);
  /// Adds the terms k in [k0, k1) of a node's sum to s[0, m), reading source
  /// rows from `rows`; `skip_nodes`: non-input sources are all zero (first update).
  void add_terms(double* s, int k0, int k1, const double* const* rows, bool skip_nodes, int m) const;
  void settle_points(QueryOutputs& outputs, int first, int& m);
  void activate_node_row(int v, double* s, int m) const;

  int num_inputs_ = 0, num_outputs_ = 0, updates_ = 10;
  std::vector<int> act_;       // activation code per compact node index
  std::vector<int> in_begin_;  // CSR over nodes: incoming links, in innovation order
  std::vector<int> in_from_;
  std::vector<double> in_weight_;
  std::vector<int> prefix_end_;  // per node: end of the leading run of links from inputs
  std::vector<int> order_;       // evaluation order for the single-pass path
  bool single_pass_ = false;     // acyclic and depth <= updates: one pass is bit-identical

  // Block scratch (nodes x kBlockPoints, row-major), sized once.
  QueryArray in_;                    // the block's inputs
  QueryArray base_;                  // per node: sum of its leading input links
  QueryArray val_[2];                // node values: previous and current update
  std::vector<char> in_zero_;        // per input: zero at every point of the block
  std::vector<char> changed_[2];     // per node: changed at some point in the previous / this update
  std::vector<char> point_changed_;  // per point: some node changed in this update
  std::vector<int> point_;           // per active column: the point's column in the batch
  std::vector<const double*> rows_;  // per node: its row of values read by this update

  QueryArray one_in_, one_out_;             // a batch of one for query(const double*, double*)
  std::vector<double> ref_cur_, ref_prev_;  // query_reference's state
  long long queries_ = 0;
  bool timing_ = false;
  bool libm_ = false;
  double query_seconds_ = 0.0;
};

}  // namespace robozoo
