#pragma once
// Whole numbers in the replay reports' sentences: any integer field of a message,
// printed in decimal.
#include <cstdint>
#include <string>

namespace robozoo::replay {

/// v in decimal ("-1", "150").
inline std::string num(int64_t v) { return std::to_string(v); }

}  // namespace robozoo::replay
