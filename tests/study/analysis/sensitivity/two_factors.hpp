#pragma once
// A sensitivity analysis of two factors, made by hand, for the report's and the figure's tests.
#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

namespace robozoo::testing {

inline SensitivityAnalysis two_factors() {
  SensitivityAnalysis a;
  a.params.generation = 30;
  a.software_version = "2f4ba41c77a6";
  FactorResult f;
  f.name = "bias-1.0";
  f.changes = {{"growth.bias_input", "0.3", "1.0"}};
  f.control_seeds = {1, 5};
  f.experimental_seeds = {2, 6};
  f.gap = student_gap({20, 24}, {10, 12});
  f.reference_gap = student_gap({12, 14}, {11, 12});
  f.difference = gap_difference(f.gap, f.reference_gap);
  f.holm_p = 0.25;
  f.reading = "inconclusive: the interval holds both 0 and the reference's gap";
  f.control_outcomes.runs = 2;
  f.control_outcomes.counts = {30, 200, 20, 10, 40, 0};
  a.factors.push_back(f);
  f.name = "cap-100";
  f.changes = {{"growth.max_spheres", "50", "100"}};
  a.factors.push_back(f);
  return a;
}

}  // namespace robozoo::testing
