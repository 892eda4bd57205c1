#include "runlog/read/log_stream.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace robozoo {
namespace {

namespace fs = std::filesystem;

void put_be(std::vector<uint8_t>& b, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

/// One LCM log event: sync word, event number, time stamp, lengths, channel, data.
void event(std::vector<uint8_t>& b, int64_t number, const std::string& channel, size_t data_bytes) {
  put_be(b, kLcmLogSyncWord, 4);
  put_be(b, static_cast<uint64_t>(number), 8);
  put_be(b, static_cast<uint64_t>(1000 + number), 8);
  put_be(b, channel.size(), 4);
  put_be(b, data_bytes, 4);
  b.insert(b.end(), channel.begin(), channel.end());
  for (size_t i = 0; i < data_bytes; ++i) b.push_back(static_cast<uint8_t>(i * 31 + number));
}

class LogStream : public ::testing::Test {
 protected:
  fs::path path = fs::temp_directory_path() / ("robozoo_log_stream_" + std::to_string(::getpid()) + ".lcmlog");
  void TearDown() override { fs::remove(path); }
  void write(const std::vector<uint8_t>& b) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  }
  std::vector<LogRecord> read(size_t window) {
    std::vector<LogRecord> got;
    const int64_t n = for_each_event(path.string(), [&](const LogRecord& r) { got.push_back(r); }, {window});
    EXPECT_EQ(n, static_cast<int64_t>(got.size()));
    return got;
  }
};

TEST_F(LogStream, SameEventsAsTheWholeFileReaderForAnyWindow) {
  std::vector<uint8_t> b;
  for (int i = 0; i < 40; ++i) event(b, i, i % 3 ? "ROBOZOO_POSE" : "ROBOZOO_GENERATION", (i * 37) % 300);
  event(b, 40, "BIG", 5000);  // longer than the small windows
  write(b);
  const ScannedLog whole = scan_event_log(path.string());
  ASSERT_EQ(whole.contents.records.size(), 41u);
  for (size_t window : {64u, 100u, 333u, 4096u, 1u << 20}) {
    const std::vector<LogRecord> got = read(window);
    ASSERT_EQ(got.size(), whole.contents.records.size()) << window;
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].eventnum, whole.contents.records[i].eventnum);
      EXPECT_EQ(got[i].timestamp, whole.contents.records[i].timestamp);
      EXPECT_EQ(got[i].channel, whole.contents.records[i].channel);
      EXPECT_EQ(got[i].data, whole.contents.records[i].data) << window << " " << i;
    }
  }
}

TEST_F(LogStream, CutLastEventIsDamageAfterTheGoodOnes) {
  std::vector<uint8_t> b;
  for (int i = 0; i < 5; ++i) event(b, i, "C", 50);
  b.resize(b.size() - 20);
  write(b);
  int seen = 0;
  try {
    for_each_event(path.string(), [&](const LogRecord&) { ++seen; }, {128});
    FAIL() << "no damage reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
  }
  EXPECT_EQ(seen, 4);
}

TEST_F(LogStream, GarbageBetweenEventsIsDamageWithItsFileOffset) {
  std::vector<uint8_t> b;
  for (int i = 0; i < 3; ++i) event(b, i, "C", 50);
  const size_t garbage_at = b.size();
  b.insert(b.end(), {'j', 'u', 'n', 'k'});
  for (int i = 3; i < 6; ++i) event(b, i, "C", 50);
  write(b);
  try {
    read(100);
    FAIL() << "no damage reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(garbage_at)), std::string::npos) << e.what();
  }
}

TEST_F(LogStream, MissingEventNumbersAcrossWindowsAreDamage) {
  std::vector<uint8_t> b;
  for (int i : {0, 1, 2, 5, 6}) event(b, i, "C", 60);
  write(b);
  EXPECT_THROW(read(90), std::runtime_error);
}

TEST_F(LogStream, FileWithoutEventsIsNotAnLcmLog) {
  write({'h', 'e', 'l', 'l', 'o', '\n'});
  try {
    read(64);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no LCM events in 6 bytes: not an LCM log"), std::string::npos) << e.what();
  }
  write({});
  EXPECT_TRUE(read(64).empty());  // an empty file: nothing to hand on, no damage
}

TEST_F(LogStream, MissingFileNamesThePath) {
  try {
    for_each_event("/nonexistent/x.lcmlog", [](const LogRecord&) {});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.lcmlog"), std::string::npos);
  }
}

}  // namespace
}  // namespace robozoo
