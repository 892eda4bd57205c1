#include "runlog/read/log_source.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

std::string error_of(const std::string& path, LoadOptions o = {}) {
  try {
    load_log(path, o);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(LogSource, ReadsARealRun) {
  TempDir dir;
  render::testing::write_small_run(dir / "run.lcmlog");
  const LoadedLog log = load_log(dir / "run.lcmlog");
  ASSERT_EQ(log.runs().size(), 1u);
  const RunRecord& run = *log.runs()[0];
  EXPECT_EQ(run.run.run_id, "feedforward-s7");
  EXPECT_EQ(run.generations.size(), 4u);
  EXPECT_GE(run.genomes.size(), 4u);
  int streams = 0;
  for (const auto& g : run.genomes) {
    EXPECT_TRUE(g->has_morphology);
    if (!g->poses.empty()) {
      ++streams;
      EXPECT_EQ(g->stream, GenomeRecord::Stream::Complete);
      EXPECT_EQ(g->poses.front().step, 0);
    }
  }
  EXPECT_GE(streams, 1);
  EXPECT_EQ(log.collector->stats().rejected(), 0);
  EXPECT_NE(describe(log).find("1 run(s)"), std::string::npos);
}

TEST(LogSource, MissingTruncatedAndForeignFiles) {
  TempDir dir;
  EXPECT_NE(error_of(dir / "none.lcmlog").find("no such log file"), std::string::npos);
  EXPECT_NE(error_of(dir.path).find("not a regular file"), std::string::npos);

  render::testing::write_small_run(dir / "run.lcmlog");
  const auto size = std::filesystem::file_size(dir / "run.lcmlog");
  std::filesystem::copy_file(dir / "run.lcmlog", dir / "cut.lcmlog");
  std::filesystem::resize_file(dir / "cut.lcmlog", size - 100);
  EXPECT_NE(error_of(dir / "cut.lcmlog").find("truncated"), std::string::npos);
  LoadOptions allow;
  allow.allow_truncated = true;
  const LoadedLog cut = load_log(dir / "cut.lcmlog", allow);
  EXPECT_TRUE(cut.truncated);
  EXPECT_EQ(cut.runs().size(), 1u);

  std::ofstream(dir / "text.lcmlog") << "this is not an LCM log at all";
  EXPECT_NE(error_of(dir / "text.lcmlog").find("not a robozoo-evolve log"), std::string::npos);
  std::ofstream(dir / "empty.lcmlog");
  EXPECT_NE(error_of(dir / "empty.lcmlog").find("not a robozoo-evolve log"), std::string::npos);
  {
    EventLogWriter w = EventLogWriter::create(dir / "other.lcmlog");
    w.write("SOMETHING_ELSE", {1, 2, 3}, 0);
    w.sync();
  }
  EXPECT_NE(error_of(dir / "other.lcmlog").find("no ROBOZOO_RUN message in 1 events"), std::string::npos);
}

TEST(LogSource, BadMessagesInALogAreCountedNotFatal) {
  TempDir dir;
  {
    EventLogWriter w = EventLogWriter::create(dir / "bad.lcmlog");
    render::testing::append(w, kChannelRun, render::testing::run_message("r"));
    w.write(kChannelGenome, {1, 2, 3}, 0);
    render::testing::append(w, kChannelGenome, render::testing::genome_message("r", 0, 5, 15.0));
    render::testing::append(w, kChannelMorphology, render::testing::morphology_message("r", 0, 5));
    w.sync();
  }
  const LoadedLog log = load_log(dir / "bad.lcmlog");
  EXPECT_EQ(log.collector->stats().undecodable, 1);
  EXPECT_TRUE(log.runs()[0]->find(5)->has_morphology);
  EXPECT_NE(describe(log).find("1 undecodable"), std::string::npos);
}

}  // namespace
}  // namespace robozoo
