#include "evolve/analysis/stats_job.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "evolve/analysis/csv_writer.hpp"
#include "evolve/analysis/experiment_tables.hpp"
#include "evolve/analysis/gnuplot_runner.hpp"
#include "evolve/analysis/plot_scripts.hpp"
#include "evolve/analysis/report.hpp"
#include "evolve/analysis/run_program.hpp"
#include "evolve/experiment/program_path.hpp"
#include "evolve/experiment/progress_estimate.hpp"
#include "evolve/run/checkpoint.hpp"

namespace fs = std::filesystem;

namespace robozoo {

namespace {

/// Name order with runs of digits compared as numbers ("s2" < "s10").
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

}  // namespace

std::vector<std::string> list_logs(const std::string& dir) {
  if (!fs::is_directory(dir)) throw std::invalid_argument(dir + " is not a folder");
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".lcmlog") out.push_back(e.path().string());
  std::sort(out.begin(), out.end(), natural_less);
  return out;
}

namespace {

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << text;
  f.close();
  if (!f) throw std::runtime_error("cannot write " + path);
}

std::string regime_title(int8_t r) { return r == 0 ? "feed-forward" : "recurrent"; }
std::string regime_file(int8_t r) { return r == 0 ? "feedforward" : "recurrent"; }

}  // namespace

