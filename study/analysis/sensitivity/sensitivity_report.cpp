#include "study/analysis/sensitivity/sensitivity_report.hpp"

#include <cmath>
#include <sstream>

#include "study/analysis/figures/csv_writer.hpp"
#include "study/analysis/report/report.hpp"

namespace robozoo {

namespace {

// Outcome columns in the report's order: index into GenerationRecord::outcomes, or -1 for
// "simulated" (completed or stopped early).
struct OutcomeColumn {
  const char* name;
  int index;
};
constexpr OutcomeColumn kOutcomeColumns[] = {{"simulated", -1},
                                             {"acceleration fault", 3},
                                             {"rolling: ground contact", 4},
                                             {"rolling: spin", 5},
                                             {"not simulated", 0}};

int64_t column_count(const ArmOutcomes& o, const OutcomeColumn& c) {
  return c.index < 0 ? o.simulated() : o.counts[static_cast<size_t>(c.index)];
}

std::string seeds_text(const std::vector<int64_t>& seeds) {
  std::string s;
  for (int64_t v : seeds) s += (s.empty() ? "" : " ") + std::to_string(v);
  return s;
}

std::string interval(const MeanGap& g) {
  if (std::isnan(g.gap)) return "n/a";
  std::string s = format_number(g.gap);
  if (std::isfinite(g.low)) s += " [" + format_number(g.low) + ", " + format_number(g.high) + "]";
  return s;
}

std::string mean_cell(double mean, size_t n) {
  return n == 0 ? "n/a" : format_number(mean) + " (" + std::to_string(n) + ")";
}

std::string share(int64_t count, int64_t total) {
  if (total <= 0) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * static_cast<double>(count) / static_cast<double>(total));
  return buf;
}

std::string changes_cell(const std::vector<ConfigChange>& changes) {
  std::string s;
  for (const auto& c : changes) s += (s.empty() ? "" : "; ") + ("`" + c.key + "` " + c.from + " → " + c.to);
  return s.empty() ? "—" : s;
}

struct OutcomeRow {
  std::string factor, source, arm;
  const ArmOutcomes* o;
};

std::vector<OutcomeRow> outcome_rows(const SensitivityAnalysis& a) {
  std::vector<OutcomeRow> rows;
  for (const FactorResult& f : a.factors) {
    rows.push_back({f.name, "factor", a.params.control_arm, &f.control_outcomes});
    rows.push_back({f.name, "factor", a.params.experimental_arm, &f.experimental_outcomes});
    rows.push_back({f.name, "reference", a.params.control_arm, &f.reference_control_outcomes});
    rows.push_back({f.name, "reference", a.params.experimental_arm, &f.reference_experimental_outcomes});
  }
  return rows;
}

}  // namespace

std::string sensitivity_csv(const SensitivityAnalysis& a) {
  CsvWriter w({"factor",
               "changes",
               "generation",
               "control_arm",
               "experimental_arm",
               "control_seeds",
               "experimental_seeds",
               "control_mean",
               "experimental_mean",
               "gap",
               "gap_low",
               "gap_high",
               "gap_df",
               "student_p",
               "holm_p",
               "significant",
               "reference_control_mean",
               "reference_experimental_mean",
               "reference_gap",
               "reference_gap_low",
               "reference_gap_high",
               "reference_p",
               "difference",
               "difference_low",
               "difference_high",
               "difference_df",
               "level",
               "reading"});
  for (const FactorResult& f : a.factors) {
    w.add_row({f.name,
               describe_changes(f.changes),
               std::to_string(a.params.generation),
               a.params.control_arm,
               a.params.experimental_arm,
               seeds_text(f.control_seeds),
               seeds_text(f.experimental_seeds),
               csv_number(f.gap.mean_a),
               csv_number(f.gap.mean_b),
               csv_number(f.gap.gap),
               csv_number(f.gap.low),
               csv_number(f.gap.high),
               csv_number(f.gap.df),
               csv_number(f.gap.p),
               csv_number(f.holm_p),
               f.significant ? "1" : "0",
               csv_number(f.reference_gap.mean_a),
               csv_number(f.reference_gap.mean_b),
               csv_number(f.reference_gap.gap),
               csv_number(f.reference_gap.low),
               csv_number(f.reference_gap.high),
               csv_number(f.reference_gap.p),
               csv_number(f.difference.gap),
               csv_number(f.difference.low),
               csv_number(f.difference.high),
               csv_number(f.difference.df),
               csv_number(a.params.level),
               f.reading});
  }
  return w.str();
}

std::string sensitivity_outcomes_csv(const SensitivityAnalysis& a) {
  std::vector<std::string> header = {"factor", "source", "arm", "generation", "runs", "evaluations"};
  const char* names[] = {"not_simulated",      "completed",       "stopped_early",
                         "acceleration_fault", "rolling_contact", "rolling_spin"};
  for (const char* n : names) header.push_back(n);
  CsvWriter w(header);
  for (const OutcomeRow& r : outcome_rows(a)) {
    std::vector<std::string> row = {r.factor,
                                    r.source,
                                    r.arm,
                                    std::to_string(a.params.generation),
                                    std::to_string(r.o->runs),
                                    std::to_string(r.o->total())};
    for (int64_t c : r.o->counts) row.push_back(std::to_string(c));
    w.add_row(row);
  }
  return w.str();
}

