// robozoo-view end to end: robozoo-evolve publishes on an LCM bus in a private
// network namespace, robozoo-view follows it, and headless Chromium (software
// WebGL) shows the page. Each test runs itself again inside `unshare -n` (lo
// up, multicast routed to it), where the browser, the view and evolve share
// the namespace's loopback. Runs alone (RUN_SERIAL: the name ends in _live_test).
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <regex>
#include <thread>

#include "evolve/io/event_log.hpp"
#include "render/png_io.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/render/messages.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::testing;
using Clock = std::chrono::steady_clock;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kPage = "http://127.0.0.1:8080/";

bool inside_namespace() { return std::getenv("ROBOZOO_VIEW_NETNS") != nullptr; }

/// Runs the current test again in a private network namespace; its output
/// comes back in the failure message.
void run_inside(const std::string& test) {
  char self[4096] = {0};
  ASSERT_GT(::readlink("/proc/self/exe", self, sizeof self - 1), 0);
  const robozoo::testing::Outcome o = run_shell("timeout 240 unshare -n sh -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
                              "ROBOZOO_VIEW_NETNS=1 exec " + std::string(self) + " --gtest_filter=" + test + "'");
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("[  PASSED  ] 1 test"), std::string::npos) << o.output;
}

#define IN_NAMESPACE()                                                                       \
  if (!inside_namespace()) {                                                                 \
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();             \
    return run_inside(std::string(info->test_suite_name()) + "." + info->name());            \
  }

/// Waits until `pred()` or `seconds`; false on timeout.
template <class Pred>
bool wait_for(Pred pred, double seconds) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return pred();
}

pid_t start_view(const TempDir& dir, std::vector<std::string> extra = {}) {
  std::vector<std::string> a = {bin("robozoo-view"), "--lcm-url", kUrl, "--port", "8080"};
  a.insert(a.end(), extra.begin(), extra.end());
  const pid_t pid = spawn(a, dir / "view.txt");
  EXPECT_TRUE(wait_for([&] { return read_file(dir / "view.txt").find("open http") != std::string::npos; }, 20))
      << read_file(dir / "view.txt");
  return pid;
}

struct Pixels {
  int red = 0, blue = 0;
};

Pixels count_colours(const render::Image& img) {
  Pixels p;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const render::Rgb c = img.at(x, y);
      p.red += render::testing::is_red(c.r, c.g, c.b);
      p.blue += render::testing::is_blue(c.r, c.g, c.b);
    }
  return p;
}

render::Image decode_png(const std::vector<uint8_t>& png, const std::string& path) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return render::read_png(path);
}

int changed_pixels(const render::Image& a, const render::Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return -1;
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const render::Rgb p = a.at(x, y), q = b.at(x, y);
      n += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b) > 30;
    }
  return n;
}

std::vector<int> generations_in(const std::string& log) {
  std::vector<int> g;
  for (int i = 0; i < static_cast<int>(count_channel(read_event_log(log), kChannelGeneration)); ++i) g.push_back(i);
  return g;
}

/// What the page says about itself (robozooView.stats() in view.js); null before it runs.
nlohmann::json page_stats(HeadlessBrowser& browser, const std::string& session) {
  return browser.evaluate(session, "window.robozooView ? robozooView.stats() : null");
}

/// The page has its first frame from the server.
bool page_connected(HeadlessBrowser& browser, const std::string& session) {
  const auto j = page_stats(browser, session);
  return !j.is_null() && j["framesReceived"] >= 1;
}

