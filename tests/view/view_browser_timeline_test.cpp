// robozoo-view's timeline, CPPN panel and strip in headless Chromium (software
// WebGL), on a hand-made log: three champions of one run, each a chain of 12
// spheres that sway, with 3 neurons and 91 sensors (94 traces) and a CPPN of
// 22 nodes and 14 links, 5 of them recurrent and 1 disabled. One view (log
// mode, a free port) and one browser serve every test; each test opens its
// own tab. ROBOZOO_VIEW_SHOTS=DIR keeps the screenshots.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <regex>
#include <thread>

#include "render/gl/png_io.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/subprocess.hpp"
#include "tests/support/wait_for.hpp"
#include "tests/view/screenshots.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::testing;
using namespace robozoo::render::testing;
using Clock = std::chrono::steady_clock;

constexpr int kSpheres = 12, kNeurons = 3, kSensors = 91;
constexpr int kSteps = 300, kPoseEvery = 4;  // 3 s of 0.01 s steps, a sample every 0.04 s
constexpr int kCppnNodes = 22, kCppnLinks = 14, kCppnRecurrent = 5, kCppnDisabled = 1;
const int64_t kChampions[3] = {101, 102, 103};

void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

/// A CPPN of the 20 inputs and outputs, hidden nodes 20 (Gaussian) and 21
/// (signed cosine) at position 0.5, and 14 links: 7 forward, 5 recurrent
/// (output to output twice, between the two hidden nodes of one position, a
/// self-loop, an output back to a hidden node) and 2 more forward, one disabled.
/// `k` varies one weight, so that each champion has genes of its own.
cppn_genome_t champion_genome(int32_t generation, int64_t id, int k) {
  cppn_genome_t g = genome_message("tl", generation, id, 20.0 + k);
  for (int32_t n = 0; n < 20; ++n)
    g.nodes.push_back({n, static_cast<int8_t>(n < 9 ? (n == 4 ? 1 : 0) : 2), 0, n < 9 ? 0.0 : 1.0});
  g.nodes.push_back({20, 3, 2, 0.5});
  g.nodes.push_back({21, 3, 1, 0.5});
  g.links = {{1, 0, 9, 2.0, true},    {2, 1, 10, -1.5, true},    {3, 2, 11, 0.7, true},    {4, 3, 20, 4.5, true},
             {5, 20, 12, -3.0, true}, {6, 4, 21, 1.0, true},     {7, 21, 13, -0.4, true},  {8, 9, 10, 1.2, true},
             {9, 13, 9, -2.2, true},  {10, 20, 21, 0.9, true},   {11, 21, 21, -1.1, true}, {12, 12, 20, 3.3, true},
             {13, 5, 14, 1.0, false}, {14, 6, 15, 0.5 + k, true}};
  g.num_nodes = static_cast<int32_t>(g.nodes.size());
  g.num_links = static_cast<int32_t>(g.links.size());
  return g;
}

morphology_t chain_robot(int32_t generation, int64_t id) {
  morphology_t m{};
  m.run_id = "tl";
  m.generation = generation;
  m.genome_id = id;
  for (int i = 0; i < kSpheres; ++i) {
    sphere_t s{};
    s.index = i;
    s.parent = i - 1;
    s.radius = 0.1 + 0.03 * (i % 3);
    s.center[0] = 0.22 * i;
    s.center[2] = 0.5;
    s.density = 1.0;
    m.spheres.push_back(s);
  }
  m.num_spheres = kSpheres;
  m.num_bodies = 1;
  m.num_neurons = kNeurons;
  m.tau.assign(kNeurons, 0.1);
  m.omega.assign(kNeurons, 0.0);
  m.num_sensors = kSensors;
  for (int s = 0; s < kSensors; ++s) {
    m.sensor_sphere.push_back(s % kSpheres);
    m.sensor_type.push_back(static_cast<int8_t>(s % 4));
    m.w_sensor_neuron.push_back(std::vector<double>(kNeurons, 0.1));
  }
  m.w_neuron_neuron.assign(kNeurons, std::vector<double>(kNeurons, 0.0));
  return m;
}

