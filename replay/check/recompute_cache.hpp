#pragma once
// Growth and evaluation of the genomes a check has already recomputed. Both
// are pure functions of (genes, configuration) (docs/method.md section 4), and NEAT
// copies an unchanged champion under a fresh id every generation it stays
// best, so a long run logs the same genes many times: they are grown and
// evaluated once. Genes are matched exactly (weights bit for bit), not by hash.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "evolve/cppn/genome.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/growth/robot.hpp"

namespace robozoo::replay {

class RecomputeCache {
 public:
  struct Entry {
    Genome genes;                  ///< id set to 0
    std::string config;            ///< the configuration, as JSON text
    int64_t first_genome_id = -1;  ///< the genome it was first computed for
    int32_t first_generation = -1;
    Robot robot;
    Evaluation evaluation;
  };
  /// The entry for these genes (any id) and configuration, or nullptr.
  const Entry* find(const Genome& genome, const std::string& config) const;
  /// Stores an entry (its genes' id is reset to 0) and returns it.
  const Entry& add(Entry e);
  int64_t hits() const { return hits_; }
  size_t size() const { return size_; }

 private:
  std::map<uint64_t, std::vector<std::unique_ptr<Entry>>> entries_;
  mutable int64_t hits_ = 0;
  size_t size_ = 0;
};

}  // namespace robozoo::replay
