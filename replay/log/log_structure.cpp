#include "replay/log/log_structure.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "evolve/messages/build.hpp"
#include "evolve/messages/log_continuation.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/run/trajectory.hpp"
#include "evolve/sim/episode/outcome.hpp"
#include "replay/compare/number_text.hpp"
#include "replay/compare/value_compare.hpp"
#include "runlog/robots/regrow.hpp"

namespace robozoo::replay {

namespace {

constexpr size_t kNone = static_cast<size_t>(-1);

/// Where a run is in its sequence of messages.
enum class Phase {
  Start,      ///< nothing of the run yet
  AfterRun,   ///< a run_t: the generation_t comes next
  InGenomes,  ///< after generation_t: genomes and their morphologies
  InPoses,    ///< the champion's trajectory
};

/// One generation's messages, gathered until the next run_t (or the end).
struct Block {
  int32_t generation = -1;
  int64_t gen_eventnum = -1;
  generation_t msg{};
  int genomes = 0;
  int64_t pending_morphology = -1;  ///< id of the genome whose morphology must come next, -1 if none
  size_t champion_event = kNone;    ///< LogIndex::events index of the champion's genome
  int64_t champion_eventnum = -1;
  bool champion_simulated = false;
  bool champion_key_known = false;
  uint64_t champion_key = 0;
  std::array<int, kNumOutcomes> outcomes{};
  int64_t poses = 0;
  size_t last_event = 0;    ///< LogIndex::events index of its last event
  int64_t undecodable = 0;  ///< events among its messages that do not decode (count)
};

struct RunState {
  const RunConfig* config = nullptr;
  run_t first{};
  Phase phase = Phase::Start;
  int32_t next_generation = 0;
  int64_t evaluations = 0;
  double best_so_far = 0.0;
  bool last_key_known = true;  ///< before generation 0 the key is 0, as in Evolution
  uint64_t last_key = 0;
  bool open = false;  ///< a block is being gathered
  Block block;
};

class Checker {
 public:
  Checker(const LogContents& log, const LogIndex& index, const std::map<std::string, RunConfig>& configs,
          bool truncated)
      : log_(log), index_(index), configs_(configs), truncated_(truncated) {}

  StructureReport run() {
    for (size_t k = 0; k < index_.events.size(); ++k) visit(k);
    // The last block of each run; only the one that ends the log may be cut short.
    size_t last_event = 0;
    for (auto& [id, s] : runs_)
      if (s.open) last_event = std::max(last_event, s.block.last_event);
    for (auto& [id, s] : runs_) {
      if (!s.open) continue;
      const bool at_end = s.block.last_event == last_event;
      const bool unfinished = s.block.generation + 1 < s.first.generations;
      close(id, s, at_end && (truncated_ || unfinished));
    }
    std::stable_sort(out_.differences.begin(), out_.differences.end(),
                     [](const LogDifference& a, const LogDifference& b) { return a.eventnum < b.eventnum; });
    return std::move(out_);
  }

 private:
  const LogRecord& record(size_t k) const { return log_.records[index_.events[k].record]; }

  void differ(size_t k, const std::string& run_id, int32_t generation, const std::string& field,
              const std::string& logged, const std::string& expected, const std::string& rule) {
    const LogRecord& r = record(k);
    out_.differences.push_back({r.eventnum, r.channel, run_id, generation, field, logged, expected, rule});
  }
  /// A difference that is an absence, found when a block closes: named at the block's last event.
  /// Found missing where the log may end early, or where events do not decode,
  /// it is a problem of the input instead.
  void missing(const std::string& run_id, const Block& b, bool may_be_cut, const std::string& channel,
               const std::string& field, const std::string& logged, const std::string& expected,
               const std::string& rule) {
    if (may_be_cut || b.undecodable > 0) {
      const LogRecord& r = record(b.last_event);
      const std::string why =
          b.undecodable > 0
              ? num(b.undecodable) + " of its events do not decode, so generation " + num(b.generation) + " of run " +
                    run_id + " cannot be proved complete"
              : "the log ends before generation " + num(b.generation) + " of run " + run_id + " is complete";
      out_.incomplete.push_back({static_cast<int64_t>(b.last_event), r.eventnum, channel,
                                 why + ": " + field + " " + logged + ", expected " + expected});
      return;
    }
    const LogRecord& r = record(b.last_event);
    out_.differences.push_back({r.eventnum, channel, run_id, b.generation, field, logged, expected, rule});
  }

