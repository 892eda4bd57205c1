#include "runlog/progress_bar.hpp"

#include <algorithm>
#include <cstdio>

namespace robozoo {

namespace {
std::string seconds_text(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600, (static_cast<int>(s) / 60) % 60);
  return buf;
}
}  // namespace

std::string progress_text(const std::string& label, int64_t done, int64_t total, double elapsed_seconds, int width) {
  const double share = total > 0 ? std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0) : 1.0;
  const int full = static_cast<int>(share * width);
  std::string s = label + " [" + std::string(static_cast<size_t>(full), '#') +
                  std::string(static_cast<size_t>(width - full), '.') + "]  " + std::to_string(done) + "/" +
                  std::to_string(total);
  char pct[16];
  std::snprintf(pct, sizeof pct, "  %3d%%", static_cast<int>(share * 100.0));
  s += pct;
  s += "  " + seconds_text(elapsed_seconds);
  if (done > 0 && done < total) s += ", ~" + seconds_text(elapsed_seconds / done * (total - done)) + " left";
  return s;
}

ProgressBar::ProgressBar(std::ostream& out, std::string label, ProgressBarParams params)
    : out_(out), label_(std::move(label)), params_(params) {}

void ProgressBar::update(int64_t done, int64_t total, double elapsed_seconds) {
  if (done < total && elapsed_seconds - last_draw_ < params_.min_redraw_seconds) return;
  last_draw_ = elapsed_seconds;
  const std::string s = progress_text(label_, done, total, elapsed_seconds, params_.width);
  // Pad with spaces over a longer previous line.
  out_ << '\r' << s << std::string(last_length_ > s.size() ? last_length_ - s.size() : 0, ' ') << std::flush;
  last_length_ = s.size();
  ++redraws_;
}

void ProgressBar::update(int64_t done, int64_t total) {
  update(done, total, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

void ProgressBar::finish() {
  if (last_length_ == 0) return;
  out_ << '\r' << std::string(last_length_, ' ') << '\r' << std::flush;
  last_length_ = 0;
}

}  // namespace robozoo
