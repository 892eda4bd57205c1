#include "evolve/io/event_log.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <limits>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

std::vector<uint8_t> bytes(int n, uint8_t v) { return std::vector<uint8_t>(static_cast<size_t>(n), v); }

TEST(EventLog, WritesWhatLcmReadsBack) {
  TempDir dir;
  {
    auto log = EventLogWriter::create(dir / "a.lcmlog");
    log.write("A", bytes(10, 1), 100);
    log.write("BB", bytes(0, 0), 200);
    log.write("A", bytes(3000, 7), 300);
    log.sync();
    EXPECT_EQ(log.events(), 3);
  }
  const auto c = read_event_log(dir / "a.lcmlog");
  ASSERT_EQ(c.records.size(), 3u);
  EXPECT_EQ(c.records[1].channel, "BB");
  EXPECT_EQ(c.records[2].data, bytes(3000, 7));
  EXPECT_EQ(c.records[2].timestamp, 300);
  EXPECT_EQ(c.records[2].eventnum, 2);
  EXPECT_FALSE(c.truncated);
}

TEST(EventLog, ResumeCutsBackAndContinuesNumbering) {
  TempDir dir;
  int64_t bytes_after_two = 0;
  {
    auto log = EventLogWriter::create(dir / "a.lcmlog");
    log.write("A", bytes(10, 1), 1);
    log.write("A", bytes(10, 2), 2);
    log.sync();
    bytes_after_two = log.bytes();
    log.write("A", bytes(10, 3), 3);  // written after the "checkpoint": must vanish
  }
  {
    auto log = EventLogWriter::resume(dir / "a.lcmlog", bytes_after_two, 2);
    log.write("A", bytes(10, 9), 4);
  }
  const auto c = read_event_log(dir / "a.lcmlog");
  ASSERT_EQ(c.records.size(), 3u);
  EXPECT_EQ(c.records[2].data, bytes(10, 9));
  EXPECT_EQ(c.records[2].eventnum, 2);
  EXPECT_THROW(EventLogWriter::resume(dir / "a.lcmlog", 1 << 30, 0), std::runtime_error);
}

TEST(EventLog, FindsTheTimestampOfTheEventEndingAtAnOffset) {
  TempDir dir;
  std::vector<int64_t> ends;
  {
    auto log = EventLogWriter::create(dir / "a.lcmlog");
    log.write("A", bytes(10, 1), 111);
    log.sync();
    ends.push_back(log.bytes());
    // A payload that holds the sync word and a plausible header: not an event.
    std::vector<uint8_t> tricky = {0xED, 0xA1, 0xDA, 0x01, 0, 0,    0, 0, 0, 0, 0, 9, 0, 0,
                                   0,    0,    0,    0,    0, 0x63, 0, 0, 0, 1, 0, 0, 0, 0};
    log.write("BB", tricky, 222);
    log.sync();
    ends.push_back(log.bytes());
    log.write("C", bytes(5000, 3), 333);
    log.sync();
    ends.push_back(log.bytes());
  }
  const std::string p = dir / "a.lcmlog";
  EXPECT_EQ(timestamp_of_event_ending_at(p, ends[0]), 111);
  EXPECT_EQ(timestamp_of_event_ending_at(p, ends[1]), 222);
  EXPECT_EQ(timestamp_of_event_ending_at(p, ends[2]), 333);
  EXPECT_EQ(timestamp_of_event_ending_at(p, ends[2] - 1), -1);  // inside an event
  EXPECT_EQ(timestamp_of_event_ending_at(p, 0), -1);
  EXPECT_EQ(timestamp_of_event_ending_at(dir / "none.lcmlog", 100), -1);
}