  /// Found where nothing may be, at the end of a generation.
  void extra(const std::string& run_id, const Block& b, const std::string& channel, const std::string& field,
             const std::string& logged, const std::string& expected, const std::string& rule) {
    const LogRecord& r = record(b.last_event);
    out_.differences.push_back({r.eventnum, channel, run_id, b.generation, field, logged, expected, rule});
  }

  void visit(size_t k) {
    const IndexedEvent& e = index_.events[k];
    if (e.kind == EventKind::Undecodable) {
      // Whose it was is unknown: every generation being gathered may miss it.
      for (auto& [id, s] : runs_)
        if (s.open) ++s.block.undecodable;
      return;
    }
    if (e.kind == EventKind::Foreign) return;
    auto it = runs_.find(e.run_id);
    if (it == runs_.end()) {
      const auto c = configs_.find(e.run_id);
      if (c == configs_.end()) return;  // no usable run_t: the check reports it
      it = runs_.emplace(e.run_id, RunState{}).first;
      it->second.config = &c->second;
    }
    RunState& s = it->second;
    if (s.phase == Phase::Start && e.kind != EventKind::Run) {
      differ(k, e.run_id, e.generation, "channel", record(k).channel, kChannelRun,
             "a run's first message is its ROBOZOO_RUN");
      // Go on as if it had been there, to find what else differs.
      s.phase = Phase::AfterRun;
      s.first.generations = s.config->generations;
      s.first.population = s.config->neat.population;
    }
    if (s.open) s.block.last_event = k;
    switch (e.kind) {
      case EventKind::Run: on_run(k, s); break;
      case EventKind::Generation: on_generation(k, s); break;
      case EventKind::Genome: on_genome(k, s); break;
      case EventKind::Morphology: on_morphology(k, s); break;
      case EventKind::Pose: on_pose(k, s); break;
      default: break;
    }
  }

  template <class T>
  T decode(size_t k) const {
    T m{};
    const LogRecord& r = record(k);
    safe_decode(r.data.data(), r.data.size(), m);  // the index decoded it already
    return m;
  }

  void on_run(size_t k, RunState& s) {
    const run_t m = decode<run_t>(k);
    if (s.phase == Phase::Start) {
      s.first = m;
      s.phase = Phase::AfterRun;
      // A log continued from a portable checkpoint begins at its generation, with the run's state then.
      try {
        if (const auto c = split_run_config(m.config_json).continues) {
          s.next_generation = c->from_generation;
          s.evaluations = c->evaluations_before;
          s.best_so_far = c->best_so_far_before;
          s.last_key = c->last_champion_key;
        }
      } catch (const std::invalid_argument&) {
        // Reported where the configuration is read (logged_config).
      }
      return;
    }
    if (s.phase == Phase::AfterRun) {
      differ(k, m.run_id, s.next_generation, "channel", kChannelRun, kChannelGeneration,
             "exactly one ROBOZOO_RUN precedes each generation's ROBOZOO_GENERATION");
    }
    const std::string rule = "every ROBOZOO_RUN of a run equals its first, utime aside";
    auto field = [&](const char* name, bool same, const std::string& a, const std::string& b) {
      if (!same) differ(k, m.run_id, s.next_generation, name, a, b, rule);
    };
    field("software_version", m.software_version == s.first.software_version, m.software_version,
          s.first.software_version);
    field("seed", m.seed == s.first.seed, num(m.seed), num(s.first.seed));
    field("regime", m.regime == s.first.regime, num(m.regime), num(s.first.regime));
    field("population", m.population == s.first.population, num(m.population), num(s.first.population));
    field("generations", m.generations == s.first.generations, num(m.generations), num(s.first.generations));
    field("steps", m.steps == s.first.steps, num(m.steps), num(s.first.steps));
    field("dt", std::memcmp(&m.dt, &s.first.dt, sizeof m.dt) == 0, exact_text(m.dt), exact_text(s.first.dt));
    field("config_json", m.config_json == s.first.config_json,
          "(" + num(static_cast<int64_t>(m.config_json.size())) + " bytes)",
          "the first ROBOZOO_RUN's (" + num(static_cast<int64_t>(s.first.config_json.size())) + " bytes)");
    if (s.open) close(m.run_id, s, false);
    s.phase = Phase::AfterRun;
  }

