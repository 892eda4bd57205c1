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
#include <fstream>
#include <regex>
#include <thread>

#include "evolve/io/event_log.hpp"
#include "render/png_io.hpp"
#include "tests/render/fixtures.hpp"
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
  const Outcome o = run_shell("timeout 240 unshare -n sh -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
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

TEST(ViewBrowser, LiveRunMovesOnThePageAndLateJoinersGetTheHistory) {
  IN_NAMESPACE();
  TempDir dir;
  const pid_t view = start_view(dir);
  HeadlessBrowser browser(dir / "profile", dir / "chromium.txt");
  const std::string a = browser.open(kPage);
  auto stats = [&](const std::string& s) { return browser.evaluate(s, "window.robozooView ? robozooView.stats() : null"); };
  ASSERT_TRUE(wait_for([&] { const auto j = stats(a); return !j.is_null() && j["framesReceived"] >= 1; }, 30))
      << read_file(dir / "chromium.txt");

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

}  // namespace
}  // namespace robozoo::view
