// The portable checkpoint's format: what it holds reads back exactly, and
// every kind of damage (tag, version, header, sizes, compressed bytes, a
// result of another run) is refused with the file named.
#include "study/experiment/portable_checkpoint.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>

#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

/// The small run stopped after 2 of 4 generations, packed.
PortableCheckpoint packed(const TempDir& dir) {
  const std::string log = dir / "r.lcmlog";
  RunConfig c = small_run_config(4);
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = log;
  o.run_id = "r";
  {
    Evolution evo(c, o, evaluator);
    evo.step();
    evo.step();
  }
  return pack_portable_checkpoint(log);
}

std::string refusal(const std::vector<uint8_t>& bytes) {
  try {
    decode_portable_checkpoint(bytes.data(), bytes.size(), "the.file");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

void put_u64(std::vector<uint8_t>& b, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) b[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
/// Rewrites the header's own CRC-32, so that a check after it is reached.
void reseal(std::vector<uint8_t>& b) {
  const uint32_t crc = static_cast<uint32_t>(crc32(crc32(0L, Z_NULL, 0), b.data(), 56));
  for (int i = 0; i < 4; ++i) b[56 + i] = static_cast<uint8_t>(crc >> (8 * i));
}

TEST(PortableCheckpoint, ReadsBackWhatItHolds) {
  TempDir dir;
  const PortableCheckpoint p = packed(dir);
  EXPECT_EQ(p.generation, 2);
  ASSERT_EQ(p.earlier.run.generations.size(), 2u);
  EXPECT_EQ(p.earlier.run.generations.back().evaluations, 48);
  const std::vector<uint8_t> bytes = encode_portable_checkpoint(p);
  EXPECT_EQ(std::memcmp(bytes.data(), "robozoo-portable", 16), 0);
  const PortableCheckpoint q = decode_portable_checkpoint(bytes.data(), bytes.size(), "f");
  EXPECT_EQ(q.checkpoint_text, p.checkpoint_text);
  EXPECT_EQ(q.results_text, p.results_text);
  EXPECT_EQ(q.generation, 2);
  EXPECT_EQ(q.checkpoint.rng_state, p.checkpoint.rng_state);
  // Smaller than its texts.
  EXPECT_LT(bytes.size(), p.checkpoint_text.size() + p.results_text.size());
  // The texts alone, unparsed: the same.
  const PortableTexts texts = unpack_portable_texts(bytes.data(), bytes.size(), "f");
  EXPECT_EQ(texts.checkpoint, p.checkpoint_text);
  EXPECT_EQ(texts.results, p.results_text);
  // Another zstd level: other bytes, larger, the same texts back.
  const std::vector<uint8_t> quick = encode_portable_checkpoint(p, 1);
  EXPECT_GT(quick.size(), bytes.size());
  const PortableCheckpoint r = decode_portable_checkpoint(quick.data(), quick.size(), "f");
  EXPECT_EQ(r.checkpoint_text, p.checkpoint_text);
  EXPECT_EQ(r.results_text, p.results_text);

  // Unpacked beside a new log path: the checkpoint says the log begins at generation 2.
  unpack_portable_checkpoint(q, dir / "new/r.lcmlog");
  const Checkpoint c = read_checkpoint(dir / "new/r.lcmlog.checkpoint");
  ASSERT_TRUE(c.log_continues.has_value());
  EXPECT_EQ(c.log_continues->from_generation, 2);
  EXPECT_EQ(c.log_continues->evaluations_before, 48);
  EXPECT_EQ(c.log_bytes, 0);
  EXPECT_EQ(read_file(earlier_results_path_for(dir / "new/r.lcmlog")), p.results_text);
  // ... and not over a trial in progress.
  EXPECT_THROW(unpack_portable_checkpoint(q, dir / "new/r.lcmlog"), std::invalid_argument);
  // Packed again before the continued run finished a generation: the same generations.
  const PortableCheckpoint again = pack_portable_checkpoint(dir / "new/r.lcmlog");
  EXPECT_EQ(again.generation, 2);
  EXPECT_EQ(again.results_text, p.results_text);
}

TEST(PortableCheckpoint, RefusesDamage) {
  TempDir dir;
  const PortableCheckpoint p = packed(dir);
  const std::vector<uint8_t> good = encode_portable_checkpoint(p);

  EXPECT_NE(refusal({}).find("the.file: not a usable portable checkpoint: no \"robozoo-portable\" format tag"),
            std::string::npos);
  std::vector<uint8_t> b = good;
  b[0] = 'R';
  EXPECT_NE(refusal(b).find("format tag"), std::string::npos);
  b = good;
  b[16] = 2;
  EXPECT_NE(refusal(b).find("format version 2 (this robozoo reads version 1)"), std::string::npos);
  b = good;
  b[30] ^= 1;
  EXPECT_NE(refusal(b).find("its header is damaged"), std::string::npos);
  b = good;
  b.push_back(0);
  EXPECT_NE(refusal(b).find("cut short, or bytes added"), std::string::npos);
  b = good;
  b[b.size() - 3] ^= 0x40;
  EXPECT_NE(refusal(b).find("its compressed bytes are damaged"), std::string::npos);
  // Sizes beyond the bound, or beyond what the compressed bytes can hold, are refused before anything is allocated.
  b = good;
  put_u64(b, 24, kMaxPortablePayload);
  put_u64(b, 32, 1);
  reseal(b);
  EXPECT_NE(refusal(b).find("would take more than"), std::string::npos);
  b = good;
  put_u64(b, 24, uint64_t{1} << 29);
  reseal(b);
  EXPECT_NE(refusal(b).find("cannot come from"), std::string::npos);
  // A decompressed size other than the header's.
  b = good;
  put_u64(b, 32, p.results_text.size() - 1);
  reseal(b);
  EXPECT_NE(refusal(b).find("not one zstd frame of the"), std::string::npos);

  // A checkpoint with the result of another run.
  PortableCheckpoint q = p;
  nlohmann::json res = nlohmann::json::parse(q.results_text);
  res["run"]["run_id"] = "other";
  q.results_text = res.dump();
  EXPECT_NE(refusal(encode_portable_checkpoint(q)).find("its checkpoint and result differ: run r and run other"),
            std::string::npos);
  // ... or with one generation less.
  q = p;
  nlohmann::json c = nlohmann::json::parse(q.checkpoint_text);
  c["population"]["generation"] = 3;
  q.checkpoint_text = c.dump();
  EXPECT_NE(refusal(encode_portable_checkpoint(q)).find("after generation 2, the result holds 2 generations"),
            std::string::npos)
      << refusal(encode_portable_checkpoint(q));
}

TEST(PortableCheckpoint, NothingToCarryBeforeTheFirstGeneration) {
  TempDir dir;
  RunConfig c = small_run_config(4);
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = dir / "r.lcmlog";
  { Evolution evo(c, o, evaluator); }
  EXPECT_THROW(pack_portable_checkpoint(dir / "r.lcmlog"), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