  void on_generation(size_t k, RunState& s) {
    const generation_t m = decode<generation_t>(k);
    const std::string& run = m.run_id;
    if (s.phase != Phase::AfterRun) {
      differ(k, run, m.generation, "channel", kChannelGeneration, kChannelRun,
             "exactly one ROBOZOO_RUN precedes each generation's ROBOZOO_GENERATION");
      if (s.open) close(run, s, false);
    }
    if (m.generation != s.next_generation)
      differ(k, run, m.generation, "generation", num(m.generation), num(s.next_generation),
             "each generation has exactly one ROBOZOO_GENERATION, numbered from 0 without gaps");
    const int64_t pop = s.first.population;
    if (m.evaluations != s.evaluations + pop)
      differ(k, run, m.generation, "evaluations", num(m.evaluations), num(s.evaluations + pop),
             "evaluations are cumulative: the previous generation's plus the population (" + num(pop) + ")");
    const double best_so_far = m.generation == 0 ? m.best_fitness : std::max(s.best_so_far, m.best_fitness);
    if (std::memcmp(&best_so_far, &m.best_so_far_fitness, sizeof best_so_far) != 0)
      differ(k, run, m.generation, "best_so_far_fitness", exact_text(m.best_so_far_fitness), exact_text(best_so_far),
             "best_so_far_fitness is the largest best_fitness since generation 0");
    const int64_t outcomes = int64_t{m.n_not_simulated} + m.n_completed + m.n_stopped_early + m.n_accel_fault +
                             m.n_rolling_contact + m.n_rolling_spin;
    if (outcomes != pop)
      differ(k, run, m.generation, "outcome counts", num(outcomes), num(pop),
             "the outcome counts (n_not_simulated ... n_rolling_spin) add up to the population");
    if (m.num_species < 1 || m.num_species > pop)
      differ(k, run, m.generation, "num_species", num(m.num_species), "1 to " + num(pop),
             "a population of " + num(pop) + " has between 1 and " + num(pop) + " species");
    if (!(m.mean_fitness <= m.best_fitness))
      differ(k, run, m.generation, "mean_fitness", exact_text(m.mean_fitness),
             "at most best_fitness " + exact_text(m.best_fitness), "the mean fitness is at most the best");
    s.next_generation = m.generation + 1;
    s.evaluations = m.evaluations;
    s.best_so_far = m.best_so_far_fitness;
    s.open = true;
    s.block = Block{};
    s.block.generation = m.generation;
    s.block.gen_eventnum = record(k).eventnum;
    s.block.msg = m;
    s.block.last_event = k;
    s.phase = Phase::InGenomes;
  }