/// The log: per generation, the generation, its champion's genome and
/// morphology and its poses (the chain sways; neurons and sensors are waves).
void write_log(const std::string& path) {
  EventLogWriter w = EventLogWriter::create(path);
  run_t run = run_message("tl", kSteps);
  run.generations = 3;
  append(w, kChannelRun, run);
  int64_t t = 0;  // log time (us)
  for (int gen = 0; gen < 3; ++gen) {
    const int64_t id = kChampions[gen];
    append(w, kChannelGeneration, generation_message("tl", gen, id), t);
    append(w, kChannelGenome, champion_genome(gen, id, gen), t);
    const morphology_t m = chain_robot(gen, id);
    append(w, kChannelMorphology, m, t);
    for (int step = 0; step <= kSteps; step += kPoseEvery) {
      pose_t p{};
      p.run_id = "tl";
      p.generation = gen;
      p.genome_id = id;
      p.step = step;
      p.sim_time = 0.01 * step;
      p.num_bodies = 1;
      p.body_position = {{0, 0, 0.5}};
      p.body_quaternion = {{1, 0, 0, 0}};
      p.num_spheres = kSpheres;
      for (int i = 0; i < kSpheres; ++i) {
        const sphere_t& s = m.spheres[static_cast<size_t>(i)];
        const double phase = p.sim_time * 2.5 + 0.5 * i;
        p.sphere_center.push_back({s.center[0] + 0.2 * p.sim_time, s.center[1] + 0.35 * std::sin(phase),
                                   s.center[2] + 0.15 * std::cos(phase)});
      }
      p.num_neurons = kNeurons;
      for (int n = 0; n < kNeurons; ++n) p.neuron_output.push_back(std::sin(p.sim_time * (2 + n)));
      p.num_sensors = kSensors;
      for (int s = 0; s < kSensors; ++s) p.sensor_value.push_back(0.8 * std::cos(p.sim_time * 3 + 0.1 * s));
      t += 40000;
      append(w, kChannelPose, p, t);
    }
  }
  w.sync();
}

int sphere_pixels(const render::Image& img) {
  int n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const render::Rgb c = img.at(x, y);
      n += is_red(c.r, c.g, c.b) || is_blue(c.r, c.g, c.b);
    }
  return n;
}

class ViewTimeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    write_log(*dir_ / "tl.lcmlog");
    view_ = spawn({bin("robozoo-view"), *dir_ / "tl.lcmlog", "--port", "0", "--speed", "20"}, *dir_ / "view.txt");
    std::smatch m;
    std::string out;
    ASSERT_TRUE(wait_for(
        [&] {
          out = read_file(*dir_ / "view.txt");
          return std::regex_search(out, m, std::regex(R"(open (http://127\.0\.0\.1:\d+/))"));
        },
        20))
        << out;
    page_ = m[1];
    browser_ = new HeadlessBrowser(*dir_ / "profile", *dir_ / "chromium.txt");
  }
  static void TearDownTestSuite() {
    delete browser_;
    browser_ = nullptr;
    if (view_ > 1) {
      kill_process(view_, SIGTERM);
      wait_status(view_);
    }
    delete dir_;
  }

  /// A tab on `fragment` of the page, once it shows a champion whose samples are all there.
  std::string open(const std::string& fragment = "", int64_t robot = kChampions[2]) {
    // One tab at a time: a tab left behind is hidden, and a hidden tab draws no frames.
    // The reply is kept: a range-for over a member of the temporary reply would read freed memory.
    const nlohmann::json targets = browser_->call("Target.getTargets", nlohmann::json::object());
    for (const auto& t : targets["targetInfos"])
      if (t["type"] == "page") browser_->call("Target.closeTarget", {{"targetId", t["targetId"]}});
    const std::string tab = browser_->open(page_ + fragment);
    EXPECT_TRUE(wait_for(
        [&] {
          const auto j = timeline(tab);
          return !j.is_null() && j["robot"] == robot && j["done"] == true && j["samples"] == kSteps / kPoseEvery + 1;
        },
        60))
        << timeline(tab).dump() << read_file(*dir_ / "view.txt");
    return tab;
  }
  nlohmann::json eval(const std::string& tab, const std::string& js) { return browser_->evaluate(tab, js); }
  nlohmann::json timeline(const std::string& tab) {
    return eval(tab, "window.robozooView ? robozooView.timeline() : null");
  }
  /// The playhead (s); -1 before the first frame drew.
  double playhead(const std::string& tab) {
    const auto j = timeline(tab);
    return j["playhead"].is_number() ? j["playhead"].get<double>() : -1.0;
  }
  /// A screenshot of element `id` (saved as `name`, and kept in ROBOZOO_VIEW_SHOTS when set).
  render::Image shot(const std::string& tab, const std::string& id, const std::string& name) {
    return keep_png(browser_->screenshot(tab, eval(tab, "robozooView.rect('" + id + "')")), *dir_ / name);
  }

  static TempDir* dir_;
  static pid_t view_;
  static std::string page_;
  static HeadlessBrowser* browser_;
};
TempDir* ViewTimeline::dir_ = nullptr;
pid_t ViewTimeline::view_ = -1;
std::string ViewTimeline::page_;
HeadlessBrowser* ViewTimeline::browser_ = nullptr;

