#include "study/analysis/sensitivity/config_difference.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "evolve/config/run_config.hpp"

namespace robozoo {

namespace {

nlohmann::json full_config(const std::string& text, const std::string& what) {
  try {
    return config_to_json(config_from_record(nlohmann::json::parse(text)));
  } catch (const std::exception& e) {
    throw std::invalid_argument(what + ": not a robozoo run configuration (" + e.what() + ")");
  }
}

void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      flatten(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), out);
    return;
  }
  out[prefix] = j.dump();
}

}  // namespace

std::vector<ConfigChange> config_difference(const std::string& a, const std::string& b,
                                            const std::vector<std::string>& ignore, const std::string& what) {
  std::map<std::string, std::string> fa, fb;
  flatten(full_config(a, what), "", fa);
  flatten(full_config(b, what), "", fb);
  std::vector<ConfigChange> out;
  auto ignored = [&ignore](const std::string& k) { return std::find(ignore.begin(), ignore.end(), k) != ignore.end(); };
  for (const auto& [key, value] : fa) {
    if (ignored(key)) continue;
    const auto other = fb.find(key);
    const std::string to = other == fb.end() ? "(absent)" : other->second;
    if (to != value) out.push_back({key, value, to});
  }
  for (const auto& [key, value] : fb)
    if (!ignored(key) && fa.count(key) == 0) out.push_back({key, "(absent)", value});
  std::sort(out.begin(), out.end(), [](const ConfigChange& x, const ConfigChange& y) { return x.key < y.key; });
  return out;
}

std::string describe_changes(const std::vector<ConfigChange>& changes) {
  if (changes.empty()) return "none";
  std::string s;
  for (const auto& c : changes) s += (s.empty() ? "" : "; ") + c.key + " " + c.from + " -> " + c.to;
  return s;
}

}  // namespace robozoo
