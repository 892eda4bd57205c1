#pragma once
// Test support: headless Chromium driven over the DevTools protocol through a
// pipe (--remote-debugging-pipe: commands on its fd 3, replies on its fd 4,
// each a JSON text ended by a NUL byte), with software WebGL (SwiftShader) so
// that it runs on machines without a GPU or a display.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace robozoo::testing {

/// The Chromium executable: Debian's binary itself (the /usr/bin/chromium
/// launcher script adds nothing headless needs).
inline std::string chromium_path() {
  if (::access("/usr/lib/chromium/chromium", X_OK) == 0) return "/usr/lib/chromium/chromium";
  return "chromium";
}

inline std::vector<uint8_t> base64_decode(const std::string& s) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<uint8_t> out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : s) {
    const int v = value(c);
    if (v < 0) continue;  // '=' padding, line breaks
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<uint8_t>((acc >> bits) & 0xFF));
    }
  }
  return out;
}

class HeadlessBrowser {
 public:
  /// Starts Chromium with its profile in `profile_dir`, a window of w x h, and
  /// its own output in `log_file`.
  HeadlessBrowser(const std::string& profile_dir, const std::string& log_file, int w = 1280, int h = 800) {
    int to_browser[2], from_browser[2];
    if (::pipe(to_browser) != 0 || ::pipe(from_browser) != 0) throw std::runtime_error("pipe failed");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (log >= 0) {
        ::dup2(log, 1);
        ::dup2(log, 2);
      }
      ::dup2(to_browser[0], 3);
      ::dup2(from_browser[1], 4);
      for (int fd = 5; fd < 1024; ++fd) ::close(fd);
      const std::string size = "--window-size=" + std::to_string(w) + "," + std::to_string(h);
      const std::string profile = "--user-data-dir=" + profile_dir;
      const std::string exe = chromium_path();
      std::vector<const char*> argv = {exe.c_str(),
                                       "--headless",
                                       "--no-sandbox",
                                       "--remote-debugging-pipe",
                                       "--use-angle=swiftshader",
                                       "--enable-unsafe-swiftshader",
                                       "--ignore-gpu-blocklist",
                                       "--no-first-run",
                                       "--no-default-browser-check",
                                       "--disable-extensions",
                                       "--disable-background-networking",
                                       "--disable-renderer-backgrounding",
                                       "--disable-background-timer-throttling",
                                       "--disable-backgrounding-occluded-windows",
                                       "--hide-scrollbars",
                                       "--force-device-scale-factor=1",
                                       size.c_str(),
                                       profile.c_str(),
                                       "about:blank",
                                       nullptr};
      ::execvp(argv[0], const_cast<char* const*>(argv.data()));
      ::_exit(127);
    }
    ::close(to_browser[0]);
    ::close(from_browser[1]);
    out_ = to_browser[1];
    in_ = from_browser[0];
    ::signal(SIGPIPE, SIG_IGN);
  }

  ~HeadlessBrowser() {
    try {
      call("Browser.close", nlohmann::json::object(), "", 5.0);
    } catch (...) {
    }
    ::close(out_);
    ::close(in_);
    for (int i = 0; i < 50; ++i) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) return;
      ::usleep(100000);
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  HeadlessBrowser(const HeadlessBrowser&) = delete;
  HeadlessBrowser& operator=(const HeadlessBrowser&) = delete;

  /// Sends a command and returns its "result"; throws on an error reply or after
  /// `timeout` seconds.
  nlohmann::json call(const std::string& method, const nlohmann::json& params, const std::string& session = "",
                      double timeout = 30.0) {
    const int id = ++next_id_;
    nlohmann::json m = {{"id", id}, {"method", method}, {"params", params}};
    if (!session.empty()) m["sessionId"] = session;
    std::string text = m.dump();
    text.push_back('\0');
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(out_, text.data() + done, text.size() - done);
      if (n <= 0) throw std::runtime_error("the browser is gone (writing " + method + ")");
      done += static_cast<size_t>(n);
    }
    const auto deadline =
        std::chrono::steady_clock::now() +
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(timeout));
    for (;;) {
      const nlohmann::json reply = next_message(deadline, method);
      if (reply.contains("id") && reply["id"] == id) {
        if (reply.contains("error")) throw std::runtime_error(method + ": " + reply["error"].dump());
        return reply.value("result", nlohmann::json::object());
      }
    }
  }

  /// Opens a tab on `url`; returns its session id.
  std::string open(const std::string& url) {
    const nlohmann::json t = call("Target.createTarget", {{"url", url}});
    const nlohmann::json a = call("Target.attachToTarget", {{"targetId", t["targetId"]}, {"flatten", true}});
    const std::string session = a["sessionId"];
    call("Runtime.enable", nlohmann::json::object(), session);
    return session;
  }

  /// The value of a JavaScript expression in a tab (JSON-able values).
  nlohmann::json evaluate(const std::string& session, const std::string& expression) {
    const nlohmann::json r = call(
        "Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}}, session);
    if (r.contains("exceptionDetails")) throw std::runtime_error(expression + ": " + r["exceptionDetails"].dump());
    return r["result"].value("value", nlohmann::json());
  }

  /// A PNG of the part of the tab's page in `rect` ({x, y, width, height} in CSS pixels).
  std::vector<uint8_t> screenshot(const std::string& session, const nlohmann::json& rect) {
    nlohmann::json clip = rect;
    clip["scale"] = 1;
    const nlohmann::json r = call("Page.captureScreenshot", {{"format", "png"}, {"clip", clip}}, session);
    return base64_decode(r["data"].get<std::string>());
  }

 private:
  nlohmann::json next_message(std::chrono::steady_clock::time_point deadline, const std::string& waiting_for) {
    for (;;) {
      const size_t end = buffer_.find('\0');
      if (end != std::string::npos) {
        const std::string text = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        return nlohmann::json::parse(text);
      }
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) throw std::runtime_error("no reply from the browser to " + waiting_for);
      pollfd p{in_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char chunk[65536];
      const ssize_t n = ::read(in_, chunk, sizeof chunk);
      if (n <= 0) throw std::runtime_error("the browser is gone (waiting for " + waiting_for + ")");
      buffer_.append(chunk, static_cast<size_t>(n));
    }
  }

  pid_t pid_ = -1;
  int out_ = -1, in_ = -1;
  int next_id_ = 0;
  std::string buffer_;
};

}  // namespace robozoo::testing
