#pragma once
// The report of `robozoo-replay check`: one line per champion and a summary as
// text, the same as JSON, and the exit status.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "replay/check/champion_check.hpp"
#include "replay/log/log_structure.hpp"
#include "runlog/read/log_index.hpp"

namespace robozoo::replay {

struct RunInfo {
  std::string run_id;
  std::string software_version;
  int64_t seed = 0;
  std::string regime;  ///< "feedforward" / "recurrent"
  int32_t population = 0;
  int32_t generations = 0;
};

struct CheckReport {
  std::string log_path;
  double tolerance = 0.0;      ///< 0: bit for bit
  bool forced = false;         ///< --force: another software version accepted
  int64_t events = 0;          ///< events read (count)
  int64_t foreign_events = 0;  ///< events of other channels, ignored (count)
  int64_t file_bytes = 0;      ///< (bytes)
  std::vector<RunInfo> runs;   ///< distinct runs, in log order
  std::vector<ChampionResult> champions;
  std::vector<LogDifference> structure;      ///< messages out of place, missing, extra, or with wrong figures
  int32_t generations_proved = 0;            ///< generation_t messages whose place and figures were checked (count)
  std::vector<InputProblem> input_problems;  ///< damage, unusable events, a last generation cut short
  std::string fatal;                         ///< not empty: the log could not be checked at all
  double seconds = 0.0;                      ///< wall time of the check (s)

  int64_t count(ChampionResult::Status s) const;
  /// 0: every champion matches, every message is where and what it should be,
  /// and the input is intact; 1: a divergence (a champion or a message); 2:
  /// unusable input (fatal, an unusable champion or a damaged/undecodable event).
  int exit_code() const;
};

/// One line for a champion: ok, or where it diverged (generation, genome,
/// step, body, field, logged vs recomputed, max error), or why it is unusable.
std::string champion_line(const ChampionResult& c, bool with_run);
/// The whole report: a header, a line per champion, input problems, a summary.
std::string format_text(const CheckReport& r);
/// The same report, machine-readable. Values are strings (%.17g) so that they
/// read back to the same bits; errors are numbers (null when infinite).
nlohmann::json to_json(const CheckReport& r);

}  // namespace robozoo::replay
