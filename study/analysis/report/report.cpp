#include "study/analysis/report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "study/analysis/report/claim_verdicts.hpp"
#include "study/analysis/compare/holm.hpp"

namespace robozoo {

namespace {

std::string fmt(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Digits after the point so that about three significant digits show.
int digits_for(double v) {
  const double a = std::fabs(v);
  if (a == 0 || !std::isfinite(a)) return 2;
  if (a >= 100) return 1;
  if (a >= 1) return 2;
  return std::min(6, 2 + static_cast<int>(std::ceil(-std::log10(a))));
}

std::string t_cell(const TTestResult& r) {
  if (std::isnan(r.t)) return "—";
  const std::string t = std::isfinite(r.t) ? fmt(r.t, 2) : (r.t > 0 ? "inf" : "-inf");
  const std::string df = std::isnan(r.df)                            ? "n/a"
                         : std::fabs(r.df - std::round(r.df)) < 1e-9 ? fmt(r.df, 0)
                                                                     : fmt(r.df, 1);
  return t + ", " + df + ", " + format_p(r.p);
}

std::string d_cell(const EffectSize& e) {
  if (std::isnan(e.d)) return "—";
  std::string s = fmt(e.d, 2);
  if (std::isfinite(e.d_low)) s += " [" + fmt(e.d_low, 2) + ", " + fmt(e.d_high, 2) + "]";
  return s;
}

std::string value_cell(const SampleStats& s, const std::string& unit) {
  const double k = unit == "share" ? 100.0 : 1.0;
  return format_mean_se(s, k) + (unit == "share" ? " %" : "") + " (" + std::to_string(s.n) + ")";
}

// "censored: 10 of 10 feed-forward and 7 of 10 recurrent best-of-run robots at max_spheres (50)".
std::string censor_note(const Comparison& c, const ExperimentAnalysis& a) {
  if (c.control_at_cap < 0) return "";
  int32_t cap = 0;
  for (const auto* side : {&a.control, &a.experimental})
    for (const auto& r : *side) cap = std::max(cap, r.max_spheres);
  return "censored: " + std::to_string(c.control_at_cap) + " of " + std::to_string(c.control.n) + " " +
         arm_title(a.control_arm) + " and " + std::to_string(c.experimental_at_cap) + " of " +
         std::to_string(c.experimental.n) + " " + arm_title(a.experimental_arm) + " best-of-run robots at max_spheres" +
         (cap > 0 ? " (" + std::to_string(cap) + ")" : std::string());
}

std::string label_cell(const Comparison& c, const ExperimentAnalysis& a) {
  const std::string note = censor_note(c, a);
  return note.empty() ? c.label : c.label + " (" + note + ")";
}

void comparison_table(std::ostringstream& s, const std::vector<Comparison>& list, const ExperimentAnalysis& a) {
  s << "| statistic | unit | " << arm_title(a.control_arm) << " (mean ± s.e., n) | " << arm_title(a.experimental_arm)
    << " (mean ± s.e., n) | Student's t, df, p | Welch's t, df, p | Cohen's d [95 % CI] |  |\n"
    << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : list) {
    s << "| " << label_cell(c, a) << " | " << (c.unit == "share" ? "%" : c.unit) << " | "
      << value_cell(c.control, c.unit) << " | " << value_cell(c.experimental, c.unit) << " | ";
    if (c.samples == Samples::PooledEvents)
      s << "— | — | — | pooled events: descriptive |\n";
    else
      s << t_cell(c.student) << " | " << t_cell(c.welch) << " | " << d_cell(c.effect) << " | " << c.stars << " |\n";
  }
  s << "\n";
}

std::string power_cell(const ClaimRow& r) {
  if (std::isnan(r.power)) return "none";
  // The paper's effect with its sign in this comparison's direction (no '|' inside a table cell).
  return fmt(r.power, 2) + " (at d = " + fmt(r.paper_direction * r.paper_effect, 2) + ")";
}

void claims_table(std::ostringstream& s, const ClaimsAssessment& claims, const ExperimentAnalysis& a) {
  const std::string ctl = arm_title(a.control_arm), exp = arm_title(a.experimental_arm);
  if (claims.paper_compared) {
    s << "| statistic | the paper (recurrent vs feed-forward) | " << ctl << " (mean ± s.e., n) | " << exp
      << " (mean ± s.e., n) | Cohen's d [95 % CI] | Student's p | Holm's p | power at the paper's effect | "
         "direction | verdict |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n";
  } else {
    s << "| statistic | " << ctl << " (mean ± s.e., n) | " << exp
      << " (mean ± s.e., n) | Cohen's d [95 % CI] | Student's p | Holm's p | verdict |\n"
      << "|---|---|---|---|---|---|---|\n";
  }
  for (const auto& r : claims.rows) {
    if (r.role == ClaimRole::Descriptive) continue;
    const Comparison& c = r.comparison;
    const std::string label = (r.role == ClaimRole::Primary ? "**primary:** " : "") + label_cell(c, a);
    const std::string holm = r.role == ClaimRole::Secondary ? format_p(r.holm_p) : "—";
    s << "| " << label << " | ";
    if (claims.paper_compared) s << r.paper << " | ";
    s << value_cell(c.control, c.unit) << " | " << value_cell(c.experimental, c.unit) << " | " << d_cell(c.effect)
      << " | " << format_p(c.student.p) << " | " << holm << " | ";
    if (claims.paper_compared) s << power_cell(r) << " | " << (r.direction.empty() ? "—" : r.direction) << " | ";
    s << r.verdict << " |\n";
  }
  s << "\n";
}

// Each other arm's best-of-run fitness against the control: a family of its own under Holm.
void other_arms_table(std::ostringstream& s, const ExperimentAnalysis& a, double alpha) {
  if (a.other_arms.empty() || a.control.empty()) return;
  std::vector<double> p;
  for (const auto& o : a.other_arms) p.push_back(o.fitness.student.p);
  const std::vector<double> q = holm_adjust(p);
  s << "### Other arms against the control\n\n"
    << "Best-so-far fitness at the last generation of every other arm in the folder against "
    << arm_title(a.control_arm) << ": secondary tests, one family under Holm's correction at α = " << fmt(alpha, 2)
    << " (not the primary test; `--compare` makes a full report of any pair).\n\n"
    << "| arm | " << arm_title(a.control_arm)
    << " (mean ± s.e., n) | arm (mean ± s.e., n) | Student's t, df, p | Welch's t, df, p | Cohen's d [95 % CI] | "
       "Holm's p | the paper |\n|---|---|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < a.other_arms.size(); ++i) {
    const Comparison& c = a.other_arms[i].fitness;
    const int orient = paper_orientation(a.control_arm, a.other_arms[i].arm);
    std::string paper = "not compared by the paper";
    if (orient != 0) {
      paper = "recurrent fitter";
      if (std::isfinite(c.effect.d) && c.effect.d != 0 && !std::isnan(q[i]))
        paper += std::string("; here the ") + ((c.effect.d > 0) == (orient > 0) ? "same" : "other") + " way, " +
                 (q[i] < alpha ? "significant" : "not significant") + " after Holm";
    }
    s << "| " << arm_title(a.other_arms[i].arm) << " | " << value_cell(c.control, c.unit) << " | "
      << value_cell(c.experimental, c.unit) << " | " << t_cell(c.student) << " | " << t_cell(c.welch) << " | "
      << d_cell(c.effect) << " | " << format_p(q[i]) << " | " << paper << " |\n";
  }
  s << "\n";
}

std::string generation_list(const std::vector<CurvePoint>& curve, double alpha) {
  std::vector<int32_t> g;
  for (const auto& p : curve)
    if (p.student.p < alpha) g.push_back(p.generation);
  if (g.empty()) return "none";
  // Runs of consecutive generations as ranges: "3-7, 9".
  std::string out;
  for (size_t i = 0; i < g.size();) {
    size_t j = i;
    while (j + 1 < g.size() && g[j + 1] == g[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += std::to_string(g[i]) + (j > i ? "-" + std::to_string(g[j]) : "");
    i = j + 1;
  }
  return out;
}

}  // namespace

std::string format_mean_se(const SampleStats& s, double scale) {
  if (s.n == 0) return "n/a";
  const double m = s.mean * scale, se = s.se * scale;
  const int d = digits_for(std::max(std::fabs(m), se));
  return fmt(m, d) + " ± " + fmt(se, d);
}

std::string format_number(double v) {
  if (std::isnan(v)) return "n/a";
  return fmt(v, digits_for(v));
}

std::string format_p(double p) {
  if (std::isnan(p)) return "n/a";
  if (p < 0.001) return "< 0.001";
  return fmt(p, 3);
}

std::string markdown_report(const ReportInputs& in) {
  const ExperimentAnalysis& a = in.analysis;
  const ClaimsAssessment claims = assess_claims(a, in.alpha);
  const std::string ctl = arm_title(a.control_arm), exp = arm_title(a.experimental_arm);
  std::ostringstream s;
  s << "# " << in.title << "\n\n";
  s << claims.headline << "\n\n";
  if (!in.source.empty()) s << "Logs: `" << in.source << "`.\n\n";
  for (const auto& p : in.preamble) s << p << "\n\n";

  s << "## The tests, fixed before the data\n\n"
    << "- **Primary test**: best-so-far fitness at the last generation, " << ctl << " (control) against " << exp
    << " (experimental), Student's two-sample t-test at α = " << fmt(in.alpha, 2)
    << ", as the paper (SciPy's `ttest_ind`, its footnote 4). Welch's t-test (unequal variances) is shown beside "
       "every Student's test.\n"
    << "- **Secondary tests**: the other " << claims.family_size
    << " statistics whose samples are runs, one family under Holm's correction (family-wise error at most α); "
       "their verdicts come from Holm's adjusted p. Not in the family: statistics true by construction for these "
       "arms (labelled), pooled champion events (descriptive: the events of a run are not independent) and the "
       "share of robots at max_spheres.\n"
    << "- Every t and d is " << exp << " minus " << ctl << " (positive: " << exp
    << " higher). Effect size: Cohen's d (the pooled s.d. of Student's test) with a 95 % confidence interval from "
       "inverting the noncentral t (exact under normality and equal variances); Hedges' g is in the CSV files.\n";
  if (claims.paper_compared)
    s << "- Power: of Student's test at α = " << fmt(in.alpha, 2)
      << " (unadjusted) with these runs, at the smallest |d| the paper's reported p implies with its 30 runs per "
         "regime (p < 0.001: |d| ≥ 0.90; \"significant\", p < 0.05: |d| ≥ 0.52); none where the paper reports no "
         "test or its samples are pooled events.\n";
  s << "- Counts bounded by the number of spheres are censored when a best-of-run robot reached "
       "growth.max_spheres; each says how many did.\n"
    << "- In the figures' tables, stars mark Student's unadjusted p as the paper's figures do (* < 0.05, "
       "** < 0.01, *** < 0.001); the verdicts use Holm's p.\n\n";

  s << "## The paper's claims beside robozoo's figures\n\n";
  if (!claims.paper_compared)
    s << "The paper compared feed-forward with recurrent CPPNs only; it says nothing about " << ctl << " against "
      << exp << ", so nothing here agrees or disagrees with it.\n\n";
  claims_table(s, claims, a);

  s << "## Figure 1: fitness\n\n";
  if (!in.fitness_png.empty()) s << "![Figure 1](" << in.fitness_png << ")\n\n";
  s << "Mean best-so-far fitness over the runs of each arm; dotted lines and shading: ± one standard error "
       "(`fitness_curve.csv`). Marked at the foot: generations where Student's t-test of that generation gives "
       "p < "
    << fmt(in.alpha, 2) << " (uncorrected, descriptive; the primary test is the last generation's): "
    << generation_list(a.fitness_curve, in.alpha) << ".\n\n";
  comparison_table(s, a.fitness, a);
  other_arms_table(s, a, in.alpha);

  s << "## Figure 2: body plans of the best-of-run robots\n\n";
  if (!in.morphology_png.empty()) s << "![Figure 2](" << in.morphology_png << ")\n\n";
  comparison_table(s, a.morphology, a);
  if (a.control_without_poses + a.experimental_without_poses > 0)
    s << "Best-of-run robots without a logged pose stream (never simulated; their ground statistics count as 0): "
      << a.control_without_poses << " " << arm_title(a.control_arm) << ", " << a.experimental_without_poses << " "
      << arm_title(a.experimental_arm) << ".\n\n";

  s << "## Figure 3: CPPNs of the best-of-run robots\n\n";
  if (!in.genotype_png.empty()) s << "![Figure 3](" << in.genotype_png << ")\n\n";
  comparison_table(s, a.genotype, a);

  s << "## Section 4: new champions\n\n";
  if (!in.champion_png.empty()) s << "![New champions](" << in.champion_png << ")\n\n";
  comparison_table(s, a.champion, a);
  s << "The per-run rows are tested: each run's share of new champions with a different topology, and its mean "
       "gain of each kind, is one sample (runs without such a new champion have none). The pooled rows put every new "
       "champion of every run of an arm together, as the paper's figures do; a run's events are not independent, "
       "so they are described, not tested.\n\n";

  s << "## Outcomes and reach\n\n";
  for (const auto& png : in.outcome_pngs) s << "![outcome shares](" << png << ")\n\n";
  s << "Share of each evaluation outcome per generation, averaged over the runs of each arm "
       "(`outcome_shares.csv`).\n\n";
  auto max_d = [](const std::vector<RunAnalysis>& side) {
    double d = 0;
    for (const auto& r : side) d = std::max(d, r.max_d);
    return d;
  };
  s << "Largest displacement towards the target (the fitness term d) any logged robot reached: "
    << fmt(max_d(a.control), 3) << " m (" << arm_title(a.control_arm) << "), " << fmt(max_d(a.experimental), 3)
    << " m (" << arm_title(a.experimental_arm) << ")";
  if (in.target_distance > 0)
    s << ", of the " << fmt(in.target_distance, 1) << " m from the start to the target: fitness did "
      << (std::max(max_d(a.control), max_d(a.experimental)) < 0.9 * in.target_distance ? "not " : "")
      << "come near its ceiling";
  s << ".\n\n";

  s << "## Figure 4: the zoo\n\n";
  for (const auto& z : in.zoo) {
    s << "**" << z.regime << "**";
    if (!z.note.empty()) s << ": " << z.note;
    s << "\n\n";
    if (!z.file.empty()) s << "![" << z.regime << " zoo](" << z.file << ")\n\n";
  }

  if (!in.notes.empty()) {
    s << "## Notes\n\n";
    for (const auto& n : in.notes) s << "- " << n << "\n";
    s << "\n";
  }
  if (!in.commands.empty()) {
    s << "## Reproduce\n\n```sh\n";
    for (const auto& c : in.commands) s << c << "\n";
    s << "```\n";
  }
  return s.str();
}

}  // namespace robozoo
