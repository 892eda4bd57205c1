// robozoo-view's one-file replays and experiment page in headless Chromium
// (software WebGL), each test again in a private network namespace (`unshare
// -n`: only its own loopback, nothing else reachable). Runs alone (RUN_SERIAL:
// the name ends in _live_test).
//  - An exported champion opened from file://, no server running: the robot is
//    drawn (red and blue sphere pixels) and it plays its samples.
//  - The experiment page of a small robozoo-experiment folder lists every
//    trial and each trial's robot in the thumbnail strips (from its log), and
//    shows the new generation when the experiment is extended by one.
//  - The experiment page of the committed M2 results: a click on a trial's row
//    (or its curve) shows its best-of-run robot moving under the chart, made
//    again by the server from its compact result, the URL naming the trial;
//    every chart's ticks are round numbers.
// ROBOZOO_VIEW_SHOTS=DIR keeps the screenshots.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "render/gl/png_io.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/private_network.hpp"
#include "tests/support/subprocess.hpp"
#include "tests/support/wait_for.hpp"
#include "tests/view/screenshots.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::testing;
using Clock = std::chrono::steady_clock;

TEST(ViewShare, ExportedChampionDrawsFromAFileWithNoServer) {
  RUN_IN_PRIVATE_NETWORK(400, false);
  TempDir dir;
  const std::string log = dir / "run.lcmlog", html = dir / "champion.html";
  render::testing::write_small_run(log);
  const robozoo::testing::Outcome e = run_shell(bin("robozoo-view") + " export " + log + " -o " + html);
  ASSERT_EQ(e.status, 0) << e.output;
  std::cout << e.output;
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string tab = browser.open("file://" + html);
  auto stats = [&] { return browser.evaluate(tab, "window.robozooView ? robozooView.stats() : null"); };
  ASSERT_TRUE(wait_for(
      [&] {
        const auto s = stats();
        return !s.is_null() && s["samples"] > 1;
      },
      60))
      << stats().dump() << "\n"
      << read_file(dir / "chromium.txt");
  EXPECT_EQ(browser.evaluate(tab, "document.getElementById('status').textContent"), "offline file");
  EXPECT_EQ(browser.evaluate(tab, "document.getElementById('save-html').hidden"), true);
  // It plays: the page draws again and its clock moves over the samples (a busy machine's
  // software WebGL may take a while between frames).
  const nlohmann::json s0 = stats();
  nlohmann::json s1;
  EXPECT_TRUE(wait_for(
      [&] {
        s1 = stats();
        return s1["frames"].get<int>() > s0["frames"].get<int>() + 2 && s1["simTime"] != s0["simTime"];
      },
      30))
      << s0.dump() << "\n"
      << s1.dump();
  EXPECT_GE(s1["chartPoints"].get<int>(), 1);
  keep_png(browser.screenshot(tab, {{"x", 0}, {"y", 0}, {"width", 1280}, {"height", 800}}), dir / "view-export.png");
  // The robot's pixels: in the 3D view only (the chart has a red line too).
  const render::testing::Pixels p =
      render::testing::count_colours(keep_png(browser.screenshot(tab, s1["canvas"]), dir / "view-export-stage.png"));
  EXPECT_GT(p.red, 30) << s1.dump();
  EXPECT_GT(p.blue, 30) << s1.dump();
  std::cout << "exported champion from file://: genome " << s1["robot"] << ", " << s1["spheres"] << " spheres, "
            << s1["samples"] << " samples, " << p.red << " red and " << p.blue << " blue pixels\n";
}

