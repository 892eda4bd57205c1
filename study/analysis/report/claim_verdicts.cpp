#include "study/analysis/report/claim_verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "study/analysis/compare/holm.hpp"
#include "study/analysis/compare/nan.hpp"
#include "study/analysis/report/paper_claims.hpp"
#include "study/analysis/compare/power.hpp"

namespace robozoo {

namespace {

bool is_recurrent_arm(const std::string& arm) { return arm.rfind("recurrent", 0) == 0; }

// Links of an arm's generation-0 CPPN (docs/method.md): 0 if unknown.
int start_links(const std::string& arm) {
  if (arm == "feedforward" || arm == "recurrent-sparse") return 99;
  if (arm == "recurrent" || arm == "recurrent-zero") return 209;
  return 0;
}

std::string num(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Whether d's confidence interval lies wholly short of the paper's effect in
// the paper's direction.
bool excludes_paper_effect(const ClaimRow& r) {
  const EffectSize& e = r.comparison.effect;
  if (!std::isfinite(r.paper_effect) || !std::isfinite(e.d_low)) return false;
  if (r.paper_direction == 1) return e.d_high < r.paper_effect;
  if (r.paper_direction == -1) return e.d_low > -r.paper_effect;
  return false;
}

std::string p_text(double p) { return p < 0.001 ? "p < 0.001" : "p = " + num(p, 3); }

}  // namespace

int paper_orientation(const std::string& control_arm, const std::string& experimental_arm) {
  if (control_arm == "feedforward" && is_recurrent_arm(experimental_arm)) return 1;
  if (experimental_arm == "feedforward" && is_recurrent_arm(control_arm)) return -1;
  return 0;
}

std::string by_construction(const std::string& key, const std::string& control_arm,
                            const std::string& experimental_arm) {
  if (key == "links") {
    const int c = start_links(control_arm), x = start_links(experimental_arm);
    if (c > 0 && x > 0 && c != x)
      return "true by construction: the " + std::string(c > x ? control_arm : experimental_arm) + " start has " +
             std::to_string(std::max(c, x)) + " links, the " + (c > x ? experimental_arm : control_arm) + " start " +
             std::to_string(std::min(c, x));
  }
  if ((key == "recurrent_links" || key == "cycle_links") &&
      ((control_arm == "feedforward") != (experimental_arm == "feedforward")))
    return "true by construction: a feed-forward CPPN has none";
  return "";
}

ClaimsAssessment assess_claims(const ExperimentAnalysis& a, double alpha) {
  ClaimsAssessment out;
  out.alpha = alpha;
  const int orient = paper_orientation(a.control_arm, a.experimental_arm);
  out.paper_compared = orient != 0;

  auto add = [&](const std::vector<Comparison>& list, const std::string& section) {
    for (const auto& c : list) {
      ClaimRow r;
      r.comparison = c;
      r.section = section;
      r.paper_effect = r.power = r.holm_p = kNaN;
      r.role = c.key == "best_fitness" ? ClaimRole::Primary : ClaimRole::Secondary;
      if (c.samples == Samples::PooledEvents) {
        r.role = ClaimRole::Descriptive;
        r.role_note = "pooled events of all runs, not independent: described, not tested";
      } else if (c.key == "hit_max_spheres") {
        r.role = ClaimRole::Descriptive;
        r.role_note = "the growth cap, described (it censors the counts it bounds)";
      } else if (const std::string why = by_construction(c.key, a.control_arm, a.experimental_arm); !why.empty()) {
        r.role = ClaimRole::ByConstruction;
        r.role_note = why;
      }
      const PaperClaim* claim = paper_claim(c.key);
      if (!out.paper_compared) {
        r.paper = "not compared by the paper";
      } else if (!claim) {
        r.paper = "silent";
      } else {
        r.paper = claim->paper;
        r.paper_direction = claim->direction == 0 ? 0 : claim->direction * orient;
        r.paper_significant = claim->significant;
        if (claim->significant && claim->run_samples && std::isfinite(claim->p_bound)) {
          r.paper_effect = smallest_effect_for_p(claim->p_bound, kPaperRunsPerRegime, kPaperRunsPerRegime);
          r.power =
              t_test_power(r.paper_effect, static_cast<int>(c.control.n), static_cast<int>(c.experimental.n), alpha);
        }
      }
      // The sign of the difference of the means (d's sign, also where d is undefined:
      // a sample of one, or two constant samples).
      const double diff = c.experimental.mean - c.control.mean;
      if ((r.paper_direction == 1 || r.paper_direction == -1) && c.control.n > 0 && c.experimental.n > 0 && diff != 0)
        r.direction = (diff > 0) == (r.paper_direction > 0) ? "same as the paper" : "opposite to the paper";
      out.rows.push_back(r);
    }
  };
  add(a.fitness, "Figure 1");
  add(a.morphology, "Figure 2");
  add(a.genotype, "Figure 3");
  add(a.champion, "Section 4");

  std::vector<double> family;
  for (const auto& r : out.rows) family.push_back(r.role == ClaimRole::Secondary ? r.comparison.student.p : kNaN);
  const std::vector<double> q = holm_adjust(family);
  for (size_t i = 0; i < out.rows.size(); ++i) {
    out.rows[i].holm_p = q[i];
    out.family_size += !std::isnan(q[i]);
  }

  for (auto& r : out.rows) {
    const Comparison& c = r.comparison;
    if (r.role == ClaimRole::ByConstruction || r.role == ClaimRole::Descriptive) {
      r.verdict = r.role_note;
      continue;
    }
    const double p = r.role == ClaimRole::Primary ? c.student.p : r.holm_p;
    const std::string which = r.role == ClaimRole::Primary ? "" : " after Holm";
    if (std::isnan(p)) {
      r.verdict = "too few data for a test";
      continue;
    }
    const bool sig = p < alpha;
    if (r.paper_direction == 1 || r.paper_direction == -1) {
      if (sig && r.direction == "same as the paper")
        r.verdict = r.paper_significant ? "agrees: significant" + which
                                        : "significant" + which + ", the paper's way (the paper reports no test)";
      else if (sig && r.direction == "opposite to the paper")
        r.verdict = "contradicts: significant" + which + ", the other way";
      else
        r.verdict = "inconclusive: not significant" + which +
                    (r.direction.empty()
                         ? ""
                         : ", the estimate points " +
                               std::string(r.direction == "same as the paper" ? "the paper's way" : "the other way"));
    } else if (r.paper_direction == 0) {
      r.verdict = sig ? "differs: significant" + which + ", where the paper found no significant difference"
                      : "not significant" + which + ", as in the paper (not a proof of equality)";
    } else {
      r.verdict = sig ? "significant" + which : "not significant" + which;
    }
  }

  // The primary verdict notes where Welch's test, which does not assume equal
  // variances, comes out the other side of alpha.
  for (auto& r : out.rows)
    if (r.role == ClaimRole::Primary && !std::isnan(r.comparison.welch.p) && !std::isnan(r.comparison.student.p) &&
        (r.comparison.welch.p < alpha) != (r.comparison.student.p < alpha))
      r.verdict +=
          std::string("; Welch's test ") + (r.comparison.welch.p < alpha ? "reaches" : "does not reach") + " α";

  // The headline: the primary test.
  const ClaimRow* primary = nullptr;
  for (const auto& r : out.rows)
    if (r.role == ClaimRole::Primary) primary = &r;
  const std::string ctl = arm_title(a.control_arm), exp = arm_title(a.experimental_arm);
  const std::string at = "at generation " + std::to_string(a.last_generation) + " (the last) with " +
                         std::to_string(primary ? primary->comparison.control.n : 0) + " " + ctl + " and " +
                         std::to_string(primary ? primary->comparison.experimental.n : 0) + " " + exp + " runs";
  if (!primary || std::isnan(primary->comparison.student.p)) {
    out.outcome = out.paper_compared ? "inconclusive" : "";
    out.headline = out.paper_compared ? "The paper's fitness result (recurrent CPPNs fitter) is **inconclusive** " +
                                            at + ": too few runs for the primary test."
                                      : "The primary test has too few runs " + at + ".";
    return out;
  }
  const Comparison& f = primary->comparison;
  const bool sig = f.student.p < alpha;
  const std::string test =
      "Student's t(" + num(f.student.df, 0) + ") = " + num(f.student.t, 2) + ", " + p_text(f.student.p) + "; Welch's " +
      p_text(f.welch.p) +
      (!std::isnan(f.welch.p) && (f.welch.p < alpha) != sig
           ? std::string(" (Welch's test, without equal variances, ") + (sig ? "does not reach" : "reaches") + " α)"
           : std::string()) +
      "; Cohen's d = " + num(f.effect.d, 2) + ", 95 % CI [" + num(f.effect.d_low, 2) + ", " + num(f.effect.d_high, 2) +
      "]";
  if (out.paper_compared) {
    out.outcome = sig ? (primary->direction == "same as the paper" ? "reproduced" : "not reproduced") : "inconclusive";
    const std::string way = primary->direction == "same as the paper"       ? "the paper's way"
                            : primary->direction == "opposite to the paper" ? "the other way"
                                                                            : "neither way";
    out.headline = "The paper's fitness result (recurrent CPPNs fitter) is **" + out.outcome + "** " + at + ": " + ctl +
                   " " + num(f.control.mean, 2) + " ± " + num(f.control.se, 2) + ", " + exp + " " +
                   num(f.experimental.mean, 2) + " ± " + num(f.experimental.se, 2) + " (mean ± s.e.), " + test +
                   ", the estimate pointing " + way + (sig ? " significantly" : " without significance") +
                   "; the paper's p < 0.001 with 30 runs per regime implies |d| ≥ " + num(primary->paper_effect, 2) +
                   ", which this test detects with power " + num(primary->power, 2) + " at α = " + num(alpha, 2) +
                   ", and the interval " + (excludes_paper_effect(*primary) ? "excludes" : "does not exclude") +
                   " d = " + num(primary->paper_direction * primary->paper_effect, 2) + ".";
  } else {
    out.headline = "The paper did not compare " + ctl + " with " + exp +
                   " CPPNs; the primary test, best-so-far "
                   "fitness " +
                   at + ", is " + (sig ? "significant" : "not significant") + " at α = " + num(alpha, 2) + ": " + ctl +
                   " " + num(f.control.mean, 2) + " ± " + num(f.control.se, 2) + ", " + exp + " " +
                   num(f.experimental.mean, 2) + " ± " + num(f.experimental.se, 2) + " (mean ± s.e.), " + test + ".";
  }
  return out;
}

}  // namespace robozoo
