#include "study/analysis/figures/csv_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace robozoo {

CsvWriter::CsvWriter(std::vector<std::string> header) : header_(std::move(header)) {
  if (header_.empty()) throw std::invalid_argument("CsvWriter: a table needs at least one column");
}

void CsvWriter::add_row(std::vector<std::string> row) {
  if (row.size() != header_.size())
    throw std::invalid_argument("CsvWriter: row of " + std::to_string(row.size()) + " fields for " +
                                std::to_string(header_.size()) + " columns");
  rows_.push_back(std::move(row));
}

std::string CsvWriter::str() const {
  std::string out;
  auto line = [&out](const std::vector<std::string>& fields) {
    for (size_t i = 0; i < fields.size(); ++i) {
      if (i) out += ',';
      out += csv_field(fields[i]);
    }
    out += '\n';
  };
  line(header_);
  for (const auto& r : rows_) line(r);
  return out;
}

void CsvWriter::write(const std::string& path) const {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << str();
  f.close();
  if (!f) throw std::runtime_error("cannot write " + path);
}

std::string csv_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

}  // namespace robozoo
