#include "view/serve/server.hpp"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

namespace robozoo::view {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;

namespace {

constexpr std::chrono::seconds kHttpTimeout{30};
constexpr size_t kMaxRequestHeader = 8 * 1024;  // bytes
constexpr size_t kMaxRequestBody = 1024;        // bytes: the page sends no bodies

/// Re-simulations asked for by pages, run one at a time off the network thread.
class ReplayWorker {
 public:
  ReplayWorker(const ViewState& state, size_t max_pending) : state_(state), max_pending_(max_pending) {
    thread_ = std::thread([this] { loop(); });
  }
  ~ReplayWorker() { shutdown(); }
  /// Ends the thread (a job under way finishes first); later submits are refused.
  void shutdown() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
  }
  /// False when too many wait.
  bool submit(std::shared_ptr<Client> client, ReplayPlan plan) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stop_ || jobs_.size() >= max_pending_) return false;
    jobs_.push_back({std::move(client), std::move(plan)});
    cv_.notify_one();
    return true;
  }

 private:
  struct Job {
    std::shared_ptr<Client> client;
    ReplayPlan plan;
  };
  void loop() {
    for (;;) {
      Job job;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        cv_.wait(lock, [&] { return stop_ || !jobs_.empty(); });
        if (stop_) return;
        job = std::move(jobs_.front());
        jobs_.pop_front();
      }
      std::vector<Frame> frames;
      try {
        frames = state_.resimulate(job.plan);
      } catch (const std::exception& e) {
        frames = {make_frame({{"t", "error"}, {"what", std::string("re-simulation failed: ") + e.what()}})};
      }
      bool wake = false;
      for (const Frame& f : frames) wake |= job.client->queue.push(f, false);
      if (wake && job.client->wake) job.client->wake();
    }
  }
  const ViewState& state_;
  size_t max_pending_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<Job> jobs_;
  bool stop_ = false;
  std::thread thread_;
};

struct Shared {
  ServerOptions options;
  const AssetTable& assets;
  ViewState& state;
  ReplayWorker replays;
  std::atomic<int64_t> refused{0};
  Shared(ServerOptions o, const AssetTable& a, ViewState& s)
      : options(std::move(o)), assets(a), state(s), replays(s, options.max_pending_replays) {}
};

/// The only request a page may send: {"t":"replay","id":N}. The id, or nullopt.
std::optional<int64_t> parse_request(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || j.size() != 2 || !j.contains("t") || !j.contains("id")) return std::nullopt;
  if (j["t"] != "replay" || !j["id"].is_number_integer()) return std::nullopt;
  return j["id"].get<int64_t>();
}