  void on_genome(size_t k, RunState& s) {
    const cppn_genome_t m = decode<cppn_genome_t>(k);
    if (s.phase != Phase::InGenomes || !s.open) {
      differ(k, m.run_id, m.generation, "channel", kChannelGenome,
             s.phase == Phase::InPoses ? kChannelPose : kChannelGeneration,
             "a generation's genomes follow its ROBOZOO_GENERATION and come before the champion's poses");
      if (!s.open) return;
      s.phase = Phase::InGenomes;
    }
    Block& b = s.block;
    if (b.pending_morphology >= 0)
      differ(k, m.run_id, b.generation, "channel", kChannelGenome, kChannelMorphology,
             "each genome is followed by its morphology (genome " + num(b.pending_morphology) + "'s is missing)");
    if (m.generation != b.generation)
      differ(k, m.run_id, b.generation, "generation", num(m.generation), num(b.generation),
             "a genome belongs to the generation whose ROBOZOO_GENERATION precedes it");
    if (b.genomes == 0) {
      // The champion comes first.
      auto at_generation = [&](const std::string& field, const std::string& logged, const std::string& expected,
                               const std::string& rule) {
        out_.differences.push_back(
            {b.gen_eventnum, kChannelGeneration, m.run_id, b.generation, field, logged, expected, rule});
      };
      if (m.genome_id != b.msg.champion_id)
        at_generation("champion_id", num(b.msg.champion_id), num(m.genome_id),
                      "champion_id names the generation's first genome message, its champion");
      if (std::memcmp(&m.fitness, &b.msg.best_fitness, sizeof m.fitness) != 0)
        at_generation(
            "best_fitness", exact_text(b.msg.best_fitness), exact_text(m.fitness),
            "best_fitness is the champion's fitness (its genome message, event " + num(record(k).eventnum) + ")");
      b.champion_event = k;
      b.champion_eventnum = record(k).eventnum;
      b.champion_simulated = m.outcome != static_cast<int8_t>(Outcome::NotSimulated);
      try {
        b.champion_key = trajectory_key(logged_genes(m));
        b.champion_key_known = true;
      } catch (const std::exception&) {
        b.champion_key_known = false;  // its check reports the genome as unusable
      }
    } else if (!s.config->publish_all) {
      differ(k, m.run_id, b.generation, "genomes", num(b.genomes + 1), "1",
             "without publish_all, a generation logs its champion only");
    }
    if (m.outcome >= 0 && m.outcome < kNumOutcomes) ++b.outcomes[m.outcome];
    ++b.genomes;
    b.pending_morphology = m.genome_id;
  }

  void on_morphology(size_t k, RunState& s) {
    const morphology_t m = decode<morphology_t>(k);
    if (!s.open || s.phase != Phase::InGenomes || s.block.pending_morphology < 0 ||
        s.block.pending_morphology != m.genome_id) {
      const int64_t want = s.open ? s.block.pending_morphology : -1;
      differ(k, m.run_id, m.generation, "genome_id", num(m.genome_id),
             want >= 0 ? num(want) : std::string("none (no genome before it awaits its morphology)"),
             "each morphology follows its own genome message");
      if (s.open && s.block.pending_morphology == m.genome_id) s.block.pending_morphology = -1;
      return;
    }
    s.block.pending_morphology = -1;
  }

  void on_pose(size_t k, RunState& s) {
    const IndexedEvent& e = index_.events[k];
    if (!s.open) {
      differ(k, e.run_id, e.generation, "channel", kChannelPose, kChannelGeneration,
             "poses belong to a generation's champion, after its ROBOZOO_GENERATION");
      return;
    }
    Block& b = s.block;
    if (s.phase == Phase::InGenomes && b.pending_morphology >= 0) {
      differ(k, e.run_id, b.generation, "channel", kChannelPose, kChannelMorphology,
             "each genome is followed by its morphology (genome " + num(b.pending_morphology) + "'s is missing)");
      b.pending_morphology = -1;
    }
    s.phase = Phase::InPoses;
    if (e.genome_id != b.msg.champion_id || e.generation != b.generation) {
      differ(k, e.run_id, b.generation, "genome_id", num(e.genome_id) + " (gen " + num(e.generation) + ")",
             num(b.msg.champion_id) + " (gen " + num(b.generation) + ")",
             "the poses after a generation's genomes are its champion's trajectory");
      return;
    }
    ++b.poses;
  }

