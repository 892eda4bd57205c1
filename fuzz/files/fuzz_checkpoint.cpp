// libFuzzer target: a checkpoint file's text (robozoo-evolve --resume).
// Anything wrong must be a std::runtime_error naming the file.
#include <stdexcept>

#include "evolve/record/checkpoint.hpp"
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace robozoo;
  try {
    const Checkpoint c =
        checkpoint_from_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.checkpoint");
    if (c.log_bytes < 0 || c.log_events < 0 || c.evaluations < 0) fuzz::violated("negative counts accepted");
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind("fuzz.checkpoint: ", 0) != 0)
      fuzz::violated("checkpoint error without the file's name");
  }
  return 0;
}
