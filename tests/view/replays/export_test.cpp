// One-file replays: the frames of a log's champion, the self-contained page
// that carries them, the atomic write, and robozoo-view export's errors.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <algorithm>
#include <fstream>

#include "evolve/io/event_log.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/subprocess.hpp"
#include "view/replays/export.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::render::testing;
using robozoo::testing::TempDir;

/// A run of two generations: genome 1 (generation 0, fitness 2.5) and genome 2
/// (generation 1, fitness 3.5) are champions with the known robot; genome 2
/// has `poses` poses, moved 1 mm along x per step, genome 1 has 3.
void write_log(const std::string& path, int poses) {
  EventLogWriter w = EventLogWriter::create(path);
  append(w, kChannelRun, run_message("r"));
  const int64_t ids[2] = {1, 2};
  const int counts[2] = {3, poses};
  for (int g = 0; g < 2; ++g) {
    append(w, kChannelGenome, genome_message("r", g, ids[g], 2.5 + g));
    append(w, kChannelMorphology, morphology_message("r", g, ids[g]));
    for (int s = 0; s < counts[g]; ++s) append(w, kChannelPose, pose_message("r", g, ids[g], 4 * s, 0.001 * s));
    append(w, kChannelGeneration, generation_message("r", g, ids[g]));
  }
}

AssetDirs source_dirs() { return {std::string(ROBOZOO_SOURCE_DIR) + "/view/page", ROBOZOO_THREE_DIR}; }

TEST(ChampionFrames, DefaultIsTheLastChampionWithAllItsPoses) {
  TempDir d;
  write_log(d / "run.lcmlog", 7);
  ExportOptions o;
  o.log = d / "run.lcmlog";
  const nlohmann::json f = champion_frames(o);
  ASSERT_EQ(f.size(), 6u);
  EXPECT_EQ(f[0]["t"], "hello");
  EXPECT_EQ(f[0]["mode"], "file");
  EXPECT_EQ(f[0]["source"], "run.lcmlog");
  EXPECT_EQ(f[1]["t"], "run");
  EXPECT_EQ(f[1]["id"], "r");
  EXPECT_EQ(f[2]["t"], "history");
  EXPECT_EQ(f[2]["gens"].size(), 2u);
  EXPECT_EQ(f[2]["gens"][1]["best"], 16.0);  // generation_message: 15 + g
  EXPECT_EQ(f[3]["list"].size(), 1u);
  EXPECT_EQ(f[3]["list"][0]["id"], 2);
  EXPECT_EQ(f[4]["t"], "robot");
  EXPECT_EQ(f[4]["id"], 2);
  EXPECT_EQ(f[4]["radius"].size(), 4u);  // the known robot
  EXPECT_EQ(f[4]["leaf"], nlohmann::json::array({0, 0, 1, 1}));
  EXPECT_EQ(f[5]["t"], "poses");
  EXPECT_EQ(f[5]["done"], true);
  EXPECT_EQ(f[5]["resimulated"], false);
  ASSERT_EQ(f[5]["list"].size(), 7u);
  EXPECT_EQ(f[5]["list"][6]["step"], 24);
  // Sphere 0 of the known robot is at x 0, moved 6 mm by the last pose (0.1 mm units).
  EXPECT_NEAR(f[5]["list"][6]["c"][0].get<double>(), 0.006, 1e-12);
}

TEST(ChampionFrames, AGenomeByIdAndTheErrors) {
  TempDir d;
  write_log(d / "run.lcmlog", 5);
  ExportOptions o;
  o.log = d / "run.lcmlog";
  o.genome = 1;
  const nlohmann::json f = champion_frames(o);
  EXPECT_EQ(f[4]["id"], 1);
  EXPECT_EQ(f[5]["list"].size(), 3u);

  o.genome = 99;
  try {
    champion_frames(o);
    FAIL() << "genome 99 exported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no genome 99"), std::string::npos) << e.what();
  }
  o.genome.reset();
  o.log = d / "missing.lcmlog";
  EXPECT_THROW(champion_frames(o), std::runtime_error);
  // Damaged: garbage after the events.
  std::filesystem::copy_file(d / "run.lcmlog", d / "bad.lcmlog");
  std::ofstream(d / "bad.lcmlog", std::ios::app) << "not an event, just bytes at the end of the log";
  o.log = d / "bad.lcmlog";
  EXPECT_THROW(champion_frames(o), std::runtime_error);
  o.allow_truncated = true;  // a log being written: its complete events
  EXPECT_EQ(champion_frames(o)[4]["id"], 2);
}

