#include "runlog/mcap/writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

#include "evolve/io/crc32.hpp"

namespace robozoo::mcap {
namespace {

namespace fs = std::filesystem;

// A minimal MCAP reader, written from the spec for this test only.
struct Cursor {
  const Bytes& b;
  size_t at;
  uint64_t u(int n) {
    if (at + n > b.size()) throw std::runtime_error("read past the end");
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(b[at + i]) << (8 * i);
    at += n;
    return v;
  }
  std::string str() {
    const size_t n = u(4);
    std::string s(b.begin() + at, b.begin() + at + n);
    at += n;
    return s;
  }
};

struct Record {
  uint8_t op;
  size_t start;    // offset of the opcode
  size_t content;  // offset of the content
  uint64_t length;
};

std::vector<Record> records_of(const Bytes& b, size_t from, size_t to) {
  std::vector<Record> out;
  Cursor c{b, from};
  while (c.at < to) {
    Record r{static_cast<uint8_t>(c.u(1)), c.at - 1, 0, 0};
    r.length = c.u(8);
    r.content = c.at;
    c.at += r.length;
    out.push_back(r);
  }
  EXPECT_EQ(c.at, to);
  return out;
}

Bytes read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class WriterTest : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("robozoo_mcap_writer_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  /// Two channels, five messages, a chunk closed once it holds 70 bytes of
  /// records. A message record is 9 + 22 + data bytes: 38 for {"v":N}, 93 for
  /// the padded one. So chunk 1 = messages 1-2 (76 bytes), chunk 2 = message 3
  /// (93), chunk 3 = messages 4-5 (76).
  fs::path write_sample(Compression c) {
    const fs::path out = dir / "sample.mcap";
    fs::remove(out);
    Writer w(out.string(), {c, 70, "robozoo test"});
    const uint16_t s = w.add_schema("robozoo.x", "jsonschema", "{}");
    const uint16_t a = w.add_channel("/a", "json", s);
    const uint16_t b = w.add_channel("/b", "json", s);
    w.write(a, 1000, 1000, R"({"v":1})");
    w.write(b, 2000, 2000, R"({"v":2})");
    w.write(a, 3000, 3000, R"({"v":3, "padding": "0123456789012345678901234567890123456789"})");
    w.write(a, 4000, 4000, R"({"v":4})");
    w.write(b, 5000, 5000, R"({"v":5})");
    EXPECT_TRUE(fs::exists(dir / "sample.mcap.partial"));
    EXPECT_FALSE(fs::exists(out));
    w.close();
    return out;
  }
};

TEST_F(WriterTest, FileReadsBackWithEveryIndexAndCrc) {
  for (Compression comp : {Compression::Zstd, Compression::Lz4, Compression::None}) {
    SCOPED_TRACE(compression_name(comp));
    const fs::path path = write_sample(comp);
    EXPECT_FALSE(fs::exists(dir / "sample.mcap.partial"));
    const Bytes f = read_file(path);
    ASSERT_GT(f.size(), 16u + kFooterRecordBytes);
    ASSERT_EQ(std::memcmp(f.data(), kMagic, 8), 0);
    ASSERT_EQ(std::memcmp(f.data() + f.size() - 8, kMagic, 8), 0);

    // Footer.
    const size_t footer_at = f.size() - 8 - kFooterRecordBytes;
    Cursor fc{f, footer_at};
    ASSERT_EQ(fc.u(1), 0x02u);
    ASSERT_EQ(fc.u(8), 20u);
    const size_t summary_start = fc.u(8), summary_offset_start = fc.u(8);
    const uint32_t summary_crc = fc.u(4);
    EXPECT_EQ(crc32(f.data() + summary_start, footer_at + 1 + 8 + 16 - summary_start), summary_crc);

    // Data section: header, schema, channels, chunks with their message indexes, data end.
    const std::vector<Record> data = records_of(f, 8, summary_start);
    ASSERT_GE(data.size(), 5u);
    EXPECT_EQ(data.front().op, 0x01);
    const Record& end = data.back();
    ASSERT_EQ(end.op, 0x0F);
    Cursor ec{f, end.content};
    EXPECT_EQ(ec.u(4), crc32(f.data(), end.start));

    std::map<size_t, Record> by_offset;
    for (const Record& r : data) by_offset[r.start] = r;
    int chunks = 0, messages = 0;
    std::map<uint16_t, int> per_channel;
    for (const Record& r : data) {
      if (r.op != 0x06) continue;
      ++chunks;
      Cursor cc{f, r.content};
      const uint64_t t0 = cc.u(8), t1 = cc.u(8), size = cc.u(8);
      const uint32_t crc = cc.u(4);
      EXPECT_EQ(cc.str(), compression_name(comp));
      const size_t n = cc.u(8);
      const Bytes packed(f.begin() + cc.at, f.begin() + cc.at + n);
      const Bytes raw = decompress(comp, packed, size);
      EXPECT_EQ(crc32(raw.data(), raw.size()), crc);
      EXPECT_LE(t0, t1);
      for (const Record& m : records_of(raw, 0, raw.size())) {
        ASSERT_EQ(m.op, 0x05);
        Cursor mc{raw, m.content};
        const uint16_t channel = mc.u(2);
        const uint32_t seq = mc.u(4);
        const uint64_t log_time = mc.u(8);
        EXPECT_EQ(seq, static_cast<uint32_t>(per_channel[channel]++));
        EXPECT_GE(log_time, t0);
        EXPECT_LE(log_time, t1);
        ++messages;
      }
    }
    EXPECT_EQ(chunks, 3);
    EXPECT_EQ(messages, 5);
    EXPECT_EQ(per_channel[0], 3);
    EXPECT_EQ(per_channel[1], 2);

    // Summary: its groups as the summary offsets say, chunk indexes pointing at chunks.
    const std::vector<Record> summary = records_of(f, summary_start, summary_offset_start);
    const std::vector<Record> offsets = records_of(f, summary_offset_start, footer_at);
    std::map<int, int> kinds;
    for (const Record& r : summary) ++kinds[r.op];
    EXPECT_EQ(kinds[0x03], 1);
    EXPECT_EQ(kinds[0x04], 2);
    EXPECT_EQ(kinds[0x0B], 1);
    EXPECT_EQ(kinds[0x08], 3);
    ASSERT_EQ(offsets.size(), 4u);
    size_t expect_start = summary_start;
    for (const Record& o : offsets) {
      Cursor oc{f, o.content};
      oc.u(1);
      EXPECT_EQ(oc.u(8), expect_start);
      expect_start += oc.u(8);
    }
    EXPECT_EQ(expect_start, summary_offset_start);
    int indexed_messages = 0;
    for (const Record& r : summary) {
      if (r.op == 0x0B) {
        Cursor sc{f, r.content};
        EXPECT_EQ(sc.u(8), 5u);  // messages
        EXPECT_EQ(sc.u(2), 1u);  // schemas
        EXPECT_EQ(sc.u(4), 2u);  // channels
        sc.u(4), sc.u(4);
        EXPECT_EQ(sc.u(4), 3u);  // chunks
        EXPECT_EQ(sc.u(8), 1000u);
        EXPECT_EQ(sc.u(8), 5000u);
      }
      if (r.op != 0x08) continue;
      Cursor ic{f, r.content};
      ic.u(8), ic.u(8);
      const size_t chunk_start = ic.u(8), chunk_length = ic.u(8);
      ASSERT_TRUE(by_offset.count(chunk_start));
      EXPECT_EQ(by_offset[chunk_start].op, 0x06);
      EXPECT_EQ(chunk_length, 9 + by_offset[chunk_start].length);
      const size_t map_bytes = ic.u(4), map_end = ic.at + map_bytes;
      while (ic.at < map_end) {
        ic.u(2);
        const size_t index_at = ic.u(8);
        ASSERT_TRUE(by_offset.count(index_at));
        const Record& mi = by_offset[index_at];
        EXPECT_EQ(mi.op, 0x07);
        indexed_messages += static_cast<int>((mi.length - 2 - 4) / 16);
      }
    }
    EXPECT_EQ(indexed_messages, 5);
  }
}

TEST_F(WriterTest, AbandonedWriterLeavesNoFile) {
  {
    Writer w((dir / "gone.mcap").string(), {});
    w.add_schema("s", "jsonschema", "{}");
  }
  EXPECT_FALSE(fs::exists(dir / "gone.mcap"));
  EXPECT_FALSE(fs::exists(dir / "gone.mcap.partial"));
}

TEST_F(WriterTest, UnwritablePathIsAnError) {
  EXPECT_THROW(Writer((dir / "no" / "such" / "dir.mcap").string(), {}), std::runtime_error);
}

TEST_F(WriterTest, UnknownIdsAreRefused) {
  Writer w((dir / "x.mcap").string(), {});
  EXPECT_THROW(w.add_channel("/t", "json", 1), std::invalid_argument);
  const uint16_t s = w.add_schema("s", "jsonschema", "{}");
  w.add_channel("/t", "json", s);
  EXPECT_THROW(w.write(1, 0, 0, "{}"), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::mcap