TEST(EventLog, ACutLastEventOrTrailingGarbageIsReported) {
  TempDir dir;
  int64_t whole = 0;
  {
    auto log = EventLogWriter::create(dir / "a.lcmlog");
    log.write("A", bytes(100, 1), 1);
    log.write("A", bytes(100, 2), 2);
    log.sync();
    whole = log.bytes();
  }
  ASSERT_EQ(whole, 2 * (28 + 1 + 100));
  for (int64_t cut : {whole - 1, whole - 50, whole - 101 - 27}) {  // inside the data, the header
    ASSERT_EQ(::truncate((dir / "a.lcmlog").c_str(), 0), 0);
    {
      auto log = EventLogWriter::create(dir / "a.lcmlog");
      log.write("A", bytes(100, 1), 1);
      log.write("A", bytes(100, 2), 2);
    }
    ASSERT_EQ(::truncate((dir / "a.lcmlog").c_str(), cut), 0);
    const auto c = read_event_log(dir / "a.lcmlog");
    EXPECT_EQ(c.records.size(), 1u) << "cut at " << cut;
    EXPECT_TRUE(c.truncated) << "cut at " << cut;
    EXPECT_EQ(c.file_bytes, cut);
    EXPECT_EQ(c.event_bytes, 28 + 1 + 100);
  }
  {
    auto log = EventLogWriter::create(dir / "b.lcmlog");
    log.write("A", bytes(100, 1), 1);
  }
  std::ofstream(dir / "b.lcmlog", std::ios::app) << "not an event";
  // LCM 1.3.1 checks the header after each event and drops the event that
  // garbage follows ("Invalid header after log data"); the flag must say so.
  const auto g = read_event_log(dir / "b.lcmlog");
  EXPECT_LE(g.records.size(), 1u);
  EXPECT_TRUE(g.truncated);
}

TEST(EventLog, MissingFileIsAClearError) {
  try {
    read_event_log("/nonexistent/x.lcmlog");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.lcmlog"), std::string::npos);
  }
  EXPECT_THROW(EventLogWriter::create("/nonexistent/dir/x.lcmlog"), std::runtime_error);
}

