#include "runlog/mcap_export.hpp"

#include <algorithm>
#include <utility>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/sim/params.hpp"
#include "runlog/lcm_json_schema.hpp"
#include "runlog/message_json.hpp"
#include "runlog/trajectory.hpp"

namespace robozoo {

namespace {

const char* const kStatsFields[] = {"generation",   "evaluations",         "best_fitness", "mean_fitness",
                                    "stderr_fitness", "best_so_far_fitness", "num_species",  "n_completed",
                                    "eval_seconds", "generation_seconds"};

uint64_t to_ns(int64_t microseconds) { return microseconds <= 0 ? 0 : static_cast<uint64_t>(microseconds) * 1000u; }

/// Channels created on first use, in order of appearance.
class Topics {
 public:
  explicit Topics(mcap::Writer& w) : w_(w) {}
  uint16_t get(const std::string& topic, const std::string& schema_name, const nlohmann::json& schema) {
    const auto it = channels_.find(topic);
    if (it != channels_.end()) return it->second;
    const uint16_t s = w_.add_schema(schema_name, "jsonschema", schema.dump());
    return channels_[topic] = w_.add_channel(topic, "json", s);
  }

 private:
  mcap::Writer& w_;
  std::map<std::string, uint16_t> channels_;
};

}  // namespace

nlohmann::json generation_stats(const nlohmann::json& generation) {
  nlohmann::json out = {{"run_id", generation.at("run_id")}};
  for (const char* f : kStatsFields) out[f] = generation.at(f);
  return out;
}

nlohmann::json generation_stats_schema() {
  nlohmann::json properties = {{"run_id", {{"type", "string"}}}};
  nlohmann::json required = {"run_id"};
  for (const char* f : kStatsFields) {
    properties[f] = {{"type", "number"}};
    required.push_back(f);
  }
  return {{"title", "robozoo.generation_stats"},
          {"type", "object"},
          {"properties", properties},
          {"required", required},
          {"additionalProperties", false}};
}

ExportReport export_mcap(const ScannedLog& log, const std::string& path, const ExportOptions& options) {
  mcap::Writer writer(path, options.writer);
  Topics topics(writer);
  ExportReport report;
  // The latest morphology of each (run, genome) and each run's target, for the scenes.
  std::map<std::pair<std::string, int64_t>, morphology_t> morphologies;
  std::map<std::string, Eigen::Vector3d> targets;
  for (const LogRecord& r : log.contents.records) {
    const std::string type = lcm_type_of_channel(r.channel);
    nlohmann::json message;
    std::string why;
    if (type.empty() || !message_to_json(r.channel, r.data.data(), r.data.size(), message, why)) {
      ++report.skipped;
      continue;
    }
    const uint64_t t = to_ns(r.timestamp);
    writer.write(topics.get(r.channel, "robozoo." + type, lcm_json_schema(type)), t, t, message.dump());
    ++report.messages[r.channel];
    if (r.channel == kChannelRun) {
      run_t run{};
      if (safe_decode(r.data.data(), r.data.size(), run, &why)) {
        try {
          targets[run.run_id] = run_target(run);
        } catch (const std::exception&) {
          // a configuration that does not parse: its scenes show the default target (SimParams)
        }
      }
    } else if (r.channel == kChannelGeneration) {
      writer.write(topics.get(options.stats_topic, "robozoo.generation_stats", generation_stats_schema()), t, t,
                   generation_stats(message).dump());
      ++report.messages[options.stats_topic];
    } else if (r.channel == kChannelMorphology) {
      morphology_t m{};
      if (safe_decode(r.data.data(), r.data.size(), m, &why)) morphologies[{m.run_id, m.genome_id}] = std::move(m);
    } else if (r.channel == kChannelPose) {
      pose_t p{};
      if (!safe_decode(r.data.data(), r.data.size(), p, &why)) continue;
      const auto m = morphologies.find({p.run_id, p.genome_id});
      if (m == morphologies.end() || m->second.num_spheres != p.num_spheres) {
        ++report.poses_unshown;
        continue;
      }
      const auto target = targets.find(p.run_id);
      const SimParams defaults;
      const Eigen::Vector3d where = target == targets.end()
                                        ? Eigen::Vector3d(defaults.target_x, defaults.target_y, defaults.target_z)
                                        : target->second;
      writer.write(topics.get(options.scene_topic, kSceneUpdateSchemaName, scene_update_schema()), t, t,
                   scene_update(m->second, p, where, t, options.scene).dump());
      ++report.messages[options.scene_topic];
    }
  }
  writer.close();
  report.chunks = writer.statistics().chunk_count;
  return report;
}

}  // namespace robozoo
