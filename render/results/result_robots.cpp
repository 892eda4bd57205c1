#include "render/results/result_robots.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "runlog/read/champion_record.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "study/analysis/stats_job.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace robozoo::render {

namespace fs = std::filesystem;

namespace {

constexpr const char* kLogExtension = ".lcmlog";

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

/// What makes two files the same run: its id, version and configuration but the generations
/// requested (a trial's portable checkpoint and its later finished result are one run).
std::string run_identity(const RunSummary& s) {
  std::string config = s.config_json;
  try {
    nlohmann::json c = nlohmann::json::parse(s.config_json);
    if (c.is_object()) c.erase("generations");
    config = c.dump();
  } catch (const nlohmann::json::exception&) {  // compared as written
  }
  return s.run_id + "\n" + s.software_version + "\n" + config;
}

double best_fitness(const RunResults& r) {
  const ChampionRecord* best = best_of_run(r.run);
  return best ? best->genome.fitness : -1e300;
}

}  // namespace

bool is_results_path(const std::string& path) {
  return ends_with(path, kRunResultsExtension) || ends_with(path, kPortableCheckpointExtension) ||
         fs::is_directory(path);
}

std::vector<std::string> results_files(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& p : paths) {
    if (fs::is_directory(p)) {
      std::vector<std::string> in = list_results(p);
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file() && ends_with(e.path().filename().string(), kPortableCheckpointExtension))
          in.push_back(e.path().string());
      // A running experiment's folder of logs: each log read as its trial's
      // compact result so far.
      if (in.empty()) in = list_logs(p);
      if (in.empty())
        throw std::invalid_argument(p + ": no compact results (*" + kRunResultsExtension +
                                    "), portable checkpoints (*" + kPortableCheckpointExtension +
                                    ") nor logs (*.lcmlog) in it");
      std::sort(in.begin(), in.end(), natural_less);
      out.insert(out.end(), in.begin(), in.end());
    } else if (ends_with(p, kRunResultsExtension) || ends_with(p, kPortableCheckpointExtension)) {
      out.push_back(p);
    } else {
      throw std::invalid_argument(p + ": neither a compact result (*" + kRunResultsExtension +
                                  "), a portable checkpoint (*" + kPortableCheckpointExtension +
                                  ") nor a folder of them");
    }
  }
  return out;
}

std::vector<RunResults> read_results(const std::vector<std::string>& files, std::vector<std::string>* left_out) {
  std::vector<RunResults> out;
  out.reserve(files.size());
  for (const std::string& f : files) {
    if (!ends_with(f, kLogExtension)) {
      out.push_back(read_results_or_portable_checkpoint(f));
    } else if (!left_out) {
      out.push_back(run_results_of_log(f));
    } else {
      // A trial's log while it runs: empty until its first generation is
      // evaluated, and perhaps unreadable for another reason, said with it.
      try {
        out.push_back(run_results_of_log(f));
      } catch (const std::exception& e) {
        left_out->push_back(f + ": " + e.what());
        continue;
      }
    }
    out.back().run.path = f;
    if (left_out && !best_of_run(out.back().run)) {
      left_out->push_back(f + ": no finished generation yet");
      out.pop_back();
    }
  }
  // One run in two files (a finished result and its trial's earlier portable checkpoint, say):
  // the file with more generations is the run, the first of equals.
  std::map<std::string, size_t> kept;  // run identity -> index in `out`
  std::vector<bool> drop(out.size(), false);
  for (size_t i = 0; i < out.size(); ++i) {
    const auto [it, fresh] = kept.emplace(run_identity(out[i].run), i);
    if (fresh) continue;
    const size_t j = it->second;
    const bool newer = out[i].run.generations.size() > out[j].run.generations.size();
    const size_t loser = newer ? j : i, winner = newer ? i : j;
    drop[loser] = true;
    if (newer) it->second = i;
    if (left_out)
      left_out->push_back(out[loser].run.path + ": the same run as " + out[winner].run.path + ", which holds " +
                          std::to_string(out[winner].run.generations.size()) + " generations");
  }
  std::vector<RunResults> unique;
  unique.reserve(out.size());
  for (size_t i = 0; i < out.size(); ++i)
    if (!drop[i]) unique.push_back(std::move(out[i]));
  return unique;
}

