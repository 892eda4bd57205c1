#pragma once
// A portable checkpoint: a trial in progress, small enough to commit, so that
// another machine continues it without its log (20-40 MB a trial, which barely
// compresses). It holds robozoo-evolve's checkpoint of the trial after
// generation k - 1 (evolve/record/checkpoint.hpp) and the trial's compact result
// of generations 0..k-1 (evolve/record/run_results.hpp), both
// compressed (zstd), in one file, <trial>.portable-checkpoint.
//
// Format (version 1), integers little-endian, a 60-byte header then the payload:
//   0  16  "robozoo-portable" (format tag)
//  16   4  format version (1)
//  20   4  0 (reserved)
//  24   8  checkpoint bytes (the checkpoint's JSON text, uncompressed)
//  32   8  result bytes (the compact result's JSON text, uncompressed)
//  40   8  compressed bytes: the rest of the file, one zstd frame (level 19,
//          content size set) of the checkpoint's text followed by the result's
//  48   4  CRC-32 of the uncompressed texts
//  52   4  CRC-32 of the compressed bytes
//  56   4  CRC-32 of header bytes 0-55
// Reading checks the tag, version, every size (the file's, the uncompressed
// total at most kMaxPortablePayload and at most 1000 times the compressed
// size, the zstd frame's content size), the three CRC-32s (zlib's), before
// anything is decompressed or allocated, then the two texts as a checkpoint
// and a compact result of the same run (run id, software version,
// configuration but the generations requested), the result holding exactly
// generations 0..k-1 and ending with the checkpoint's evaluations and
// best-so-far fitness. Every refusal names the file.
//
// Unpacked beside a trial's log path on a machine without the log, it leaves
// the checkpoint there (<log>.checkpoint, saying that the log begins at
// generation k: log_continuation.hpp) and the earlier result
// (<log>.earlier.json: continued_results.hpp); robozoo-evolve --resume then
// starts a new log at generation k, and the finished trial's compact result is
// the earlier one merged with the new log's.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/record/checkpoint.hpp"
#include "evolve/record/run_results.hpp"
#include "study/experiment/trial_plan.hpp"

namespace robozoo {

inline constexpr const char* kPortableCheckpointTag = "robozoo-portable";
inline constexpr uint32_t kPortableCheckpointVersion = 1;
inline constexpr size_t kPortableHeaderBytes = 60;
/// The largest uncompressed payload read (bytes): a population-150 trial's is about 1 MB.
inline constexpr uint64_t kMaxPortablePayload = uint64_t{1} << 30;
inline constexpr const char* kPortableCheckpointExtension = ".portable-checkpoint";

struct PortableCheckpoint {
  std::string checkpoint_text;  ///< the checkpoint as robozoo-evolve wrote it
  std::string results_text;     ///< the compact result of generations 0..k-1 (JSON)
  Checkpoint checkpoint;        ///< read from checkpoint_text
  RunResults earlier;           ///< read from results_text
  int32_t generation = 0;       ///< k: finished generations, the first the continued log holds (count)
};

/// DIR/<trial>.portable-checkpoint
std::string portable_checkpoint_path(const std::string& dir, const Trial& t);

/// The portable checkpoint of the run logged at `log_path`, from its
/// checkpoint and the log up to it. Throws std::invalid_argument when there is
/// nothing to carry (no generation finished yet), std::runtime_error for
/// unreadable files. A finished run packs too (all its generations are done).
PortableCheckpoint pack_portable_checkpoint(const std::string& log_path);

/// zstd's level for the files robozoo writes: about a third smaller than zlib's best on a
/// checkpoint, and well under a second for a population-150 trial's.
inline constexpr int kPortableZstdLevel = 19;

/// The file's bytes, the texts compressed at zstd level `zstd_level` (1-22; a file of any level
/// reads back the same; a lower one is quicker and larger, as the fuzz target's mutator wants).
std::vector<uint8_t> encode_portable_checkpoint(const PortableCheckpoint& p, int zstd_level = kPortableZstdLevel);
/// The two texts the bytes hold, the checkpoint's and the compact result's, once the header, the
/// sizes, the CRC-32s and the zstd frame are checked (the texts themselves are not read);
/// throws std::invalid_argument starting with `path`.
struct PortableTexts {
  std::string checkpoint;
  std::string results;
};
PortableTexts unpack_portable_texts(const uint8_t* data, size_t size, const std::string& path);
/// Checks everything the format says; throws std::invalid_argument starting with `path`.
PortableCheckpoint decode_portable_checkpoint(const uint8_t* data, size_t size, const std::string& path);

/// Writes atomically (temporary file, rename).
void write_portable_checkpoint(const std::string& path, const PortableCheckpoint& p);
/// Reads and decodes; std::invalid_argument (bad content) or std::runtime_error (unreadable), naming `path`.
PortableCheckpoint read_portable_checkpoint(const std::string& path);

/// The compact result a file gives: a *.portable-checkpoint's of its finished
/// generations (a trial in progress), else the file read as a compact result
/// (*.results.json); its run.path is `path`. Throws as the two readers do.
RunResults read_results_or_portable_checkpoint(const std::string& path);

/// Empty when `p` (read from `path`) may continue trial `t` of experiment `e`:
/// its run id is the trial's name, its configuration the trial's
/// (trial_mismatch), and its software version this robozoo's (always: the
/// trial's compact result is one run of one version). Otherwise one sentence
/// naming the file and what differs.
std::string portable_refusal(const PortableCheckpoint& p, const std::string& path, const Trial& t,
                             const ExperimentParams& e);

/// Leaves the checkpoint and the earlier result beside `log_path` (see above).
/// Throws std::invalid_argument when the log or its checkpoint is already
/// there (a trial that runs here is not replaced).
void unpack_portable_checkpoint(const PortableCheckpoint& p, const std::string& log_path);

}  // namespace robozoo
