// robozoo-log export, checked with the MCAP format's own library: tiny runs of
// every kind robozoo-evolve writes (feed-forward, recurrent, with poses, with
// hardly any, without any, every genome published, resumed) exported with each compression
// and read by tests/tools/log/mcap_check.cjs under Debian's node with @mcap/core
// and ajv (installed by tools/npm_deps.sh into build/npm).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::testing {
namespace {

namespace fs = std::filesystem;

// M1/M2's bias input 1.0, at which a feed-forward CPPN grows robots before any mutation.
const std::vector<std::string> kTiny = {"--seed",  "5",     "--population",         "10", "--steps", "300",
                                        "--quiet", "--set", "growth.bias_input=1.0"};

fs::path work_dir() { return fs::temp_directory_path() / ("robozoo_log_export_" + std::to_string(::getpid())); }

std::string source(const std::string& rel) { return std::string(ROBOZOO_SOURCE_DIR) + "/" + rel; }

class LogExport : public ::testing::Test {
 protected:
  static inline std::map<std::string, fs::path> logs;
  static inline std::string node_modules;

  static void SetUpTestSuite() {
    fs::create_directories(work_dir());
    const Outcome npm =
        run_shell("'" + source("tools/npm_deps.sh") + "' '" + std::string(ROBOZOO_BIN_DIR) + "/../npm'");
    ASSERT_EQ(npm.status, 0) << npm.output;
    node_modules = npm.output.substr(npm.output.rfind('\n', npm.output.size() - 2) + 1);
    while (!node_modules.empty() && node_modules.back() == '\n') node_modules.pop_back();
  }

  /// The log of one kind of run, evolved on first use (ctest runs each test in a process of its own).
  static fs::path log_of(const std::string& name) {
    if (logs.count(name)) return logs[name];
    auto evolve = [](const fs::path& log, std::vector<std::string> extra, int generations) {
      std::vector<std::string> size = kTiny;
      size.insert(size.end(), {"--generations", std::to_string(generations)});
      const Outcome o = run_shell(join(evolve_args(log.string(), 2, extra, size)));
      EXPECT_EQ(o.status, 0) << log << ": " << o.output;
    };
    const fs::path log = work_dir() / (name + ".lcmlog");
    if (name == "feedforward") evolve(log, {"--regime", "feedforward", "--pose-every", "10"}, 3);
    if (name == "recurrent") evolve(log, {"--regime", "recurrent", "--pose-every", "10"}, 3);
    if (name == "few-poses") evolve(log, {"--regime", "recurrent", "--pose-every", "1000000", "--publish-all"}, 2);
    if (name == "resumed") {
      evolve(log, {"--regime", "recurrent", "--pose-every", "25"}, 2);
      evolve(log, {"--regime", "recurrent", "--pose-every", "25", "--resume"}, 3);  // one generation more
    }
    if (name == "no-poses") {  // the recurrent run's log without its pose events
      EventLogWriter out = EventLogWriter::create(log.string());
      for (const LogRecord& r : read_event_log(log_of("recurrent").string()).records)
        if (r.channel != "ROBOZOO_POSE") out.write(r.channel, r.data, r.timestamp);
      out.sync();
    }
    EXPECT_TRUE(fs::exists(log)) << name;
    return logs[name] = log;
  }
  static void TearDownTestSuite() { fs::remove_all(work_dir()); }

