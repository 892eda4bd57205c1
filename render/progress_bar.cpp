#include "render/progress_bar.hpp"

#include <algorithm>
#include <cmath>

namespace robozoo::render {

ProgressBar::ProgressBar(std::string label, int total, bool enabled, std::FILE* out)
    : label_(std::move(label)), total_(std::max(1, total)), enabled_(enabled), out_(out),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

std::string ProgressBar::format(const std::string& label, int done, int total, double rate, int width) {
  total = std::max(1, total);
  done = std::clamp(done, 0, total);
  const double f = static_cast<double>(done) / total;
  const int filled = static_cast<int>(std::lround(f * width));
  std::string bar = label + " [" + std::string(static_cast<size_t>(filled), '#') +
                    std::string(static_cast<size_t>(width - filled), '.') + "] ";
  char tail[96];
  if (rate > 0) {
    const double eta = (total - done) / rate;
    std::snprintf(tail, sizeof tail, "%3d%% %d/%d  %.1f/s  eta %.0fs", static_cast<int>(std::lround(100 * f)), done,
                  total, rate, eta);
  } else {
    std::snprintf(tail, sizeof tail, "%3d%% %d/%d", static_cast<int>(std::lround(100 * f)), done, total);
  }
  return bar + tail;
}

void ProgressBar::update(int done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  std::fprintf(out_, "\r%s\033[K", format(label_, done, total_, rate).c_str());
  std::fflush(out_);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (enabled_ && drawn_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
  drawn_ = false;
}

}  // namespace robozoo::render
