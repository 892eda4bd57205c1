#pragma once
// The compact results of one run: what the experiment's statistics need from
// its log, small enough to commit (a few tens of kB per run where the log holds
// tens or hundreds of MB), one JSON file per run (<run id>.results.json).
//
// A compact result is a RunSummary reduced to what analyze_run() reads
// (compact_summary): every generation record; every generation's champion
// with its fitness, r, d, outcome, species and the shape of its sphere tree
// (parents, hinge joints: the champion-change analysis); the best-of-run
// champion in full (its genome in the genome JSON format of robozoo-evolve
// eval --genome, its spheres' radii and sensors, the lowest centre height of
// each sphere in its pose stream); the run's identity and resolved
// configuration; and robozoo-evolve's wall time from the checkpoint. The
// statistics read logs through the same reduction, so a folder of logs and
// the folder of their compact results give the same report.
//
// Format (version 1): {"format": "robozoo-run-results", "version": 1,
//  "run": {run_id, software_version, seed, regime, population, generations,
//          steps, dt, config (object; a string when the log's text is not JSON)},
//  "max_d", "undecodable", "truncated", "evolve_seconds" (null: no checkpoint),
//  "generations": {generation, best_fitness, mean_fitness, stderr_fitness,
//                  best_so_far_fitness, evaluations, champion_id, num_species,
//                  compatibility_threshold: one array each, one entry per
//                  generation; outcomes: one array of 6 counts per generation},
//  "champions": [{generation, genome_id, species_id, fitness, r_term, d_term,
//                 outcome, parents (null: morphology not logged), joints
//                 ("0"/"1" per sphere)}],
//  "best": null or {generation, genome (genome JSON), radius, sensors (per
//           sphere), min_center_z (null: no pose stream)}}.
// A double that is not finite is written as the string "nan", "inf" or "-inf".
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/record/run_summary.hpp"

namespace robozoo {

struct RunResults {
  RunSummary run;  ///< compact (compact_summary)
  bool has_evolve_seconds = false;
  double evolve_seconds = 0;  ///< robozoo-evolve's wall time from the run's checkpoint (s)
};

inline constexpr const char* kRunResultsFormat = "robozoo-run-results";
inline constexpr int kRunResultsVersion = 1;
inline constexpr const char* kRunResultsExtension = ".results.json";

/// `full` reduced to what analyze_run() reads: analyze_run gives the same
/// result on both, for any AnalysisParams.
RunSummary compact_summary(const RunSummary& full);

nlohmann::json run_results_to_json(const RunResults& r);
/// Checks every key, type, count and cross-reference; throws
/// std::invalid_argument naming `path` and the first problem.
RunResults run_results_from_json(const nlohmann::json& j, const std::string& path);
/// The same from the file's text (invalid JSON too).
RunResults run_results_from_text(const std::string& text, const std::string& path);

/// Writes atomically (temporary file, rename). std::runtime_error when it cannot.
void write_run_results(const std::string& path, const RunResults& r);
/// std::runtime_error for an unreadable file, std::invalid_argument for bad content; both name `path`.
RunResults read_run_results(const std::string& path);

}  // namespace robozoo
