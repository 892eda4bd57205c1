#include "study/analysis/sensitivity/sensitivity_job.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "evolve/record/checkpoint.hpp"
#include "study/analysis/figures/csv_writer.hpp"
#include "study/analysis/figures/gnuplot_runner.hpp"
#include "evolve/record/run_results.hpp"
#include "study/analysis/sensitivity/sensitivity_plot.hpp"
#include "study/analysis/sensitivity/sensitivity_report.hpp"
#include "study/analysis/stats_job.hpp"
#include "util/shell_word.hpp"

namespace fs = std::filesystem;

namespace robozoo {

namespace {

std::vector<RunSummary> read_folder(const std::string& dir, std::ostream& progress) {
  std::vector<RunSummary> runs;
  for (const std::string& path : list_results(dir)) runs.push_back(read_run_results(path).run);
  progress << "  " << dir << ": " << runs.size() << " compact results\n";
  return runs;
}

// The generation compared: the one asked for, else the factors' runs' common length.
int32_t generation_of(const SensitivityOptions& o, const std::vector<SensitivityFactor>& factors) {
  if (o.generation > 0) return o.generation;
  int32_t g = 0;
  std::string first;
  for (const auto& f : factors)
    for (const RunSummary& r : f.runs) {
      if (g == 0) {
        g = r.generations_requested;
        first = r.run_id;
      } else if (r.generations_requested != g) {
        throw std::invalid_argument("the factors' runs were asked for different generations (" + first + ": " +
                                    std::to_string(g) + ", " + r.run_id + ": " +
                                    std::to_string(r.generations_requested) + "): say which with --generation");
      }
    }
  if (g < 1) throw std::invalid_argument("the factors' runs say no generations: say which with --generation");
  return g;
}

std::string command_of(const SensitivityOptions& o, int32_t generation) {
  std::string c = "build/bin/robozoo-stats " + shell_word(o.factors_dir) + " --sensitivity " +
                  shell_word(o.reference_dir) + " --generation " + std::to_string(generation);
  if (o.control_arm != SensitivityOptions{}.control_arm || o.experimental_arm != SensitivityOptions{}.experimental_arm)
    c += " --compare " + o.control_arm + "," + o.experimental_arm;
  if (o.alpha != 0.05) c += " --alpha " + csv_number(o.alpha);
  if (!o.plots) c += " --no-plots";
  if (!o.out_dir.empty()) c += " --out " + shell_word(o.out_dir);
  if (o.title != SensitivityOptions{}.title) c += " --title " + shell_word(o.title);
  for (const auto& note : o.notes) c += " --note " + shell_word(note);
  return c;
}

}  // namespace

SensitivityOutcome run_sensitivity(const SensitivityOptions& o, std::ostream& progress) {
  if (!fs::is_directory(o.factors_dir)) throw std::invalid_argument(o.factors_dir + " is not a folder");
  SensitivityOutcome out;
  out.out_dir = o.out_dir.empty() ? o.factors_dir : o.out_dir;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(o.factors_dir))
    if (e.is_directory() && fs::is_directory(e.path() / "results")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  progress << "robozoo-stats: the sensitivity study in " << o.factors_dir << ", against " << o.reference_dir << "\n";
  std::vector<SensitivityFactor> factors;
  for (const std::string& name : names) {
    SensitivityFactor f{name, read_folder((fs::path(o.factors_dir) / name / "results").string(), progress)};
    if (f.runs.empty())
      out.waiting.push_back(name);
    else
      factors.push_back(std::move(f));
  }
  if (factors.empty())
    throw std::invalid_argument("no factor in " + o.factors_dir + " has compact results (<factor>/results/*" +
                                kRunResultsExtension + ")");
  const std::vector<RunSummary> reference = read_folder(o.reference_dir, progress);
  if (reference.empty()) throw std::invalid_argument("no compact results in the reference folder " + o.reference_dir);
  SensitivityParams params;
  params.generation = generation_of(o, factors);
  params.alpha = o.alpha;
  params.control_arm = o.control_arm;
  params.experimental_arm = o.experimental_arm;
  SensitivityReportInputs in;
  in.analysis = analyze_sensitivity(reference, factors, params);
  in.title = o.title;
  in.factors_dir = o.factors_dir;
  in.reference_dir = o.reference_dir;
  in.waiting = out.waiting;
  in.notes = o.notes;
  in.command = command_of(o, params.generation);
  if (o.plots && !gnuplot_available(o.gnuplot))
    throw std::runtime_error("cannot run " + o.gnuplot +
                             " with the pngcairo terminal (install gnuplot-nox), or use --no-plots");
  fs::create_directories(out.out_dir);
  if (o.plots) in.figure = "sensitivity.png";
  const std::pair<const char*, std::string> files[] = {
      {"sensitivity.csv", sensitivity_csv(in.analysis)},
      {"sensitivity_outcomes.csv", sensitivity_outcomes_csv(in.analysis)},
      {"sensitivity.gp",
       sensitivity_plot_script(in.analysis, "sensitivity.png",
                               "The gap at generation record " + std::to_string(params.generation - 1) +
                                   ", factor by factor, beside the reference's on the same seeds")},
      {"report.md", sensitivity_markdown(in)}};
  for (const auto& [name, text] : files) {
    write_file_atomic((fs::path(out.out_dir) / name).string(), text);
    out.files.push_back(name);
  }
  if (o.plots) {
    // gnuplot runs in the output folder: the script names its PNG relatively.
    run_gnuplot("sensitivity.gp", o.gnuplot, out.out_dir);
    out.files.push_back("sensitivity.png");
  }
  out.analysis = std::move(in.analysis);
  return out;
}

}  // namespace robozoo
