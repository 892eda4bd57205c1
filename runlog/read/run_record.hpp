#pragma once
// What a program knows about runs: the ROBOZOO_* messages of each run,
// gathered by MessageCollector from a log or the bus.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "robozoo/generation_t.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo {

/// A published genome and what arrived with it.
struct GenomeRecord {
  cppn_genome_t genome;
  bool has_morphology = false;
  morphology_t morphology;
  /// Its generation's champion (generation_t.champion_id), or published
  /// without a generation_t to say otherwise.
  bool champion = false;
  enum class Stream { None, Open, Complete };
  Stream stream = Stream::None;  ///< its ROBOZOO_POSE stream
  std::vector<pose_t> poses;     ///< in arrival order, steps increasing
  int64_t pose_count = 0;        ///< poses received (also when not kept)
  int32_t last_step = -1;        ///< step of the last pose received
};

struct RunRecord {
  run_t run;           ///< the latest ROBOZOO_RUN of this run
  std::string source;  ///< the log or URL it came from
  std::vector<generation_t> generations;
  std::vector<std::unique_ptr<GenomeRecord>> genomes;  ///< arrival order (stable addresses)
  std::map<int64_t, GenomeRecord*> by_id;

  const generation_t* generation(int32_t g) const;
  GenomeRecord* find(int64_t genome_id) const;
};

}  // namespace robozoo