StatsOutcome run_stats(const StatsOptions& o, std::ostream& progress) {
  StatsOutcome out;
  out.out_dir = o.out_dir.empty() ? (fs::path(o.log_dir) / "stats").string() : o.out_dir;
  const std::vector<std::string> logs = list_logs(o.log_dir);
  if (logs.empty()) throw std::invalid_argument("no *.lcmlog in " + o.log_dir);

  std::vector<RunAnalysis> runs;
  std::map<std::string, std::vector<std::string>> per_regime_logs;
  std::set<std::tuple<int32_t, int32_t, int32_t>> sizes;  // population, generations, steps
  double evolve_seconds = 0;
  int with_checkpoint = 0;
  for (const auto& path : logs) {
    const std::string name = fs::path(path).filename().string();
    RunAnalysis a;
    try {
      const RunSummary s = summarize_run_file(path);
      if (!s.complete() && !o.include_unfinished) {
        out.skipped.push_back(name + ": unfinished (" + std::to_string(s.generations.size()) + " of " +
                              std::to_string(s.generations_requested) + " generations)");
        progress << "  " << name << ": unfinished, skipped\n";
        continue;
      }
      a = analyze_run(s, o.analysis);
    } catch (const std::exception& e) {
      out.skipped.push_back(name + ": " + e.what());
      progress << "  " << name << ": skipped: " << e.what() << "\n";
      continue;
    }
    progress << "  " << name << ": " << regime_title(a.regime) << " seed " << a.seed << ", "
             << a.best_so_far.size() << " generations, best " << (a.best_so_far.empty() ? 0.0 : a.best_so_far.back())
             << "\n";
    sizes.insert({a.population, a.generations_requested, a.steps});
    per_regime_logs[regime_file(a.regime)].push_back(path);
    try {
      if (fs::exists(path + ".checkpoint")) {
        evolve_seconds += read_checkpoint(path + ".checkpoint").elapsed_seconds;
        ++with_checkpoint;
      }
    } catch (const std::exception&) {
      // The time is informative only.
    }
    runs.push_back(std::move(a));
  }
  if (runs.empty()) throw std::invalid_argument("no usable run in " + o.log_dir);
  out.analysis = analyze_experiment(std::move(runs));
  const ExperimentAnalysis& A = out.analysis;

  fs::create_directories(out.out_dir);
  auto file = [&out](const std::string& name) {
    out.files.push_back(name);
    return (fs::path(out.out_dir) / name).string();
  };
  fitness_curve_table(A).write(file("fitness_curve.csv"));
  comparison_table(A.fitness).write(file("fitness.csv"));
  comparison_table(A.morphology).write(file("morphology.csv"));
  comparison_table(A.genotype).write(file("genotype.csv"));
  comparison_table(A.champion).write(file("champion_changes.csv"));
  champion_change_table(A).write(file("champion_change_events.csv"));
  runs_table(A).write(file("runs.csv"));

  ReportInputs rep;
  rep.title = o.title;
  rep.source = o.log_dir;
  rep.preamble = o.notes;
  {
    std::string p = "Data: " + std::to_string(A.control.size()) + " feed-forward and " +
                    std::to_string(A.experimental.size()) + " recurrent runs";
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
  for (const auto& s : out.skipped) rep.notes.push_back("Left out: " + s);
  rep.notes.push_back(
      "Best-of-run robot: the champion with the highest fitness in a run (the earliest, among equals). Leaves: "
      "spheres other than the root with no child. Radius variance: within a robot, divided by the number of "
      "spheres. Depth: parent links from the root. A sphere touched the ground when its centre height minus its "
      "radius was at most " + csv_number(o.analysis.morphology.ground_epsilon) +
      " m at some pose of the champion's logged pose stream (every k-th step of its simulation).");
  rep.notes.push_back(
      "CPPN links are the enabled link genes; a forward link lies on no directed cycle of the expressed network.");
  rep.notes.push_back(std::string("New champion: a generation whose champion is fitter than the previous "
                                  "generation's") +
                      (o.analysis.changes.simulated_only ? ", both champions simulated (gains of the r term before "
                                                           "the first simulation are left out)"
                                                         : ", every fitness gain counted") +
                      ". Topology: the sphere tree as a rooted unordered tree (sorted nested parentheses)" +
                      (o.analysis.changes.topology.joints ? ", hinge joints included" : ", joints not included") +
                      ". Pooled statistics treat every new champion of every run of a regime as one sample.");

  if (o.plots) {
    if (!gnuplot_available(o.gnuplot))
      throw std::runtime_error("cannot run " + o.gnuplot + " with the pngcairo terminal (install gnuplot-nox), "
                               "or use --no-plots");
    auto plot = [&](const std::string& stem, const std::string& script_text) {
      const std::string gp = file(stem + ".gp");
      write_text(gp, script_text);
      // gnuplot runs in the output folder so that the scripts name their PNG relatively.
      run_gnuplot(stem + ".gp", o.gnuplot, out.out_dir);
      out.files.push_back(stem + ".png");
      return stem + ".png";
    };
    PlotStyle wide;
    wide.width = 1500;
    wide.height = 1050;
    rep.fitness_png = plot("fig1_fitness", fitness_curve_script(A.fitness_curve, "fig1_fitness.png",
                                                                "Figure 1: mean best-so-far fitness, ± 1 s.e."));
    rep.morphology_png = plot("fig2_morphology",
                              comparison_panels_script(A.morphology, "fig2_morphology.png",
                                                       "Figure 2: best-of-run robots (mean ± 1 s.e.; white "
                                                       "feed-forward, red recurrent)",
                                                       4, wide));
    PlotStyle mid;
    mid.width = 1500;
    mid.height = 750;
    rep.genotype_png = plot("fig3_genotype",
                            comparison_panels_script(A.genotype, "fig3_genotype.png",
                                                     "Figure 3: best-of-run CPPNs (mean ± 1 s.e.)", 4, mid));
    rep.champion_png = plot("champion_changes",
                            comparison_panels_script(A.champion, "champion_changes.png",
                                                     "Section 4: new champions (mean ± 1 s.e.)", 3, mid));
  }

  std::string render = o.render;
  if (render.empty()) {
    try {
      render = program_dir() + "/robozoo-render";
    } catch (const std::exception&) {
      render = "robozoo-render";
    }
  }
  for (int8_t r : {int8_t{0}, int8_t{1}}) {
    ZooSheet z;
    z.regime = regime_title(r);
    const auto& regime_logs = per_regime_logs[regime_file(r)];
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
      const std::string png = "zoo-" + regime_file(r) + ".png";
      std::vector<std::string> argv = {render, "zoo"};
      argv.insert(argv.end(), regime_logs.begin(), regime_logs.end());
      argv.insert(argv.end(), {"-o", (fs::path(out.out_dir) / png).string(), "--best-of-run"});
      progress << "  rendering the " << z.regime << " zoo sheet\n";
      const ProgramResult res = run_program(argv);
      if (res.status == 0 && fs::exists(fs::path(out.out_dir) / png)) {
        z.file = png;
        z.note = "best-of-run robots of the " + std::to_string(regime_logs.size()) + " runs (robozoo-render zoo " +
                 "... --best-of-run)";
        out.files.push_back(png);
      } else {
        z.note = "robozoo-render failed (exit status " + std::to_string(res.status) + "): " +
                 res.output.substr(0, 300);
      }
    }
    rep.zoo.push_back(z);
  }

  if (!sizes.empty()) {
    const auto& [pop, gens, steps] = *sizes.begin();
    const size_t trials = std::max(A.control.size(), A.experimental.size());
    rep.commands.push_back("# this experiment");
    rep.commands.push_back("build/bin/robozoo-experiment --trials " + std::to_string(trials) + " --generations " +
                           std::to_string(gens) + " --population " + std::to_string(pop) +
                           (steps != 2500 ? " --steps " + std::to_string(steps) : std::string()) + " --out " +
                           o.log_dir);
    rep.commands.push_back("build/bin/robozoo-stats " + o.log_dir);
    rep.commands.push_back("# the paper's full size (30 trials per regime, population 150, 500 generations), on a "
                           "bigger machine");
    rep.commands.push_back("build/bin/robozoo-experiment --trials 30 --generations 500 --population 150 --workers "
                           "$(nproc) --out runs/paper");
    rep.commands.push_back("build/bin/robozoo-stats runs/paper");
  }
  rep.analysis = A;
  write_text(file("report.md"), markdown_report(rep));
  return out;
}

}  // namespace robozoo
