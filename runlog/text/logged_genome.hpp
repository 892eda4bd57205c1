#pragma once
// Finding one logged CPPN genome in a log (robozoo-log cppn): by genome id, or
// the champion of the log's last generation.
#include <cstdint>
#include <optional>

#include "robozoo/cppn_genome_t.hpp"
#include "runlog/read/log_reader.hpp"

namespace robozoo {

/// The last ROBOZOO_GENOME message of genome `id`, or (no id) that of the last
/// ROBOZOO_GENERATION's champion. Throws std::invalid_argument saying what is
/// missing: no such genome, no generation, or a champion that was not logged.
cppn_genome_t find_logged_genome(const ScannedLog& log, std::optional<int64_t> id);

}  // namespace robozoo