/// The text of <script type="application/json" id="robozoo-data">.
std::string inline_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"robozoo-data\">";
  const size_t a = html.find(open);
  if (a == std::string::npos) return "";
  const size_t b = html.find("</script>", a);
  return html.substr(a + open.size(), b - a - open.size());
}

TEST(OfflinePage, CarriesTheFramesThePageAndThreeJs) {
  nlohmann::json frames = nlohmann::json::array({{{"t", "hello"}, {"source", "a </script><!-- b"}}});
  const std::string html = offline_page(source_dirs(), frames);
  EXPECT_EQ(nlohmann::json::parse(inline_data(html)), frames);  // '<' escaped, so the element ends where it should
  EXPECT_EQ(html.find("</script><!-- b"), std::string::npos);
  // Nothing left to fetch: no src= or href= to the server, one import map, the page's modules in it.
  EXPECT_EQ(html.find("src=\""), std::string::npos);
  EXPECT_EQ(html.find("href=\"/"), std::string::npos);
  const std::string open = "<script type=\"importmap\">";
  const size_t map_at = html.find(open);
  ASSERT_NE(map_at, std::string::npos);
  const nlohmann::json map =
      nlohmann::json::parse(html.substr(map_at + open.size(), html.find("</script>", map_at) - map_at - open.size()));
  for (const char* k : {"three", "rz/view.js", "rz/offline.js", "rz/scene.js", "rz/playback.js",
                        "rz/three/examples/jsm/controls/OrbitControls.js"})
    EXPECT_TRUE(map["imports"].contains(k)) << k;
  for (const auto& [k, v] : map["imports"].items())
    EXPECT_EQ(v.get<std::string>().rfind("data:text/javascript;base64,", 0), 0u) << k;
  EXPECT_EQ(html.find("<script type=\"importmap\">"), html.rfind("<script type=\"importmap\">"));
  EXPECT_NE(html.find("<script type=\"module\">import \"rz/view.js\";</script>"), std::string::npos);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  for (size_t a = html.find("<style>"); a != std::string::npos; a = html.find("<style>", a + 1))  // scripts outside
    EXPECT_EQ(html.substr(a, html.find("</style>", a) - a).find("<script"), std::string::npos);
  // three.min.js, in a classic script before the import map.
  const size_t three = html.find("<script>\n");
  ASSERT_NE(three, std::string::npos);
  EXPECT_LT(three, html.find("<script type=\"importmap\">"));
  EXPECT_GT(html.size(), 800'000u);
}

TEST(OfflinePage, MissingPageFilesAreNamed) {
  AssetDirs dirs = source_dirs();
  dirs.three = "/nonexistent/three";
  try {
    offline_page(dirs, nlohmann::json::array());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/three"), std::string::npos) << e.what();
  }
}

TEST(WriteWholeFile, AllOrNothing) {
  TempDir d;
  write_whole_file(d / "a.html", "hello");
  std::ifstream in(d / "a.html");
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "hello");
  EXPECT_FALSE(std::filesystem::exists(d / "a.html.partial"));
  EXPECT_THROW(write_whole_file(d / "no/such/folder/a.html", "x"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(d / "no"));
}

TEST(ExportCommand, WritesTheFileAndRefusesBadInput) {
  TempDir d;
  const std::string log = d / "run.lcmlog", out = d / "c.html", x = d / "x.html";
  write_log(log, 6);
  const std::string view = robozoo::testing::bin("robozoo-view") + " export ";
  robozoo::testing::Outcome o = robozoo::testing::run_shell(view + log + " -o " + out);
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("genome 2"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(" MB"), std::string::npos) << o.output;
  std::ifstream in(out);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json frames = nlohmann::json::parse(inline_data(html));
  EXPECT_EQ(frames[4]["id"], 2);
  EXPECT_EQ(frames[5]["list"].size(), 6u);

  const auto refused = [&](const std::string& args, const std::string& says) {
    const robozoo::testing::Outcome r = robozoo::testing::run_shell(view + args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.output.find(says), std::string::npos) << args << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << ": " << r.output;
  };
  refused(log + " --genome 77 -o " + x, "no genome 77");
  const std::string none = d / "none.lcmlog";
  refused(none + " -o " + x, "none.lcmlog");
  const std::string nowhere = d / "nofolder";
  refused(log + " -o " + nowhere + "/x.html", "cannot write");
  EXPECT_FALSE(std::filesystem::exists(x));
  EXPECT_FALSE(std::filesystem::exists(x + ".partial"));
  EXPECT_NE(robozoo::testing::run_shell(view + log + " -o " + x + " --bogus").status, 0);
  EXPECT_EQ(robozoo::testing::run_shell(view + "--help").status, 0);
}

}  // namespace
}  // namespace robozoo::view
