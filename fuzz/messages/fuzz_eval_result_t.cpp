// libFuzzer target: safe_decode of a eval_result_t from untrusted bytes (a log or the bus).
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  robozoo::eval_result_t m;
  robozoo::fuzz::decode_and_check(data, size, m);
  return 0;
}
