#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "study/analysis/compare/holm.hpp"

namespace robozoo {

int64_t ArmOutcomes::total() const {
  int64_t t = 0;
  for (int64_t c : counts) t += c;
  return t;
}

int64_t ArmOutcomes::simulated() const { return counts[1] + counts[2]; }

namespace {

using RunKey = std::pair<std::string, int64_t>;  // arm, seed

std::string run_name(const RunSummary& r) { return r.run_id.empty() ? r.path : r.run_id; }

// The run's generation record `generation - 1`, checked.
const GenerationRecord& record_at(const RunSummary& r, int32_t generation, const std::string& where) {
  const size_t i = static_cast<size_t>(generation - 1);
  if (r.generations.size() <= i)
    throw std::invalid_argument(where + " run " + run_name(r) + " holds " + std::to_string(r.generations.size()) +
                                " generations, fewer than the " + std::to_string(generation) + " compared");
  const GenerationRecord& g = r.generations[i];
  if (g.generation != generation - 1)
    throw std::invalid_argument(where + " run " + run_name(r) + ": its record " + std::to_string(i) +
                                " is generation " + std::to_string(g.generation));
  return g;
}

std::map<RunKey, const RunSummary*> index_runs(const std::vector<RunSummary>& runs, const SensitivityParams& p,
                                               const std::string& where) {
  std::map<RunKey, const RunSummary*> out;
  for (const RunSummary& r : runs) {
    if (r.arm != p.control_arm && r.arm != p.experimental_arm)
      throw std::invalid_argument(where + " run " + run_name(r) + " is of arm " + r.arm + ", neither " + p.control_arm +
                                  " nor " + p.experimental_arm);
    if (!out.emplace(RunKey{r.arm, r.seed}, &r).second)
      throw std::invalid_argument(where + " holds two " + r.arm + " runs of seed " + std::to_string(r.seed) + " (" +
                                  run_name(r) + ")");
  }
  return out;
}

bool same_changes(const std::vector<ConfigChange>& a, const std::vector<ConfigChange>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].key != b[i].key || a[i].from != b[i].from || a[i].to != b[i].to) return false;
  return true;
}

void add_outcomes(ArmOutcomes& o, const GenerationRecord& g) {
  ++o.runs;
  for (size_t i = 0; i < o.counts.size(); ++i) o.counts[i] += g.outcomes[i];
}

std::string reading_of(const FactorResult& f, const SensitivityParams& p) {
  if (!std::isfinite(f.gap.low)) return "no test (an arm has fewer than two runs, or no spread)";
  std::string ref;
  if (std::isfinite(f.reference_gap.gap))
    ref = f.gap.covers(f.reference_gap.gap) ? "its interval holds the reference's gap"
                                            : "its interval excludes the reference's gap";
  if (f.significant) {
    const std::string fitter = f.gap.gap > 0 ? p.control_arm : p.experimental_arm;
    return fitter + " fitter, significant after Holm" + (ref.empty() ? "" : "; " + ref);
  }
  if (f.gap.covers(0) && !ref.empty() && f.gap.covers(f.reference_gap.gap))
    return "inconclusive: the interval holds both 0 and the reference's gap";
  return "not significant after Holm" + (ref.empty() ? "" : "; " + ref);
}

}  // namespace

SensitivityAnalysis analyze_sensitivity(const std::vector<RunSummary>& reference,
                                        const std::vector<SensitivityFactor>& factors,
                                        const SensitivityParams& params) {
  if (params.generation < 1) throw std::invalid_argument("the sensitivity study compares a generation >= 1");
  if (params.control_arm == params.experimental_arm)
    throw std::invalid_argument("the sensitivity study compares two different arms");
  SensitivityAnalysis out;
  out.params = params;
  const auto ref = index_runs(reference, params, "the reference");
  for (const RunSummary& r : reference) {
    if (out.software_version.empty()) out.software_version = r.software_version;
    if (r.software_version != out.software_version)
      throw std::invalid_argument("the reference's runs ran different versions of robozoo (" + out.software_version +
                                  ", " + r.software_version + " in " + run_name(r) + ")");
  }
  std::vector<double> p_values;
  for (const SensitivityFactor& factor : factors) {
    const std::string where = "factor " + factor.name;
    const auto runs = index_runs(factor.runs, params, where);
    FactorResult f;
    f.name = factor.name;
    std::vector<double> control, experimental, ref_control, ref_experimental;
    bool first = true;
    for (const auto& [key, run] : runs) {
      const auto match = ref.find(key);
      if (match == ref.end())
        throw std::invalid_argument(where + " run " + run_name(*run) + ": the reference has no " + key.first +
                                    " run of seed " + std::to_string(key.second));
      const RunSummary& r = *match->second;
      if (run->software_version != r.software_version)
        throw std::invalid_argument(where + " run " + run_name(*run) + " ran robozoo " + run->software_version +
                                    ", the reference's run of its seed " + r.software_version);
      const auto changes =
          config_difference(r.config_json, run->config_json, {"generations"}, where + " run " + run_name(*run));
      if (changes.empty())
        throw std::invalid_argument(where + " run " + run_name(*run) +
                                    " has the reference's configuration: nothing was changed");
      if (first) {
        f.changes = changes;
        first = false;
      } else if (!same_changes(changes, f.changes)) {
        throw std::invalid_argument(where + " run " + run_name(*run) + " changes " + describe_changes(changes) +
                                    " where the factor's other runs change " + describe_changes(f.changes));
      }
      const GenerationRecord& g = record_at(*run, params.generation, where);
      const GenerationRecord& rg = record_at(r, params.generation, "the reference");
      const bool is_control = key.first == params.control_arm;
      (is_control ? control : experimental).push_back(g.best_so_far_fitness);
      (is_control ? ref_control : ref_experimental).push_back(rg.best_so_far_fitness);
      (is_control ? f.control_seeds : f.experimental_seeds).push_back(key.second);
      add_outcomes(is_control ? f.control_outcomes : f.experimental_outcomes, g);
      add_outcomes(is_control ? f.reference_control_outcomes : f.reference_experimental_outcomes, rg);
    }
    f.gap = student_gap(control, experimental, params.level);
    f.reference_gap = student_gap(ref_control, ref_experimental, params.level);
    f.difference = gap_difference(f.gap, f.reference_gap, params.level);
    p_values.push_back(f.gap.p);
    out.factors.push_back(std::move(f));
  }
  const std::vector<double> holm = holm_adjust(p_values);
  for (size_t i = 0; i < out.factors.size(); ++i) {
    FactorResult& f = out.factors[i];
    f.holm_p = holm[i];
    f.significant = f.holm_p < params.alpha;
    f.reading = reading_of(f, params);
  }
  return out;
}

std::vector<std::string> factors_with_fewer_runs(const SensitivityAnalysis& a) {
  size_t most_control = 0, most_experimental = 0;
  for (const FactorResult& f : a.factors) {
    most_control = std::max(most_control, f.control_seeds.size());
    most_experimental = std::max(most_experimental, f.experimental_seeds.size());
  }
  std::vector<std::string> out;
  for (const FactorResult& f : a.factors) {
    if (f.control_seeds.size() == most_control && f.experimental_seeds.size() == most_experimental) continue;
    out.push_back(f.name + " (" + std::to_string(f.control_seeds.size()) + " " + a.params.control_arm + " and " +
                  std::to_string(f.experimental_seeds.size()) + " " + a.params.experimental_arm + " runs, against " +
                  std::to_string(most_control) + " and " + std::to_string(most_experimental) + ")");
  }
  return out;
}

}  // namespace robozoo
