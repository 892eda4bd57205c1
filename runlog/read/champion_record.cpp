#include "runlog/read/champion_record.hpp"

#include <memory>
#include <utility>

namespace robozoo {

RunRecord champion_run_record(const ChampionReplay& replay, const std::string& source, const RunSummary* history) {
  RunRecord run;
  run.run = replay.run;
  run.run.generations = replay.generations;
  run.source = source;
  if (history) {
    for (const GenerationRecord& g : history->generations)
      run.generations.push_back(generation_message_of(g, run.run.run_id, replay.run.utime));
  } else {
    generation_t summary = replay.summary;
    summary.generation = replay.generation;
    run.generations.push_back(summary);
  }
  auto g = std::make_unique<GenomeRecord>();
  g->genome = replay.genome;
  g->genome.generation = replay.generation;
  g->has_morphology = true;
  g->morphology = replay.morphology;
  g->morphology.generation = replay.generation;
  g->champion = true;
  g->poses = replay.poses;
  for (pose_t& p : g->poses) p.generation = replay.generation;
  g->pose_count = static_cast<int64_t>(g->poses.size());
  g->last_step = g->poses.empty() ? -1 : g->poses.back().step;
  g->stream = g->poses.empty() ? GenomeRecord::Stream::None : GenomeRecord::Stream::Complete;
  run.by_id[g->genome.genome_id] = g.get();
  run.genomes.push_back(std::move(g));
  return run;
}

}  // namespace robozoo
