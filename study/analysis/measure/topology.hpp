#pragma once
// Topological sameness of two robots, for the paper's champion-change analysis
// (section 4: "its morphology is topologically different from the previous champ").
//
// The topology of a robot is its sphere tree as a rooted, unordered tree: which
// sphere is attached to which, nothing else. Radii, densities, positions, sensors
// and the order in which growth added siblings do not matter; a branch moved to
// another sphere does. Its canonical form is the sorted nested-parentheses
// encoding (Aho, Hopcroft and Ullman's tree isomorphism): a sphere is "(" + the
// sorted codes of its children + ")", so two trees are isomorphic exactly when
// their codes are equal.
//
// With `joints`, the hinge that attaches a sphere to its parent is part of the
// topology too (a child's code is prefixed by "j"), so a fused sphere that
// becomes jointed changes the topology. The default is off: the paper speaks of
// the morphology's topology, and a joint is an attribute of an attachment, not
// a change of which spheres are attached.
#include <string>

#include "robozoo/morphology_t.hpp"

namespace robozoo {

struct TopologyOptions {
  bool joints = false;  ///< hinge joints are part of the topology (default: the tree shape alone)
};

/// Canonical code of `m`'s sphere tree. Throws std::invalid_argument for a
/// malformed tree (see sphere_tree).
std::string topology_code(const morphology_t& m, const TopologyOptions& options = {});

/// True when `a` and `b` have the same topology.
bool same_topology(const morphology_t& a, const morphology_t& b, const TopologyOptions& options = {});

}  // namespace robozoo
