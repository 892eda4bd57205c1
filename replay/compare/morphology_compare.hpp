#pragma once
// A logged ROBOZOO_MORPHOLOGY against the one make_morphology_message builds
// from the re-grown robot: every field but utime, naming field and indices.
#include "replay/compare/value_compare.hpp"
#include "robozoo/morphology_t.hpp"

namespace robozoo::replay {

/// Adds every difference to `cmp` (context "morphology"); returns true when
/// none was found. Arrays are compared only where their counts agree.
bool compare_morphology(const morphology_t& logged, const morphology_t& recomputed, ValueComparer& cmp);

}  // namespace robozoo::replay
