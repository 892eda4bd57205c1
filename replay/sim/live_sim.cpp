#include "replay/sim/live_sim.hpp"

#include <cmath>
#include <stdexcept>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "evolve/sim/episode/trajectory_sampler.hpp"
#include "replay/log/logged_config.hpp"
#include "runlog/robots/regrow.hpp"

namespace robozoo::replay {

namespace {

std::string logged_ids(const LogIndex& index) {
  std::string s;
  size_t n = 0;
  for (const auto& g : index.genomes) {
    if (n == 12) {
      s += ", ...";
      break;
    }
    s += (n++ ? ", " : "") + std::to_string(g.genome_id) + " (gen " + std::to_string(g.generation) + ")";
  }
  return s.empty() ? "none" : s;
}

}  // namespace

LiveSimStats live_simulate(const LogContents& log, const LogIndex& index, const LiveSimOptions& o, PlayClock& clock,
                           const PublishFn& publish) {
  if (!(o.speed > 0.0) || !std::isfinite(o.speed)) throw std::invalid_argument("--speed must be a positive number");
  if (o.pose_every < 1) throw std::invalid_argument("--pose-every must be >= 1");
  const LoggedGenome* g = index.find_genome(o.genome_id, o.run_id);
  if (!g)
    throw std::invalid_argument("genome " + std::to_string(o.genome_id) +
                                (o.run_id.empty() ? "" : " of run " + o.run_id) +
                                " is not in the log; logged genomes: " + logged_ids(index));
  if (g->run_event < 0)
    throw std::invalid_argument("no ROBOZOO_RUN of run " + g->run_id + " before genome " +
                                std::to_string(g->genome_id) + ": its configuration is unknown");
  const LogRecord& run_record = log.records[index.events[static_cast<size_t>(g->run_event)].record];
  const LogRecord& genome_record = log.records[index.events[g->genome_event].record];
  run_t run{};
  cppn_genome_t gm{};
  std::string why;
  if (!safe_decode(run_record.data.data(), run_record.data.size(), run, &why))
    throw std::invalid_argument("its ROBOZOO_RUN does not decode: " + why);
  if (!safe_decode(genome_record.data.data(), genome_record.data.size(), gm, &why))
    throw std::invalid_argument("its ROBOZOO_GENOME does not decode: " + why);
  const std::string refusal = version_refusal(run);
  if (!refusal.empty() && !o.force) throw std::invalid_argument(refusal);
  const RunConfig config = config_from_run_message(run);
  const Robot robot = regrow_genome(gm, config).robot;

  LiveSimStats stats;
  stats.run_id = g->run_id;
  stats.generation = g->generation;
  stats.simulated_in_evolution = robot.simulate;
  auto send = [&](const char* channel, const std::vector<uint8_t>& bytes) {
    if (!publish(channel, bytes)) ++stats.publish_failures;
  };
  send(kChannelRun, run_record.data);
  send(kChannelGenome, genome_record.data);
  send(kChannelMorphology,
       encode_message(make_morphology_message(g->run_id, g->generation, g->genome_id, robot, now_us())));

  Simulation sim(robot, config.eval.sim);
  const double t0 = clock.now();
  const SimResult r = sample_trajectory(sim, o.pose_every, [&](const SimState& state) {
    clock.sleep_until(t0 + state.time / o.speed);
    send(kChannelPose, encode_message(make_pose_message(g->run_id, g->generation, g->genome_id, state, now_us())));
    ++stats.poses_sent;
  });
  stats.steps_run = r.steps_run;
  stats.d = r.d;
  return stats;
}

}  // namespace robozoo::replay