TEST_F(ViewTimeline, PausingHoldsThePictureStill) {
  const std::string tab = open();
  ASSERT_TRUE(wait_for([&] { return playhead(tab) > 0.3; }, 20)) << timeline(tab).dump();
  eval(tab, "robozooView.pause()");
  sleep_ms(300);
  const auto j0 = timeline(tab);
  const render::Image a = shot(tab, "stage", "paused-1.png");
  sleep_ms(800);
  const render::Image b = shot(tab, "stage", "paused-2.png");
  const auto j1 = timeline(tab);
  EXPECT_EQ(j0["playing"], false);
  EXPECT_EQ(j1["playhead"], j0["playhead"]);
  EXPECT_GT(sphere_pixels(a), 200) << "no robot drawn";
  EXPECT_EQ(changed_pixels(a, b), 0) << "the picture moved while paused";
  EXPECT_EQ(j1["following"], false);
  EXPECT_NE(j1["stateText"].get<std::string>().find("paused at"), std::string::npos) << j1.dump();
  // Playing again, it moves: the comparison above could fail.
  eval(tab, "robozooView.play()");
  sleep_ms(800);
  const render::Image c = shot(tab, "stage", "playing.png");
  EXPECT_GT(timeline(tab)["playhead"].get<double>(), j0["playhead"].get<double>());
  EXPECT_GT(changed_pixels(a, c), 100) << "playing, the picture did not change";
}

TEST_F(ViewTimeline, SeekingToATimeShowsThatPoseAndStepsGoOneSample) {
  const std::string tab = open();
  // Paused where playback has got to: that pose, as drawn while playing.
  ASSERT_TRUE(wait_for([&] { return playhead(tab) > 0.2; }, 20));
  eval(tab, "robozooView.pause()");
  const double t = timeline(tab)["playhead"].get<double>();
  ASSERT_LT(t, 1.5);
  sleep_ms(300);
  const render::Image there = shot(tab, "stage", "seek-there.png");
  eval(tab, "robozooView.seek(" + nlohmann::json(t + 1.3).dump() + ")");
  sleep_ms(300);
  const render::Image elsewhere = shot(tab, "stage", "seek-elsewhere.png");
  EXPECT_NEAR(timeline(tab)["playhead"].get<double>(), t + 1.3, 1e-9);
  eval(tab, "robozooView.seek(" + nlohmann::json(t).dump() + ")");
  sleep_ms(300);
  const render::Image back = shot(tab, "stage", "seek-back.png");
  EXPECT_GT(changed_pixels(there, elsewhere), 100) << "another time, yet the same picture";
  EXPECT_EQ(changed_pixels(there, back), 0) << "seeking back did not show the pose drawn at that time";

  // Samples every 0.04 s: from 1.00 s one forward is 1.04 s; from 1.02 s
  // (between two samples) one back is 1.00 s; stepping pauses.
  eval(tab, "robozooView.play(); robozooView.seek(1.0); robozooView.step(1)");
  auto j = timeline(tab);
  EXPECT_NEAR(j["playhead"].get<double>(), 1.04, 1e-9);
  EXPECT_EQ(j["playing"], false);
  EXPECT_EQ(j["pose"]["a"], 104);
  eval(tab, "robozooView.seek(1.02); robozooView.step(-1)");
  EXPECT_NEAR(timeline(tab)["playhead"].get<double>(), 1.0, 1e-9);
  // Keys: right arrow one sample forward, space plays.
  eval(tab, "document.body.focus(); window.dispatchEvent(new KeyboardEvent('keydown', {key: 'ArrowRight'}))");
  EXPECT_NEAR(timeline(tab)["playhead"].get<double>(), 1.04, 1e-9);
  eval(tab, "window.dispatchEvent(new KeyboardEvent('keydown', {key: ' '}))");
  EXPECT_EQ(timeline(tab)["playing"], true);
}

