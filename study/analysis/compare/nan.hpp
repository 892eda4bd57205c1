#pragma once
// The statistics' "no value" (a test with too few trials, an effect size without
// variance): a quiet NaN, which the reports print as "n/a".
#include <limits>

namespace robozoo {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace robozoo
