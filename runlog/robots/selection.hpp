#pragma once
// Which robots to draw: champions chosen from the runs of one or more logs.
#include <cstdint>
#include <vector>

#include "runlog/read/run_record.hpp"

namespace robozoo {

/// A champion of a run (genome with its morphology).
struct Pick {
  const RunRecord* run = nullptr;
  const GenomeRecord* genome = nullptr;
};

/// The champions of a run that have a morphology, in generation order.
std::vector<Pick> champions(const RunRecord& run);

/// The best champion of each run (highest fitness; the earliest on ties).
std::vector<Pick> best_of_run(const std::vector<const RunRecord*>& runs);
/// The n best distinct champions of the runs (a champion copied unchanged
/// into later generations counts once, at its first generation), best first.
std::vector<Pick> top_champions(const std::vector<const RunRecord*>& runs, int n);
/// The champion of generation g in each run that has it.
std::vector<Pick> generation_champions(const std::vector<const RunRecord*>& runs, int32_t g);
/// The genome with this id in the runs (champion or not), if it has a morphology.
std::vector<Pick> genome_by_id(const std::vector<const RunRecord*>& runs, int64_t genome_id);

/// Hash of a genome's genes (nodes and links), ignoring its id and scores:
/// equal for NEAT's unchanged copies of a champion.
uint64_t gene_hash(const cppn_genome_t& g);

}  // namespace robozoo
