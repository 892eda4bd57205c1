#include "study/analysis/stats_job.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "study/analysis/figures/csv_writer.hpp"
#include "study/analysis/figures/experiment_tables.hpp"
#include "study/analysis/figures/gnuplot_runner.hpp"
#include "study/analysis/figures/plot_scripts.hpp"
#include "study/analysis/read/log_results.hpp"
#include "study/analysis/report/report.hpp"
#include "study/analysis/report/reproduce_commands.hpp"
#include "util/run_program.hpp"
#include "study/experiment/progress_estimate.hpp"
#include "util/program_path.hpp"
#include "util/shell_word.hpp"

namespace fs = std::filesystem;

namespace robozoo {

bool natural_less(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      size_t ie = i, je = j;
      while (ie < a.size() && digit(a[ie])) ++ie;
      while (je < b.size() && digit(b[je])) ++je;
      // Compare without leading zeros: first by length, then digit by digit.
      size_t is = i, js = j;
      while (is + 1 < ie && a[is] == '0') ++is;
      while (js + 1 < je && b[js] == '0') ++js;
      if (ie - is != je - js) return ie - is < je - js;
      const int c = a.compare(is, ie - is, b, js, je - js);
      if (c != 0) return c < 0;
      if (ie - i != je - j) return ie - i < je - j;  // "s01" after "s1": still a strict order
      i = ie;
      j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

namespace {

std::vector<std::string> list_ending(const std::string& dir, const std::string& ending) {
  if (!fs::is_directory(dir)) throw std::invalid_argument(dir + " is not a folder");
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.size() > ending.size() &&
        name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
      out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end(), natural_less);
  return out;
}

}  // namespace

std::vector<std::string> list_logs(const std::string& dir) { return list_ending(dir, ".lcmlog"); }

std::vector<std::string> list_results(const std::string& dir) { return list_ending(dir, kRunResultsExtension); }

std::vector<std::string> export_results(const std::string& log_dir, const std::string& out_dir, bool include_unfinished,
                                        std::ostream& progress, std::vector<std::string>& skipped) {
  const std::vector<std::string> logs = list_logs(log_dir);
  if (logs.empty()) throw std::invalid_argument("no *.lcmlog in " + log_dir);
  fs::create_directories(out_dir);
  std::vector<std::string> written;
  for (const auto& path : logs) {
    const std::string name = fs::path(path).filename().string();
    RunResults r;
    try {
      r = results_from_log(path);
    } catch (const std::exception& e) {
      skipped.push_back(name + ": " + e.what());
      progress << "  " << name << ": skipped: " << e.what() << "\n";
      continue;
    }
    if (!r.run.complete() && !include_unfinished) {
      skipped.push_back(name + ": unfinished (" + std::to_string(r.run.generations.size()) + " of " +
                        std::to_string(r.run.generations_requested) + " generations)");
      progress << "  " << name << ": unfinished, skipped\n";
      continue;
    }
    const std::string out = (fs::path(out_dir) / results_file_name(path)).string();
    write_run_results(out, r);
    progress << "  " << name << " -> " << out << " (" << fs::file_size(out) << " bytes)\n";
    written.push_back(out);
  }
  return written;
}

std::string results_file_name(const std::string& log_path) {
  return fs::path(log_path).stem().string() + kRunResultsExtension;
}

namespace {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  f.close();
  if (!f) throw std::runtime_error("cannot write " + path);
}

/// What robozoo-stats read from a folder of logs or compact results.
struct RunsRead {
  std::vector<RunAnalysis> runs;
  bool from_results = false;                                     ///< compact results, not logs
  std::map<std::string, std::vector<std::string>> per_arm_logs;  ///< logs (or compact results) by arm
  std::set<std::tuple<int32_t, int32_t, int32_t>> sizes;         ///< population, generations, steps
  double evolve_seconds = 0;                                     ///< robozoo-evolve's wall time (s)
  int with_checkpoint = 0;                                       ///< runs that know it (count)
};

/// Reads and analyses every run of the folder; a run that cannot be used is
/// left out, with why, in `skipped`. Throws std::invalid_argument when the
/// folder holds no run, or no usable one.
RunsRead read_runs(const StatsOptions& o, std::vector<std::string>& skipped, std::ostream& progress) {
  // A folder of logs, or else a folder of compact results (robozoo-experiment's
  // results/, or robozoo-stats --export-results): both read through compact_summary.
  std::vector<std::string> logs = list_logs(o.log_dir);
  const bool from_results = logs.empty();
  if (from_results) logs = list_results(o.log_dir);
  if (logs.empty())
    throw std::invalid_argument("no *.lcmlog in " + o.log_dir + " (nor compact results, *" +
                                std::string(kRunResultsExtension) + ")");
  RunsRead r;
  r.from_results = from_results;
  for (const auto& path : logs) {
    const std::string name = fs::path(path).filename().string();
    RunAnalysis a;
    RunResults results;
    try {
      results = from_results ? read_run_results(path) : results_from_log(path);
      const RunSummary& s = results.run;
      if (!s.complete() && !o.include_unfinished) {
        skipped.push_back(name + ": unfinished (" + std::to_string(s.generations.size()) + " of " +
                          std::to_string(s.generations_requested) + " generations)");
        progress << "  " << name << ": unfinished, skipped\n";
        continue;
      }
      a = analyze_run(s, o.analysis);
    } catch (const std::exception& e) {
      skipped.push_back(name + ": " + e.what());
      progress << "  " << name << ": skipped: " << e.what() << "\n";
      continue;
    }
    progress << "  " << name << ": " << arm_title(a.arm) << " seed " << a.seed << ", " << a.best_so_far.size()
             << " generations, best " << (a.best_so_far.empty() ? 0.0 : a.best_so_far.back()) << "\n";
    r.sizes.insert({a.population, a.generations_requested, a.steps});
    r.per_arm_logs[a.arm].push_back(path);
    if (results.has_evolve_seconds) {
      r.evolve_seconds += results.evolve_seconds;
      ++r.with_checkpoint;
    }
    r.runs.push_back(std::move(a));
  }
  if (r.runs.empty()) throw std::invalid_argument("no usable run in " + o.log_dir);
  return r;
}

/// Records `name` among the files written and gives its path in the output folder.
std::string output_file(StatsOutcome& out, const std::string& name) {
  out.files.push_back(name);
  return (fs::path(out.out_dir) / name).string();
}

/// The CSV tables.
void write_tables(const StatsOptions& o, StatsOutcome& out) {
  const ExperimentAnalysis& A = out.analysis;
  auto file = [&out](const std::string& name) { return output_file(out, name); };
  fitness_curve_table(A).write(file("fitness_curve.csv"));
  comparison_table(A.fitness, A.control_arm, A.experimental_arm).write(file("fitness.csv"));
  comparison_table(A.morphology, A.control_arm, A.experimental_arm).write(file("morphology.csv"));
  comparison_table(A.genotype, A.control_arm, A.experimental_arm).write(file("genotype.csv"));
  comparison_table(A.champion, A.control_arm, A.experimental_arm).write(file("champion_changes.csv"));
  outcome_shares_table(A).write(file("outcome_shares.csv"));
  champion_change_table(A).write(file("champion_change_events.csv"));
  runs_table(A).write(file("runs.csv"));
  claims_table(assess_claims(A, o.alpha)).write(file("claims.csv"));
}

/// The report's text: its data paragraph and its notes.
ReportInputs report_text(const StatsOptions& o, const StatsOutcome& out, const RunsRead& r) {
  const ExperimentAnalysis& A = out.analysis;
  const std::string ctl = arm_title(A.control_arm), exp = arm_title(A.experimental_arm);
  const auto& sizes = r.sizes;
  const double evolve_seconds = r.evolve_seconds;
  const int with_checkpoint = r.with_checkpoint;
  ReportInputs rep;
  rep.title = o.title;
  rep.alpha = o.alpha;
  rep.source = o.log_dir;
  rep.preamble = o.notes;
  {
    std::string p = "Data: " + std::to_string(A.control.size()) + " " + ctl + " and " +
                    std::to_string(A.experimental.size()) + " " + exp + " runs";
    for (const auto& [pop, gens, steps] : sizes)
      p += "; population " + std::to_string(pop) + ", " + std::to_string(gens) + " generations, " +
           std::to_string(steps) + " steps per evaluation";
    p += " (the paper: 30 runs per regime, population 150, 500 generations, 2,500 steps).";
    if (with_checkpoint > 0)
      p += " robozoo-evolve spent " + format_duration(evolve_seconds) + " of wall time on the " +
           std::to_string(with_checkpoint) + " runs with a checkpoint.";
    rep.preamble.insert(rep.preamble.begin(), p);
  }
  if (sizes.size() > 1) rep.notes.push_back("The runs do not all have the same sizes: compare with care.");
  if (!A.other.empty())
    rep.notes.push_back(std::to_string(A.other.size()) +
                        " runs of other arms are in the folder: only their "
                        "fitness is compared, against the control, under Figure 1 (robozoo-stats --compare chooses "
                        "the two arms of the full comparison).");
  for (const auto* side : {&A.control, &A.experimental})
    if (!side->empty() && side->front().target_distance > 0) rep.target_distance = side->front().target_distance;
  for (const auto& s : out.skipped) rep.notes.push_back("Left out: " + s);
  rep.notes.push_back(
      "Best-of-run robot: the champion with the highest fitness in a run (the earliest, among equals). Leaves: "
      "spheres other than the root with no child. Radius variance: within a robot, divided by the number of "
      "spheres. Depth: parent links from the root. A sphere touched the ground when its centre height minus its "
      "radius was at most " +
      csv_number(o.analysis.morphology.ground_epsilon) +
      " m at some pose of the champion's logged pose stream (every k-th step of its simulation).");
  rep.notes.push_back(
      "CPPN links are the enabled link genes; a forward link goes from a node at a lower drawing position to one at "
      "a higher (HyperNEAT's definition, docs/method.md section 2.2), every other one is recurrent; links on a "
      "directed cycle of the expressed network are counted apart.");
  rep.notes.push_back(std::string("New champion: a generation whose champion is fitter than the previous "
                                  "generation's") +
                      (o.analysis.changes.simulated_only ? ", both champions simulated (gains of the r term before "
                                                           "the first simulation are left out)"
                                                         : ", every fitness gain counted") +
                      ". Topology: the sphere tree as a rooted unordered tree (sorted nested parentheses)" +
                      (o.analysis.changes.topology.joints ? ", hinge joints included" : ", joints not included") +
                      ". Pooled statistics put every new champion of every run of an arm together (described, not "
                      "tested); the tested champion statistics take one value per run.");
  return rep;
}

/// The figures (gnuplot), put in the report. Throws std::runtime_error when gnuplot cannot run.
void make_plots(const StatsOptions& o, StatsOutcome& out, ReportInputs& rep) {
  const ExperimentAnalysis& A = out.analysis;
  const std::string ctl = arm_title(A.control_arm), exp = arm_title(A.experimental_arm);
  auto file = [&out](const std::string& name) { return output_file(out, name); };
  if (!gnuplot_available(o.gnuplot))
    throw std::runtime_error("cannot run " + o.gnuplot +
                             " with the pngcairo terminal (install gnuplot-nox), "
                             "or use --no-plots");
  auto plot = [&](const std::string& stem, const std::string& script_text) {
    const std::string gp = file(stem + ".gp");
    write_text(gp, script_text);
    // gnuplot runs in the output folder so that the scripts name their PNG relatively.
    run_gnuplot(stem + ".gp", o.gnuplot, out.out_dir);
    out.files.push_back(stem + ".png");
    return stem + ".png";
  };
  PlotStyle labels;
  labels.control_label = ctl;
  labels.experimental_label = exp;
  PlotStyle wide = labels;
  wide.width = 1500;
  wide.height = 1050;
  rep.fitness_png =
      plot("fig1_fitness", fitness_curve_script(A.fitness_curve, "fig1_fitness.png",
                                                "Figure 1: mean best-so-far fitness, ± 1 s.e.", labels, o.alpha));
  rep.morphology_png =
      plot("fig2_morphology",
           comparison_panels_script(A.morphology, "fig2_morphology.png",
                                    "Figure 2: best-of-run robots (mean ± 1 s.e.; white " + ctl + ", red " + exp + ")",
                                    4, wide));
  PlotStyle mid = labels;
  mid.width = 1500;
  mid.height = 750;
  rep.genotype_png = plot(
      "fig3_genotype",
      comparison_panels_script(A.genotype, "fig3_genotype.png", "Figure 3: best-of-run CPPNs (mean ± 1 s.e.)", 4, mid));
  rep.champion_png = plot(
      "champion_changes",
      comparison_panels_script(A.champion, "champion_changes.png", "Section 4: new champions (mean ± 1 s.e.)", 3, mid));
  for (const auto* side : {&A.control, &A.experimental}) {
    if (side->empty()) continue;
    const std::string arm = side == &A.control ? A.control_arm : A.experimental_arm;
    rep.outcome_pngs.push_back(
        plot("outcomes-" + arm,
             outcome_shares_script(mean_outcome_shares(*side), "outcomes-" + arm + ".png",
                                   "Outcome shares per generation: " + arm_title(arm) + " CPPNs", labels)));
  }
}

/// The zoo sheets (robozoo-render zoo of each compared arm's best-of-run robots), put in the report.
void make_zoo_sheets(const StatsOptions& o, const RunsRead& r, StatsOutcome& out, ReportInputs& rep,
                     std::ostream& progress) {
  const ExperimentAnalysis& A = out.analysis;
  const bool from_results = r.from_results;
  std::string render = o.render;
  if (render.empty()) {
    try {
      render = program_dir() + "/robozoo-render";
    } catch (const std::exception&) {
      render = "robozoo-render";
    }
  }
  for (const std::string& arm : {A.control_arm, A.experimental_arm}) {
    ZooSheet z;
    z.regime = arm_title(arm);
    const auto it = r.per_arm_logs.find(arm);
    const std::vector<std::string> regime_logs = it == r.per_arm_logs.end() ? std::vector<std::string>{} : it->second;
    if (!o.zoo) {
      z.note = "not made (--no-zoo)";
    } else if (regime_logs.empty()) {
      z.note = "no run";
    } else if (!is_executable(render)) {
      // A path inside the current folder is shown relative to it (the report may be committed).
      std::error_code ec;
      const fs::path rel = fs::relative(render, fs::current_path(), ec);
      const std::string shown = !ec && !rel.empty() && rel.string().rfind("..", 0) != 0 ? rel.string() : render;
      z.note = "robozoo-render is missing (looked for " + shown + "), so no zoo sheet was made";
    } else {
      const std::string png = "zoo-" + arm + ".png";
      std::vector<std::string> argv = {render, "zoo"};
      argv.insert(argv.end(), regime_logs.begin(), regime_logs.end());
      argv.insert(argv.end(), {"-o", (fs::path(out.out_dir) / png).string()});
      // Compact results hold only the best-of-run robot, grown and simulated again and checked
      // against its committed fitness; drawn at one scale and without the ground's grid (whose
      // texture triples a committed sheet's size).
      if (from_results)
        argv.insert(argv.end(), {"--same-scale", "--no-grid", "--quiet"});
      else
        argv.push_back("--best-of-run");
      progress << "  rendering the " << z.regime << " zoo sheet\n";
      const ProgramResult res = run_program(argv);
      if (res.status == 0 && fs::exists(fs::path(out.out_dir) / png)) {
        z.file = png;
        z.note =
            "best-of-run robots of the " + std::to_string(regime_logs.size()) + " runs (robozoo-render zoo " +
            (from_results ? "RESULTS... --same-scale --no-grid: each re-grown and re-simulated, its fitness checked)"
                          : "... --best-of-run)");
        out.files.push_back(png);
      } else {
        z.note = "robozoo-render failed (exit status " + std::to_string(res.status) + "): " + res.output.substr(0, 300);
      }
    }
    rep.zoo.push_back(z);
  }
}

/// The robozoo-stats command that makes this report again (its files, in the same folder).
std::string stats_command(const StatsOptions& o, const ExperimentAnalysis& A) {
  std::string stats = "build/bin/robozoo-stats " + o.log_dir + " --compare " + A.control_arm + "," + A.experimental_arm;
  if (o.include_unfinished) stats += " --include-unfinished";
  if (o.analysis.morphology.ground_epsilon != AnalysisParams{}.morphology.ground_epsilon)
    stats += " --ground-epsilon " + csv_number(o.analysis.morphology.ground_epsilon);
  if (o.analysis.changes.topology.joints) stats += " --topology-joints";
  if (!o.analysis.changes.simulated_only) stats += " --all-champion-changes";
  if (o.alpha != 0.05) stats += " --alpha " + csv_number(o.alpha);
  // What else shapes the files: where they go, and the report's own words.
  if (!o.out_dir.empty()) stats += " --out " + shell_word(o.out_dir);
  if (!o.plots) stats += " --no-plots";
  if (!o.zoo) stats += " --no-zoo";
  if (o.title != StatsOptions{}.title) stats += " --title " + shell_word(o.title);
  for (const auto& note : o.notes) stats += " --note " + shell_word(note);
  return stats;
}

}  // namespace

StatsOutcome run_stats(const StatsOptions& o, std::ostream& progress) {
  StatsOutcome out;
  out.out_dir = o.out_dir.empty() ? (fs::path(o.log_dir) / "stats").string() : o.out_dir;
  RunsRead r = read_runs(o, out.skipped, progress);
  out.analysis = analyze_experiment(std::move(r.runs), o.control_arm, o.experimental_arm);
  const ExperimentAnalysis& A = out.analysis;
  if (A.control.empty() && A.experimental.empty())
    throw std::invalid_argument("no run of the arms " + o.control_arm + " and " + o.experimental_arm + " in " +
                                o.log_dir);
  fs::create_directories(out.out_dir);
  write_tables(o, out);
  ReportInputs rep = report_text(o, out, r);
  if (o.plots) make_plots(o, out, rep);
  make_zoo_sheets(o, r, out, rep, progress);
  rep.commands = reproduce_commands(A, o.log_dir, stats_command(o, A));
  rep.analysis = A;
  write_text(output_file(out, "report.md"), markdown_report(rep));
  return out;
}

}  // namespace robozoo
