#include "evolve/record/run_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "evolve/config/run_config.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/log_continuation.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/neat/arm.hpp"

namespace robozoo {

bool RunSummary::complete() const {
  if (generations_requested <= 0 || generations.size() != static_cast<size_t>(generations_requested)) return false;
  for (size_t i = 0; i < generations.size(); ++i)
    if (generations[i].generation != static_cast<int32_t>(i)) return false;
  return true;
}

void apply_run_configuration(RunSummary& s) {
  s.arm = s.regime == 0 ? "feedforward" : "recurrent";
  s.max_spheres = 0;
  s.target_distance = 0;
  try {
    const RunConfig c = config_from_record(nlohmann::json::parse(s.config_json));
    // run_t's regime is authoritative; the start topology comes from the configuration.
    s.arm = arm_name(arm_of(s.regime == 0 ? Regime::FeedForward : Regime::Recurrent, c.neat.initial_links));
    s.max_spheres = c.eval.growth.max_spheres;
    const auto& sim = c.eval.sim;
    s.target_distance =
        std::sqrt(sim.target_x * sim.target_x + sim.target_y * sim.target_y + sim.target_z * sim.target_z);
  } catch (const std::exception&) {
    // A configuration this robozoo cannot read: the arm from the regime alone.
  }
}

RunSummary summarize_run(const LogContents& log, const std::string& path) {
  RunSummary s;
  s.path = path;
  s.truncated = log.truncated;
  bool have_run = false;
  std::map<int32_t, GenerationRecord> gens;
  // First pass: the run and the generations (each champion id is known before its genome).
  for (const auto& r : log.records) {
    if (r.channel == kChannelRun) {
      run_t m;
      if (!safe_decode(r.data.data(), r.data.size(), m)) {
        ++s.undecodable;
        continue;
      }
      if (have_run && m.run_id != s.run_id)
        throw std::invalid_argument(path + ": holds two runs, '" + s.run_id + "' and '" + m.run_id + "'");
      have_run = true;
      s.run_id = m.run_id;
      s.software_version = m.software_version;
      s.seed = m.seed;
      s.regime = m.regime;
      s.population = m.population;
      s.generations_requested = m.generations;
      s.steps = m.steps;
      s.dt = m.dt;
      try {
        // A log continued from a portable checkpoint says so in its configuration text; what is
        // compared is the configuration without it (log_continuation.hpp).
        SplitRunConfig split = split_run_config(m.config_json);
        s.config_json = std::move(split.config_json);
        s.continues = split.continues;
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(path + ": " + e.what());
      }
    } else if (r.channel == kChannelGeneration) {
      generation_t m;
      if (!safe_decode(r.data.data(), r.data.size(), m)) {
        ++s.undecodable;
        continue;
      }
      GenerationRecord g;
      g.generation = m.generation;
      g.best_fitness = m.best_fitness;
      g.mean_fitness = m.mean_fitness;
      g.best_so_far_fitness = m.best_so_far_fitness;
      g.stderr_fitness = m.stderr_fitness;
      g.evaluations = m.evaluations;
      g.champion_id = m.champion_id;
      g.num_species = m.num_species;
      g.compatibility_threshold = m.compatibility_threshold;
      g.outcomes = {m.n_not_simulated, m.n_completed,       m.n_stopped_early,
                    m.n_accel_fault,   m.n_rolling_contact, m.n_rolling_spin};
      gens[m.generation] = g;  // the last record of a generation wins
    }
  }
  if (!have_run) throw std::invalid_argument(path + ": no decodable ROBOZOO_RUN message (not a robozoo log?)");
  apply_run_configuration(s);
  for (const auto& [gen, g] : gens) s.generations.push_back(g);

  // Second pass: the champions' genomes and morphologies, and the pose streams.
  std::map<int32_t, ChampionRecord> champs;
  std::map<int32_t, morphology_t> morphs;
  for (const auto& r : log.records) {
    if (r.channel == kChannelGenome) {
      cppn_genome_t m;
      if (!safe_decode(r.data.data(), r.data.size(), m)) {
        ++s.undecodable;
        continue;
      }
      if (std::isfinite(m.d_term)) s.max_d = std::max(s.max_d, m.d_term);
      const auto g = gens.find(m.generation);
      if (g == gens.end() || g->second.champion_id != m.genome_id) continue;
      ChampionRecord c;
      c.generation = m.generation;
      c.genome = std::move(m);
      champs[c.generation] = std::move(c);
    } else if (r.channel == kChannelMorphology) {
      morphology_t m;
      if (!safe_decode(r.data.data(), r.data.size(), m)) {
        ++s.undecodable;
        continue;
      }
      const auto g = gens.find(m.generation);
      if (g == gens.end() || g->second.champion_id != m.genome_id) continue;
      morphs[m.generation] = std::move(m);
    } else if (r.channel == kChannelPose) {
      pose_t m;
      if (!safe_decode(r.data.data(), r.data.size(), m)) {
        ++s.undecodable;
        continue;
      }
      auto [it, fresh] = s.min_center_z.try_emplace(m.genome_id);
      std::vector<double>& z = it->second;
      if (fresh) z.assign(m.sphere_center.size(), std::numeric_limits<double>::infinity());
      if (z.size() != m.sphere_center.size())
        throw std::invalid_argument(path + ": the pose stream of genome " + std::to_string(m.genome_id) +
                                    " changes its number of spheres");
      for (size_t i = 0; i < z.size(); ++i) z[i] = std::min(z[i], m.sphere_center[i][2]);
    }
  }
  for (auto& [gen, c] : champs) {
    const auto m = morphs.find(gen);
    if (m != morphs.end()) {
      c.morphology = std::move(m->second);
      c.has_morphology = true;
    }
    s.champions.push_back(std::move(c));
  }
  return s;
}

const ChampionRecord* best_of_run(const RunSummary& run) {
  const ChampionRecord* best = nullptr;
  for (const auto& c : run.champions)
    if (!best || c.genome.fitness > best->genome.fitness) best = &c;
  return best;
}

}  // namespace robozoo
