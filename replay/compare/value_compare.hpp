#pragma once
// Comparing logged values with recomputed ones, field by field, and keeping a
// record of every difference: bit for bit by default, or within a relative
// error (--tolerance) for logs made on another machine.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace robozoo::replay {

/// One value that differs.
struct Mismatch {
  std::string what;        ///< "genome", "morphology", "pose" or "fitness"
  int64_t step = -1;       ///< pose: the physics step; -1 otherwise
  std::string element;     ///< "body 2", "sphere 5", "neuron 0", "sensor 3"; empty for scalars
  std::string field;       ///< full field path, e.g. "body_position[2][0]" or "spheres[5].radius"
  std::string logged;      ///< the logged value, as text (doubles: %.17g, which round-trips)
  std::string recomputed;  ///< the recomputed value, as text
  double error = 0.0;      ///< value_error() of the two; infinite for counts, ids and other exact fields
};

/// The error measure of --tolerance: |a - b| / max(1, |a|, |b|), a relative
/// error for values of magnitude 1 or more and an absolute one below (every
/// robozoo quantity is of order 1: metres, radians, unit quaternions, neuron
/// outputs). 0 for identical values (two NaNs with the same bits included);
/// infinite when one is NaN or an infinity and the other is not the same.
double value_error(double a, double b);

/// Names a field: printf-style `format` with up to two indices, and the element
/// ("body", "sphere"...) that the first index counts, or nullptr.
struct FieldRef {
  const char* format;
  int i = -1;
  int j = -1;
  const char* element = nullptr;
};

/// True when both arrays of a message hold exactly `n` values (its count field),
/// so that their values may be compared index by index.
template <class V>
bool sizes_agree(const V& a, const V& b, int32_t n) {
  return n >= 0 && a.size() == static_cast<size_t>(n) && b.size() == static_cast<size_t>(n);
}

/// Accumulates the comparison of one champion (or one message).
class ValueComparer {
 public:
  /// tolerance 0: bit for bit. `keep`: mismatches kept with their details (the
  /// count of all of them is kept regardless).
  explicit ValueComparer(double tolerance = 0.0, size_t keep = 20);

  /// Sets what the following comparisons are about ("pose", step 120).
  void set_context(const char* what, int64_t step = -1);

  /// Real field: equal when bit-identical, or with tolerance > 0 when
  /// value_error <= tolerance. Returns true when equal.
  bool real(const FieldRef& f, double logged, double recomputed);
  /// Exact field (count, id, flag, code): equal only when identical.
  bool integer(const FieldRef& f, int64_t logged, int64_t recomputed);
  bool text(const FieldRef& f, const std::string& logged, const std::string& recomputed);
  /// A count that must match before the arrays it sizes can be compared.
  bool count(const FieldRef& f, int64_t logged, int64_t recomputed) { return integer(f, logged, recomputed); }

  double tolerance() const { return tolerance_; }
  const std::vector<Mismatch>& mismatches() const { return kept_; }
  int64_t mismatch_count() const { return count_; }
  int64_t values_compared() const { return compared_; }
  /// Largest value_error over every real value compared (0 when all equal).
  double max_error() const { return max_error_; }
  bool ok() const { return count_ == 0; }
  /// Records a difference that is no single value (e.g. "a logged pose at a
  /// step the re-simulation never reached").
  void note(const std::string& field, const std::string& logged, const std::string& recomputed);

 private:
  void record(const FieldRef& f, std::string logged, std::string recomputed, double error);
  double tolerance_;
  size_t keep_;
  const char* what_ = "";
  int64_t step_ = -1;
  std::vector<Mismatch> kept_;
  int64_t count_ = 0;
  int64_t compared_ = 0;
  double max_error_ = 0.0;
};

/// A double as text that reads back to the same bits (%.17g).
std::string exact_text(double v);

}  // namespace robozoo::replay