  /// The end of a generation's messages: what must have been there.
  void close(const std::string& run_id, RunState& s, bool may_be_cut) {
    s.open = false;
    const Block& b = s.block;
    const int pop = s.first.population;
    const int want_genomes = s.config->publish_all ? pop : 1;
    if (b.genomes < want_genomes)
      missing(run_id, b, may_be_cut, kChannelGenome, "genomes", num(b.genomes), num(want_genomes),
              s.config->publish_all ? "with publish_all, a generation logs every genome"
                                    : "a generation logs its champion's genome");
    if (b.pending_morphology >= 0)
      missing(run_id, b, may_be_cut, kChannelMorphology, "morphology of genome " + num(b.pending_morphology), "none",
              "one", "each genome is followed by its morphology");
    if (s.config->publish_all && b.genomes == pop) {
      const std::array<int, kNumOutcomes> counted = {b.msg.n_not_simulated,   b.msg.n_completed,
                                                     b.msg.n_stopped_early,   b.msg.n_accel_fault,
                                                     b.msg.n_rolling_contact, b.msg.n_rolling_spin};
      for (int o = 0; o < kNumOutcomes; ++o)
        if (counted[o] != b.outcomes[o])
          out_.differences.push_back({b.gen_eventnum, kChannelGeneration, run_id, b.generation,
                                      "n_" + outcome_name(static_cast<Outcome>(o)), num(counted[o]), num(b.outcomes[o]),
                                      "with publish_all, the outcome counts are those of the logged genomes"});
    }
    if (b.champion_event == kNone) return;
    // Was a trajectory due? Exactly when Evolution logs one.
    TrajectoryRule rule = TrajectoryRule::None;
    const bool changed = !(s.last_key_known && b.champion_key_known && s.last_key == b.champion_key);
    if (changed && b.champion_simulated) rule = may_be_cut ? TrajectoryRule::MayBeCut : TrajectoryRule::Complete;
    if (!b.champion_key_known) rule = TrajectoryRule::MayBeCut;  // unknowable: its check says why
    if (rule != TrajectoryRule::None && b.undecodable > 0) rule = TrajectoryRule::Damaged;
    out_.trajectory[b.champion_event] = rule;
    s.last_key = b.champion_key;
    s.last_key_known = b.champion_key_known;
    if ((rule == TrajectoryRule::Complete || rule == TrajectoryRule::Damaged) && b.poses == 0)
      missing(run_id, b, false, kChannelPose, "poses of champion " + num(b.msg.champion_id), "none", "its trajectory",
              "a new champion that was simulated has its trajectory logged");
    if (rule == TrajectoryRule::None && b.poses > 0)
      extra(run_id, b, kChannelPose, "poses of champion " + num(b.msg.champion_id), num(b.poses), "none",
            b.champion_simulated ? "a champion with the previous champion's genes has no trajectory of its own"
                                 : "a champion that was not simulated has no trajectory");
    ++out_.generations;
  }

  const LogContents& log_;
  const LogIndex& index_;
  const std::map<std::string, RunConfig>& configs_;
  bool truncated_;
  std::map<std::string, RunState> runs_;
  StructureReport out_;
};

}  // namespace

StructureReport check_log_structure(const LogContents& log, const LogIndex& index,
                                    const std::map<std::string, RunConfig>& config_of_run, bool truncated) {
  return Checker(log, index, config_of_run, truncated).run();
}

std::string describe(const LogDifference& d) {
  std::string s = d.eventnum >= 0 ? "event " + std::to_string(d.eventnum) : std::string("end of log");
  s += " (" + d.channel + ")";
  if (!d.run_id.empty()) s += " run " + d.run_id;
  if (d.generation >= 0) s += " gen " + std::to_string(d.generation);
  s += " " + d.field + ": logged " + d.logged + ", expected " + d.expected;
  if (!d.rule.empty()) s += " (" + d.rule + ")";
  return s;
}

}  // namespace robozoo::replay