TEST(ViewShare, ExperimentPageShowsEveryTrialAndFollowsThem) {
  RUN_IN_PRIVATE_NETWORK(400, false);
  TempDir dir;
  const std::string out = dir / "exp";
  auto experiment = [&](int generations) {
    return run_shell(
        join({bin("robozoo-experiment"), "--out", out, "--trials", "2", "--population", "8", "--steps", "200",
              "--workers", "1", "--progress-interval", "0", "--generations", std::to_string(generations)}));
  };
  const robozoo::testing::Outcome first = experiment(2);
  ASSERT_EQ(first.status, 0) << first.output;
  const pid_t view =
      spawn({bin("robozoo-view"), "--experiment", out, "--port", "8080", "--poll", "0.5"}, dir / "view.txt");
  ASSERT_TRUE(wait_for([&] { return read_file(dir / "view.txt").find("open http") != std::string::npos; }, 20))
      << read_file(dir / "view.txt");
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string tab = browser.open("http://127.0.0.1:8080/experiment.html");
  auto stats = [&] { return browser.evaluate(tab, "window.robozooExperiment ? robozooExperiment.stats() : null"); };
  auto all_at = [&](int g) {
    const nlohmann::json s = stats();
    if (s.is_null() || s["rows"] != 4) return false;
    for (const auto& t : s["trials"])
      if (t["generations"] != g || t["state"] != "finished") return false;
    return true;
  };
  ASSERT_TRUE(wait_for([&] { return all_at(2); }, 30)) << stats().dump() << read_file(dir / "view.txt");
  const nlohmann::json s = stats();
  EXPECT_EQ(s["arms"], nlohmann::json::array({"feedforward", "recurrent"}));
  for (const char* name : {"feedforward-s1", "recurrent-s2", "feedforward-s5", "recurrent-s6"})
    EXPECT_NE(s.dump().find(name), std::string::npos) << name;
  // A trial's champion: the one-file replay of its log.
  const nlohmann::json trial = browser.evaluate(
      tab, "fetch('/trial?name=recurrent-s2').then(async r => ({status: r.status, text: await r.text()}))");
  EXPECT_EQ(trial["status"], 200);
  EXPECT_NE(trial["text"].get<std::string>().find("id=\"robozoo-data\""), std::string::npos);
  EXPECT_EQ(browser.evaluate(tab, "fetch('/trial?name=recurrent-s99').then(r => r.status)"), 404);
  // The thumbnail strips: every trial's best-of-run robot, read from its log.
  const nlohmann::json two_each =
      nlohmann::json::parse(R"([{"arm":"feedforward","robots":2},{"arm":"recurrent","robots":2}])");
  ASSERT_TRUE(wait_for([&] { return stats()["zoo"] == two_each; }, 30)) << stats().dump();

  // One more generation for every trial: the page follows.
  const robozoo::testing::Outcome more = experiment(3);
  ASSERT_EQ(more.status, 0) << more.output;
  ASSERT_TRUE(wait_for([&] { return all_at(3); }, 30)) << stats().dump();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const render::Image shot = keep_png(browser.screenshot(tab, {{"x", 0}, {"y", 0}, {"width", 1280}, {"height", 800}}),
                                      dir / "view-experiment.png");
  int coloured = 0;  // the curves: the arms' colours, not grey
  for (int y = 0; y < shot.height(); ++y)
    for (int x = 0; x < 860; ++x) {
      const render::Rgb c = shot.at(x, y);
      coloured += std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 60;
    }
  EXPECT_GT(coloured, 500);
  kill_process(view, SIGTERM);
  EXPECT_EQ(wait_status(view), 0) << read_file(dir / "view.txt");
  std::cout << "experiment page: 4 trials followed from 2 to 3 generations, " << coloured << " coloured pixels\n";
}

/// True when the labels are consecutive multiples of one step of 1, 2 or 5 times a power of ten.
::testing::AssertionResult round_ticks(const nlohmann::json& labels) {
  if (!labels.is_array() || labels.size() < 2) return ::testing::AssertionFailure() << "too few ticks: " << labels;
  std::vector<double> v;
  for (const auto& l : labels) v.push_back(std::stod(l.get<std::string>()));
  const double step = v[1] - v[0];
  const double p = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double m = step / p;
  if (std::abs(m - 1) > 1e-6 && std::abs(m - 2) > 1e-6 && std::abs(m - 5) > 1e-6)
    return ::testing::AssertionFailure() << "step " << step << " is not 1, 2 or 5 x 10^k: " << labels;
  for (size_t i = 0; i < v.size(); ++i) {
    const double k = v[i] / step;
    if (std::abs(k - std::round(k)) > 1e-6) return ::testing::AssertionFailure() << v[i] << " is off the step " << step;
    if (i > 0 && std::abs(v[i] - v[i - 1] - step) > 1e-6 * step)
      return ::testing::AssertionFailure() << "uneven ticks: " << labels;
  }
  return ::testing::AssertionSuccess();
}

