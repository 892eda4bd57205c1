#pragma once
// Summary of one sample of numbers: size, mean, standard deviation and
// standard error of the mean (the error bars of the experiment's figures).
#include <cstddef>
#include <vector>

namespace robozoo {

struct SampleStats {
  size_t n = 0;       ///< sample size (count)
  double mean = 0.0;  ///< arithmetic mean (NaN when n = 0)
  double sd = 0.0;    ///< standard deviation with n - 1 in the denominator (0 when n < 2)
  double se = 0.0;    ///< standard error of the mean, sd / sqrt(n) (0 when n < 2)
};

/// Describes `x`. NaN values are not allowed (std::invalid_argument).
SampleStats describe(const std::vector<double>& x);

}  // namespace robozoo
