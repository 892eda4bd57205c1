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
#include <zstd.h>

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

uint64_t get_u64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

/// The two texts of a portable checkpoint whose header and zstd frame hold together; false otherwise.
bool unpack_texts(const uint8_t* data, size_t size, std::string& checkpoint, std::string& results) {
  using namespace robozoo;
  if (size < kPortableHeaderBytes || std::memcmp(data, kPortableCheckpointTag, 16) != 0) return false;
  const uint64_t checkpoint_bytes = get_u64(data + 24), results_bytes = get_u64(data + 32);
  const uint64_t total = checkpoint_bytes + results_bytes;
  if (checkpoint_bytes > (1u << 24) || results_bytes > (1u << 24)) return false;
  const unsigned long long framed = ZSTD_getFrameContentSize(data + kPortableHeaderBytes, size - kPortableHeaderBytes);
  if (framed != total) return false;
  std::string payload(total, '\0');
  const size_t got =
      ZSTD_decompress(payload.data(), payload.size(), data + kPortableHeaderBytes, size - kPortableHeaderBytes);
  if (ZSTD_isError(got) || got != total) return false;
  checkpoint = payload.substr(0, checkpoint_bytes);
  results = payload.substr(checkpoint_bytes);
  return true;
}

/// `text` mutated by libFuzzer, with room to grow by a quarter.
std::string mutated(const std::string& text) {
  std::vector<uint8_t> buf(text.begin(), text.end());
  buf.resize(text.size() + text.size() / 4 + 64);
  buf.resize(LLVMFuzzerMutate(buf.data(), text.size(), buf.size()));
  return std::string(buf.begin(), buf.end());
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  std::string checkpoint, results;
  if (seed % 2 == 0 || !unpack_texts(data, size, checkpoint, results)) return LLVMFuzzerMutate(data, size, max_size);
  robozoo::PortableCheckpoint p;
  p.checkpoint_text = (seed / 2) % 2 == 0 ? mutated(checkpoint) : checkpoint;
  p.results_text = (seed / 2) % 2 == 1 ? mutated(results) : results;
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
