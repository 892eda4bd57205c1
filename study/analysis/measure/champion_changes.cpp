#include "study/analysis/measure/champion_changes.hpp"

#include <map>

namespace robozoo {

ChampionChanges champion_changes(const RunSummary& run, const ChampionChangeParams& params) {
  ChampionChanges out;
  std::map<int32_t, const ChampionRecord*> by_gen;
  for (const auto& c : run.champions) by_gen[c.generation] = &c;
  // Gains are read from the generation records, so a champion missing from the log is counted, not hidden.
  for (size_t i = 1; i < run.generations.size(); ++i) {
    const GenerationRecord& prev = run.generations[i - 1];
    const GenerationRecord& cur = run.generations[i];
    if (cur.generation != prev.generation + 1 || !(cur.best_fitness > prev.best_fitness)) continue;
    const auto a = by_gen.find(prev.generation), b = by_gen.find(cur.generation);
    if (a == by_gen.end() || b == by_gen.end() || !a->second->has_morphology || !b->second->has_morphology) {
      ++out.unknown;
      continue;
    }
    const ChampionRecord& pa = *a->second;
    const ChampionRecord& pb = *b->second;
    if (params.simulated_only && (pa.genome.outcome == 0 || pb.genome.outcome == 0)) {
      ++out.not_simulated;
      continue;
    }
    ChampionChange c;
    c.generation = cur.generation;
    c.previous_id = pa.genome.genome_id;
    c.genome_id = pb.genome.genome_id;
    c.previous_fitness = pa.genome.fitness;
    c.fitness = pb.genome.fitness;
    c.improvement = c.fitness - c.previous_fitness;
    c.topology_changed = !same_topology(pa.morphology, pb.morphology, params.topology);
    out.changes.push_back(c);
  }
  return out;
}

}  // namespace robozoo