TEST(ViewBrowser, LiveRunMovesOnThePageAndLateJoinersGetTheHistory) {
  IN_NAMESPACE();
  TempDir dir;
  const pid_t view = start_view(dir);
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string a = browser.open(kPage);
  auto stats = [&](const std::string& s) { return page_stats(browser, s); };
  ASSERT_TRUE(wait_for([&] { return page_connected(browser, a); }, 30)) << read_file(dir / "chromium.txt");

  const std::vector<std::string> size = {"--seed", "7", "--population", "24", "--generations", "6",
                                         "--steps", "600", "--quiet"};
  const pid_t evolve = spawn(evolve_args(dir / "run.lcmlog", 2, {"--lcm-url", kUrl}, size), dir / "evolve.txt");

  // A robot with red and blue spheres, shown in the middle of its trajectory.
  ASSERT_TRUE(wait_for(
      [&] {
        const auto j = stats(a);
        return j["leaves"] > 0 && j["leaves"] < j["spheres"] && j["samples"] > 10 && j["simTime"].is_number() &&
               j["simTime"].get<double>() + 1.5 < j["endTime"].get<double>();
      },
      90))
      << stats(a).dump() << read_file(dir / "view.txt");
  const auto s0 = stats(a);
  const render::Image one = decode_png(browser.screenshot(a, s0["canvas"]), dir / "one.png");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const render::Image two = decode_png(browser.screenshot(a, s0["canvas"]), dir / "two.png");
  const Pixels p1 = count_colours(one), p2 = count_colours(two);
  EXPECT_GT(p1.red, 30) << s0.dump();
  EXPECT_GT(p1.blue, 30) << s0.dump();
  EXPECT_GT(p2.red, 30);
  EXPECT_GT(p2.blue, 30);
  EXPECT_GT(changed_pixels(one, two), 50) << "the robot did not move between the screenshots";

  ASSERT_EQ(wait_status(evolve), 0) << read_file(dir / "evolve.txt");
  const std::vector<int> gens = generations_in(dir / "run.lcmlog");
  ASSERT_EQ(gens.size(), 6u);
  EXPECT_TRUE(wait_for([&] { return stats(a)["chartPoints"] == gens.size(); }, 20)) << stats(a).dump();
  EXPECT_EQ(stats(a)["chartGenerations"], nlohmann::json(gens));

  // A page that joins after the run: the same history, the champion with its poses.
  const std::string b = browser.open(kPage);
  EXPECT_TRUE(wait_for([&] { const auto j = stats(b); return !j.is_null() && j["chartPoints"] == gens.size(); }, 30))
      << stats(b).dump();
  const auto sa = stats(a), sb = stats(b);
  EXPECT_EQ(sb["chartGenerations"], sa["chartGenerations"]);
  EXPECT_EQ(sb["champions"], sa["champions"]);
  EXPECT_EQ(sb["robot"], sa["robot"]);
  EXPECT_GT(sb["samples"], 10);
  EXPECT_EQ(sb["dropped"], 0);

  ASSERT_TRUE(kill_process(view, SIGTERM));
  EXPECT_EQ(wait_status(view), 0);
  const std::string out = read_file(dir / "view.txt");
  EXPECT_NE(out.find("(0 bad, skipped), run feedforward-s7, 6 generations"), std::string::npos) << out;
}

/// A page that connects and never reads, with a tiny receive window.
class StuckPage {
 public:
  explicit StuckPage(unsigned short port) : socket_(ioc_) {
    socket_.open(boost::asio::ip::tcp::v4());
    socket_.set_option(boost::asio::socket_base::receive_buffer_size(4096));
    socket_.connect({boost::asio::ip::make_address("127.0.0.1"), port});
    const std::string upgrade =
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n";
    boost::asio::write(socket_, boost::asio::buffer(upgrade));
  }

 private:
  boost::asio::io_context ioc_;
  boost::asio::ip::tcp::socket socket_;
};

