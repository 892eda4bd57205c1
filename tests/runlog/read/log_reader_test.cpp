#include "runlog/read/log_reader.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

std::vector<uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put_file(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

/// A log of `n` events on two channels, payloads of different lengths.
std::string make_log(const TempDir& dir, int n) {
  const std::string path = dir / "in.lcmlog";
  EventLogWriter w = EventLogWriter::create(path);
  for (int i = 0; i < n; ++i) {
    std::vector<uint8_t> data(static_cast<size_t>(10 + 7 * i));
    for (size_t k = 0; k < data.size(); ++k) data[k] = static_cast<uint8_t>(i * 31 + k);
    w.write(i % 3 == 0 ? "LCM_SELF_TEST" : "ROBOZOO_POSE", data, 1000 + i);
  }
  w.sync();
  return path;
}

void expect_same_records(const LogContents& a, const LogContents& b) {
  ASSERT_EQ(a.records.size(), b.records.size());
  for (size_t i = 0; i < a.records.size(); ++i) {
    EXPECT_EQ(a.records[i].eventnum, b.records[i].eventnum) << i;
    EXPECT_EQ(a.records[i].timestamp, b.records[i].timestamp) << i;
    EXPECT_EQ(a.records[i].channel, b.records[i].channel) << i;
    EXPECT_EQ(a.records[i].data, b.records[i].data) << i;
  }
}

TEST(LogReader, IntactLogReadsAsLcmReadsItWithNoDamage) {
  TempDir dir;
  const std::string path = make_log(dir, 7);
  const ScannedLog s = scan_event_log(path);
  EXPECT_TRUE(s.damage.empty());
  EXPECT_FALSE(s.contents.truncated);
  expect_same_records(s.contents, read_event_log(path));
  ASSERT_EQ(s.offsets.size(), 7u);
  EXPECT_EQ(s.offsets[0], 0);
  EXPECT_EQ(s.offsets[1], 28 + 13 + 10);  // header, "LCM_SELF_TEST", 10 bytes
}

TEST(LogReader, GarbageBetweenEventsIsSkippedAndReportedWithItsOffset) {
  TempDir dir;
  const std::string path = make_log(dir, 6);
  const ScannedLog clean = scan_event_log(path);
  std::vector<uint8_t> b = file_bytes(path);
  const int64_t at = clean.offsets[3];
  const std::vector<uint8_t> garbage = {1, 2, 3, 0xED, 0xA1, 4, 5, 6, 7, 8, 9};
  b.insert(b.begin() + at, garbage.begin(), garbage.end());
  put_file(dir / "garbage.lcmlog", b);
  const ScannedLog s = scan_event_log(dir / "garbage.lcmlog");
  expect_same_records(s.contents, clean.contents);
  // (LCM 1.3.1's own reader stops here: "Invalid header after log data".)
  ASSERT_EQ(s.damage.size(), 1u);
  EXPECT_EQ(s.damage[0].kind, LogDamage::Kind::Garbage);
  EXPECT_EQ(s.damage[0].offset, at);
  EXPECT_EQ(s.damage[0].bytes, static_cast<int64_t>(garbage.size()));
  EXPECT_EQ(s.damage[0].after_event, 2);
  EXPECT_NE(s.damage[0].describe().find("11 bytes"), std::string::npos) << s.damage[0].describe();
}

TEST(LogReader, OverwrittenEventIsReportedAsGarbageAndMissingEvent) {
  TempDir dir;
  const std::string path = make_log(dir, 6);
  const ScannedLog clean = scan_event_log(path);
  std::vector<uint8_t> b = file_bytes(path);
  for (int k = 0; k < 6; ++k) b[clean.offsets[2] + k] = 0x55;  // its sync word and event number
  put_file(dir / "hole.lcmlog", b);
  const ScannedLog s = scan_event_log(dir / "hole.lcmlog");
  ASSERT_EQ(s.contents.records.size(), 5u);
  EXPECT_EQ(s.contents.records[2].eventnum, 3);
  ASSERT_EQ(s.damage.size(), 2u);
  EXPECT_EQ(s.damage[0].kind, LogDamage::Kind::Garbage);
  EXPECT_EQ(s.damage[0].offset, clean.offsets[2]);
  EXPECT_EQ(s.damage[0].bytes, clean.offsets[3] - clean.offsets[2]);
  EXPECT_EQ(s.damage[1].kind, LogDamage::Kind::MissingEvents);
  EXPECT_EQ(s.damage[1].after_event, 1);
  EXPECT_EQ(s.damage[1].next_event, 3);
  EXPECT_NE(s.damage[1].describe().find("1 events missing"), std::string::npos) << s.damage[1].describe();
}

TEST(LogReader, CutLastEventIsReportedAsTruncated) {
  TempDir dir;
  const std::string path = make_log(dir, 5);
  const ScannedLog clean = scan_event_log(path);
  std::vector<uint8_t> b = file_bytes(path);
  b.resize(b.size() - 4);
  put_file(dir / "cut.lcmlog", b);
  const ScannedLog s = scan_event_log(dir / "cut.lcmlog");
  EXPECT_EQ(s.contents.records.size(), 4u);
  EXPECT_TRUE(s.contents.truncated);
  ASSERT_EQ(s.damage.size(), 1u);
  EXPECT_EQ(s.damage[0].kind, LogDamage::Kind::Truncated);
  EXPECT_EQ(s.damage[0].offset, clean.offsets[4]);
  EXPECT_EQ(s.damage[0].bytes, static_cast<int64_t>(b.size()) - clean.offsets[4]);
}

TEST(LogReader, SyncWordInGarbageWithAbsurdLengthsDoesNotStopTheReading) {
  TempDir dir;
  const std::string path = make_log(dir, 4);
  const ScannedLog clean = scan_event_log(path);
  std::vector<uint8_t> b = file_bytes(path);
  // A fake header: sync word, event number, timestamp, channel length -5, data length 2^31-1.
  std::vector<uint8_t> fake = {0xED, 0xA1, 0xDA, 0x01};
  fake.insert(fake.end(), 16, 0);
  for (uint8_t x : {0xFF, 0xFF, 0xFF, 0xFB, 0x7F, 0xFF, 0xFF, 0xFF}) fake.push_back(x);
  b.insert(b.begin() + clean.offsets[2], fake.begin(), fake.end());
  put_file(dir / "fake.lcmlog", b);
  const ScannedLog s = scan_event_log(dir / "fake.lcmlog");
  expect_same_records(s.contents, clean.contents);
  ASSERT_EQ(s.damage.size(), 1u);
  EXPECT_EQ(s.damage[0].kind, LogDamage::Kind::Garbage);
  EXPECT_EQ(s.damage[0].bytes, static_cast<int64_t>(fake.size()));
}

TEST(LogReader, EmptyFileHasNoEventAndNoDamage) {
  const ScannedLog s = scan_event_log_bytes({});
  EXPECT_TRUE(s.contents.records.empty());
  EXPECT_TRUE(s.damage.empty());
}

TEST(LogReader, UnreadablePathsThrowNamingThePath) {
  TempDir dir;
  EXPECT_THROW(scan_event_log(dir / "missing.lcmlog"), std::runtime_error);
  try {
    scan_event_log(dir.path);
    FAIL() << "a directory was read as a log";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.path), std::string::npos);
  }
}

}  // namespace
}  // namespace robozoo
