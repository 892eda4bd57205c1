#include "replay/compare/value_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace robozoo::replay {

double value_error(double a, double b) {
  uint64_t ba, bb;
  std::memcpy(&ba, &a, sizeof ba);
  std::memcpy(&bb, &b, sizeof bb);
  if (ba == bb || a == b) return 0.0;  // a == b: +0 and -0
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  return std::fabs(a - b) / std::max({1.0, std::fabs(a), std::fabs(b)});
}

std::string exact_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

ValueComparer::ValueComparer(double tolerance, size_t keep) : tolerance_(tolerance), keep_(keep) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("tolerance must be a finite number >= 0, got " + exact_text(tolerance));
}

void ValueComparer::set_context(const char* what, int64_t step) {
  what_ = what;
  step_ = step;
}

bool ValueComparer::real(const FieldRef& f, double logged, double recomputed) {
  ++compared_;
  uint64_t a, b;
  std::memcpy(&a, &logged, sizeof a);
  std::memcpy(&b, &recomputed, sizeof b);
  if (a == b) return true;
  const double e = value_error(logged, recomputed);
  max_error_ = std::max(max_error_, e);
  if (tolerance_ > 0.0 && e <= tolerance_) return true;
  record(f, exact_text(logged), exact_text(recomputed), e);
  return false;
}

bool ValueComparer::integer(const FieldRef& f, int64_t logged, int64_t recomputed) {
  ++compared_;
  if (logged == recomputed) return true;
  record(f, std::to_string(logged), std::to_string(recomputed), std::numeric_limits<double>::infinity());
  return false;
}

bool ValueComparer::text(const FieldRef& f, const std::string& logged, const std::string& recomputed) {
  ++compared_;
  if (logged == recomputed) return true;
  record(f, "\"" + logged + "\"", "\"" + recomputed + "\"", std::numeric_limits<double>::infinity());
  return false;
}

void ValueComparer::note(const std::string& field, const std::string& logged, const std::string& recomputed) {
  ++count_;
  if (kept_.size() >= keep_) return;
  Mismatch m;
  m.what = what_;
  m.step = step_;
  m.field = field;
  m.logged = logged;
  m.recomputed = recomputed;
  m.error = std::numeric_limits<double>::infinity();
  kept_.push_back(std::move(m));
}

void ValueComparer::record(const FieldRef& f, std::string logged, std::string recomputed, double error) {
  ++count_;
  if (kept_.size() >= keep_) return;
  Mismatch m;
  m.what = what_;
  m.step = step_;
  char buf[160];
  std::snprintf(buf, sizeof buf, f.format, f.i, f.j);
  m.field = buf;
  if (f.element) m.element = std::string(f.element) + " " + std::to_string(f.i);
  m.logged = std::move(logged);
  m.recomputed = std::move(recomputed);
  m.error = error;
  kept_.push_back(std::move(m));
}

}  // namespace robozoo::replay
