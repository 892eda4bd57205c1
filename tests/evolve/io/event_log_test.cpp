#include "evolve/io/event_log.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

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

}  // namespace
}  // namespace robozoo
