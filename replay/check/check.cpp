#include "replay/check/check.hpp"

#include <chrono>
#include <map>
#include <stdexcept>

#include "evolve/core/wall_time.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "replay/log/log_structure.hpp"
#include "replay/log/logged_config.hpp"

namespace robozoo::replay {

CheckReport check_log(const ScannedLog& scanned, const CheckOptions& options, const CheckProgress& progress) {
  if (!(options.tolerance >= 0.0)) throw std::invalid_argument("--tolerance must be >= 0");
  const auto t0 = std::chrono::steady_clock::now();
  const LogContents& log = scanned.contents;
  CheckReport report;
  report.tolerance = options.tolerance;
  report.forced = options.force;
  report.events = static_cast<int64_t>(log.records.size());
  report.file_bytes = log.file_bytes;
  for (const auto& d : scanned.damage) report.input_problems.push_back({-1, -1, "", d.describe()});

  const LogIndex index = index_log(log);
  report.foreign_events = static_cast<int64_t>(index.foreign_events);
  report.input_problems.insert(report.input_problems.end(), index.problems.begin(), index.problems.end());

  // Every ROBOZOO_RUN: its configuration, once per distinct message.
  std::map<size_t, RunConfig> config_of_event;
  std::map<std::string, RunConfig> parsed;  // config_json -> configuration
  for (size_t e : index.run_events) {
    run_t m{};
    const auto& r = log.records[index.events[e].record];
    safe_decode(r.data.data(), r.data.size(), m);  // the index decoded it already
    bool known = false;
    for (const auto& info : report.runs) known = known || info.run_id == m.run_id;
    if (!known)
      report.runs.push_back({m.run_id, m.software_version, m.seed, m.regime == 1 ? "recurrent" : "feedforward",
                             m.population, m.generations});
    if (report.fatal.empty()) {
      const std::string refusal = version_refusal(m);
      if (!refusal.empty() && !options.force) report.fatal = refusal;
    }
    auto it = parsed.find(m.config_json);
    if (it == parsed.end()) {
      try {
        it = parsed.emplace(m.config_json, config_from_run_message(m)).first;
      } catch (const std::invalid_argument& err) {
        if (report.fatal.empty()) report.fatal = err.what();
        continue;
      }
    }
    config_of_event[e] = it->second;
  }
  if (report.fatal.empty() && log.records.empty()) report.fatal = "the log holds no event";
  if (report.fatal.empty() && index.run_events.empty())
    report.fatal = "the log holds no ROBOZOO_RUN, so the configuration of its run is unknown";
  if (report.fatal.empty() && index.genomes.empty()) report.fatal = "the log holds no ROBOZOO_GENOME: nothing to check";
  if (!report.fatal.empty()) {
    report.seconds = seconds_since(t0);
    return report;
  }

  // The order, counts and figures of every message; which champions owe a trajectory.
  std::map<std::string, RunConfig> config_of_run;
  for (const auto& [event, config] : config_of_event) config_of_run.emplace(index.events[event].run_id, config);
  StructureReport structure = check_log_structure(log, index, config_of_run, log.truncated);
  report.structure = std::move(structure.differences);
  report.generations_proved = structure.generations;
  report.input_problems.insert(report.input_problems.end(), structure.incomplete.begin(), structure.incomplete.end());

  const auto todo = index.to_check(options.all_genomes);
  ChampionCheckParams params;
  params.tolerance = options.tolerance;
  params.keep = options.keep;
  RecomputeCache cache;
  for (size_t i = 0; i < todo.size(); ++i) {
    const LoggedGenome& g = *todo[i];
    const auto config =
        g.run_event >= 0 ? config_of_event.find(static_cast<size_t>(g.run_event)) : config_of_event.end();
    if (config == config_of_event.end()) {
      ChampionResult c;
      c.status = ChampionResult::Status::Unusable;
      c.run_id = g.run_id;
      c.generation = g.generation;
      c.genome_id = g.genome_id;
      c.champion = g.champion;
      c.problems.push_back("no ROBOZOO_RUN of run " + g.run_id + " before it, so its configuration is unknown");
      report.champions.push_back(std::move(c));
    } else {
      const auto rule = structure.trajectory.find(g.genome_event);
      report.champions.push_back(
          check_champion(log, index, g, config->second, params, &cache,
                         rule == structure.trajectory.end() ? TrajectoryRule::MayBeCut : rule->second));
    }
    if (progress) progress(i + 1, todo.size());
  }
  report.seconds = seconds_since(t0);
  return report;
}

CheckReport check_log_file(const std::string& path, const CheckOptions& options, const CheckProgress& progress) {
  ScannedLog scanned;
  try {
    scanned = scan_event_log(path);
  } catch (const std::exception& e) {
    CheckReport r;
    r.log_path = path;
    r.tolerance = options.tolerance;
    r.forced = options.force;
    r.fatal = e.what();
    return r;
  }
  CheckReport r = check_log(scanned, options, progress);
  r.log_path = path;
  return r;
}

}  // namespace robozoo::replay
