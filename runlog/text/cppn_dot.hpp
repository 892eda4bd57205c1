#pragma once
// A logged CPPN genome as a Graphviz drawing (robozoo-log cppn): nodes in
// columns by their drawing position (inputs left, outputs right), labelled
// with their role (docs/method.md's input and output names for robozoo's
// layout of 9 inputs and 11 outputs) and activation function; links coloured by sign (blue
// positive, red negative), as wide as |weight|; recurrent links (against the
// drawing order: position(from) >= position(to)) dashed, disabled ones dotted
// grey.
#include <string>

#include "robozoo/cppn_genome_t.hpp"

namespace robozoo {

struct CppnDrawingParams {
  double min_pen_width = 0.6;  ///< width of a link of weight 0 (points)
  double max_pen_width = 4.0;  ///< width of a link of |weight| >= max_weight (points)
  double max_weight = 5.0;     ///< |weight| drawn widest (the genome's weight bound)
};

/// The activation's short name ("sigmoid", "cos", "gauss", ...), "act N" for unknown codes.
std::string activation_label(int8_t activation);

/// Whether the link from -> to runs against the drawing order.
bool is_recurrent_link(double from_position, double to_position);

/// The genome as a DOT graph. Throws std::invalid_argument when a link names
/// a node the genome does not have.
std::string cppn_to_dot(const cppn_genome_t& genome, const CppnDrawingParams& params = {});

}  // namespace robozoo
