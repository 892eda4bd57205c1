#pragma once
// `robozoo-replay check`: every champion of a log re-grown, re-simulated and
// re-evaluated with the configuration of its run's ROBOZOO_RUN, compared with
// what was logged.
#include <cstddef>
#include <functional>
#include <string>

#include "replay/check/check_report.hpp"
#include "runlog/read/log_reader.hpp"

namespace robozoo::replay {

struct CheckOptions {
  double tolerance = 0.0;    ///< 0: bit for bit; else the largest value_error allowed (dimensionless)
  bool force = false;        ///< check runs written by another software version
  bool all_genomes = false;  ///< every logged genome, not only the champions
  size_t keep = 20;          ///< mismatches kept per genome with their details (count)
};

/// Called after each genome with (genomes done, genomes to check).
using CheckProgress = std::function<void(size_t done, size_t total)>;

/// Checks a scanned log. Never throws on bad input: it ends up in the report
/// (fatal, input problems, unusable genomes). Throws std::invalid_argument for
/// bad options.
CheckReport check_log(const ScannedLog& log, const CheckOptions& options, const CheckProgress& progress = {});

/// Reads `path` and checks it; an unreadable file is a fatal report.
CheckReport check_log_file(const std::string& path, const CheckOptions& options, const CheckProgress& progress = {});

}  // namespace robozoo::replay
