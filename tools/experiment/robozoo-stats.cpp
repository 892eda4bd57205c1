// robozoo-stats: the paper's figures from a folder of robozoo-evolve logs:
// Figure 1 (mean best-so-far fitness per generation, +-1 standard
// error), Figure 2 (body plans of the best-of-run robots), Figure 3 (their
// CPPNs), the champion-change analysis of section 4; for every compared
// statistic Student's and Welch's t-tests, Cohen's d with its confidence
// interval, Holm's correction over the secondary tests and the power at the
// paper's effect; CSV tables, gnuplot PNGs, zoo sheets (robozoo-render) and a
// Markdown report that puts each of the paper's claims beside robozoo's figure.
#include <CLI/CLI.hpp>

#include <iostream>

#include "study/analysis/read/results_agreement.hpp"
#include "study/analysis/sensitivity/sensitivity_job.hpp"
#include "study/analysis/stats_job.hpp"
#include "evolve/core/version.hpp"
#include "util/exit_status.hpp"
#include "study/experiment/trial_plan.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-stats: read every log (*.lcmlog) in DIR (e.g. a robozoo-experiment folder), compare two arms\n"
      "as the paper does (Figures 1-3, new champions of section 4): the primary test (best-so-far fitness at the\n"
      "last generation, Student's t at --alpha), the secondary tests under Holm's correction, Welch's t, Cohen's d\n"
      "with its 95 % CI and the power at the paper's effect; write CSV tables, gnuplot PNGs, zoo sheets and\n"
      "report.md into --out (default DIR/stats). A DIR without logs is read as a folder of compact results\n"
      "(*.results.json, robozoo-experiment's results/ folder): the same report, its zoo sheets re-grown and\n"
      "re-simulated from the results (each robot's fitness checked).\n"
      "--export-results OUT writes the compact results of DIR's logs into OUT instead of a report.\n"
      "--same-as OTHER checks that each trial whose compact result is in both DIR and OTHER (e.g. one run to\n"
      "generation 30, one to 60) agrees over the generations both hold, field for field, instead of a report:\n"
      "exit 0 when all agree, 1 at any difference (named: trial, generation, field) or when none is in both.\n"
      "--sensitivity REFERENCE reads DIR as a sensitivity study (DIR/<factor>/results/: one factor changed from\n"
      "REFERENCE's configuration, on REFERENCE's seeds) and writes, instead of the paper's report, each factor's\n"
      "gap (control minus experimental best-so-far fitness at --generation) beside REFERENCE's gap on the same\n"
      "seeds, Holm's correction across the factors, and the outcome shares (report.md, sensitivity*.csv; --out\n"
      "default DIR)."};
  StatsOptions o;
  bool no_plots = false, no_zoo = false;
  app.add_option("DIR", o.log_dir, "folder of the runs' logs, or of their compact results")->required();
  std::string export_dir;
  app.add_option("--export-results", export_dir,
                 "write one compact result (<log name>.results.json) per finished log of DIR into this folder "
                 "(with --include-unfinished: every log), and no report");
  std::string same_as;
  app.add_option("--same-as", same_as,
                 "compare DIR's compact results with OTHER's (a folder of compact results), and no report")
      ->excludes("--export-results");
  std::string sensitivity_of;
  app.add_option("--sensitivity", sensitivity_of,
                 "read DIR as a sensitivity study against REFERENCE (a folder of compact results), and write its "
                 "report")
      ->excludes("--export-results")
      ->excludes("--same-as");
  int generation = 0;
  app.add_option("--generation", generation,
                 "with --sensitivity: compare best-so-far fitness after this many generations (default: the "
                 "factors' runs' length)")
      ->check(CLI::PositiveNumber);
  app.add_option("--out,-o", o.out_dir, "output folder (default: DIR/stats)");
  app.add_flag("--include-unfinished", o.include_unfinished,
               "also use runs that did not reach their last generation (default: left out, and listed)");
  app.add_option("--ground-epsilon", o.analysis.morphology.ground_epsilon,
                 "a sphere touched the ground when centre z - radius <= this at a logged pose (m)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--topology-joints", o.analysis.changes.topology.joints,
               "count a changed hinge joint as a change of topology (default: the sphere tree alone)");
  bool all_changes = false;
  app.add_flag("--all-champion-changes", all_changes,
               "count every fitness gain as a new champion, also before the first simulated robot");
  app.add_option("--gnuplot", o.gnuplot, "the gnuplot program");
  app.add_flag("--no-plots", no_plots, "write the tables and the report without running gnuplot");
  app.add_option("--render", o.render, "the robozoo-render program (default: the one next to this program)");
  app.add_flag("--no-zoo", no_zoo, "do not make zoo sheets");
  app.add_option("--title", o.title, "title of the report");
  std::vector<std::string> compare = {"feedforward", "recurrent"};
  std::vector<std::string> arms;
  for (int a = 0; a < kNumArms; ++a) arms.push_back(arm_name(static_cast<Arm>(a)));
  std::string arm_list;
  for (const auto& a : arms) arm_list += (arm_list.empty() ? "" : ", ") + a;
  app.add_option(
         "--compare", compare,
         "the two arms to compare, control first: " + arm_list +
             " (robozoo-experiment --arms); runs of other arms are listed, their fitness compared with the control's")
      ->delimiter(',')
      ->expected(2)
      ->check(CLI::IsMember(arms))
      ->capture_default_str();
  app.add_option("--alpha", o.alpha, "significance level of the primary test and of Holm's family (the paper: 0.05)")
      ->check(CLI::Range(1e-6, 0.5))
      ->capture_default_str();
  app.add_option("--note", o.notes, "a paragraph for the top of the report (repeatable)");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-stats")) return *stop;
  if (compare.size() != 2 || compare[0] == compare[1]) {
    std::cerr << "robozoo-stats: --compare needs two different arms, e.g. feedforward,recurrent-sparse\n";
    return 2;
  }
  o.control_arm = compare[0];
  o.experimental_arm = compare[1];
  o.plots = !no_plots;
  o.zoo = !no_zoo;
  o.analysis.changes.simulated_only = !all_changes;
  if (generation != 0 && sensitivity_of.empty()) {
    std::cerr << "robozoo-stats: --generation belongs to --sensitivity\n";
    return 2;
  }
  if (!sensitivity_of.empty()) {
    return exit_status_of("robozoo-stats", [&] {
      SensitivityOptions s;
      s.factors_dir = o.log_dir;
      s.reference_dir = sensitivity_of;
      s.out_dir = o.out_dir;
      s.generation = generation;
      s.alpha = o.alpha;
      s.control_arm = o.control_arm;
      s.experimental_arm = o.experimental_arm;
      if (app.count("--title") > 0) s.title = o.title;
      s.notes = o.notes;
      s.plots = o.plots;
      s.gnuplot = o.gnuplot;
      const SensitivityOutcome r = run_sensitivity(s, std::cerr);
      std::cerr << "robozoo-stats: " << r.analysis.factors.size() << " factors compared at generation "
                << r.analysis.params.generation;
      if (!r.waiting.empty()) std::cerr << ", " << r.waiting.size() << " without results yet";
      for (const std::string& f : factors_with_fewer_runs(r.analysis)) std::cerr << "; fewer runs: " << f;
      std::cerr << "\n  wrote";
      for (const auto& f : r.files) std::cerr << " " << f;
      std::cerr << "\n  in " << r.out_dir << "\n";
      return 0;
    });
  }
  if (!same_as.empty()) {
    return exit_status_of("robozoo-stats", [&] {
      const FolderAgreement f = compare_results_folders(o.log_dir, same_as);
      print_agreement(f, o.log_dir, same_as, std::cout);
      return f.agree() ? 0 : 1;
    });
  }
  if (!export_dir.empty()) {
    return exit_status_of("robozoo-stats", [&] {
      std::vector<std::string> skipped;
      const auto written = export_results(o.log_dir, export_dir, o.include_unfinished, std::cerr, skipped);
      std::cerr << "robozoo-stats: wrote " << written.size() << " compact results into " << export_dir;
      if (!skipped.empty()) std::cerr << "; " << skipped.size() << " logs left out";
      std::cerr << "\n";
      return written.empty() ? 1 : 0;
    });
  }
  return exit_status_of("robozoo-stats", [&] {
    std::cerr << "robozoo-stats: reading " << o.log_dir << "\n";
    const StatsOutcome r = run_stats(o, std::cerr);
    std::cerr << "robozoo-stats: " << r.analysis.control.size() << " " << arm_title(r.analysis.control_arm) << " and "
              << r.analysis.experimental.size() << " " << arm_title(r.analysis.experimental_arm) << " runs";
    if (!r.skipped.empty()) std::cerr << ", " << r.skipped.size() << " left out (listed in the report)";
    std::cerr << "\n  wrote";
    for (const auto& f : r.files) std::cerr << " " << f;
    std::cerr << "\n  in " << r.out_dir << "\n";
    return 0;
  });
}
