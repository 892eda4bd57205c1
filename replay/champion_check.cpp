#include "replay/champion_check.hpp"

#include <algorithm>

#include "evolve/fitness/evaluate.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/sim/simulation.hpp"
#include "replay/morphology_compare.hpp"
#include "replay/pose_compare.hpp"

namespace robozoo {

const char* status_name(ChampionResult::Status s) {
  switch (s) {
    case ChampionResult::Status::Ok: return "ok";
    case ChampionResult::Status::Diverged: return "diverged";
    case ChampionResult::Status::Unusable: return "unusable";
  }
  return "?";
}

namespace {

template <class T>
bool decode_event(const LogContents& log, const LogIndex& index, size_t event, T& out) {
  const auto& r = log.records[index.events[event].record];
  return safe_decode(r.data.data(), r.data.size(), out);
}

/// Poses a trajectory of `steps_run` steps has when every k-th step is logged,
/// plus step 0 and the last step (as Evolution::publish_trajectory writes them).
int64_t expected_poses(int steps_run, int k) {
  return 1 + steps_run / k + (steps_run % k != 0 ? 1 : 0);
}

void compare_poses(const LogContents& log, const LogIndex& index, const LoggedGenome& g, const Robot& robot,
                   const RunConfig& config, ValueComparer& cmp, ChampionResult& out) {
  std::vector<pose_t> poses;
  poses.reserve(g.pose_events.size());
  for (size_t e : g.pose_events) {
    pose_t p{};
    if (decode_event(log, index, e, p)) poses.push_back(std::move(p));
  }
  out.poses_logged = static_cast<int64_t>(poses.size());
  if (poses.empty()) return;
  std::stable_sort(poses.begin(), poses.end(), [](const pose_t& a, const pose_t& b) { return a.step < b.step; });
  Simulation sim(robot, config.eval.sim);
  for (const pose_t& p : poses) {
    while (sim.state().step < p.step && sim.step()) {
    }
    ++out.poses_compared;
    bool same;
    if (sim.state().step != p.step) {
      cmp.set_context("pose", p.step);
      cmp.note("step", std::to_string(p.step),
               "the re-simulation ends at step " + std::to_string(sim.state().step));
      same = false;
    } else {
      same = compare_pose(p, make_pose_message(g.run_id, g.generation, g.genome_id, sim.state(), 0), cmp);
    }
    if (!same) {
      ++out.poses_diverged;
      if (out.first_divergent_step < 0) out.first_divergent_step = p.step;
    }
  }
}

}  // namespace

ChampionResult check_champion(const LogContents& log, const LogIndex& index, const LoggedGenome& g,
                              const RunConfig& config, const ChampionCheckParams& params, RecomputeCache* cache) {
  ChampionResult out;
  out.run_id = g.run_id;
  out.generation = g.generation;
  out.genome_id = g.genome_id;
  out.champion = g.champion;
  ValueComparer cmp(params.tolerance, params.keep);
  auto finish = [&]() -> ChampionResult& {
    out.mismatches = cmp.mismatches();
    out.mismatch_count = cmp.mismatch_count();
    out.values_compared = cmp.values_compared();
    out.max_error = cmp.max_error();
    if (!cmp.ok())
      out.status = ChampionResult::Status::Diverged;
    else if (!out.problems.empty())
      out.status = ChampionResult::Status::Unusable;
    return out;
  };

  cppn_genome_t gm{};
  if (!decode_event(log, index, g.genome_event, gm)) {
    out.problems.push_back("its genome message does not decode");
    return finish();
  }
  Genome genome;
  try {
    genome = genome_from_message(gm, robot_layout());
  } catch (const std::exception& e) {
    out.problems.push_back(std::string("its genome cannot be used: ") + e.what());
    return finish();
  }
  try {
    validate_regime_links(genome, config.regime, config.neat);
  } catch (const std::invalid_argument& e) {
    cmp.set_context("genome");
    cmp.note("links", e.what(), "only links the run's regime allows");
  }
  try {
    // Growth and evaluation: pure functions of (genes, configuration).
    const std::string config_key = cache ? config_to_json(config).dump() : std::string();
    const RecomputeCache::Entry* done = cache ? cache->find(genome, config_key) : nullptr;
    RecomputeCache::Entry fresh;
    if (done) {
      out.same_genes_as = done->first_genome_id;
      out.same_genes_generation = done->first_generation;
    } else {
      fresh.genes = genome;
      fresh.config = config_key;
      fresh.first_genome_id = g.genome_id;
      fresh.first_generation = g.generation;
      fresh.robot = grow_genome(genome, config.eval);
      fresh.evaluation = evaluate(genome, config.eval);
      done = cache ? &cache->add(std::move(fresh)) : &fresh;
    }
    const Robot& robot = done->robot;
    const Evaluation& e = done->evaluation;
    out.spheres = static_cast<int>(robot.spheres.size());
    if (g.morphology_event >= 0) {
      morphology_t logged{};
      if (decode_event(log, index, static_cast<size_t>(g.morphology_event), logged)) {
        out.morphology_logged = true;
        out.morphology_ok =
            compare_morphology(logged, make_morphology_message(g.run_id, g.generation, g.genome_id, robot, 0), cmp);
      }
    }
    if (!out.morphology_logged) out.problems.push_back("its morphology is not in the log");
    compare_poses(log, index, g, robot, config, cmp, out);

    out.fitness_compared = true;
    out.logged_fitness = gm.fitness;
    out.recomputed_fitness = e.fitness;
    out.logged_outcome = gm.outcome;
    out.recomputed_outcome = static_cast<int>(e.outcome);
    cmp.set_context("fitness");
    cmp.real({"fitness"}, gm.fitness, e.fitness);
    cmp.real({"r_term"}, gm.r_term, e.r);
    cmp.real({"d_term"}, gm.d_term, e.d);
    cmp.integer({"outcome"}, gm.outcome, static_cast<int>(e.outcome));
    if (e.outcome != Outcome::NotSimulated && out.poses_logged > 0)
      out.poses_expected = expected_poses(e.sim.steps_run, config.pose_every);
  } catch (const std::exception& e) {
    out.problems.push_back(std::string("re-computing it failed: ") + e.what());
  }
  return finish();
}

}  // namespace robozoo
