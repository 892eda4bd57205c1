#include "runlog/export/mcap_export.hpp"

#include <algorithm>
#include <utility>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/sim/params.hpp"
#include "runlog/export/lcm_json_schema.hpp"
#include "runlog/text/message_json.hpp"
#include "runlog/robots/trajectory.hpp"

namespace robozoo {

namespace {

const char* const kStatsFields[] = {"generation",     "evaluations",         "best_fitness", "mean_fitness",
                                    "stderr_fitness", "best_so_far_fitness", "num_species",  "n_completed",
                                    "eval_seconds",   "generation_seconds"};

// Generations a morphology is kept for the poses that may still follow it.
constexpr int32_t kMorphologyGenerationsKept = 2;

uint64_t to_ns(int64_t microseconds) { return microseconds <= 0 ? 0 : static_cast<uint64_t>(microseconds) * 1000u; }

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

McapExporter::McapExporter(const std::string& path, const ExportOptions& options)
    : options_(options), writer_(path, options.writer) {}

uint16_t McapExporter::topic(const std::string& name, const std::string& schema_name, const nlohmann::json& schema) {
  const auto it = channels_.find(name);
  if (it != channels_.end()) return it->second;
  const uint16_t s = writer_.add_schema(schema_name, "jsonschema", schema.dump());
  return channels_[name] = writer_.add_channel(name, "json", s);
}

void McapExporter::add(const LogRecord& r) {
  const std::string type = lcm_type_of_channel(r.channel);
  nlohmann::json message;
  std::string why;
  if (type.empty() || !message_to_json(r.channel, r.data.data(), r.data.size(), message, why)) {
    ++report_.skipped;
    return;
  }
  const uint64_t t = to_ns(r.timestamp);
  writer_.write(topic(r.channel, "robozoo." + type, lcm_json_schema(type)), t, t, message.dump());
  ++report_.messages[r.channel];
  if (r.channel == kChannelRun) {
    run_t run{};
    if (safe_decode(r.data.data(), r.data.size(), run, &why)) {
      try {
        targets_[run.run_id] = run_target(run);
      } catch (const std::exception&) {
        // a configuration that does not parse: its scenes show the default target (SimParams)
      }
    }
  } else if (r.channel == kChannelGeneration) {
    // Poses follow their morphology within a generation or two (a champion's
    // trajectory may be logged after the next generation): older ones go.
    const int32_t g = message.at("generation").get<int32_t>();
    const std::string& run_id = message.at("run_id").get_ref<const std::string&>();
    for (auto it = morphologies_.begin(); it != morphologies_.end();)
      it = it->first.first == run_id && it->second.generation + kMorphologyGenerationsKept < g ? morphologies_.erase(it)
                                                                                               : std::next(it);
    writer_.write(topic(options_.stats_topic, "robozoo.generation_stats", generation_stats_schema()), t, t,
                  generation_stats(message).dump());
    ++report_.messages[options_.stats_topic];
  } else if (r.channel == kChannelMorphology) {
    morphology_t m{};
    if (safe_decode(r.data.data(), r.data.size(), m, &why)) morphologies_[{m.run_id, m.genome_id}] = std::move(m);
  } else if (r.channel == kChannelPose) {
    pose_t p{};
    if (!safe_decode(r.data.data(), r.data.size(), p, &why)) return;
    const auto m = morphologies_.find({p.run_id, p.genome_id});
    if (m == morphologies_.end() || m->second.num_spheres != p.num_spheres) {
      ++report_.poses_unshown;
      return;
    }
    const auto target = targets_.find(p.run_id);
    const SimParams defaults;
    const Eigen::Vector3d where = target == targets_.end()
                                      ? Eigen::Vector3d(defaults.target_x, defaults.target_y, defaults.target_z)
                                      : target->second;
    writer_.write(topic(options_.scene_topic, kSceneUpdateSchemaName, scene_update_schema()), t, t,
                  scene_update(m->second, p, where, t, options_.scene).dump());
    ++report_.messages[options_.scene_topic];
  }
}

ExportReport McapExporter::finish() {
  writer_.close();
  report_.chunks = writer_.statistics().chunk_count;
  return report_;
}

}  // namespace robozoo
