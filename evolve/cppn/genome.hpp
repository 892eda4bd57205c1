#pragma once
// A CPPN genome: node genes and link genes (NEAT). Pure data plus checks.
//
// Node numbering (docs/method.md, "The CPPN") is fixed by the layout: inputs are
// nodes 0..num_inputs-1 (one of them may be the bias), outputs follow, hidden
// nodes are numbered from num_inputs + num_outputs upwards.
//
// Every node has a drawing position, as in HyperNEAT: inputs 0, outputs 1, a
// hidden node the mean of the positions of the two ends of the link it split.
// A link is forward when pos(from) < pos(to), recurrent otherwise.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/cppn/activation.hpp"

namespace robozoo {

enum class NodeKind : int8_t { Input = 0, Bias = 1, Output = 2, Hidden = 3 };

/// Drawing positions of the fixed nodes.
constexpr double kInputPosition = 0.0;
constexpr double kOutputPosition = 1.0;

struct NodeGene {
  int32_t id = 0;
  NodeKind kind = NodeKind::Hidden;
  Activation activation = Activation::SignedSigmoid;
  double position = 0.5;  ///< drawing position (inputs 0, outputs 1, hidden in between)
  bool operator==(const NodeGene& o) const {
    return id == o.id && kind == o.kind && activation == o.activation && position == o.position;
  }
};

struct LinkGene {
  int64_t innovation = 0;
  int32_t from = 0;
  int32_t to = 0;
  double weight = 0.0;
  bool enabled = true;
  int32_t born = 0;  ///< generation the gene first appeared in (for age-dependent mutation)
  bool operator==(const LinkGene& o) const {
    return innovation == o.innovation && from == o.from && to == o.to && weight == o.weight && enabled == o.enabled &&
           born == o.born;
  }
};

/// Shape of the inputs and outputs every genome of a run shares.
struct GenomeLayout {
  int num_inputs = 9;    ///< input nodes, including the bias (count)
  int bias_input = 4;    ///< index of the bias among the inputs (-1: none)
  int num_outputs = 11;  ///< output nodes (count)
  Activation output_activation = Activation::SignedSigmoid;
  int first_hidden() const { return num_inputs + num_outputs; }
  bool operator==(const GenomeLayout& o) const {
    return num_inputs == o.num_inputs && bias_input == o.bias_input && num_outputs == o.num_outputs &&
           output_activation == o.output_activation;
  }
};

/// The robot CPPN layout of docs/method.md: 9 inputs (x, y, z, r_parent, bias,
/// s_distance, s_touch, s_proprio, s_time), 11 outputs.
GenomeLayout robot_layout();

struct Genome {
  int64_t id = -1;
  std::vector<NodeGene> nodes;  ///< sorted by id
  std::vector<LinkGene> links;  ///< sorted by innovation
  bool operator==(const Genome& o) const { return id == o.id && nodes == o.nodes && links == o.links; }
};

/// Checks a genome against a layout: node ids unique, sorted, the fixed inputs and
/// outputs present with the right kinds and positions (0 and 1), hidden ids >=
/// first_hidden with positions in [0, 1], valid activation codes, links sorted by unique innovation, endpoints that exist,
/// no link into an input, finite weights. Throws std::invalid_argument with a
/// message naming the first problem.
void validate_genome(const Genome& g, const GenomeLayout& layout);

/// True if the enabled links of g contain a directed cycle (self-loops included).
bool has_cycle(const Genome& g);

/// Drawing position of node `id` of g; throws std::invalid_argument if g has no such node.
double node_position(const Genome& g, int32_t id);
/// True when pos(from) < pos(to) (HyperNEAT's forward link).
bool is_forward_link(const Genome& g, const LinkGene& l);
/// Number of link genes (enabled or not) that are not forward.
int count_recurrent_links(const Genome& g);

/// Stable 64-bit hash of a genome's content (ids, kinds, activations, links
/// with exact weight bits). Used by determinism tests.
uint64_t genome_hash(const Genome& g);

/// Number of hidden nodes.
int count_hidden(const Genome& g);
/// Number of enabled links.
int count_enabled_links(const Genome& g);

}  // namespace robozoo
