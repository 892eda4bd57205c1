#pragma once
// robozoo-log export: a log as an MCAP file for Foxglove. Every ROBOZOO_*
// message on its LCM channel's topic as JSON (message_json) with its JSON
// Schema (lcm_json_schema); every pose also as a foxglove.SceneUpdate on
// `scene_topic`; every generation's figures on `stats_topic`. Log and publish
// times are the log's event timestamps, in ns.
#include <cstdint>
#include <map>
#include <string>

#include "runlog/foxglove_scene.hpp"
#include "runlog/log_reader.hpp"
#include "runlog/mcap/writer.hpp"

namespace robozoo {

struct ExportOptions {
  mcap::WriterOptions writer;
  std::string scene_topic = "/robot/scene";
  std::string stats_topic = "/generation/stats";
  SceneStyleParams scene;
};

struct ExportReport {
  std::map<std::string, int64_t> messages;  ///< per topic
  int64_t skipped = 0;        ///< events of other channels, or that do not decode (count)
  int64_t poses_unshown = 0;  ///< poses without a matching morphology: no SceneUpdate (count)
  int64_t chunks = 0;
};

/// The JSON of `stats_topic` for one generation_t (as message_json gives it).
nlohmann::json generation_stats(const nlohmann::json& generation);
/// Its JSON Schema.
nlohmann::json generation_stats_schema();

/// Writes `log` to `path` (through PATH.partial). Throws std::runtime_error
/// when the file cannot be written.
ExportReport export_mcap(const ScannedLog& log, const std::string& path, const ExportOptions& options);

}  // namespace robozoo