TEST_F(ViewTimeline, StripAndChartCursorsMoveWithThePlayhead) {
  const std::string tab = open();
  // The strip is drawn at the next frame.
  auto cursor_at = [&](double t) {
    eval(tab, "robozooView.pause(); robozooView.seek(" + nlohmann::json(t).dump() + ")");
    EXPECT_TRUE(wait_for(
        [&] {
          const auto j = timeline(tab);
          return j["stripCursorX"].is_number() && j["playhead"] == t && eval(tab, "robozooView.strip().at") == t;
        },
        5))
        << timeline(tab).dump();
    return timeline(tab)["stripCursorX"].get<double>();
  };
  const double x1 = cursor_at(0.5), x2 = cursor_at(2.5);
  const auto j = timeline(tab);
  // The time axis runs over the run's 3 s from the names' column (96 px) to
  // 4 px before the right edge: 2 s is two thirds of it.
  const double w = eval(tab, "robozooView.rect('strip-scroll').width").get<double>();
  EXPECT_NEAR(x2 - x1, 2.0 / 3.0 * (w - 100), 0.5);
  // The cursor is drawn there: a red column in the strip's picture.
  const render::Image strip = shot(tab, "strip-scroll", "strip-cursor.png");
  int red_at_cursor = 0, red_elsewhere = 0;
  for (int y = 0; y < strip.height(); ++y)
    for (int x = 0; x < strip.width(); ++x) {
      const render::Rgb c = strip.at(x, y);
      const bool red = c.r > 200 && c.g < 60 && c.b < 60;
      (std::abs(x - x2) <= 2 ? red_at_cursor : red_elsewhere) += red;
    }
  EXPECT_GT(red_at_cursor, strip.height() / 2) << "no cursor at x = " << x2;
  EXPECT_EQ(red_elsewhere, 0);
  // The chart marks the shown champion's generation.
  EXPECT_EQ(j["chartCursor"], 2);
  EXPECT_TRUE(j["chartCursorX"].is_number()) << j.dump();
}

TEST_F(ViewTimeline, StripDrawsNinetyFourTracesGroupedByKind) {
  const std::string tab = open();
  ASSERT_TRUE(wait_for([&] { return eval(tab, "robozooView.strip()")["drawnPoints"].get<int>() > 0; }, 10));
  auto s = eval(tab, "robozooView.strip()");
  EXPECT_EQ(s["traces"], kNeurons + kSensors);
  EXPECT_EQ(s["groups"],
            (nlohmann::json{{"neurons", 3}, {"distance", 23}, {"touch", 23}, {"proprio", 23}, {"time", 22}}));
  EXPECT_EQ(s["rows"], 94);
  EXPECT_GE(s["drawnRows"].get<int>(), 5) << "rows too small to read" << s.dump();
  EXPECT_LT(s["drawnRows"].get<int>(), 94) << "94 rows in one panel: too thin" << s.dump();
  // Drawn: the neurons' purple traces are on the panel.
  const render::Image img = shot(tab, "strip-scroll", "strip-94.png");
  int purple = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 100; x < img.width(); ++x) {
      const render::Rgb c = img.at(x, y);
      purple += c.r > 90 && c.r < 160 && c.g < 110 && c.b > 140;
    }
  EXPECT_GT(purple, 200) << "no neuron traces drawn";
  // Scrolled to the end: the last rows are drawn.
  eval(tab, "document.getElementById('strip-scroll').scrollTop = 1e6");
  ASSERT_TRUE(wait_for([&] { return eval(tab, "robozooView.strip()")["first"].get<int>() > 0; }, 5));
  s = eval(tab, "robozooView.strip()");
  EXPECT_GE(s["first"].get<int>() + s["drawnRows"].get<int>(), 94) << s.dump();
  // A group's button hides its rows; hiding every group shows them all.
  eval(tab, "document.querySelector('#strip-groups button[data-group=\"touch\"]').click()");
  EXPECT_TRUE(wait_for([&] { return eval(tab, "robozooView.strip()")["rows"] == 71; }, 5));
  eval(tab,
       "for (const g of ['neurons', 'distance', 'proprio', 'time'])"
       " document.querySelector(`#strip-groups button[data-group=\"${g}\"]`).click()");
  EXPECT_TRUE(wait_for([&] { return eval(tab, "robozooView.strip()")["rows"] == 94; }, 5));
}