TEST(ViewShare, ExperimentPageShowsATrialsBestOfRunRobotFromItsCompactResult) {
  RUN_IN_PRIVATE_NETWORK(400, false);
  TempDir dir;
  const std::string m2 = std::string(ROBOZOO_SOURCE_DIR) + "/media/experiment/paper/m2";
  const nlohmann::json result = nlohmann::json::parse(read_file(m2 + "/results/recurrent-s42.results.json"));
  const int64_t best = result["best"]["genome"]["id"];
  const pid_t view =
      spawn({bin("robozoo-view"), "--experiment", m2, "--port", "8080", "--poll", "5"}, dir / "view.txt");
  ASSERT_TRUE(wait_for([&] { return read_file(dir / "view.txt").find("open http") != std::string::npos; }, 20))
      << read_file(dir / "view.txt");
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt", 1280, 1000);
  const std::string tab = browser.open("http://127.0.0.1:8080/experiment.html");
  auto stats = [&] { return browser.evaluate(tab, "window.robozooExperiment ? robozooExperiment.stats() : null"); };
  ASSERT_TRUE(wait_for(
      [&] {
        const nlohmann::json s = stats();
        return !s.is_null() && s["rows"] == 60;
      },
      30))
      << stats().dump() << read_file(dir / "view.txt");
  // The thumbnail strips: each arm's 30 best-of-run robots, re-made by the server.
  ASSERT_TRUE(wait_for([&] { return !stats()["zoo"].is_null(); }, 60)) << stats().dump();
  EXPECT_EQ(stats()["zoo"],
            nlohmann::json::parse(R"([{"arm":"feedforward","robots":30},{"arm":"recurrent","robots":30}])"));
  keep_png(browser.screenshot(tab, {{"x", 0}, {"y", 0}, {"width", 1280}, {"height", 1000}}),
           dir / "view-experiment-zoo.png");
  // The curves' axes: round numbers.
  const nlohmann::json s0 = stats();
  EXPECT_TRUE(round_ticks(s0["ticks"]["y"])) << s0["ticks"];
  EXPECT_TRUE(round_ticks(s0["ticks"]["x"])) << s0["ticks"];
  EXPECT_EQ(s0["trial"], nullptr);

  // A click on a trial's row: its robot, made again from its result, below the chart.
  browser.evaluate(tab, "document.querySelector('#trials tr[data-name=\"recurrent-s42\"]').click()");
  auto trial_view = [&] { return browser.evaluate(tab, "robozooExperiment.trialView()"); };
  ASSERT_TRUE(wait_for(
      [&] {
        const nlohmann::json t = trial_view();
        return !t.is_null() && t["stats"]["samples"] > 100 && t["stats"]["frames"] > 5;
      },
      90))
      << trial_view().dump() << read_file(dir / "view.txt");
  const nlohmann::json s1 = stats();
  EXPECT_EQ(s1["trial"], "recurrent-s42");
  EXPECT_EQ(s1["hash"], "#trial=recurrent-s42");
  nlohmann::json t = trial_view();
  EXPECT_EQ(t["stats"]["robot"], best) << t.dump();
  EXPECT_EQ(t["stats"]["spheres"], 50) << t.dump();
  EXPECT_EQ(t["stats"]["run"], "recurrent-s42");
  EXPECT_EQ(t["status"], "offline file");
  EXPECT_EQ(t["timeline"]["stateText"].get<std::string>().find("following live"), std::string::npos) << t.dump();
  EXPECT_GE(t["timeline"]["start"].get<double>(), 0.0) << t.dump();
  EXPECT_GE(t["timeline"]["playhead"].get<double>(), 0.0) << t.dump();
  EXPECT_TRUE(round_ticks(t["chartTicks"]["fitness"])) << t["chartTicks"];
  EXPECT_TRUE(round_ticks(t["chartTicks"]["species"])) << t["chartTicks"];
  // It moves: two pictures of its 3D view a second apart differ.
  const render::Image a = keep_png(browser.screenshot(tab, t["stage"]), dir / "view-trial-a.png");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  t = trial_view();
  const render::Image b = keep_png(browser.screenshot(tab, t["stage"]), dir / "view-trial-b.png");
  const int changed = changed_pixels(a, b);
  EXPECT_GT(changed, 100) << t.dump();
  const render::testing::Pixels colours = render::testing::count_colours(b);
  EXPECT_GT(colours.red, 30);
  EXPECT_GT(colours.blue, 30);
  keep_png(browser.screenshot(tab, {{"x", 0}, {"y", 0}, {"width", 1280}, {"height", 1000}}),
           dir / "view-experiment-trial.png");

  // A click on another trial's curve opens that one.
  const nlohmann::json at = browser.evaluate(tab, "robozooExperiment.curvePoint('feedforward-s21', 45)");
  ASSERT_FALSE(at.is_null());
  for (const char* type : {"mousePressed", "mouseReleased"})
    browser.call("Input.dispatchMouseEvent",
                 {{"type", type}, {"x", at["x"]}, {"y", at["y"]}, {"button", "left"}, {"clickCount", 1}}, tab);
  EXPECT_TRUE(wait_for([&] { return stats()["trial"] == "feedforward-s21"; }, 10)) << stats().dump();
  EXPECT_EQ(stats()["hash"], "#trial=feedforward-s21");

  // A click on a thumbnail opens its trial.
  browser.evaluate(tab, "document.querySelector('#zoo canvas[data-name=\"recurrent-s6\"]').click()");
  EXPECT_TRUE(wait_for([&] { return stats()["trial"] == "recurrent-s6"; }, 10)) << stats().dump();

  // The link, shared: a new page on it opens that trial.
  const std::string shared = browser.open("http://127.0.0.1:8080/experiment.html#trial=recurrent-s2");
  EXPECT_TRUE(wait_for(
      [&] {
        const nlohmann::json v =
            browser.evaluate(shared, "window.robozooExperiment ? robozooExperiment.trialView() : null");
        return !v.is_null() && v["stats"]["run"] == "recurrent-s2" && v["stats"]["samples"] > 100;
      },
      90));
  kill_process(view, SIGTERM);
  EXPECT_EQ(wait_status(view), 0) << read_file(dir / "view.txt");
  std::cout << "experiment page: recurrent-s42's best-of-run robot (genome " << best << ") re-made and moving, "
            << changed << " pixels changed in 1.5 s\n";
}

}  // namespace
}  // namespace robozoo::view
