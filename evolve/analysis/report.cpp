#include "evolve/analysis/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "evolve/analysis/paper_claims.hpp"

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

const std::vector<Comparison>& group_list(const ExperimentAnalysis& a, ClaimGroup g) {
  switch (g) {
    case ClaimGroup::Fitness: return a.fitness;
    case ClaimGroup::Morphology: return a.morphology;
    case ClaimGroup::Genotype: return a.genotype;
    case ClaimGroup::Champion: return a.champion;
  }
  return a.fitness;
}

// Whether robozoo's comparison goes the paper's way. Only a significant
// difference (p < 0.05) can agree or disagree; anything else cannot decide.
std::string agreement(const PaperClaim& claim, const Comparison& c) {
  if (claim.direction == 2) return "—";
  if (c.control.n < 2 || c.experimental.n < 2 || std::isnan(c.test.p)) return "too few data";
  if (!(c.test.p < 0.05)) return "inconclusive (p ≥ 0.05)";
  const double diff = c.experimental.mean - c.control.mean;
  if (claim.direction == 0) return "no: robozoo finds a significant difference";
  if (diff == 0) return "no: no difference";
  const bool same_way = claim.direction > 0 ? diff > 0 : diff < 0;
  if (!same_way) return "no: significant, the other way";
  return claim.significant ? "yes, significant" : "yes, significant (the paper: not significant)";
}

void comparison_table(std::ostringstream& s, const std::vector<Comparison>& list, const ExperimentAnalysis& a) {
  s << "| statistic | unit | " << arm_title(a.control_arm) << " (mean ± s.e., n) | " << arm_title(a.experimental_arm)
    << " (mean ± s.e., n) | t | p |  |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (const auto& c : list) {
    const double k = c.unit == "share" ? 100.0 : 1.0;
    s << "| " << c.label << " | " << (c.unit == "share" ? "%" : c.unit) << " | " << format_mean_se(c.control, k)
      << " (" << c.control.n << ") | " << format_mean_se(c.experimental, k) << " (" << c.experimental.n << ") | "
      << (std::isfinite(c.test.t) ? fmt(c.test.t, 2) : std::string(std::isnan(c.test.t) ? "n/a" : "inf")) << " | "
      << format_p(c.test.p) << " | " << c.stars << " |\n";
  }
  s << "\n";
}

}  // namespace

std::string format_mean_se(const SampleStats& s, double scale) {
  if (s.n == 0) return "n/a";
  const double m = s.mean * scale, se = s.se * scale;
  const int d = digits_for(std::max(std::fabs(m), se));
  return fmt(m, d) + " ± " + fmt(se, d);
}

std::string format_p(double p) {
  if (std::isnan(p)) return "n/a";
  if (p < 0.001) return "< 0.001";
  return fmt(p, 3);
}

std::string markdown_report(const ReportInputs& in) {
  const ExperimentAnalysis& a = in.analysis;
  std::ostringstream s;
  s << "# " << in.title << "\n\n";
  if (!in.source.empty()) s << "Logs: `" << in.source << "`.\n\n";
  for (const auto& p : in.preamble) s << p << "\n\n";
  s << "Control: " << arm_title(a.control_arm) << " CPPNs, " << a.control.size() << " runs; experimental: "
    << arm_title(a.experimental_arm) << " CPPNs, " << a.experimental.size() << " runs. Every p-value is Student's two-sample t-test with equal variances "
    << "(SciPy's `ttest_ind`, as in the paper; t distribution from Boost.Math): * p < 0.05, ** p < 0.01, "
    << "*** p < 0.001.\n\n";

  s << "## The paper's claims beside robozoo's figures\n\n"
    << "| statistic | paper (Auerbach & Bongard) | robozoo " << arm_title(a.control_arm) << " | robozoo "
    << arm_title(a.experimental_arm) << " | p | robozoo agrees |\n"
    << "|---|---|---|---|---|---|\n";
  for (const auto& claim : paper_claims()) {
    const Comparison* c = find_comparison(group_list(a, claim.group), claim.key);
    if (!c) continue;
    const double k = c->unit == "share" ? 100.0 : 1.0;
    const std::string unit = c->unit == "share" ? " %" : "";
    s << "| " << c->label << " | " << claim.paper << " | " << format_mean_se(c->control, k) << unit << " | "
      << format_mean_se(c->experimental, k) << unit << " | " << format_p(c->test.p) << " " << c->stars << " | "
      << agreement(claim, *c) << " |\n";
  }
  s << "\n";

  s << "## Figure 1: fitness\n\n";
  if (!in.fitness_png.empty()) s << "![Figure 1](" << in.fitness_png << ")\n\n";
  s << "Mean best-so-far fitness over the runs of each regime; dotted lines and shading: ± one standard error "
       "(`fitness_curve.csv`).\n\n";
  comparison_table(s, a.fitness, a);

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

  s << "## Outcomes and reach\n\n";
  for (const auto& png : in.outcome_pngs) s << "![outcome shares](" << png << ")\n\n";
  s << "Share of each evaluation outcome per generation, averaged over the runs of each arm "
       "(`outcome_shares.csv`).\n\n";
  auto max_d = [](const std::vector<RunAnalysis>& side) {
    double d = 0;
    for (const auto& r : side) d = std::max(d, r.max_d);
    return d;
  };
  s << "Largest d (displacement towards the target) any logged robot reached: " << fmt(max_d(a.control), 3)
    << " m (" << arm_title(a.control_arm) << "), " << fmt(max_d(a.experimental), 3) << " m ("
    << arm_title(a.experimental_arm) << ")";
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
