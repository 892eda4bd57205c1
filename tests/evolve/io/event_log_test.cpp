#include "evolve/io/event_log.hpp"

#include <gtest/gtest.h>

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
