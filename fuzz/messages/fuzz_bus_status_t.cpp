// libFuzzer target: safe_decode of a bus_status_t from untrusted bytes (the bus).
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  robozoo::bus_status_t m;
  robozoo::fuzz::decode_and_check(data, size, m);
  return 0;
}
