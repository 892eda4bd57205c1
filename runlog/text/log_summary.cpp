#include "runlog/text/log_summary.hpp"

#include <cstdio>
#include <set>
#include <sstream>

#include "runlog/read/message_collector.hpp"
#include "runlog/robots/selection.hpp"

namespace robozoo {

LogSummary summarize_log(const ScannedLog& log, const std::string& path) {
  LogSummary s;
  s.path = path;
  s.file_bytes = log.contents.file_bytes;
  s.events = static_cast<int64_t>(log.contents.records.size());
  CollectorOptions co;
  co.keep_poses = false;
  MessageCollector collector(co);
  for (const LogRecord& r : log.contents.records) {
    ChannelCount& c = s.channels[r.channel];
    ++c.messages;
    c.bytes += static_cast<int64_t>(r.data.size());
    collector.ingest(r.channel, r.data.data(), r.data.size(), path);
  }
  collector.close_open_streams();
  for (const LogDamage& d : log.damage) s.damage.push_back(d.describe());
  s.bad_messages = collector.stats().rejected();
  s.problems = collector.stats().problems;
  for (const auto& run : collector.runs()) {
    RunSummaryLine l;
    l.run_id = run->run.run_id;
    l.regime = run->run.regime == 1 ? "recurrent" : "feedforward";
    l.software_version = run->run.software_version;
    l.seed = run->run.seed;
    l.population = run->run.population;
    l.generations_requested = run->run.generations;
    l.steps = run->run.steps;
    l.generations = static_cast<int64_t>(run->generations.size());
    if (!run->generations.empty()) {
      l.first_generation = run->generations.front().generation;
      l.last_generation = run->generations.back().generation;
    }
    std::set<uint64_t> genes;
    for (const Pick& p : champions(*run)) {
      genes.insert(gene_hash(p.genome->genome));
      if (l.best_genome < 0 || p.genome->genome.fitness > l.best_fitness) {
        l.best_genome = p.genome->genome.genome_id;
        l.best_generation = p.genome->genome.generation;
        l.best_fitness = p.genome->genome.fitness;
      }
    }
    l.champions = static_cast<int64_t>(genes.size());
    for (const auto& g : run->genomes) l.pose_streams += g->pose_count > 0;
    s.runs.push_back(l);
  }
  return s;
}

std::string format_summary(const LogSummary& s) {
  std::ostringstream o;
  o << s.path << ": " << s.events << " messages, " << s.file_bytes << " bytes\n";
  o << "channels:\n";
  for (const auto& [name, c] : s.channels) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-20s %8lld messages %12lld bytes\n", name.c_str(),
                  static_cast<long long>(c.messages), static_cast<long long>(c.bytes));
    o << line;
  }
  for (const RunSummaryLine& r : s.runs) {
    o << "run " << r.run_id << ": " << r.regime << ", seed " << r.seed << ", version " << r.software_version
      << ", population " << r.population << ", " << r.steps << " steps\n";
    o << "  generations: " << r.generations << " of " << r.generations_requested;
    if (r.generations > 0) o << " (" << r.first_generation << " to " << r.last_generation << ")";
    o << "\n  champions: " << r.champions << " distinct, " << r.pose_streams << " with a pose stream\n";
    if (r.best_genome >= 0) {
      char best[120];
      std::snprintf(best, sizeof best, "  best: genome %lld of generation %d, fitness %.4f\n",
                    static_cast<long long>(r.best_genome), r.best_generation, r.best_fitness);
      o << best;
    }
  }
  if (s.runs.empty()) o << "no ROBOZOO_RUN: not a robozoo-evolve log\n";
  for (const std::string& d : s.damage) o << "damage: " << d << "\n";
  if (s.bad_messages > 0) {
    o << "bad messages: " << s.bad_messages << " (skipped)\n";
    for (const std::string& p : s.problems) o << "  " << p << "\n";
  }
  return o.str();
}

nlohmann::json to_json(const LogSummary& s) {
  nlohmann::json channels = nlohmann::json::object(), runs = nlohmann::json::array();
  for (const auto& [name, c] : s.channels) channels[name] = {{"messages", c.messages}, {"bytes", c.bytes}};
  for (const RunSummaryLine& r : s.runs)
    runs.push_back(
        {{"run_id", r.run_id},
         {"regime", r.regime},
         {"seed", r.seed},
         {"software_version", r.software_version},
         {"population", r.population},
         {"generations_requested", r.generations_requested},
         {"steps", r.steps},
         {"generations", r.generations},
         {"first_generation", r.first_generation},
         {"last_generation", r.last_generation},
         {"champions", r.champions},
         {"pose_streams", r.pose_streams},
         {"best", {{"genome_id", r.best_genome}, {"generation", r.best_generation}, {"fitness", r.best_fitness}}}});
  return {{"path", s.path}, {"file_bytes", s.file_bytes}, {"messages", s.events},           {"channels", channels},
          {"runs", runs},   {"damage", s.damage},         {"bad_messages", s.bad_messages}, {"problems", s.problems}};
}

}  // namespace robozoo
