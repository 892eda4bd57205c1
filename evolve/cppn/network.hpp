#pragma once
// A decoded CPPN, queried as docs/method.md section 2 says: reset all node values,
// run `updates` synchronous updates (every node reads the previous update's
// values; input nodes hold their input), read the outputs.
//
// Querying is the hot path of growth: after construction, query() allocates
// nothing.
#include <vector>

#include "evolve/cppn/genome.hpp"

namespace robozoo {

class Network {
 public:
  /// Decodes the enabled links of g. Throws std::invalid_argument if g does not
  /// fit the layout (see validate_genome).
  Network(const Genome& g, const GenomeLayout& layout, int updates = 10);

  int num_inputs() const;
  int num_outputs() const;
  /// True when the enabled links are acyclic and no path is longer than the
  /// number of updates: then one pass in topological order gives exactly (bit
  /// for bit) what the synchronous updates give, and query() takes that path.
  bool single_pass() const { return single_pass_; }
  /// The synchronous-update procedure, always (for tests of the single-pass path).
  /// A node is recomputed only when one of its inputs changed in the previous
  /// update: a pure function of unchanged values gives the same bits, so this is
  /// exactly the plain procedure (query_reference) at a fraction of the cost once
  /// parts of the network have settled.
  void query_synchronous(const double* inputs, double* outputs);
  /// The plain procedure: every node recomputed in every update (tests compare).
  void query_reference(const double* inputs, double* outputs);

  /// inputs: num_inputs() values in node order (the bias input is read from
  /// inputs like any other); outputs: num_outputs() values written.
  void query(const double* inputs, double* outputs);

  /// Queries answered so far (for benchmarks: growth's CPPN share).
  long long queries() const { return queries_; }

  /// Convenience wrapper (allocates the result).
  std::vector<double> query(const std::vector<double>& inputs);

 private:
  int num_inputs_ = 0, num_outputs_ = 0, updates_ = 10;
  std::vector<int> act_;            // activation code per compact node index
  std::vector<int> in_begin_;       // CSR over non-input nodes: incoming links
  std::vector<int> in_from_;
  std::vector<double> in_weight_;
  std::vector<int> order_;          // evaluation order for the single-pass path
  bool single_pass_ = false;        // acyclic and depth <= updates: one pass is bit-identical
  std::vector<double> cur_, prev_;  // node values
  std::vector<char> changed_cur_, changed_prev_;  // value changed in this / the previous update
  long long queries_ = 0;
};

}  // namespace robozoo
