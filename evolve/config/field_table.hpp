#pragma once
// A table of named, range-checked fields of one parameter struct, used to read
// and write a configuration section as JSON. Unknown keys, wrong types and
// out-of-range values are rejected with a message naming "section.key".
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace robozoo {

struct ConfigError;  // run_config.hpp

[[noreturn]] void throw_config_error(const std::string& message);

/// A value as an error message shows it: a number, true/false or a string
/// (cut after 60 characters) as written; an array or object by its size only,
/// since writing out a deeply nested one recurses as deep as it nests.
inline std::string shown(const nlohmann::json& v) {
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " values";
  if (v.is_object()) return "an object of " + std::to_string(v.size()) + " keys";
  std::string s = v.dump();
  if (s.size() > 60) s = s.substr(0, 60) + "...";
  return s;
}

template <class S>
class FieldTable {
 public:
  explicit FieldTable(std::string section) : section_(std::move(section)) {}

  static constexpr double kInf = std::numeric_limits<double>::infinity();

  /// A real field in [lo, hi] (open ends when lo_open / hi_open).
  FieldTable& real(const std::string& name, double S::*m, double lo, double hi, bool lo_open = false,
                   bool hi_open = false) {
    fields_[name] = {[m](nlohmann::json& j, const S& s, const std::string& n) { j[n] = s.*m; },
                     [q = qualified(name), m, lo, hi, lo_open, hi_open](S& s, const nlohmann::json& v) {
                       if (!v.is_number()) fail(q, "must be a number, got " + shown(v));
                       const double x = v.get<double>();
                       const bool below = lo_open ? !(x > lo) : !(x >= lo);
                       const bool above = hi_open ? !(x < hi) : !(x <= hi);
                       if (!std::isfinite(x) || below || above)
                         fail(q, "must be in " + std::string(lo_open ? "(" : "[") + num(lo) + ", " + num(hi) +
                                     (hi_open ? ")" : "]") + ", got " + shown(v));
                       s.*m = x;
                     }};
    return *this;
  }
  /// An integer field in [lo, hi].
  template <class I>
  FieldTable& integer(const std::string& name, I S::*m, long long lo, long long hi) {
    fields_[name] = {[m](nlohmann::json& j, const S& s, const std::string& n) { j[n] = s.*m; },
                     [q = qualified(name), m, lo, hi](S& s, const nlohmann::json& v) {
                       if (!v.is_number_integer()) fail(q, "must be an integer, got " + shown(v));
                       const long long x = v.get<long long>();
                       if (x < lo || x > hi)
                         fail(q,
                              "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + shown(v));
                       s.*m = static_cast<I>(x);
                     }};
    return *this;
  }
  FieldTable& boolean(const std::string& name, bool S::*m) {
    fields_[name] = {[m](nlohmann::json& j, const S& s, const std::string& n) { j[n] = s.*m; },
                     [q = qualified(name), m](S& s, const nlohmann::json& v) {
                       if (!v.is_boolean()) fail(q, "must be true or false, got " + shown(v));
                       s.*m = v.get<bool>();
                     }};
    return *this;
  }
  /// An enumerated field written and read by name (`name_of` / `from_name`,
  /// which throws std::invalid_argument listing the names).
  template <class E>
  FieldTable& choice(const std::string& name, E S::*m, std::string (*name_of)(E), E (*from_name)(const std::string&)) {
    return custom(
        name, [m, name_of](const S& s) { return nlohmann::json(name_of(s.*m)); },
        [m, from_name](S& s, const nlohmann::json& v, const std::string& q) {
          if (!v.is_string()) fail(q, "must be a name, got " + shown(v));
          try {
            s.*m = from_name(v.get<std::string>());
          } catch (const std::invalid_argument& e) {
            fail(q, e.what());
          }
        });
  }

  /// A field with its own conversion; `read` gets the qualified key for its errors.
  FieldTable& custom(const std::string& name, std::function<nlohmann::json(const S&)> write,
                     std::function<void(S&, const nlohmann::json&, const std::string&)> read) {
    fields_[name] = {[write](nlohmann::json& j, const S& s, const std::string& n) { j[n] = write(s); },
                     [read, q = qualified(name)](S& s, const nlohmann::json& v) { read(s, v, q); }};
    return *this;
  }

  nlohmann::json write(const S& s) const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, f] : fields_) f.write(j, s, name);
    return j;
  }
  void read(S& s, const nlohmann::json& j) const {
    if (!j.is_object()) throw_config_error(section_ + ": must be a table/object, got " + shown(j));
    for (const auto& [key, value] : j.items()) {
      auto it = fields_.find(key);
      if (it == fields_.end()) throw_config_error(qualified(key) + ": unknown key");
      it->second.read(s, value);
    }
  }
  [[noreturn]] static void fail(const std::string& qualified_name, const std::string& what) {
    throw_config_error(qualified_name + ": " + what);
  }
  std::string qualified(const std::string& name) const { return section_.empty() ? name : section_ + "." + name; }

 private:
  static std::string num(double x) {
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    nlohmann::json j = x;
    return j.dump();
  }
  struct Field {
    std::function<void(nlohmann::json&, const S&, const std::string&)> write;
    std::function<void(S&, const nlohmann::json&)> read;
  };
  std::string section_;
  std::map<std::string, Field> fields_;
};

}  // namespace robozoo
