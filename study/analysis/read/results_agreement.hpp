#pragma once
// Whether two compact results of the same trial agree over the generations
// both hold: a trial run to generation 30 on one machine and to 60 on another
// (the paper experiment's M1 and M2) must give the same first 30 generations,
// field for field, because runs are deterministic. The check compares the
// results' JSON (run_results_to_json): the run's identity and configuration
// except the generations requested, every generation record both hold, and
// every champion of those generations. Doubles are compared by their bits
// (as JSON numbers written round-trip), so a difference in the last bit counts.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "evolve/record/run_results.hpp"

namespace robozoo {

/// The first place where `a` and `b` disagree, as "generation 17: mean_fitness
/// 4.5228... != 4.5229..." (or "run.seed: ...", "champions of generation 3:
/// ..."); nullopt when they agree over min(a, b) generations.
std::optional<std::string> first_disagreement(const RunResults& a, const RunResults& b);

struct TrialAgreement {
  std::string trial;                      ///< file name without .results.json
  size_t generations_a = 0;               ///< generations in the first folder's result (count)
  size_t generations_b = 0;               ///< ... in the second's (count)
  std::optional<std::string> difference;  ///< first_disagreement
};

struct FolderAgreement {
  std::vector<TrialAgreement> trials;       ///< trials in both folders, in list_results order
  std::vector<std::string> only_a, only_b;  ///< trials in one folder only
  /// Some trial is in both folders, and every such trial agrees.
  bool agree() const;
};

/// Compares every trial whose compact result is in both folders (the same
/// file name). Throws like read_run_results for an unreadable or bad result,
/// std::invalid_argument when a folder is not one.
FolderAgreement compare_results_folders(const std::string& dir_a, const std::string& dir_b);

/// One line per trial and a closing line, for robozoo-stats --same-as.
void print_agreement(const FolderAgreement& f, const std::string& dir_a, const std::string& dir_b, std::ostream& out);

}  // namespace robozoo