std::vector<ResultRobot> result_robots(const std::vector<RunResults>& results, bool poses, int jobs,
                                       const std::function<void(size_t, size_t)>& progress) {
  const std::vector<ChampionReplay> replays = replay_champions(results, poses, jobs, progress);
  std::vector<ResultRobot> out(results.size());
  for (size_t i = 0; i < results.size(); ++i) {
    const RunSummary& s = results[i].run;
    out[i].file = s.path;
    out[i].run_id = s.run_id;
    out[i].arm = s.arm;
    out[i].seed = s.seed;
    out[i].generations = static_cast<int32_t>(s.generations.size());
    out[i].planned = s.generations_requested;
    out[i].record = champion_run_record(replays[i], s.path);
  }
  return out;
}

int sphere_count(const morphology_t& m) { return static_cast<int>(m.spheres.size()); }

int joint_count(const morphology_t& m) {
  return static_cast<int>(
      std::count_if(m.spheres.begin(), m.spheres.end(), [](const sphere_t& s) { return s.has_joint; }));
}

RobotCard result_card(const ResultRobot& robot) {
  const GenomeRecord& g = robot.champion();
  RobotCard c = make_card(robot.record, g);
  const int spheres = sphere_count(g.morphology), joints = joint_count(g.morphology);
  char line[200];
  std::snprintf(line, sizeof line, "%s \u00b7 seed %lld", robot.arm.c_str(), static_cast<long long>(robot.seed));
  if (robot.generations < robot.planned)  // in progress: its champion so far
    std::snprintf(line + std::strlen(line), sizeof line - std::strlen(line), " \u00b7 %d of %d generations",
                  robot.generations, robot.planned);
  c.caption.push_back(line);
  std::snprintf(line, sizeof line, "fitness %.2f \u00b7 %d sphere%s \u00b7 %d joint%s", c.fitness, spheres,
                spheres == 1 ? "" : "s", joints, joints == 1 ? "" : "s");
  c.caption.push_back(line);
  return c;
}

std::vector<size_t> figure_order(const std::vector<RunResults>& results) {
  std::vector<std::string> arms;
  for (const RunResults& r : results)
    if (std::find(arms.begin(), arms.end(), r.run.arm) == arms.end()) arms.push_back(r.run.arm);
  auto arm_rank = [&](const RunResults& r) { return std::find(arms.begin(), arms.end(), r.run.arm) - arms.begin(); };
  std::vector<size_t> order(results.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const RunResults &x = results[a], &y = results[b];
    if (arm_rank(x) != arm_rank(y)) return arm_rank(x) < arm_rank(y);
    if (best_fitness(x) != best_fitness(y)) return best_fitness(x) > best_fitness(y);
    return x.run.seed < y.run.seed;
  });
  return order;
}

size_t pick_result(const std::vector<RunResults>& results, const std::string& which) {
  if (which != "best" && which != "median" && which != "worst")
    throw std::invalid_argument("--pick: best, median or worst, got '" + which + "'");
  std::vector<size_t> order;
  for (size_t i = 0; i < results.size(); ++i)
    if (best_of_run(results[i].run)) order.push_back(i);
  if (order.empty()) throw std::invalid_argument("no result has a best-of-run champion");
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (best_fitness(results[a]) != best_fitness(results[b]))
      return best_fitness(results[a]) > best_fitness(results[b]);
    return results[a].run.seed < results[b].run.seed;
  });
  if (which == "best") return order.front();
  if (which == "worst") return order.back();
  return order[(order.size() + 1) / 2 - 1];
}

}  // namespace robozoo::render
