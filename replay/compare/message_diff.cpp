#include "replay/compare/message_diff.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "runlog/text/message_json.hpp"

namespace robozoo::replay {

namespace {

bool walk(const nlohmann::json& a, const nlohmann::json& b, const std::string& path, FieldDifference& out) {
  if (a.type() != b.type() || a.is_primitive()) {
    if (a == b) return false;
    out.field = path;
    out.a = a.dump();
    out.b = b.dump();
    return true;
  }
  if (a.is_array()) {
    if (a.size() != b.size()) {
      out.field = path + " (length)";
      out.a = std::to_string(a.size());
      out.b = std::to_string(b.size());
      return true;
    }
    for (size_t i = 0; i < a.size(); ++i)
      if (walk(a[i], b[i], path + "[" + std::to_string(i) + "]", out)) return true;
    return false;
  }
  for (auto it = a.begin(); it != a.end(); ++it) {
    const auto jt = b.find(it.key());
    const std::string p = path.empty() ? it.key() : path + "." + it.key();
    if (jt == b.end()) {
      out.field = p;
      out.a = it.value().dump();
      out.b = "(absent)";
      return true;
    }
    if (walk(it.value(), *jt, p, out)) return true;
  }
  return false;
}

}  // namespace

FieldDifference first_field_difference(const std::string& channel, const std::vector<uint8_t>& a,
                                       const std::vector<uint8_t>& b, const std::vector<std::string>& ignore) {
  FieldDifference out;
  nlohmann::json ja, jb;
  std::string why_a, why_b;
  const bool ok_a = message_to_json(channel, a.data(), a.size(), ja, why_a);
  const bool ok_b = message_to_json(channel, b.data(), b.size(), jb, why_b);
  if (!ok_a || !ok_b) {
    out.field = "(bytes)";
    out.a = ok_a ? "a valid message" : "not a valid message: " + why_a;
    out.b = ok_b ? "a valid message" : "not a valid message: " + why_b;
    return out;
  }
  for (const auto& f : ignore) {
    ja.erase(f);
    jb.erase(f);
  }
  walk(ja, jb, "", out);
  return out;
}

}  // namespace robozoo::replay
