#pragma once
// Robots from compact results (robozoo-experiment's *.results.json, and the
// trials in progress of its portable checkpoints, *.portable-checkpoint, whose
// compact result of the finished generations gives the champion so far): each
// result's best-of-run champion grown and simulated again by this build in
// memory (evolve/run/champion_log's replay_champion: no log is written), its fitness checked
// against the committed one, as the run record that zoo sheets and videos draw
// from a log.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/scene/robot_card.hpp"
#include "runlog/read/run_record.hpp"
#include "evolve/record/run_results.hpp"

namespace robozoo::render {

/// True when `path` names compact results: a *.results.json or
/// *.portable-checkpoint file, or a folder.
bool is_results_path(const std::string& path);

/// The compact result files that `paths` name: files as given, folders' own
/// *.results.json and *.portable-checkpoint in name order (seeds as numbers);
/// a folder with neither gives its logs (*.lcmlog: a running experiment's
/// folder of trials). Throws std::invalid_argument for a path that is none of
/// these, or for a folder without one.
std::vector<std::string> results_files(const std::vector<std::string>& paths);

/// Reads every file, a portable checkpoint as the compact result it carries and
/// a log as its compact result so far; each result's run.path is its file, so
/// that a replay's errors name it. Throws std::invalid_argument or
/// std::runtime_error naming the first file that cannot be read, except with
/// `left_out`: then a log that cannot be read (a trial's log is empty until its
/// first generation is evaluated) and a result without a champion are left
/// out, each added to `left_out` as "file: why". One run found in two files
/// (the same run id, version and configuration, generations requested aside:
/// a trial's portable checkpoint beside its finished result) counts once, from
/// the file with more generations; the other is left out (noted in `left_out`).
std::vector<RunResults> read_results(const std::vector<std::string>& files,
                                     std::vector<std::string>* left_out = nullptr);

/// One result's best-of-run robot, grown and simulated again.
struct ResultRobot {
  std::string file;    ///< the compact result
  std::string run_id;  ///< e.g. feedforward-s7
  std::string arm;     ///< the experiment arm
  int64_t seed = 0;
  int32_t generations = 0;  ///< generations in its result (count)
  int32_t planned = 0;      ///< generations its run was started for (count): more while in progress
  RunRecord record;         ///< one run, one complete champion (with its poses when asked)
  const GenomeRecord& champion() const { return *record.genomes.front(); }
};

/// Replays each result's champion, `jobs` at once (0: one per core; the same
/// robots for any number), with its pose stream when `poses`. `progress` (may
/// be empty) gets (done, total). Throws, before anything is returned, when a
/// result has no champion or this build does not reproduce its fitness; the
/// message names the trial's file.
std::vector<ResultRobot> result_robots(const std::vector<RunResults>& results, bool poses, int jobs,
                                       const std::function<void(size_t, size_t)>& progress = {});

/// The robot's card with Figure 4's caption: "arm · seed S" (with "· G of N
/// generations" while in progress), then "fitness F · N spheres · J joints".
RobotCard result_card(const ResultRobot& robot);

/// Spheres and hinge joints of a morphology (counts).
int sphere_count(const morphology_t& m);
int joint_count(const morphology_t& m);

/// Order of a zoo sheet: by arm (first appearance in `results`), then by
/// committed best-of-run fitness, best first, then by seed. Indices into `results`.
std::vector<size_t> figure_order(const std::vector<RunResults>& results);

/// The index of the result whose best-of-run fitness ranks `which` ("best",
/// "median": rank ceil(n/2) of n, best first; "worst"). Throws
/// std::invalid_argument for another word or no result with a champion.
size_t pick_result(const std::vector<RunResults>& results, const std::string& which);

}  // namespace robozoo::render
