#include "runlog/read/log_index.hpp"

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo {

EventKind kind_of_channel(const std::string& channel) {
  if (channel == kChannelRun) return EventKind::Run;
  if (channel == kChannelGeneration) return EventKind::Generation;
  if (channel == kChannelGenome) return EventKind::Genome;
  if (channel == kChannelMorphology) return EventKind::Morphology;
  if (channel == kChannelPose) return EventKind::Pose;
  return EventKind::Foreign;
}

namespace {

/// Decodes the bytes of a robozoo event into `e`'s navigation fields; false (and
/// `why`) when they are not a message of the channel's type.
bool fill(const LogRecord& r, IndexedEvent& e, std::string& why) {
  switch (e.kind) {
    case EventKind::Run: {
      run_t m{};
      if (!safe_decode(r.data.data(), r.data.size(), m, &why)) return false;
      e.run_id = m.run_id;
      return true;
    }
    case EventKind::Generation: {
      generation_t m{};
      if (!safe_decode(r.data.data(), r.data.size(), m, &why)) return false;
      e.run_id = m.run_id;
      e.generation = m.generation;
      e.genome_id = m.champion_id;
      return true;
    }
    case EventKind::Genome: {
      cppn_genome_t m{};
      if (!safe_decode(r.data.data(), r.data.size(), m, &why)) return false;
      e.run_id = m.run_id;
      e.generation = m.generation;
      e.genome_id = m.genome_id;
      return true;
    }
    case EventKind::Morphology: {
      morphology_t m{};
      if (!safe_decode(r.data.data(), r.data.size(), m, &why)) return false;
      e.run_id = m.run_id;
      e.generation = m.generation;
      e.genome_id = m.genome_id;
      return true;
    }
    case EventKind::Pose: {
      pose_t m{};
      if (!safe_decode(r.data.data(), r.data.size(), m, &why)) return false;
      e.run_id = m.run_id;
      e.generation = m.generation;
      e.genome_id = m.genome_id;
      e.step = m.step;
      e.sim_time = m.sim_time;
      return true;
    }
    default: return true;
  }
}

}  // namespace

LogIndex index_log(const LogContents& log) {
  LogIndex ix;
  std::map<std::pair<std::string, int64_t>, size_t> latest_genome;  // (run, id) -> genomes index
  std::map<std::string, size_t> latest_run;                         // run -> events index
  std::map<std::pair<std::string, int32_t>, int64_t> champion_of;   // (run, generation) -> id
  auto problem = [&](size_t event, const std::string& what) {
    const LogRecord& r = log.records[ix.events[event].record];
    ix.problems.push_back({static_cast<int64_t>(event), r.eventnum, r.channel, what});
  };
  ix.events.reserve(log.records.size());
  for (size_t i = 0; i < log.records.size(); ++i) {
    const LogRecord& r = log.records[i];
    IndexedEvent e;
    e.record = i;
    e.kind = kind_of_channel(r.channel);
    std::string why;
    if (e.kind != EventKind::Foreign && !fill(r, e, why)) {
      e.kind = EventKind::Undecodable;
      ix.events.push_back(e);
      problem(ix.events.size() - 1, "not a valid " + r.channel + " message: " + why);
      continue;
    }
    ix.events.push_back(e);
    const size_t k = ix.events.size() - 1;
    switch (e.kind) {
      case EventKind::Foreign: ++ix.foreign_events; break;
      case EventKind::Run:
        ix.run_events.push_back(k);
        latest_run[e.run_id] = k;
        break;
      case EventKind::Generation: champion_of[{e.run_id, e.generation}] = e.genome_id; break;
      case EventKind::Genome: {
        LoggedGenome g;
        g.run_id = e.run_id;
        g.generation = e.generation;
        g.genome_id = e.genome_id;
        g.genome_event = k;
        const auto run = latest_run.find(e.run_id);
        if (run != latest_run.end()) g.run_event = static_cast<int64_t>(run->second);
        latest_genome[{e.run_id, e.genome_id}] = ix.genomes.size();
        ix.genomes.push_back(std::move(g));
        break;
      }
      case EventKind::Morphology:
      case EventKind::Pose: {
        const auto it = latest_genome.find({e.run_id, e.genome_id});
        const char* what = e.kind == EventKind::Pose ? "pose" : "morphology";
        if (it == latest_genome.end()) {
          problem(k, std::string(what) + " of genome " + std::to_string(e.genome_id) + " (run " + e.run_id +
                         ") with no genome message before it");
          break;
        }
        LoggedGenome& g = ix.genomes[it->second];
        if (e.kind == EventKind::Pose) {
          g.pose_events.push_back(k);
        } else if (g.morphology_event >= 0) {
          problem(k, "a second morphology for genome " + std::to_string(e.genome_id) + " (run " + e.run_id +
                         "); the first is checked");
        } else {
          g.morphology_event = static_cast<int64_t>(k);
        }
        break;
      }
      case EventKind::Undecodable: break;
    }
  }
  for (auto& g : ix.genomes) {
    const auto it = champion_of.find({g.run_id, g.generation});
    g.champion = it == champion_of.end() || it->second == g.genome_id;
  }
  return ix;
}

std::vector<const LoggedGenome*> LogIndex::to_check(bool all) const {
  std::vector<const LoggedGenome*> out;
  for (const auto& g : genomes)
    if (all || g.champion) out.push_back(&g);
  return out;
}

const LoggedGenome* LogIndex::find_genome(int64_t genome_id, const std::string& run_id) const {
  for (auto it = genomes.rbegin(); it != genomes.rend(); ++it)
    if (it->genome_id == genome_id && (run_id.empty() || it->run_id == run_id)) return &*it;
  return nullptr;
}

}  // namespace robozoo
