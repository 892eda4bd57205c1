#pragma once
// robozoo-log export: a log as an MCAP file for Foxglove. Every ROBOZOO_*
// message on its LCM channel's topic as JSON (message_json) with its JSON
// Schema (lcm_json_schema); every pose also as a foxglove.SceneUpdate on
// `scene_topic`; every generation's figures on `stats_topic`. Log and publish
// times are the log's event timestamps, in ns.
#include <cstdint>
#include <map>
#include <utility>
#include <string>

#include "runlog/export/foxglove_scene.hpp"
#include "runlog/read/log_reader.hpp"
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
  int64_t skipped = 0;                      ///< events of other channels, or that do not decode (count)
  int64_t poses_unshown = 0;                ///< poses without a matching morphology: no SceneUpdate (count)
  int64_t chunks = 0;
};

/// The JSON of `stats_topic` for one generation_t (as message_json gives it).
nlohmann::json generation_stats(const nlohmann::json& generation);
/// Its JSON Schema.
nlohmann::json generation_stats_schema();

/// Writes a log's events, one at a time, to an MCAP file (through
/// PATH.partial: an exporter destroyed before finish() leaves no file).
class McapExporter {
 public:
  /// Throws std::runtime_error when `path`'s .partial cannot be created.
  McapExporter(const std::string& path, const ExportOptions& options);
  void add(const LogRecord& event);
  /// Completes the file and renames it to `path`. Throws std::runtime_error on a write error.
  ExportReport finish();

 private:
  uint16_t topic(const std::string& name, const std::string& schema_name, const nlohmann::json& schema);

  ExportOptions options_;
  mcap::Writer writer_;
  ExportReport report_;
  std::map<std::string, uint16_t> channels_;
  // The morphologies of the last generations by (run, genome) and each run's target, for the scenes.
  std::map<std::pair<std::string, int64_t>, morphology_t> morphologies_;
  std::map<std::string, Eigen::Vector3d> targets_;
};

}  // namespace robozoo
