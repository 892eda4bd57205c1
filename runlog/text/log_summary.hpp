#pragma once
// robozoo-log summary: what a log holds, in one look: its channels (messages,
// bytes), its runs (id, regime, seed, software version, sizes), their
// generations, champions (distinct genes) and pose streams, the best champion,
// and what could not be used (damage, bad messages).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runlog/read/log_reader.hpp"

namespace robozoo {

struct ChannelCount {
  int64_t messages = 0;  ///< (count)
  int64_t bytes = 0;     ///< payload bytes (bytes)
};

struct RunSummaryLine {
  std::string run_id, regime, software_version;
  int64_t seed = 0;
  int32_t population = 0, generations_requested = 0, steps = 0;
  int32_t first_generation = -1, last_generation = -1;
  int64_t generations = 0;   ///< generation messages (count)
  int64_t champions = 0;     ///< distinct champions (count)
  int64_t pose_streams = 0;  ///< genomes with poses (count)
  int64_t best_genome = -1;  ///< the best champion's id
  int32_t best_generation = -1;
  double best_fitness = 0.0;
};

struct LogSummary {
  std::string path;
  int64_t file_bytes = 0, events = 0;
  std::map<std::string, ChannelCount> channels;
  std::vector<RunSummaryLine> runs;
  std::vector<std::string> damage;    ///< described
  int64_t bad_messages = 0;           ///< undecodable or inconsistent (count)
  std::vector<std::string> problems;  ///< the first few, described
};

LogSummary summarize_log(const ScannedLog& log, const std::string& path);
std::string format_summary(const LogSummary& s);
nlohmann::json to_json(const LogSummary& s);

}  // namespace robozoo