class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket&& socket, Shared& shared)
      : ws_(std::move(socket)), shared_(shared), timer_(ws_.get_executor()), in_(shared.options.max_client_frame) {}
  ~WsSession() {
    if (client_) shared_.state.leave(client_);
  }

  void run(http::request<http::string_body> req) {
    beast::error_code ec;
    beast::get_lowest_layer(ws_).socket().set_option(net::socket_base::send_buffer_size(shared_.options.send_buffer),
                                                     ec);
    beast::get_lowest_layer(ws_).expires_never();
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    // The size limit is in_'s: a message that does not fit ends the read with
    // buffer_overflow at once, the connection still open, so it is counted
    // before the page is told. (Beast's own read_message_max would fail the
    // connection first and report it only once the peer has closed its end:
    // a page that stays silent after an oversized frame would go uncounted
    // until then, and at shutdown not at all.)
    ws_.read_message_max(0);
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) { self->on_accept(ec); });
  }

 private:
  void on_accept(beast::error_code ec) {
    if (ec) return;
    std::weak_ptr<WsSession> weak = shared_from_this();
    auto executor = ws_.get_executor();
    client_ = shared_.state.join([weak, executor] {
      net::post(executor, [weak] {
        if (auto self = weak.lock()) self->write_next();
      });
    });
    read_next();
    tick();
  }

  void tick() {
    timer_.expires_after(std::chrono::milliseconds(static_cast<int64_t>(shared_.options.stats_interval * 1000)));
    timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->closing_) return;
      if (self->client_->queue.push(self->shared_.state.stats_frame(*self->client_), false)) self->write_next();
      self->tick();
    });
  }

  void read_next() {
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (ec == websocket::error::buffer_overflow) {  // a message over max_client_frame
      ++shared_.refused;
      close(websocket::close_code::too_big);
      return;
    }
    if (ec) {  // closed by the page, or a broken connection
      stop();
      return;
    }
    const std::string text = beast::buffers_to_string(in_.data());
    in_.consume(in_.size());
    const std::optional<int64_t> id = ws_.got_text() ? parse_request(text) : std::nullopt;
    if (!id) {
      ++shared_.refused;
      close(websocket::close_code::policy_error);
      return;
    }
    ReplayPlan plan = shared_.state.plan_replay(*id);
    if (!plan.error.empty()) {
      push(make_frame({{"t", "error"}, {"what", plan.error}}));
    } else if (!plan.frames.empty()) {
      for (const Frame& f : plan.frames) push(f);
    } else if (!shared_.replays.submit(client_, std::move(plan))) {
      push(make_frame({{"t", "error"}, {"what", "too many re-simulations waiting; try again"}}));
    }
    read_next();
  }

  void push(const Frame& f) {
    if (client_->queue.push(f, false)) write_next();
  }

  void write_next() {
    if (writing_ || closing_) return;
    if (client_->queue.counters().overflowed) {
      close(websocket::close_code::try_again_later);
      return;
    }
    std::optional<Frame> f = client_->queue.pop();
    if (!f) return;
    writing_ = true;
    ws_.text(true);
    const Frame frame = *f;
    ws_.async_write(net::buffer(*frame), [self = shared_from_this(), frame](beast::error_code ec, size_t) {
      self->writing_ = false;
      if (ec) return self->stop();
      self->write_next();
    });
  }

  void close(websocket::close_code code) {
    if (closing_) return;
    closing_ = true;
    timer_.cancel();
    if (writing_) {  // a write is in flight: drop the connection instead of a polite close
      beast::error_code ec;
      beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ec);
      return;
    }
    ws_.async_close(code, [self = shared_from_this()](beast::error_code) {});
  }

  void stop() {
    closing_ = true;
    timer_.cancel();
  }

  websocket::stream<beast::tcp_stream> ws_;
  Shared& shared_;
  net::steady_timer timer_;
  beast::flat_buffer in_;
  std::shared_ptr<Client> client_;
  bool writing_ = false, closing_ = false;
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, Shared& shared) : stream_(std::move(socket)), shared_(shared) {}
  void run() { read_next(); }

 private:
  void read_next() {
    parser_.emplace();
    parser_->header_limit(kMaxRequestHeader);
    parser_->body_limit(kMaxRequestBody);
    stream_.expires_after(kHttpTimeout);
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (ec) {
      if (ec != http::error::end_of_stream && ec != beast::error::timeout && ec != net::error::operation_aborted)
        ++shared_.refused;  // over a limit, or not HTTP
      beast::error_code ignored;
      stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
      return;
    }
    http::request<http::string_body> req = parser_->release();
    if (websocket::is_upgrade(req)) {
      if (req.target() != "/ws" || !same_origin(req)) {
        ++shared_.refused;
        return respond(req, http::status::forbidden, "text/plain", "forbidden\n");
      }
      std::make_shared<WsSession>(stream_.release_socket(), shared_)->run(std::move(req));
      return;
    }
    if (req.method() != http::verb::get && req.method() != http::verb::head)
      return respond(req, http::status::method_not_allowed, "text/plain", "only GET and HEAD\n");
    const Asset* a = shared_.assets.find(std::string(req.target()));
    if (a) return respond(req, http::status::ok, a->content_type, a->body);
    std::optional<HttpReply> r;
    if (shared_.options.route) r = shared_.options.route(std::string(req.target()));
    if (!r) return respond(req, http::status::not_found, "text/plain", "not found\n");
    respond(req, static_cast<http::status>(r->status), r->content_type, r->body, r->download);
  }

  /// A page from another site must not open the socket (cross-site WebSocket
  /// hijacking): a browser's Origin must name the host the page was served from.
  static bool same_origin(const http::request<http::string_body>& req) {
    const auto origin = req.find(http::field::origin);
    if (origin == req.end()) return true;  // not a browser
    const auto host = req.find(http::field::host);
    return host != req.end() && std::string(origin->value()) == "http://" + std::string(host->value());
  }

  void respond(const http::request<http::string_body>& req, http::status status, const std::string& type,
               const std::string& body, const std::string& download = "") {
    auto res = std::make_shared<http::response<http::string_body>>(status, req.version());
    res->set(http::field::server, "robozoo-view");
    res->set(http::field::content_type, type);
    if (!download.empty()) res->set(http::field::content_disposition, "attachment; filename=\"" + download + "\"");
    res->set(http::field::cache_control, "no-cache");
    res->set("X-Content-Type-Options", "nosniff");
    res->keep_alive(req.keep_alive() && status == http::status::ok);
    if (req.method() == http::verb::head) {
      res->content_length(body.size());
    } else {
      res->body() = body;
      res->prepare_payload();
    }
    http::async_write(stream_, *res, [self = shared_from_this(), res](beast::error_code ec, size_t) {
      if (ec || !res->keep_alive()) {
        beast::error_code ignored;
        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read_next();
    });
  }

  beast::tcp_stream stream_;
  Shared& shared_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

}  // namespace

struct Server::Impl {
  // Destroyed in reverse: the io_context (and with it every session, which
  // leaves the state) before what the sessions use.
  Shared shared;
  net::io_context ioc{1};
  tcp::acceptor acceptor{ioc};
  std::thread thread;
  Impl(ServerOptions o, const AssetTable& a, ViewState& s) : shared(std::move(o), a, s) {}

  void accept() {
    acceptor.async_accept(net::make_strand(ioc), [this](beast::error_code ec, tcp::socket socket) {
      if (ec == net::error::operation_aborted) return;
      if (!ec) std::make_shared<HttpSession>(std::move(socket), shared)->run();
      accept();
    });
  }
};

Server::Server(ServerOptions options, const AssetTable& assets, ViewState& state)
    : impl_(std::make_unique<Impl>(std::move(options), assets, state)) {
  const ServerOptions& o = impl_->shared.options;
  const std::string where = o.bind + ":" + std::to_string(o.port);
  beast::error_code ec;
  const net::ip::address address = net::ip::make_address(o.bind, ec);
  if (ec) throw std::runtime_error("--bind " + o.bind + ": not an IP address");
  const tcp::endpoint endpoint(address, o.port);
  impl_->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl_->acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (!ec) impl_->acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
}

Server::~Server() { stop(); }

unsigned short Server::port() const { return impl_->acceptor.local_endpoint().port(); }

void Server::start() {
  impl_->accept();
  impl_->thread = std::thread([this] { impl_->ioc.run(); });
}

void Server::stop() {
  if (!impl_) return;
  impl_->shared.replays.shutdown();
  impl_->ioc.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

int64_t Server::refused() const { return impl_->shared.refused.load(); }

}  // namespace robozoo::view
