#pragma once
// robozoo-view's web server (Boost.Beast on one Asio thread): the fixed set of
// files of AssetTable over HTTP, and /ws, a WebSocket per page that carries
// ViewState's frames out and one kind of request in: {"t":"replay","id":N}.
// Anything else a page sends (another kind, binary, not JSON, a frame over
// max_client_frame) closes its connection. Re-simulations for replays run on a
// worker thread of their own, so neither the bus nor the pages wait for them.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "view/serve/assets.hpp"
#include "view/state/view_state.hpp"

namespace robozoo::view {

/// The answer to a request for a path the program serves itself (not a file).
struct HttpReply {
  int status = 200;  ///< HTTP status
  std::string content_type;
  std::string body;
  std::string download;  ///< when set, a file to save under this name (Content-Disposition)
};

/// Answers a GET target that is not a file of the table ("/export?genome=3");
/// nullopt: 404. Called on the network thread.
using Route = std::function<std::optional<HttpReply>(const std::string& target)>;

struct ServerOptions {
  std::string bind = "127.0.0.1";  ///< address to listen on (loopback unless asked)
  unsigned short port = 8080;      ///< 0: any free port
  size_t max_client_frame = 4096;  ///< largest message a page may send (bytes)
  int send_buffer = 64 * 1024;     ///< kernel send buffer per page (bytes): a slow page's backlog
                                   ///< stays in its ClientQueue, where old poses can be dropped
  double stats_interval = 1.0;     ///< a "stats" frame to each page this often (s)
  size_t max_pending_replays = 4;  ///< re-simulations waiting at once, more are refused (count)
  Route route;                     ///< paths the program answers itself (none when empty)
};

class Server {
 public:
  /// Binds and listens at once; throws std::runtime_error naming the address
  /// when it cannot (port in use, bad address). Serves after start().
  Server(ServerOptions options, const AssetTable& assets, ViewState& state);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The port listened on (the chosen one when options.port was 0).
  unsigned short port() const;
  /// Starts the network and replay threads.
  void start();
  /// Closes every connection and joins the threads (also done by the destructor).
  void stop();
  /// Pages refused or closed for what they sent (count).
  int64_t refused() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace robozoo::view
