#include "runlog/text/cppn_dot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace robozoo {

namespace {

std::string number(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// The names of robozoo's CPPN inputs and outputs (docs/method.md, "The CPPN"),
// used when a genome has exactly that many.
const char* const kInputNames[] = {"x", "y", "z", "r_parent", "bias", "s_distance", "s_touch", "s_proprio", "s_time"};
const char* const kOutputNames[] = {"m",        "r_scale", "j",       "theta", "tau", "omega",
                                    "distance", "touch",   "proprio", "time",  "w"};
constexpr int kNamedInputs = 9, kNamedOutputs = 11;

std::string node_label(const cppn_node_t& n, int input_index, int output_index, bool named) {
  switch (n.kind) {
    case 0: return named ? kInputNames[input_index] : "in " + std::to_string(input_index);
    case 1: return "bias";
    case 2:
      return (named ? std::string(kOutputNames[output_index]) : "out " + std::to_string(output_index)) + "\\n" +
             activation_label(n.activation);
    default: return "h" + std::to_string(n.id) + "\\n" + activation_label(n.activation);
  }
}

}  // namespace

std::string activation_label(int8_t activation) {
  switch (activation) {
    case 0: return "sigmoid";
    case 1: return "cos";
    case 2: return "gauss";
    case 3: return "linear";
    case 4: return "sin";
    case 5: return "steep sigmoid";
    default: return "act " + std::to_string(activation);
  }
}

bool is_recurrent_link(double from_position, double to_position) { return !(from_position < to_position); }

std::string cppn_to_dot(const cppn_genome_t& g, const CppnDrawingParams& params) {
  std::map<int32_t, const cppn_node_t*> nodes;
  for (const cppn_node_t& n : g.nodes) nodes[n.id] = &n;
  std::ostringstream out;
  out << "digraph cppn {\n"
      << "  graph [rankdir=LR, ranksep=2.2, nodesep=0.2, label=\"genome " << g.genome_id << ", generation "
      << g.generation << ", fitness " << number(g.fitness, 3) << "\", labelloc=t, fontname=\"DejaVu Sans\"];\n"
      << "  node [shape=circle, fixedsize=true, width=0.75, fontsize=9, fontname=\"DejaVu Sans\", style=filled];\n"
      << "  edge [arrowsize=0.6];\n";
  // Columns: one per distinct drawing position, in order, chained by invisible links.
  std::map<double, std::vector<int32_t>> columns;
  int all_inputs = 0, all_outputs = 0;
  for (const cppn_node_t& n : g.nodes) {
    all_inputs += n.kind == 0 || n.kind == 1;
    all_outputs += n.kind == 2;
  }
  const bool named = all_inputs == kNamedInputs && all_outputs == kNamedOutputs;
  int inputs = 0, outputs = 0;  // inputs count the bias: it is one of them
  for (const cppn_node_t& n : g.nodes) {
    const int in = n.kind == 0 || n.kind == 1 ? inputs++ : inputs;
    const int o = n.kind == 2 ? outputs++ : outputs;
    const char* fill = n.kind == 0 ? "#e2e8f0" : n.kind == 1 ? "#fefcbf" : n.kind == 2 ? "#c6f6d5" : "#ffffff";
    out << "  n" << n.id << " [label=\"" << node_label(n, in, o, named) << "\", fillcolor=\"" << fill
        << "\", tooltip=\"node " << n.id << ", position " << number(n.position, 4) << "\"];\n";
    columns[n.position].push_back(n.id);
  }
  // Within a column, nodes keep their id order (invisible links between neighbours).
  for (const auto& [position, ids] : columns) {
    out << "  { rank=same;";
    for (int32_t id : ids) out << " n" << id << ";";
    for (size_t i = 1; i < ids.size(); ++i) out << " n" << ids[i - 1] << " -> n" << ids[i] << " [style=invis];";
    out << " }\n";
  }
  for (auto it = columns.begin(); it != columns.end() && std::next(it) != columns.end(); ++it)
    out << "  n" << it->second.front() << " -> n" << std::next(it)->second.front() << " [style=invis, weight=10];\n";
  for (const link_t& l : g.links) {
    const auto from = nodes.find(l.from_node), to = nodes.find(l.to_node);
    if (from == nodes.end() || to == nodes.end())
      throw std::invalid_argument("genome " + std::to_string(g.genome_id) + ": link " + std::to_string(l.innovation) +
                                  " joins a node it does not have");
    const bool recurrent = is_recurrent_link(from->second->position, to->second->position);
    const double w = std::min(std::fabs(l.weight), params.max_weight) / params.max_weight;
    out << "  n" << l.from_node << " -> n" << l.to_node << " [";
    if (!l.enabled)
      out << "color=\"#b0b0b0\", style=dotted, penwidth=" << number(params.min_pen_width, 2);
    else
      out << "color=\"" << (l.weight >= 0 ? "#2b6cb0" : "#c53030")
          << "\", penwidth=" << number(params.min_pen_width + w * (params.max_pen_width - params.min_pen_width), 2)
          << (recurrent ? ", style=dashed" : "");
    if (recurrent || !l.enabled) out << ", constraint=false";
    out << ", tooltip=\"" << (recurrent ? "recurrent " : "") << "weight " << number(l.weight, 4) << "\"];\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace robozoo
