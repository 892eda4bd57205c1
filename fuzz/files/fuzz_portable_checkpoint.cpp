// libFuzzer target: a portable checkpoint (robozoo-experiment --checkpoints
// DIR): decode_portable_checkpoint. Every refusal is a std::invalid_argument
// naming the file; an accepted one encodes to bytes that decode to the same
// texts, and its result holds exactly its checkpoint's finished generations.
//
// Its mutator: a mutation of the bytes alone almost never gets past the CRC-32s,
// so half the mutations change the texts inside instead (the checkpoint or the
// compact result, unpacked from zstd) and pack them again with the right sizes
// and CRC-32s: the decoder's checks of the texts and of their agreement are
// fuzzed too, not only its refusal of damaged bytes.
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.hpp"
#include "study/experiment/portable_checkpoint.hpp"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

/// zstd's quickest level: the decoder reads any level, and level 19 held the target to ~80 inputs/s.
constexpr int kQuickLevel = 1;

/// `text` mutated by libFuzzer, with room to grow by a quarter.
std::string mutated(const std::string& text) {
  std::vector<uint8_t> buf(text.begin(), text.end());
  buf.resize(text.size() + text.size() / 4 + 64);
  buf.resize(LLVMFuzzerMutate(buf.data(), text.size(), buf.size()));
  return std::string(buf.begin(), buf.end());
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  if (seed % 2 == 0) return LLVMFuzzerMutate(data, size, max_size);
  robozoo::PortableTexts texts;
  try {
    texts = robozoo::unpack_portable_texts(data, size, "mutated");
  } catch (const std::invalid_argument&) {  // damaged bytes: mutate them as they are
    return LLVMFuzzerMutate(data, size, max_size);
  }
  robozoo::PortableCheckpoint p;
  p.checkpoint_text = (seed / 2) % 2 == 0 ? mutated(texts.checkpoint) : texts.checkpoint;
  p.results_text = (seed / 2) % 2 == 1 ? mutated(texts.results) : texts.results;
  const std::vector<uint8_t> bytes = robozoo::encode_portable_checkpoint(p, kQuickLevel);
  if (bytes.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, bytes.data(), bytes.size());
  return bytes.size();
}

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
  const std::vector<uint8_t> again = encode_portable_checkpoint(p, kQuickLevel);
  const PortableCheckpoint back = decode_portable_checkpoint(again.data(), again.size(), "again");
  if (back.checkpoint_text != p.checkpoint_text || back.results_text != p.results_text)
    fuzz::violated("an accepted portable checkpoint does not encode back to itself");
  return 0;
}
