#pragma once
// A small CSV writer (RFC 4180 quoting) for the experiment's tables.
#include <string>
#include <vector>

namespace robozoo {

class CsvWriter {
 public:
  explicit CsvWriter(std::vector<std::string> header);
  /// Appends a row; throws std::invalid_argument when its width differs from the header's.
  void add_row(std::vector<std::string> row);
  /// The whole table, header first, "\n" line ends.
  std::string str() const;
  /// Writes str() to `path`; throws std::runtime_error naming the path on failure.
  void write(const std::string& path) const;
  size_t rows() const { return rows_.size(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// A number for a CSV cell: up to 10 significant digits, "nan", "inf", "-inf".
std::string csv_number(double v);
/// One field, quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s);

}  // namespace robozoo
