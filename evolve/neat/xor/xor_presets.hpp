#pragma once
// The two parameter sets robozoo-xor checks NEAT with on XOR:
// - "default": the project's CPPN-NEAT as robots use it (HyperNEAT's defaults
//   and topology rules), signed-sigmoid output;
// - "neat-paper": the NEAT paper's own XOR settings (Stanley & Miikkulainen
//   2002, section 4): steepened sigmoid 1/(1+e^(-4.9x)) everywhere, c1 = c2 = 1,
//   c3 = 0.4, a fixed threshold of 3.0, classic add-node (the split link is
//   disabled), a gene disabled in either parent inherited disabled with
//   probability 0.75, interspecies mating 0.001, weight mutation in 80 % of
//   offspring, and the classic topology: a start of inputs-to-outputs links, the
//   cycle test, add-link by tries, classic excess/disjoint counting. Where the
//   paper is silent or summarises, the mechanics of Stanley's own NEAT C++ (the
//   code behind its figures; see xor_presets.cpp and params.hpp), his XOR
//   evaluation and the paper's evaluation count.
#include <string>
#include <vector>

#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"
#include "evolve/neat/xor/xor_task.hpp"

namespace robozoo {

struct XorPreset {
  std::string name;
  NeatParams params;
  GenomeLayout layout;
  /// The hidden activation mask of "sigmoid only" for this preset (signed
  /// sigmoid, or the steepened sigmoid of the NEAT paper).
  uint32_t sigmoid_only = 0;
  /// The mask of "all three": the preset's sigmoid, signed cosine and Gaussian.
  uint32_t all_three = 0;
  /// How networks are read (the neat-paper preset: Stanley's activation and winner test).
  XorRules rules;
  /// Evaluations counted up to and including the first solver of the solving generation, in
  /// population order (the NEAT paper: networks evaluated until the solution; Stanley's
  /// xor_test: pop_size x (generation - 1) + the winner's number). false: whole generations.
  bool count_to_solver = false;
};

/// Names of the presets ("default", "neat-paper").
std::vector<std::string> xor_preset_names();
/// The preset of that name; throws std::invalid_argument for an unknown one.
XorPreset xor_preset(const std::string& name);

}  // namespace robozoo
