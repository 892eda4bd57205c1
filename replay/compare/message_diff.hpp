#pragma once
// Naming the first field in which two messages of the same channel differ
// (for check --full and check --lcm-url): "best_fitness", "links[12].weight".
#include <cstdint>
#include <string>
#include <vector>

namespace robozoo::replay {

struct FieldDifference {
  std::string field;  ///< path of the first differing field; empty if none was found
  std::string a, b;   ///< the two values as JSON text (doubles round-trip)
};

/// Decodes both as `channel`'s type (safe_decode) and walks their fields
/// (alphabetically at each level, array elements in order). Fields named in `ignore` (top level, e.g. "utime") are
/// skipped. A side that does not decode is named as field "(bytes)" with the
/// reason. Empty field when the decoded values are equal (bits may still differ,
/// e.g. 0.0 and -0.0; the caller compares bytes).
FieldDifference first_field_difference(const std::string& channel, const std::vector<uint8_t>& a,
                                       const std::vector<uint8_t>& b, const std::vector<std::string>& ignore = {});

}  // namespace robozoo::replay
