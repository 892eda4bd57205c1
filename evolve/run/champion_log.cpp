#include "evolve/run/champion_log.hpp"

#include <cstdio>
#include <stdexcept>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/run/trajectory.hpp"

namespace robozoo {

namespace {

std::string g17(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

}  // namespace

ChampionLogInfo write_champion_log(const RunResults& results, const std::string& log_path) {
  const RunSummary& s = results.run;
  const ChampionRecord* best = best_of_run(s);
  if (!best || best->genome.nodes.empty())
    throw std::invalid_argument(s.path + ": no best-of-run champion genome in the result");
  const GenerationRecord* gen = nullptr;
  for (const auto& g : s.generations)
    if (g.generation == best->generation) gen = &g;
  if (!gen) throw std::invalid_argument(s.path + ": the champion's generation is not in the result");
  RunConfig config;
  try {
    config = config_from_record(nlohmann::json::parse(s.config_json));
  } catch (const std::exception& e) {
    throw std::invalid_argument(s.path + ": its configuration cannot be read by this robozoo: " + e.what());
  }
  config.generations = 1;
  // Its genes as every program reads a logged genome (runlog/robots/regrow.hpp's logged_genes).
  const Genome genome = genome_from_message(best->genome, robot_layout());
  const cppn_genome_t& logged = best->genome;

  // This build must give the committed evaluation, or the log would show another robot.
  const Evaluation e = evaluate(genome, config.eval);
  auto differ = [&](const char* what, const std::string& committed, const std::string& now) {
    throw std::runtime_error(s.path + ": genome " + std::to_string(genome.id) + " evaluates to " + what + " " + now +
                             " with this build, the result says " + committed +
                             " (another robozoo version grows or simulates differently)");
  };
  if (static_cast<int>(e.outcome) != logged.outcome)
    differ("outcome", std::to_string(logged.outcome), std::to_string(static_cast<int>(e.outcome)));
  if (e.fitness != logged.fitness) differ("fitness", g17(logged.fitness), g17(e.fitness));
  if (e.r != logged.r_term) differ("r", g17(logged.r_term), g17(e.r));
  if (e.d != logged.d_term) differ("d", g17(logged.d_term), g17(e.d));
  const Robot robot = grow_genome(genome, config.eval);
  std::vector<pose_t> poses;
  if (e.outcome != Outcome::NotSimulated)
    poses = simulate_pose_stream(robot, config.eval.sim, config.pose_every, s.run_id, 0, genome.id).poses;

  GenerationSummary g;
  g.generation = 0;
  g.evaluations = config.neat.population;
  g.best_fitness = logged.fitness;
  g.mean_fitness = gen->mean_fitness;
  g.stderr_fitness = gen->stderr_fitness;
  g.best_so_far_fitness = logged.fitness;
  g.champion_id = genome.id;
  g.num_species = gen->num_species;
  g.compatibility_threshold = gen->compatibility_threshold;
  for (size_t k = 0; k < gen->outcomes.size(); ++k) g.outcome_counts[k] = gen->outcomes[k];

  EventLogWriter log = EventLogWriter::create(log_path);
  int64_t t = now_us();
  log.write(kChannelRun, encode_message(make_run_message(s.run_id, config, t)), t);
  t = now_us();
  log.write(kChannelGeneration, encode_message(make_generation_message(s.run_id, g, t)), t);
  t = now_us();
  log.write(kChannelGenome,
            encode_message(make_genome_message(s.run_id, 0, genome, logged.species_id,
                                               GenomeScore{e.fitness, e.r, e.d, e.outcome}, t)),
            t);
  t = now_us();
  log.write(kChannelMorphology, encode_message(make_morphology_message(s.run_id, 0, genome.id, robot, t)), t);
  for (pose_t& p : poses) {
    p.utime = now_us();
    log.write(kChannelPose, encode_message(p), p.utime);
  }
  log.sync();
  ChampionLogInfo info;
  info.generation = best->generation;
  info.genome_id = genome.id;
  info.fitness = logged.fitness;
  info.poses = poses.size();
  return info;
}

}  // namespace robozoo
