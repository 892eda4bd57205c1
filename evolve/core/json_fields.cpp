#include "evolve/core/json_fields.hpp"

#include <limits>
#include <stdexcept>

namespace robozoo::json_fields {

using nlohmann::json;

void fail(const std::string& path, const std::string& what) { throw std::invalid_argument(path + ": " + what); }

const json& field(const json& j, const char* key, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("expected an object, got ") + j.type_name());
  const auto it = j.find(key);
  if (it == j.end()) fail(path + "." + key, "missing");
  return *it;
}

int64_t as_int(const json& v, const std::string& path, int64_t lo, int64_t hi) {
  if (!v.is_number_integer()) fail(path, std::string("expected an integer, got ") + v.type_name());
  if (v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(hi)) fail(path, "out of range");
  const int64_t x = v.get<int64_t>();
  if (x < lo || x > hi) fail(path, "out of range: " + std::to_string(x));
  return x;
}
int64_t as_i64(const json& v, const std::string& path) {
  return as_int(v, path, std::numeric_limits<int64_t>::min(), std::numeric_limits<int64_t>::max());
}
int32_t as_i32(const json& v, const std::string& path) {
  return static_cast<int32_t>(
      as_int(v, path, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max()));
}
uint64_t as_u64(const json& v, const std::string& path) {
  if (!v.is_number_integer()) fail(path, std::string("expected an integer, got ") + v.type_name());
  if (!v.is_number_unsigned() && v.get<int64_t>() < 0) fail(path, "out of range: " + v.dump());
  return v.get<uint64_t>();
}
double as_double(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, std::string("expected a number, got ") + v.type_name());
  return v.get<double>();
}
bool as_bool(const json& v, const std::string& path) {
  if (!v.is_boolean()) fail(path, std::string("expected true or false, got ") + v.type_name());
  return v.get<bool>();
}
std::string as_string(const json& v, const std::string& path) {
  if (!v.is_string()) fail(path, std::string("expected a string, got ") + v.type_name());
  return v.get<std::string>();
}
const json& as_array(const json& v, const std::string& path) {
  if (!v.is_array()) fail(path, std::string("expected an array, got ") + v.type_name());
  return v;
}
std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

}  // namespace robozoo::json_fields