TEST(ViewBrowser, SlowPageLosesOldPosesWhileTheBusIsReadInFull) {
  IN_NAMESPACE();
  TempDir dir;
  const pid_t view = start_view(dir, {"--queue-poses", "20", "--idle-exit", "4"});
  StuckPage stuck(8080);
  // A page that reads everything, alongside.
  namespace websocket = boost::beast::websocket;
  boost::asio::io_context ioc;
  websocket::stream<boost::asio::ip::tcp::socket> ws(ioc);
  ws.next_layer().connect({boost::asio::ip::make_address("127.0.0.1"), 8080});
  ws.handshake("127.0.0.1:8080", "/ws");
  int gens = 0, poses = 0;
  std::thread reader([&] {
    try {
      for (;;) {
        boost::beast::flat_buffer buf;
        ws.read(buf);
        const auto j = nlohmann::json::parse(boost::beast::buffers_to_string(buf.data()));
        gens += j["t"] == "gen";
        poses += j["t"] == "pose";
      }
    } catch (...) {  // the view closes when it exits
    }
  });
  const pid_t evolve = spawn(evolve_args(dir / "run.lcmlog", 2, {"--lcm-url", kUrl, "--pose-every", "1"}), dir / "evolve.txt");
  ASSERT_EQ(wait_status(evolve), 0) << read_file(dir / "evolve.txt");
  EXPECT_EQ(wait_status(view), 0);  // --idle-exit
  reader.join();
  const std::string out = read_file(dir / "view.txt");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"((\d+) messages \((\d+) bad, skipped\).* (\d+) poses, (\d+) poses dropped)")))
      << out;
  const LogContents log = read_event_log(dir / "run.lcmlog");
  EXPECT_EQ(std::stoll(m[1]), static_cast<long long>(log.records.size())) << "the bus was not read in full\n" << out;
  EXPECT_EQ(std::stoll(m[2]), 0);
  const long long published = static_cast<long long>(count_channel(log, kChannelPose));
  EXPECT_EQ(std::stoll(m[3]), published);
  EXPECT_GT(published, 400);  // at least one full-rate trajectory
  const long long dropped = std::stoll(m[4]);
  EXPECT_GT(dropped, published / 2) << out;  // the stuck page took at most its queue and socket buffers
  EXPECT_EQ(gens, 4);
  EXPECT_GT(poses, 0);
}

/// A log of one hand-made robot of `n` spheres (a chain with side branches)
/// whose spheres sway, `steps` steps of 0.01 s with a pose every 4: what the
/// page draws costs the same for it as for an evolved robot of n spheres.
void write_swaying_robot(const std::string& path, int n, int steps) {
  using namespace robozoo::render::testing;
  EventLogWriter w = EventLogWriter::create(path);
  run_t run = run_message("sway", steps);
  append(w, kChannelRun, run);
  append(w, kChannelGeneration, generation_message("sway", 0, 1));
  append(w, kChannelGenome, genome_message("sway", 0, 1, 20.0));
  morphology_t m{};
  m.run_id = "sway";
  m.genome_id = 1;
  for (int i = 0; i < n; ++i) {
    sphere_t s{};
    s.index = i;
    s.parent = i == 0 ? -1 : (i % 3 == 0 ? i - 2 : i - 1);
    s.radius = 0.08 + 0.04 * (i % 4);
    s.center[0] = 0.25 * (i / 3);
    s.center[1] = 0.3 * (i % 3) - 0.3;
    s.center[2] = 0.5;
    s.density = 1.0;
    m.spheres.push_back(s);
  }
  m.num_spheres = n;
  m.num_bodies = 1;
  append(w, kChannelMorphology, m);
  for (int step = 0; step <= steps; step += 4) {
    pose_t p{};
    p.run_id = "sway";
    p.genome_id = 1;
    p.step = step;
    p.sim_time = 0.01 * step;
    p.num_bodies = 1;
    p.body_position = {{0, 0, 0.5}};
    p.body_quaternion = {{1, 0, 0, 0}};
    p.num_spheres = n;
    for (int i = 0; i < n; ++i) {
      const sphere_t& s = m.spheres[static_cast<size_t>(i)];
      const double phase = p.sim_time * 3.0 + 0.3 * i;
      p.sphere_center.push_back({s.center[0] + 0.1 * p.sim_time, s.center[1] + 0.1 * std::sin(phase),
                                 s.center[2] + 0.1 * std::cos(phase)});
    }
    append(w, kChannelPose, p, 1000);
  }
  w.sync();
}

/// Frames the page draws per second over `seconds`, counted in the page.
double page_frame_rate(HeadlessBrowser& browser, const std::string& session, double seconds) {
  const std::string ms = std::to_string(static_cast<int>(seconds * 1000));
  return browser
      .evaluate(session, "new Promise((done) => { let n = 0; const t0 = performance.now();"
                         " const f = () => { n++; if (performance.now() - t0 < " + ms + ") requestAnimationFrame(f);"
                         " else done(n * 1000 / (performance.now() - t0)); }; requestAnimationFrame(f); })")
      .get<double>();
}

