#pragma once
// A compact result's champion, replayed in memory (evolve/run/champion_log's
// replay_champion), as the record that robozoo-render and robozoo-view draw a
// logged run from: no log file in between.
#include <string>

#include "evolve/run/champion_log.hpp"
#include "runlog/read/run_record.hpp"

namespace robozoo {

/// The replay as MessageCollector gathers it from a log, with the generation
/// the champion won in place of 0 (genome, morphology, poses, generation_t)
/// and its run's generations in run_t:
/// one run whose one genome is a complete champion (its pose stream complete
/// when it has poses). `source` names where it came from (the result's file).
/// With `history` (the result's run), its generation records are every
/// generation of the run as logged; without, the one the champion won.
RunRecord champion_run_record(const ChampionReplay& replay, const std::string& source,
                              const RunSummary* history = nullptr);

}  // namespace robozoo
