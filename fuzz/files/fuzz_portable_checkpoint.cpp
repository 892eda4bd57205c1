// libFuzzer target: a portable checkpoint (robozoo-experiment --checkpoints
// DIR): decode_portable_checkpoint. Every refusal is a std::invalid_argument
// naming the file; an accepted one encodes to bytes that decode to the same
// texts, and its result holds exactly its checkpoint's finished generations.
#include <stdexcept>
#include <string>

#include "fuzz/fuzz_check.hpp"
#include "study/experiment/portable_checkpoint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace robozoo;
  PortableCheckpoint p;
  try {
    p = decode_portable_checkpoint(data, size, "dir/fuzz.portable-checkpoint");
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).rfind("dir/fuzz.portable-checkpoint: ", 0) != 0)
      fuzz::violated(std::string("a refusal does not name the file: ") + e.what());
    return 0;
  }
  if (p.generation < 1 || p.earlier.run.generations.size() != static_cast<size_t>(p.generation))
    fuzz::violated("an accepted portable checkpoint's result does not hold its generations");
  const std::vector<uint8_t> again = encode_portable_checkpoint(p);
  const PortableCheckpoint back = decode_portable_checkpoint(again.data(), again.size(), "again");
  if (back.checkpoint_text != p.checkpoint_text || back.results_text != p.results_text)
    fuzz::violated("an accepted portable checkpoint does not encode back to itself");
  return 0;
}