TEST(ViewBrowser, FrameRateOfAFiftySphereRobot) {
  IN_NAMESPACE();
  TempDir dir;
  // ROBOZOO_VIEW_FPS_LOG and ROBOZOO_VIEW_FPS_GENERATION measure a real log instead (README's figure).
  const char* real = std::getenv("ROBOZOO_VIEW_FPS_LOG");
  std::string log = dir / "sway.lcmlog";
  std::vector<std::string> args = {bin("robozoo-view"), "--port", "8080", "--loop"};
  if (real) {
    log = real;
    const char* g = std::getenv("ROBOZOO_VIEW_FPS_GENERATION");
    if (g) args.insert(args.end(), {"--generation", g});
  } else {
    write_swaying_robot(log, 50, 2500);
  }
  args.insert(args.begin() + 1, log);
  const pid_t view = spawn(args, dir / "view.txt");
  ASSERT_TRUE(wait_for([&] { return read_file(dir / "view.txt").find("open http") != std::string::npos; }, 20))
      << read_file(dir / "view.txt");
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string a = browser.open(kPage);
  auto stats = [&] { return page_stats(browser, a); };
  ASSERT_TRUE(wait_for([&] { const auto j = stats(); return !j.is_null() && j["spheres"] >= 40 && j["samples"] > 50; }, 60))
      << stats().dump();
  const double fps = page_frame_rate(browser, a, 4.0);
  const auto j = stats();
  std::cout << "frame rate: " << fps << " frames/s for a " << j["spheres"] << "-sphere robot (page "
            << j["canvas"]["width"] << "x" << j["canvas"]["height"] << " canvas, software WebGL)\n";
  RecordProperty("fps", std::to_string(fps));
  EXPECT_GE(fps, 15.0);  // the aim is 30; below 15 the page has become too slow to watch
  kill_process(view, SIGTERM);
  EXPECT_EQ(wait_status(view), 0);
}

/// CPU seconds (user + system) a process has used so far.
double cpu_seconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::istringstream rest(all.substr(all.rfind(')') + 2));
  std::vector<std::string> f;
  for (std::string x; rest >> x;) f.push_back(x);
  return (std::stod(f.at(11)) + std::stod(f.at(12))) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

TEST(ViewBrowser, LatencyAndServerCpuWhileEvolvePublishes) {
  IN_NAMESPACE();
  TempDir dir;
  const pid_t view = start_view(dir);
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string a = browser.open(kPage);
  ASSERT_TRUE(wait_for([&] { return page_connected(browser, a); }, 30)) << read_file(dir / "chromium.txt");
  // ROBOZOO_VIEW_MEASURE_ARGS: other evolve sizes for the README's figures.
  std::vector<std::string> size = {"--seed", "7", "--population", "24", "--generations", "6", "--steps", "600", "--quiet"};
  if (const char* e = std::getenv("ROBOZOO_VIEW_MEASURE_ARGS")) {
    size.clear();
    std::istringstream in(e);
    for (std::string w; in >> w;) size.push_back(w);
  }
  const double cpu0 = cpu_seconds(view);
  const auto t0 = Clock::now();
  const pid_t evolve = spawn(evolve_args(dir / "run.lcmlog", 2, {"--lcm-url", kUrl}, size), dir / "evolve.txt");
  std::map<int64_t, double> latency;  // per shown robot: publication of its first pose -> drawn (ms)
  int status = -1;
  while (true) {
    const auto j = browser.evaluate(a, "robozooView.stats()");
    if (j["robot"].is_number() && j["firstPoseLatencyMs"].is_number())
      latency.emplace(j["robot"].get<int64_t>(), j["firstPoseLatencyMs"].get<double>());
    int st = 0;
    if (::waitpid(evolve, &st, WNOHANG) == evolve) {
      status = st;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double cpu = cpu_seconds(view) - cpu0;
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_file(dir / "evolve.txt");
  ASSERT_FALSE(latency.empty());
  std::vector<double> l;
  for (const auto& [id, ms] : latency) l.push_back(ms);
  std::sort(l.begin(), l.end());
  std::cout << "server CPU: " << cpu << " s over " << wall << " s of evolution (" << 100 * cpu / wall
            << " % of a core); pose publication -> drawn: median " << l[l.size() / 2] << " ms, max " << l.back()
            << " ms over " << l.size() << " champions\n";
  EXPECT_LT(cpu / wall, 0.5);
  EXPECT_LT(l[l.size() / 2], 1000.0);
  kill_process(view, SIGTERM);
  EXPECT_EQ(wait_status(view), 0);
}

}  // namespace
}  // namespace robozoo::view