std::string sensitivity_markdown(const SensitivityReportInputs& in) {
  const SensitivityAnalysis& a = in.analysis;
  const SensitivityParams& p = a.params;
  const int level = static_cast<int>(std::lround(100 * p.level));
  std::ostringstream md;
  md << "# " << in.title << "\n\n";
  for (const auto& note : in.notes) md << note << "\n\n";
  md << "Each factor's runs (`" << in.factors_dir << "/<factor>/results`) changed one thing from the reference's "
     << "configuration (`" << in.reference_dir << "`, robozoo "
     << (a.software_version.empty() ? "?" : a.software_version)
     << ") and ran the reference's seeds again. Compared: best-so-far fitness after " << p.generation
     << " generations (generation record " << p.generation - 1 << ", counted from 0), the **gap** " << p.control_arm
     << " mean minus " << p.experimental_arm << " mean (positive: " << p.control_arm << " fitter), with its " << level
     << " % interval from Student's pooled-variance t; beside it the reference's "
     << "own gap on the same seeds at the same generation. The factors' tests (gap = 0) are **secondary**: a family of "
     << "their own under Holm's correction at α = " << csv_number(p.alpha)
     << ", apart from the reference's primary test (in the reference's own report), and the reference is not a "
     << "member. The difference of the "
     << "two gaps has a Welch-Satterthwaite interval that treats them as independent samples: descriptive, not a "
     << "test. A factor whose interval holds both 0 and the reference's gap is inconclusive.\n\n";
  md << "## The gap, factor by factor\n\n";
  md << "| factor | the change | " << p.control_arm << " (mean, runs) | " << p.experimental_arm
     << " (mean, runs) | gap [" << level << " % CI] | Student's p | Holm's p | the reference's gap, same seeds ["
     << level << " % CI] | difference of gaps [" << level << " % CI] | reading |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FactorResult& f : a.factors) {
    md << "| " << f.name << " | " << changes_cell(f.changes) << " | " << mean_cell(f.gap.mean_a, f.gap.n_a) << " | "
       << mean_cell(f.gap.mean_b, f.gap.n_b) << " | " << interval(f.gap) << " | " << format_p(f.gap.p) << " | "
       << format_p(f.holm_p) << " | " << interval(f.reference_gap) << " | " << interval(f.difference) << " | "
       << f.reading << " |\n";
  }
  if (a.factors.empty()) md << "| (none yet) | | | | | | | | | |\n";
  md << "\n";
  if (!in.figure.empty())
    md << "![Each factor's gap (filled) with its " << level << " % interval, and the reference's on the same seeds "
       << "(open) below it; the dashed line is no gap](" << in.figure << ")\n\n";
  for (const FactorResult& f : a.factors)
    md << "- " << f.name << ": seeds " << p.control_arm << " " << seeds_text(f.control_seeds) << "; "
       << p.experimental_arm << " " << seeds_text(f.experimental_seeds) << ".\n";
  if (!in.waiting.empty()) {
    md << "- Factors without results yet:";
    for (const auto& w : in.waiting) md << " " << w;
    md << ".\n";
  }
  const std::vector<std::string> short_factors = factors_with_fewer_runs(a);
  if (!short_factors.empty()) {
    md << "- **Fewer runs than the other factors** (still running, or trials missing; compared on the seeds it has):";
    for (size_t i = 0; i < short_factors.size(); ++i) md << (i == 0 ? " " : "; ") << short_factors[i];
    md << ".\n";
  }
  md << "\n## What the evaluations of generation record " << p.generation - 1 << " came to\n\n";
  md << "Shares of the generation's evaluations, pooled over the runs; *simulated* counts the robots that "
     << "completed their steps or stopped early at rest; the others were disqualified (acceleration fault, "
     << "rolling by ground contact or by spin) or never reached the simulator.\n\n";
  md << "| factor | runs of | arm | runs | evaluations |";
  for (const auto& c : kOutcomeColumns) md << " " << c.name << " |";
  md << "\n|---|---|---|---|---|";
  for (size_t i = 0; i < std::size(kOutcomeColumns); ++i) md << "---|";
  md << "\n";
  for (const OutcomeRow& r : outcome_rows(a)) {
    md << "| " << r.factor << " | " << (r.source == "factor" ? "the factor" : "the reference") << " | " << r.arm
       << " | " << r.o->runs << " | " << r.o->total() << " |";
    for (const auto& c : kOutcomeColumns) md << " " << share(column_count(*r.o, c), r.o->total()) << " |";
    md << "\n";
  }
  md << "\nThe same as numbers: `sensitivity.csv` and `sensitivity_outcomes.csv`.\n\n";
  md << "## Reproduce\n\n```sh\n" << in.command << "\n```\n";
  return md.str();
}

}  // namespace robozoo