  /// Exports `name`'s log, then checks it with @mcap/core; returns mcap_check's line.
  std::string export_and_check(const std::string& name, const std::string& compression) {
    const fs::path log = log_of(name);
    const fs::path out = work_dir() / (name + "-" + compression + ".mcap");
    const fs::path summary = work_dir() / (name + "-summary.json");
    const Outcome s =
        run_shell("'" + bin("robozoo-log") + "' summary --json '" + log.string() + "' > '" + summary.string() + "'");
    EXPECT_EQ(s.status, 0) << s.output;
    const Outcome e = run_shell("'" + bin("robozoo-log") + "' export '" + log.string() + "' -o '" + out.string() +
                                "' --compression " + compression + " --chunk-kib 64");
    EXPECT_EQ(e.status, 0) << e.output;
    EXPECT_FALSE(fs::exists(out.string() + ".partial"));
    const Outcome c = run_shell("node '" + source("tests/tools/log/mcap_check.cjs") + "' '" + node_modules + "' '" +
                                out.string() + "' '" + summary.string() + "'");
    EXPECT_EQ(c.status, 0) << c.output;
    return c.output;
  }
};

TEST_F(LogExport, FeedForwardRunWithPosesZstd) {
  const std::string line = export_and_check("feedforward", "zstd");
  EXPECT_NE(line.find("\"compression\":\"zstd\""), std::string::npos) << line;
  EXPECT_EQ(line.find("\"scenes\":0,"), std::string::npos) << "poses expected: " << line;
}

TEST_F(LogExport, FrameDrawnFromTheFileHasOneCirclePerSphere) {
  export_and_check("feedforward", "zstd");
  const fs::path mcap = work_dir() / "feedforward-zstd.mcap", svg = work_dir() / "frame.svg";
  const Outcome o = run_shell("node '" + source("tools/log/mcap_frame.cjs") + "' '" + node_modules + "' '" +
                              mcap.string() + "' '" + svg.string() + "' --index 0");
  ASSERT_EQ(o.status, 0) << o.output;
  const size_t at = o.output.find(" spheres");
  ASSERT_NE(at, std::string::npos) << o.output;
  const size_t from = o.output.rfind(' ', at - 1) + 1;
  const int spheres = std::stoi(o.output.substr(from, at - from));
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int circles = 0;
  for (size_t p = text.find("<circle "); p != std::string::npos; p = text.find("<circle ", p + 1)) ++circles;
  EXPECT_GT(spheres, 0);
  EXPECT_EQ(circles, spheres) << o.output;
  EXPECT_NE(text.find("/robot/scene #0 "), std::string::npos);
  EXPECT_EQ(run_shell("node '" + source("tools/log/mcap_frame.cjs") + "' --bogus").status, 2);
}

TEST_F(LogExport, RecurrentRunLz4) {
  const std::string line = export_and_check("recurrent", "lz4");
  EXPECT_NE(line.find("\"compression\":\"lz4\""), std::string::npos) << line;
}

TEST_F(LogExport, UncompressedChunks) {
  const std::string line = export_and_check("recurrent", "none");
  EXPECT_NE(line.find("\"compression\":\"\""), std::string::npos) << line;
}

TEST_F(LogExport, EveryGenomePublishedFewPoses) { export_and_check("few-poses", "zstd"); }

TEST_F(LogExport, RunWithoutPosesHasNoScenes) {
  const std::string line = export_and_check("no-poses", "zstd");
  EXPECT_NE(line.find("\"scenes\":0,"), std::string::npos) << line;
  EXPECT_EQ(line.find("/robot/scene"), std::string::npos) << line;
}

TEST_F(LogExport, ResumedRun) {
  const std::string line = export_and_check("resumed", "zstd");
  EXPECT_NE(line.find("\"/generation/stats\":3"), std::string::npos) << line;
}

TEST_F(LogExport, CheckerCatchesAFlippedByte) {
  export_and_check("recurrent", "none");
  const fs::path good = work_dir() / "recurrent-none.mcap", bad = work_dir() / "flipped.mcap";
  fs::copy_file(good, bad, fs::copy_options::overwrite_existing);
  {
    std::fstream f(bad, std::ios::in | std::ios::out | std::ios::binary);
    const auto middle = static_cast<std::streamoff>(fs::file_size(bad) / 2);
    f.seekg(middle);
    const char c = static_cast<char>(f.get());
    f.seekp(middle);
    f.put(static_cast<char>(c ^ 0x01));
  }
  const fs::path summary = work_dir() / "recurrent-summary.json";
  const Outcome c = run_shell("node '" + source("tests/tools/log/mcap_check.cjs") + "' '" + node_modules + "' '" +
                              bad.string() + "' '" + summary.string() + "'");
  EXPECT_NE(c.status, 0) << c.output;
  EXPECT_NE(c.output.find("CRC"), std::string::npos) << c.output;
}

TEST_F(LogExport, SmallChunksMakeManyChunks) {
  const fs::path out = work_dir() / "small-chunks.mcap";
  const Outcome e = run_shell("'" + bin("robozoo-log") + "' export '" + log_of("feedforward").string() + "' -o '" +
                              out.string() + "' --chunk-kib 1");
  ASSERT_EQ(e.status, 0) << e.output;
  const size_t at = e.output.find(" chunks");
  ASSERT_NE(at, std::string::npos) << e.output;
  const size_t from = e.output.rfind(' ', at - 1) + 1;
  EXPECT_GT(std::stoi(e.output.substr(from, at - from)), 10) << e.output;
}

TEST_F(LogExport, DamagedLogIsRefusedWithOneLine) {
  const fs::path damaged = work_dir() / "damaged.lcmlog";
  fs::copy_file(log_of("recurrent"), damaged, fs::copy_options::overwrite_existing);
  fs::resize_file(damaged, fs::file_size(damaged) - 100);  // the last event cut
  const fs::path out = work_dir() / "damaged.mcap";
  const Outcome e =
      run_shell("'" + bin("robozoo-log") + "' export '" + damaged.string() + "' -o '" + out.string() + "'");
  EXPECT_NE(e.status, 0);
  EXPECT_NE(e.output.find("damaged"), std::string::npos) << e.output;
  EXPECT_EQ(std::count(e.output.begin(), e.output.end(), '\n'), 1) << e.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

TEST_F(LogExport, UnwritablePathIsRefusedWithOneLine) {
  const Outcome e = run_shell("'" + bin("robozoo-log") + "' export '" + log_of("recurrent").string() +
                              "' -o /nonexistent-dir/x.mcap");
  EXPECT_NE(e.status, 0);
  EXPECT_NE(e.output.find("/nonexistent-dir/x.mcap.partial: cannot create"), std::string::npos) << e.output;
  EXPECT_EQ(std::count(e.output.begin(), e.output.end(), '\n'), 1) << e.output;
}

TEST_F(LogExport, UnknownCompressionAndOptionsAreRefused) {
  const std::string log = log_of("recurrent").string();
  EXPECT_NE(run_shell("'" + bin("robozoo-log") + "' export '" + log + "' -o /tmp/x.mcap --compression gzip").status, 0);
  EXPECT_NE(run_shell("'" + bin("robozoo-log") + "' export '" + log + "' -o /tmp/x.mcap --bogus").status, 0);
  EXPECT_NE(run_shell("'" + bin("robozoo-log") + "' export '" + log + "'").status, 0);  // no -o
  const Outcome help = run_shell("'" + bin("robozoo-log") + "' export --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--compression"), std::string::npos);
}

}  // namespace
}  // namespace robozoo::testing
