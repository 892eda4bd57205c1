#pragma once
// What every fuzz target asserts beyond "no crash, no sanitizer report": a
// property that could fail. A broken property aborts, which libFuzzer reports
// as a crash and saves the input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo::fuzz {

[[noreturn]] inline void violated(const std::string& what) {
  std::fprintf(stderr, "fuzz property violated: %s\n", what.c_str());
  std::abort();
}

/// safe_decode<T> on the input; when it accepts, the message must re-encode to
/// exactly the same bytes (the layout walk and LCM's decoder agree).
template <class T>
bool decode_and_check(const uint8_t* data, size_t size, T& m) {
  std::string why;
  if (!safe_decode(data, size, m, &why)) {
    if (why.empty()) violated("safe_decode refused without saying why");
    return false;
  }
  const std::vector<uint8_t> again = encode_message(m);
  if (again.size() != size || !std::equal(again.begin(), again.end(), data))
    violated("a message safe_decode accepted does not re-encode to the same bytes");
  return true;
}

/// Every number in `j` is finite (accepted input never carries NaN or Inf).
inline void require_finite(const nlohmann::json& j, const std::string& where) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) violated(where + ": a non-finite number was accepted");
  if (j.is_structured())
    for (const auto& [k, v] : j.items()) require_finite(v, where + "." + k);
}

}  // namespace robozoo::fuzz
