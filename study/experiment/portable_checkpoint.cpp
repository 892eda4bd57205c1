#include "study/experiment/portable_checkpoint.hpp"

#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "evolve/messages/build.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "study/experiment/trial_status.hpp"

namespace robozoo {

namespace {

void put_u32(std::vector<uint8_t>& out, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) out[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
void put_u64(std::vector<uint8_t>& out, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) out[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
uint32_t get_u32(const uint8_t* p) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
uint64_t get_u64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

uint32_t crc_of(const uint8_t* p, size_t n) {
  uLong crc = crc32(0L, Z_NULL, 0);
  while (n > 0) {
    const uInt chunk = static_cast<uInt>(std::min<size_t>(n, 1u << 30));
    crc = crc32(crc, p, chunk);
    p += chunk;
    n -= chunk;
  }
  return static_cast<uint32_t>(crc);
}

/// A checkpoint's text compresses about 12:1 (its genomes' weights are random
/// doubles); more than this claimed is damage, refused before allocating.
constexpr uint64_t kMaxRatio = 1000;

/// The configuration without the generations requested (an extended run raises them).
nlohmann::json without_generations(nlohmann::json config) {
  if (config.is_object()) config.erase("generations");
  return config;
}

/// Checks that the compact result `r` is the generations 0..k-1 of the run whose checkpoint is `c`.
void check_results_match(const Checkpoint& c, const RunResults& r, int32_t k) {
  const RunSummary& s = r.run;
  auto refuse = [](const std::string& why) { throw std::invalid_argument("its checkpoint and result differ: " + why); };
  if (s.run_id != c.run_id) refuse("run " + c.run_id + " and run " + s.run_id);
  if (s.software_version != c.software_version)
    refuse("robozoo " + c.software_version + " and robozoo " + s.software_version);
  if (s.continues) refuse("the result does not begin at generation 0");
  const nlohmann::json rc = nlohmann::json::parse(s.config_json, nullptr, false);
  if (without_generations(rc).dump() != without_generations(c.config).dump())
    refuse("the result's configuration is not the checkpoint's");
  if (s.generations.size() != static_cast<size_t>(k))
    refuse("the checkpoint is after generation " + std::to_string(k - 1) + ", the result holds " +
           std::to_string(s.generations.size()) + " generations");
  for (size_t i = 0; i < s.generations.size(); ++i)
    if (s.generations[i].generation != static_cast<int32_t>(i))
      refuse("the result's generation record " + std::to_string(i) + " is generation " +
             std::to_string(s.generations[i].generation));
  const GenerationRecord& last = s.generations.back();
  if (last.evaluations != c.evaluations)
    refuse(std::to_string(c.evaluations) + " and " + std::to_string(last.evaluations) + " evaluations");
  if (std::memcmp(&last.best_so_far_fitness, &c.best_so_far, sizeof(double)) != 0)
    refuse("their best-so-far fitnesses");
}

}  // namespace

std::string portable_checkpoint_path(const std::string& dir, const Trial& t) {
  return dir + "/" + t.name() + kPortableCheckpointExtension;
}

PortableCheckpoint pack_portable_checkpoint(const std::string& log_path) {
  const std::string cp = checkpoint_path_for(log_path);
  PortableCheckpoint p;
  p.checkpoint = read_checkpoint(cp);
  p.generation = generations_done(p.checkpoint);
  if (p.generation < 1) throw std::invalid_argument(cp + ": no generation finished yet; there is nothing to carry");
  p.checkpoint_text = checkpoint_to_text(p.checkpoint);
  p.earlier = run_results_up_to(log_path, p.checkpoint);
  check_results_match(p.checkpoint, p.earlier, p.generation);
  p.results_text = run_results_to_json(p.earlier).dump();
  return p;
}

std::vector<uint8_t> encode_portable_checkpoint(const PortableCheckpoint& p, int zstd_level) {
  const std::string payload = p.checkpoint_text + p.results_text;
  std::vector<uint8_t> out(kPortableHeaderBytes + ZSTD_compressBound(payload.size()));
  const size_t bound = ZSTD_compress(out.data() + kPortableHeaderBytes, out.size() - kPortableHeaderBytes,
                                     payload.data(), payload.size(), zstd_level);
  if (ZSTD_isError(bound))
    throw std::runtime_error("portable checkpoint: zstd could not compress " + std::to_string(payload.size()) +
                             " bytes: " + ZSTD_getErrorName(bound));
  out.resize(kPortableHeaderBytes + bound);
  std::memcpy(out.data(), kPortableCheckpointTag, 16);
  put_u32(out, 16, kPortableCheckpointVersion);
  put_u32(out, 20, 0);
  put_u64(out, 24, p.checkpoint_text.size());
  put_u64(out, 32, p.results_text.size());
  put_u64(out, 40, bound);
  put_u32(out, 48, crc_of(reinterpret_cast<const uint8_t*>(payload.data()), payload.size()));
  put_u32(out, 52, crc_of(out.data() + kPortableHeaderBytes, bound));
  put_u32(out, 56, crc_of(out.data(), 56));
  return out;
}

namespace {

[[noreturn]] void refuse_portable(const std::string& path, const std::string& why) {
  throw std::invalid_argument(path + ": not a usable portable checkpoint: " + why);
}

}  // namespace

PortableTexts unpack_portable_texts(const uint8_t* data, size_t size, const std::string& path) {
  auto refuse = [&path](const std::string& why) { refuse_portable(path, why); };
  if (size < kPortableHeaderBytes || std::memcmp(data, kPortableCheckpointTag, 16) != 0)
    refuse("no \"robozoo-portable\" format tag (" + std::to_string(size) + " bytes)");
  const uint32_t version = get_u32(data + 16);
  if (version != kPortableCheckpointVersion)
    refuse("format version " + std::to_string(version) + " (this robozoo reads version " +
           std::to_string(kPortableCheckpointVersion) + ")");
  if (get_u32(data + 56) != crc_of(data, 56)) refuse("its header is damaged (CRC-32)");
  if (get_u32(data + 20) != 0) refuse("reserved header bytes are not 0");
  const uint64_t checkpoint_bytes = get_u64(data + 24), results_bytes = get_u64(data + 32);
  const uint64_t compressed = get_u64(data + 40);
  if (compressed != size - kPortableHeaderBytes)
    refuse("the header says " + std::to_string(compressed) + " compressed bytes, the file holds " +
           std::to_string(size - kPortableHeaderBytes) + " (cut short, or bytes added?)");
  if (checkpoint_bytes > kMaxPortablePayload || results_bytes > kMaxPortablePayload - checkpoint_bytes)
    refuse("its texts would take more than " + std::to_string(kMaxPortablePayload) + " bytes");
  const uint64_t total = checkpoint_bytes + results_bytes;
  if (total > compressed * kMaxRatio + 1024)
    refuse(std::to_string(total) + " bytes cannot come from " + std::to_string(compressed) + " compressed bytes");
  if (get_u32(data + 52) != crc_of(data + kPortableHeaderBytes, compressed))
    refuse("its compressed bytes are damaged (CRC-32)");
  const unsigned long long framed = ZSTD_getFrameContentSize(data + kPortableHeaderBytes, compressed);
  if (framed != total)
    refuse("its compressed bytes are not one zstd frame of the " + std::to_string(total) + " bytes its header says");
  std::string payload(total, '\0');
  const size_t got = ZSTD_decompress(payload.data(), payload.size(), data + kPortableHeaderBytes, compressed);
  if (ZSTD_isError(got) || got != total)
    refuse("zstd cannot decompress it to the " + std::to_string(total) + " bytes its header says");
  if (get_u32(data + 48) != crc_of(reinterpret_cast<const uint8_t*>(payload.data()), payload.size()))
    refuse("its decompressed texts are damaged (CRC-32)");
  return PortableTexts{payload.substr(0, checkpoint_bytes), payload.substr(checkpoint_bytes)};
}

PortableCheckpoint decode_portable_checkpoint(const uint8_t* data, size_t size, const std::string& path) {
  PortableTexts texts = unpack_portable_texts(data, size, path);
  PortableCheckpoint p;
  p.checkpoint_text = std::move(texts.checkpoint);
  p.results_text = std::move(texts.results);
  try {
    p.checkpoint = checkpoint_from_text(p.checkpoint_text, "checkpoint");
    p.earlier = run_results_from_text(p.results_text, "compact result");
    p.generation = generations_done(p.checkpoint);
    if (p.generation < 1) throw std::invalid_argument("the checkpoint holds no finished generation");
    check_results_match(p.checkpoint, p.earlier, p.generation);
  } catch (const std::exception& e) {
    refuse_portable(path, e.what());
  }
  return p;
}

void write_portable_checkpoint(const std::string& path, const PortableCheckpoint& p) {
  const std::vector<uint8_t> bytes = encode_portable_checkpoint(p);
  write_file_atomic(path, std::string(bytes.begin(), bytes.end()));
}

PortableCheckpoint read_portable_checkpoint(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot read the portable checkpoint (" + ec.message() + ")");
  if (size > kPortableHeaderBytes + kMaxPortablePayload)
    throw std::invalid_argument(path + ": not a usable portable checkpoint: " + std::to_string(size) +
                                " bytes is more than one can hold");
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!in || in.gcount() != static_cast<std::streamsize>(bytes.size()))
    throw std::runtime_error(path + ": cannot read the portable checkpoint");
  return decode_portable_checkpoint(bytes.data(), bytes.size(), path);
}

std::string portable_refusal(const PortableCheckpoint& p, const std::string& path, const Trial& t,
                             const ExperimentParams& e) {
  if (p.checkpoint.run_id != t.name())
    return path + " is the portable checkpoint of run " + p.checkpoint.run_id + ", not of trial " + t.name();
  const std::string why = trial_mismatch(p.checkpoint, t, e);
  if (!why.empty()) return path + " belongs to another experiment: " + why;
  // Not even with --force: the continued trial's compact result joins the earlier generations'
  // with the new log's as one run, and a run has one version (merge_run_results refuses two).
  if (p.checkpoint.software_version != software_version())
    return path + " was written by robozoo " + p.checkpoint.software_version + ", this is robozoo " +
           software_version() +
           "; continue it with that version (another version may grow, simulate or breed differently, and a "
           "trial's result is one run of one version, so --force does not apply here)";
  return "";
}

void unpack_portable_checkpoint(const PortableCheckpoint& p, const std::string& log_path) {
  const std::string cp = checkpoint_path_for(log_path);
  for (const std::string& f : {log_path, cp})
    if (std::filesystem::exists(f))
      throw std::invalid_argument(f + " is already there: a portable checkpoint does not replace a trial in progress");
  Checkpoint c = p.checkpoint;
  c.log_bytes = 0;
  c.log_events = 0;
  c.log_continues = LogContinuation{p.generation, c.evaluations, c.best_so_far, c.last_champion_hash};
  const auto parent = std::filesystem::path(log_path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  // The earlier result first: the checkpoint's presence makes the trial one to resume.
  write_file_atomic(earlier_results_path_for(log_path), p.results_text);
  write_checkpoint(cp, c);
}

RunResults read_results_or_portable_checkpoint(const std::string& path) {
  const std::string ext = kPortableCheckpointExtension;
  const bool portable = path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  RunResults r = portable ? read_portable_checkpoint(path).earlier : read_run_results(path);
  r.run.path = path;
  return r;
}

}  // namespace robozoo
