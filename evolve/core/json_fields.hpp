#pragma once
// Strict reading of JSON fields from files robozoo did not necessarily write
// (genome files, checkpoints): each reader checks the value's JSON type and the
// range of its C++ type before converting, and throws std::invalid_argument
// naming the field's path ("population.genomes[3].id: out of range"). nlohmann's
// own get<int64_t>() converts a JSON float such as 1e20 by a plain cast, which is
// undefined behaviour when the value does not fit (found by fuzz_checkpoint), and
// truncates 2.5 to 2 without a word.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace robozoo::json_fields {

[[noreturn]] void fail(const std::string& path, const std::string& what);
/// j[key] of an object; "PATH.KEY: missing" when absent.
const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& path);
/// An integer in [lo, hi] (JSON integers only, not 2.0).
int64_t as_int(const nlohmann::json& v, const std::string& path, int64_t lo, int64_t hi);
int64_t as_i64(const nlohmann::json& v, const std::string& path);
int32_t as_i32(const nlohmann::json& v, const std::string& path);
/// A non-negative JSON integer up to 2^64 - 1.
uint64_t as_u64(const nlohmann::json& v, const std::string& path);
/// Any JSON number.
double as_double(const nlohmann::json& v, const std::string& path);
bool as_bool(const nlohmann::json& v, const std::string& path);
std::string as_string(const nlohmann::json& v, const std::string& path);
const nlohmann::json& as_array(const nlohmann::json& v, const std::string& path);
/// "PATH[i]".
std::string at(const std::string& path, size_t i);

}  // namespace robozoo::json_fields
