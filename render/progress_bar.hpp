#pragma once
// A progress bar on the terminal (stderr), redrawn in place; silent when the
// stream is not a terminal unless forced.
#include <chrono>
#include <cstdio>
#include <string>

namespace robozoo::render {

class ProgressBar {
 public:
  /// `enabled`: draw at all (e.g. isatty(2) and not --quiet).
  ProgressBar(std::string label, int total, bool enabled, std::FILE* out = stderr);
  /// Shows `done` of total (redraws at most ~10 times a second, and at the end).
  void update(int done);
  /// Ends the line.
  void finish();
  /// The text of the bar for `done` of `total` at `rate` per second (for tests).
  static std::string format(const std::string& label, int done, int total, double rate, int width = 30);

 private:
  std::string label_;
  int total_;
  bool enabled_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace robozoo::render