// The raw bytes of one event header (big-endian), as a damaged log may hold them.
std::vector<uint8_t> header(int64_t eventnum, int32_t channellen, int32_t datalen) {
  std::vector<uint8_t> out;
  auto be = [&](uint64_t v, int n) {
    for (int i = n - 1; i >= 0; --i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  be(0xEDA1DA01u, 4);
  be(static_cast<uint64_t>(eventnum), 8);
  be(77, 8);
  be(static_cast<uint32_t>(channellen), 4);
  be(static_cast<uint32_t>(datalen), 4);
  return out;
}

std::vector<uint8_t> event(int64_t eventnum, const std::string& channel, const std::vector<uint8_t>& data) {
  auto out = header(eventnum, static_cast<int32_t>(channel.size()), static_cast<int32_t>(data.size()));
  out.insert(out.end(), channel.begin(), channel.end());
  out.insert(out.end(), data.begin(), data.end());
  return out;
}

std::vector<uint8_t> operator+(std::vector<uint8_t> a, const std::vector<uint8_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

LogContents parse(const std::vector<uint8_t>& b) { return parse_event_log(b.data(), b.size()); }

// LCM 1.3.1's reader, which read_event_log used before, crashes on these
// (seen with a small program on LCM's lcm_eventlog_read_next_event): a data
// length of 2^31 - 1 made it allocate datalen + 1 bytes (a signed overflow),
// fail, and read into a null pointer (SIGSEGV); a length of 10^9 made it
// allocate 1 GB for a small file (SIGSEGV under a 500 MB address-space limit).
// Lengths are now checked against the bytes left first (fuzz/files/fuzz_event_log).
TEST(EventLog, AbsurdLengthsAreACutEventNotAnAllocation) {
  const auto first = event(0, "A", bytes(10, 1));
  for (int32_t datalen : {std::numeric_limits<int32_t>::max(), 1000000000, 1 << 20, 11}) {
    const auto b = first + header(1, 1, datalen) + std::vector<uint8_t>{'A'} + bytes(10, 2);
    const auto c = parse(b);
    ASSERT_EQ(c.records.size(), 1u) << datalen;
    EXPECT_EQ(c.records[0].data, bytes(10, 1));
    EXPECT_TRUE(c.truncated);
    EXPECT_EQ(c.event_bytes, static_cast<int64_t>(first.size()));
  }
  for (int32_t channellen : {0, -1, 1000, std::numeric_limits<int32_t>::max()}) {
    const auto c = parse(first + header(1, channellen, 0) + bytes(1100, 'A'));
    EXPECT_EQ(c.records.size(), 1u) << channellen;
    EXPECT_TRUE(c.truncated);
  }
  EXPECT_EQ(parse(first + header(1, 1, -5) + bytes(10, 'A')).records.size(), 1u);
  // A file on disk goes through the same reader.
  TempDir dir;
  const auto b = first + header(1, 1, std::numeric_limits<int32_t>::max()) + bytes(4096, 3);
  std::ofstream(dir / "big.lcmlog", std::ios::binary).write(reinterpret_cast<const char*>(b.data()), b.size());
  const auto c = read_event_log(dir / "big.lcmlog");
  EXPECT_EQ(c.records.size(), 1u);
  EXPECT_TRUE(c.truncated);
}

TEST(EventLog, ReadsAsLcmDoes) {
  const auto a = event(5, "CHAN", bytes(3, 1)), b = event(6, "B", {}), c = event(7, "C", bytes(2, 9));
  const auto all = parse(a + b + c);
  ASSERT_EQ(all.records.size(), 3u);
  EXPECT_EQ(all.records[0].eventnum, 5);
  EXPECT_EQ(all.records[0].timestamp, 77);
  EXPECT_EQ(all.records[0].channel, "CHAN");
  EXPECT_EQ(all.records[1].data.size(), 0u);
  EXPECT_FALSE(all.truncated);
  // Bytes before the first sync word are skipped (and reported).
  const auto lead = parse(bytes(7, 0x55) + a + b);
  EXPECT_EQ(lead.records.size(), 2u);
  EXPECT_TRUE(lead.truncated);
  // An event followed by four bytes that are not a sync word is dropped, and
  // reading stops there.
  const auto garbage = parse(a + bytes(4, 0) + b);
  EXPECT_EQ(garbage.records.size(), 0u);
  EXPECT_TRUE(garbage.truncated);
  // One to three stray bytes at the end cannot be a header: the event stays.
  const auto stray = parse(a + b + bytes(3, 0));
  EXPECT_EQ(stray.records.size(), 2u);
  EXPECT_TRUE(stray.truncated);
  // No sync word at all, and nothing at all.
  EXPECT_EQ(parse(bytes(100, 0xED)).records.size(), 0u);
  EXPECT_TRUE(parse(bytes(100, 0xED)).truncated);
  EXPECT_FALSE(parse({}).truncated);
  TempDir dir;
  std::ofstream(dir / "empty.lcmlog").close();
  EXPECT_EQ(read_event_log(dir / "empty.lcmlog").records.size(), 0u);
  EXPECT_FALSE(read_event_log(dir / "empty.lcmlog").truncated);
  EXPECT_THROW(read_event_log(dir.path), std::runtime_error);  // a folder
}

TEST(EventLog, ParsesWhatTheWriterWrote) {
  TempDir dir;
  {
    auto log = EventLogWriter::create(dir / "a.lcmlog");
    log.write("ROBOZOO_POSE", bytes(1000, 4), 10);
    log.write("X", bytes(1, 5), 20);
  }
  std::ifstream in(dir / "a.lcmlog", std::ios::binary);
  const std::vector<uint8_t> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto c = parse(b);
  ASSERT_EQ(c.records.size(), 2u);
  EXPECT_EQ(c.records[0].channel, "ROBOZOO_POSE");
  EXPECT_EQ(c.records[0].data, bytes(1000, 4));
  EXPECT_EQ(c.records[1].eventnum, 1);
  EXPECT_EQ(c.records[1].timestamp, 20);
  EXPECT_FALSE(c.truncated);
  EXPECT_EQ(c.event_bytes, static_cast<int64_t>(b.size()));
}

}  // namespace
}  // namespace robozoo