TEST_F(ViewTimeline, CppnPanelDrawsTheChampionsNodesAndLinks) {
  const std::string tab = open();
  const auto c = eval(tab, "robozooView.cppn()");
  EXPECT_EQ(c["id"], kChampions[2]);
  EXPECT_EQ(c["nodes"], kCppnNodes);
  EXPECT_EQ(c["links"], kCppnLinks);
  EXPECT_EQ(c["recurrent"], kCppnRecurrent);
  EXPECT_EQ(c["dashed"], kCppnRecurrent);
  EXPECT_EQ(c["disabled"], kCppnDisabled);
  EXPECT_EQ(c["titled"], kCppnNodes + kCppnLinks) << "every node and link names itself on hover";
  // The node titles say what they are: hidden node 20 is Gaussian at 0.5.
  const std::string title = eval(tab,
                                 "[...document.querySelectorAll('#cppn g.node > title')]"
                                 ".map((t) => t.textContent).find((t) => t.startsWith('h20'))");
  EXPECT_EQ(title, "h20: node 20, hidden, Gaussian, position 0.500");
  shot(tab, "cppn-box", "cppn.png");
}

TEST_F(ViewTimeline, PageOpenedAtAUrlLandsAtItsMomentAndTheSliderBringsBackChampions) {
  const std::string tab = open("#run=tl&genome=101&t=1.5", kChampions[0]);
  ASSERT_TRUE(wait_for([&] { return timeline(tab)["playhead"] == 1.5; }, 10)) << timeline(tab).dump();
  auto j = timeline(tab);
  EXPECT_EQ(j["playing"], false);
  EXPECT_EQ(j["following"], false);
  EXPECT_EQ(j["gen"], 0);
  EXPECT_EQ(j["chartCursor"], 0);
  // The controls and the URL follow at the next frame.
  EXPECT_TRUE(wait_for([&] { return timeline(tab)["stateText"] == "paused at 1.50 s of genome 101"; }, 5))
      << timeline(tab).dump();
  EXPECT_TRUE(wait_for([&] { return timeline(tab)["hash"] == "#run=tl&genome=101&t=1.50"; }, 5))
      << timeline(tab).dump();
  // The champion slider: its middle position is generation 1's champion.
  eval(tab, "const g = document.getElementById('tl-gen'); g.value = 1; g.dispatchEvent(new Event('change'))");
  ASSERT_TRUE(wait_for(
      [&] {
        const auto k = timeline(tab);
        return k["robot"] == kChampions[1] && k["done"] == true;
      },
      20))
      << timeline(tab).dump();
  EXPECT_EQ(timeline(tab)["playing"], true);
  // Back to live: the newest champion again, followed.
  eval(tab, "document.getElementById('tl-live').click()");
  j = timeline(tab);
  EXPECT_EQ(j["robot"], kChampions[2]);
  EXPECT_EQ(j["following"], true);
  EXPECT_TRUE(wait_for([&] { return timeline(tab)["stateText"] == "following the log"; }, 5)) << timeline(tab).dump();
  EXPECT_TRUE(wait_for([&] { return timeline(tab)["hash"] == ""; }, 5)) << "following, the URL names no moment";
}

}  // namespace
}  // namespace robozoo::view
