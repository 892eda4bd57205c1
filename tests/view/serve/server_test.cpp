// robozoo-view's web server in this process, on a free loopback port: the
// fixed set of files, and what closes a page's connection.
#include "view/serve/server.hpp"

#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "tests/render/messages.hpp"

namespace robozoo::view {
namespace {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;
using namespace robozoo::render::testing;

AssetDirs test_dirs() { return {std::string(ROBOZOO_SOURCE_DIR) + "/view/page", ROBOZOO_THREE_DIR}; }

struct Fixture {
  AssetTable assets = AssetTable::load(test_dirs());
  ViewState state{"log", "test"};
  Server server;
  Fixture() : server(options(), assets, state) { server.start(); }
  static ServerOptions options() {
    ServerOptions o;
    o.port = 0;
    o.stats_interval = 0.2;
    return o;
  }
};

http::response<http::string_body> get(unsigned short port, const std::string& target,
                                      http::verb verb = http::verb::get) {
  net::io_context ioc;
  tcp::socket s(ioc);
  s.connect({net::ip::make_address("127.0.0.1"), port});
  http::request<http::string_body> req{verb, target, 11};
  req.set(http::field::host, "127.0.0.1");
  http::write(s, req);
  beast::flat_buffer b;
  http::response_parser<http::string_body> parser;
  // A response to HEAD carries the GET's Content-Length but no body (RFC 9110 9.3.2);
  // a parser cannot tell from the response alone and would wait for those bytes.
  parser.skip(verb == http::verb::head);
  http::read(s, b, parser);
  return parser.release();
}

struct Page {
  net::io_context ioc;
  websocket::stream<tcp::socket> ws{ioc};
  explicit Page(unsigned short port, const std::string& origin = "") {
    ws.next_layer().connect({net::ip::make_address("127.0.0.1"), port});
    ws.set_option(websocket::stream_base::decorator([origin](websocket::request_type& r) {
      if (!origin.empty()) r.set(http::field::origin, origin);
    }));
    ws.handshake("127.0.0.1:" + std::to_string(port), "/ws");
  }
  nlohmann::json read() {
    beast::flat_buffer b;
    ws.read(b);
    return nlohmann::json::parse(beast::buffers_to_string(b.data()));
  }
  /// Reads until a frame of kind `t`; throws when the connection closes first.
  nlohmann::json read_until(const std::string& t) {
    for (;;) {
      nlohmann::json j = read();
      if (j["t"] == t) return j;
    }
  }
  /// True when the server closes the connection (reads fail) within a few frames.
  bool closed_by_server() {
    try {
      for (int i = 0; i < 100; ++i) read();
    } catch (const beast::system_error&) {
      return true;
    }
    return false;
  }
};

TEST(ViewServer, RouteAnswersWhatIsNoFileAndOnlyThat) {
  AssetTable assets = AssetTable::load(test_dirs());
  ViewState state{"log", "test"};
  ServerOptions o = Fixture::options();
  std::vector<std::string> asked;
  o.route = [&asked](const std::string& target) -> std::optional<HttpReply> {
    asked.push_back(target);
    if (target == "/export?genome=7")
      return HttpReply{200, "text/html; charset=utf-8", "<p>seven</p>", "champion-7.html"};
    if (target == "/export?genome=8") return HttpReply{404, "text/plain", "no genome 8\n", ""};
    return std::nullopt;
  };
  Server server(o, assets, state);
  server.start();
  const auto ok = get(server.port(), "/export?genome=7");
  EXPECT_EQ(ok.result_int(), 200);
  EXPECT_EQ(ok.body(), "<p>seven</p>");
  EXPECT_EQ(ok[http::field::content_disposition], "attachment; filename=\"champion-7.html\"");
  const auto missing = get(server.port(), "/export?genome=8");
  EXPECT_EQ(missing.result_int(), 404);
  EXPECT_EQ(missing.body(), "no genome 8\n");
  EXPECT_EQ(missing[http::field::content_disposition], "");
  EXPECT_EQ(get(server.port(), "/elsewhere").result_int(), 404);
  EXPECT_EQ(get(server.port(), "/view.js").result_int(), 200);  // files first: the route is not asked
  server.stop();
  EXPECT_EQ(asked, (std::vector<std::string>{"/export?genome=7", "/export?genome=8", "/elsewhere"}));
}

TEST(ViewServer, ServesTheFixedFilesOnly) {
  Fixture f;
  const unsigned short port = f.server.port();
  auto index = get(port, "/");
  EXPECT_EQ(index.result(), http::status::ok);
  EXPECT_NE(index.body().find("robozoo-view"), std::string::npos);
  EXPECT_EQ(index[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(get(port, "/view.js?v=1").result(), http::status::ok);
  // Every module view.js imports is served.
  for (const std::string js : {"/scene.js", "/chart.js", "/strip.js", "/playback.js", "/timeline.js", "/cppn.js"}) {
    auto r = get(port, js);
    EXPECT_EQ(r.result(), http::status::ok) << js;
    EXPECT_EQ(r[http::field::content_type], "text/javascript; charset=utf-8") << js;
  }
  auto three = get(port, "/three/build/three.module.js");
  EXPECT_EQ(three.result(), http::status::ok);
  EXPECT_NE(three.body().find("REVISION"), std::string::npos);
  EXPECT_EQ(get(port, "/three/examples/jsm/controls/OrbitControls.js").result(), http::status::ok);
  for (const std::string bad : {"/../../etc/passwd", "/%2e%2e/etc/passwd", "/three/build/three.js", "/page/view.js",
                                "//etc/passwd", "/view.js/", "/CMakeLists.txt"})
    EXPECT_EQ(get(port, bad).result(), http::status::not_found) << bad;
  EXPECT_EQ(get(port, "/", http::verb::post).result(), http::status::method_not_allowed);
  auto head = get(port, "/view.js", http::verb::head);
  EXPECT_EQ(head.result(), http::status::ok);
  EXPECT_EQ(head[http::field::content_length], std::to_string(get(port, "/view.js").body().size()));
  EXPECT_TRUE(head.body().empty());
}

TEST(ViewServer, AnswersReplayRequestsAndSendsStats) {
  Fixture f;
  // A run whose champion 11 has logged poses.
  auto send = [&](const char* ch, const auto& m) {
    const std::vector<uint8_t> b = encode_message(m);
    f.state.ingest(ch, b.data(), b.size());
  };
  send(kChannelRun, run_message("r", 100));
  send(kChannelGeneration, generation_message("r", 0, 11));
  send(kChannelGenome, genome_message("r", 0, 11, 15.0));
  send(kChannelMorphology, morphology_message("r", 0, 11));
  for (int s = 0; s <= 100; s += 20) send(kChannelPose, pose_message("r", 0, 11, s, 0.01 * s));
  Page p(f.server.port());
  // First what a joining page gets: hello, run, history, champions, and the
  // robot shown now (11, live, not a replay) with its poses so far.
  EXPECT_EQ(p.read()["t"], "hello");
  EXPECT_EQ(p.read_until("history")["gens"].size(), 1u);
  const nlohmann::json shown = p.read_until("robot");
  EXPECT_EQ(shown["id"], 11);
  EXPECT_EQ(shown["replay"], false);
  EXPECT_EQ(p.read_until("poses")["list"].size(), 6u);
  // Then the replay asked for: the same genome's logged poses, as a replay.
  p.ws.write(net::buffer(std::string(R"({"t":"replay","id":11})")));
  const nlohmann::json robot = p.read_until("robot");
  EXPECT_EQ(robot["id"], 11);
  EXPECT_EQ(robot["replay"], true);
  const nlohmann::json poses = p.read_until("poses");
  EXPECT_EQ(poses["list"].size(), 6u);
  EXPECT_EQ(poses["resimulated"], false);
  p.ws.write(net::buffer(std::string(R"({"t":"replay","id":999})")));
  EXPECT_NE(p.read_until("error")["what"].get<std::string>().find("999"), std::string::npos);
  const nlohmann::json stats = p.read_until("stats");
  EXPECT_EQ(stats["dropped"], 0);
  EXPECT_EQ(stats["pages"], 1);
}

TEST(ViewServer, UnexpectedMessagesCloseTheConnection) {
  Fixture f;
  const unsigned short port = f.server.port();
  {
    Page p(port);
    p.ws.write(net::buffer(std::string(R"({"t":"shutdown"})")));
    EXPECT_TRUE(p.closed_by_server());
  }
  {
    Page p(port);
    p.ws.write(net::buffer(std::string("not json")));
    EXPECT_TRUE(p.closed_by_server());
  }
  {
    Page p(port);
    p.ws.binary(true);
    p.ws.write(net::buffer(std::string(R"({"t":"replay","id":1})")));
    EXPECT_TRUE(p.closed_by_server());
  }
  {
    Page p(port);
    p.ws.write(net::buffer(std::string(5000, 'x')));  // over the 4096-byte limit
    EXPECT_TRUE(p.closed_by_server());
  }
  EXPECT_EQ(f.server.refused(), 4);
  // A page still works after all that.
  Page ok(port);
  EXPECT_EQ(ok.read()["t"], "hello");
}

TEST(ViewServer, RefusesASocketForAPageOfAnotherSite) {
  Fixture f;
  const unsigned short port = f.server.port();
  EXPECT_THROW(Page(port, "http://evil.example"), beast::system_error);
  Page same(port, "http://127.0.0.1:" + std::to_string(port));
  EXPECT_EQ(same.read()["t"], "hello");
}

TEST(ViewServer, RefusesABusyPortAndABadAddress) {
  Fixture f;
  ServerOptions o;
  o.port = f.server.port();
  EXPECT_THROW(Server(o, f.assets, f.state), std::runtime_error);
  o.port = 0;
  o.bind = "localhost:80";
  EXPECT_THROW(Server(o, f.assets, f.state), std::runtime_error);
}

TEST(ViewAssets, MissingFilesAreNamed) {
  AssetDirs d = test_dirs();
  d.three = "/nonexistent";
  try {
    AssetTable::load(d);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace robozoo::view
