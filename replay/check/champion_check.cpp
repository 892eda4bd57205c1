#include "replay/check/champion_check.hpp"

#include <algorithm>
#include <map>

#include "evolve/fitness/evaluate.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/run/trajectory.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "replay/compare/morphology_compare.hpp"
#include "replay/compare/pose_compare.hpp"
#include "runlog/robots/regrow.hpp"

namespace robozoo::replay {

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

/// The logged poses of `g` against its re-simulated trajectory: with a rule,
/// the i-th logged pose must be the trajectory's i-th (each step once, in
/// order; all of them unless the log may end early); every logged pose's values
/// are compared with the trajectory's pose at its step.
void compare_poses(const LogContents& log, const LogIndex& index, const LoggedGenome& g, const Robot& robot,
                   const RunConfig& config, TrajectoryRule rule, ValueComparer& cmp, ChampionResult& out) {
  struct Logged {
    pose_t pose;
    int64_t eventnum;
  };
  std::vector<Logged> poses;
  poses.reserve(g.pose_events.size());
  for (size_t e : g.pose_events) {
    Logged p{pose_t{}, log.records[index.events[e].record].eventnum};
    if (decode_event(log, index, e, p.pose)) poses.push_back(std::move(p));
  }
  out.poses_logged = static_cast<int64_t>(poses.size());
  if (poses.empty() && rule != TrajectoryRule::Complete) return;
  const PoseStream t =
      simulate_pose_stream(robot, config.eval.sim, config.pose_every, g.run_id, g.generation, g.genome_id);
  const auto& want = t.poses;
  if (rule == TrajectoryRule::Lossy) {
    out.poses_expected = static_cast<int64_t>(want.size());
    cmp.set_context("trajectory");
    size_t j = 0, matched = 0;
    bool ordered = true;
    for (size_t i = 0; i < poses.size() && ordered; ++i) {
      while (j < want.size() && want[j].step < poses[i].pose.step) ++j;
      if (j == want.size() || want[j].step != poses[i].pose.step) {
        cmp.note("pose " + std::to_string(i) + " (received) step", std::to_string(poses[i].pose.step),
                 j == want.size() ? std::string("none after the trajectory's last step")
                                  : "a later step than the previous pose's, of the trajectory (next: " +
                                        std::to_string(want[j].step) + ")");
        ordered = false;
        break;
      }
      ++matched;
      ++j;
    }
    if (ordered) out.poses_missing = static_cast<int64_t>(want.size() - matched);
  } else if (rule != TrajectoryRule::None) {
    out.poses_expected = static_cast<int64_t>(want.size());
    cmp.set_context("trajectory");
    for (size_t i = 0; i < std::max(poses.size(), want.size()); ++i) {
      if (rule == TrajectoryRule::Damaged &&
          (i >= poses.size() || i >= want.size() || poses[i].pose.step != want[i].step)) {
        out.problems.push_back("its trajectory cannot be proved complete: events near it do not decode (" +
                               std::to_string(poses.size()) + " of " + std::to_string(want.size()) + " poses read)");
        break;
      }
      if (i >= poses.size()) {
        if (rule == TrajectoryRule::Complete)
          cmp.note("poses", std::to_string(poses.size()) + " (none from step " + std::to_string(want[i].step) + ")",
                   std::to_string(want.size()) + " (steps 0 to " + std::to_string(want.back().step) + " every " +
                       std::to_string(config.pose_every) + ", and the last)");
        break;
      }
      if (i >= want.size()) {
        cmp.note("pose " + std::to_string(i) + " (event " + std::to_string(poses[i].eventnum) + ") step",
                 std::to_string(poses[i].pose.step),
                 "none: the trajectory has " + std::to_string(want.size()) + " poses");
        break;
      }
      if (poses[i].pose.step != want[i].step) {
        cmp.note("pose " + std::to_string(i) + " (event " + std::to_string(poses[i].eventnum) + ") step",
                 std::to_string(poses[i].pose.step), std::to_string(want[i].step));
        break;  // the first difference of the sequence; the values are compared below
      }
    }
  }
  std::map<int32_t, size_t> at_step;
  for (size_t i = 0; i < want.size(); ++i) at_step.emplace(want[i].step, i);
  for (const Logged& p : poses) {
    ++out.poses_compared;
    bool same;
    const auto it = at_step.find(p.pose.step);
    if (it == at_step.end()) {
      cmp.set_context("pose", p.pose.step);
      cmp.note("step (event " + std::to_string(p.eventnum) + ")", std::to_string(p.pose.step),
               "a step of the trajectory (0 to " + std::to_string(t.result.steps_run) + ", every " +
                   std::to_string(config.pose_every) + ", and the last)");
      same = false;
    } else {
      same = compare_pose(p.pose, want[it->second], cmp);
    }
    if (!same) {
      ++out.poses_diverged;
      if (out.first_divergent_step < 0) out.first_divergent_step = p.pose.step;
    }
  }
}

}  // namespace

ChampionResult check_champion(const LogContents& log, const LogIndex& index, const LoggedGenome& g,
                              const RunConfig& config, const ChampionCheckParams& params, RecomputeCache* cache,
                              TrajectoryRule trajectory) {
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
    genome = logged_genes(gm);
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
    compare_poses(log, index, g, robot, config, trajectory, cmp, out);

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
  } catch (const std::exception& e) {
    out.problems.push_back(std::string("re-computing it failed: ") + e.what());
  }
  return finish();
}

}  // namespace robozoo::replay
