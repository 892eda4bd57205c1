#pragma once
// The one progress bar of robozoo's log readers (render, replay, view, log): a
// line redrawn in place with '\r' on a terminal. update() with an elapsed time
// is a pure function of its inputs (testable without a clock); update() without
// one measures the time since the bar was made.
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace robozoo {

struct ProgressBarParams {
  int width = 30;                   ///< cells of the bar (count)
  double min_redraw_seconds = 0.1;  ///< at most one redraw per this interval, the last always (s)
};

/// "label [#########.....................]  12/40  30%  3.2 s, ~7.5 s left"
std::string progress_text(const std::string& label, int64_t done, int64_t total, double elapsed_seconds,
                          int width = 30);

class ProgressBar {
 public:
  ProgressBar(std::ostream& out, std::string label, ProgressBarParams params = {});
  /// Redraws (when enough time passed since the last redraw, or done == total).
  void update(int64_t done, int64_t total, double elapsed_seconds);
  /// The same, with the time since the bar was made (steady clock).
  void update(int64_t done, int64_t total);
  /// Clears the line so that the report starts on a clean line.
  void finish();
  int64_t redraws() const { return redraws_; }

 private:
  std::ostream& out_;
  std::string label_;
  ProgressBarParams params_;
  double last_draw_ = -1e300;
  size_t last_length_ = 0;
  int64_t redraws_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace robozoo
