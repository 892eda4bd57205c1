#include "evolve/messages/log_continuation.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "evolve/core/json_fields.hpp"

namespace robozoo {

bool LogContinuation::operator==(const LogContinuation& o) const {
  return from_generation == o.from_generation && evaluations_before == o.evaluations_before &&
         std::memcmp(&best_so_far_before, &o.best_so_far_before, sizeof(double)) == 0 &&
         last_champion_key == o.last_champion_key;
}

nlohmann::json log_continuation_to_json(const LogContinuation& c) {
  return {{"from_generation", c.from_generation},
          {"evaluations_before", c.evaluations_before},
          {"best_so_far_before", c.best_so_far_before},
          {"last_champion_key", c.last_champion_key}};
}

LogContinuation log_continuation_from_json(const nlohmann::json& j, const std::string& path) {
  using namespace json_fields;
  try {
    if (!j.is_object()) fail(kLogContinuesKey, "not a JSON object");
    const std::string p = kLogContinuesKey;
    LogContinuation c;
    c.from_generation =
        static_cast<int32_t>(as_int(field(j, "from_generation", p), p + ".from_generation", 1, 1000000000));
    c.evaluations_before =
        as_int(field(j, "evaluations_before", p), p + ".evaluations_before", 0, std::numeric_limits<int64_t>::max());
    c.best_so_far_before = as_double(field(j, "best_so_far_before", p), p + ".best_so_far_before");
    if (!std::isfinite(c.best_so_far_before)) fail(p + ".best_so_far_before", "not finite");
    c.last_champion_key = as_u64(field(j, "last_champion_key", p), p + ".last_champion_key");
    if (j.size() != 4)
      fail(p, "has keys besides from_generation, evaluations_before, best_so_far_before, last_champion_key");
    return c;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

run_t mark_continued(run_t m, const LogContinuation& c) {
  nlohmann::json j = nlohmann::json::parse(m.config_json);
  j[kLogContinuesKey] = log_continuation_to_json(c);
  m.config_json = j.dump();
  return m;
}

SplitRunConfig split_run_config(const std::string& config_json) {
  SplitRunConfig s;
  nlohmann::json j = nlohmann::json::parse(config_json, nullptr, false);
  if (!j.is_object() || !j.contains(kLogContinuesKey)) {
    s.config_json = config_json;
    return s;
  }
  s.continues = log_continuation_from_json(j.at(kLogContinuesKey), "run_t.config_json");
  j.erase(kLogContinuesKey);
  s.config_json = j.dump();
  return s;
}

}  // namespace robozoo
