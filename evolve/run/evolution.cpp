#include "evolve/run/evolution.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "evolve/core/wall_time.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/run/trajectory.hpp"
#include "evolve/sim/episode/simulation.hpp"

namespace robozoo {

namespace {

std::string human_time(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char buf[32];
  const long t = std::lround(s);
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  return buf;
}

/// A generation's results in figures: the fields of its summary that come from the results alone,
/// its champion and how many robots were simulated.
struct ResultFigures {
  GenerationSummary summary;
  size_t champion = 0;  ///< index of the best genome (the first of equals)
  int simulated = 0;    ///< genomes whose robots went to the simulator (count)
};

/// Throws std::logic_error when the results are not the genomes' in order.
ResultFigures summarize_results(const std::vector<EvalSummary>& results, const std::vector<Genome>& genomes,
                                int32_t gen) {
  ResultFigures f;
  GenerationSummary& s = f.summary;
  s.generation = gen;
  size_t champ = 0;
  double sum = 0.0;
  for (size_t i = 0; i < results.size(); ++i) {
    if (results[i].genome_id != genomes[i].id) throw std::logic_error("evaluator returned results out of order");
    sum += results[i].fitness;
    if (results[i].fitness > results[champ].fitness) champ = i;
    ++s.outcome_counts[static_cast<int>(results[i].outcome)];
    f.simulated += results[i].outcome != Outcome::NotSimulated;
  }
  const double n = static_cast<double>(results.size());
  s.mean_fitness = sum / n;
  double ss = 0.0;
  for (const auto& r : results) ss += (r.fitness - s.mean_fitness) * (r.fitness - s.mean_fitness);
  s.stderr_fitness = results.size() > 1 ? std::sqrt(ss / (n - 1.0)) / std::sqrt(n) : 0.0;
  s.best_fitness = results[champ].fitness;
  s.champion_id = genomes[champ].id;
  f.champion = champ;
  return f;
}

bool file_exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

std::string default_run_id(const RunConfig& c) { return regime_name(c.regime) + "-s" + std::to_string(c.seed); }

std::string format_progress(const ProgressReport& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "gen %4d/%d  best %8.3f  mean %7.3f  species %2d  simulated %5.1f%%  %6.1f eval/s  "
                "elapsed %s  remaining %s",
                r.summary.generation + 1, r.generations_total, r.summary.best_fitness, r.summary.mean_fitness,
                r.summary.num_species, 100.0 * r.simulated_share, r.evals_per_second,
                human_time(r.elapsed_seconds).c_str(), human_time(r.remaining_seconds).c_str());
  std::string line = buf;
  if (r.publish_failures >= 0) line += "  bus failures " + std::to_string(r.publish_failures);
  return line;
}

Evolution::Evolution(const RunConfig& config, const EvolveOptions& options, Evaluator& evaluator)
    : config_(config), options_(options), evaluator_(evaluator), pacer_(options.bus_pacing) {
  if (options_.log_path.empty()) throw std::runtime_error("no log path given");
  if (options_.overlap_trajectory && evaluator_.simulates_in_process())
    throw std::invalid_argument(
        "overlap_trajectory needs an evaluator whose simulations run in other processes: ODE's random "
        "constraint order is process-wide, so two simulations at once in one process differ");
  checkpoint_path_ =
      options_.checkpoint_path.empty() ? checkpoint_path_for(options_.log_path) : options_.checkpoint_path;
  const GenomeLayout layout = robot_layout();
  if (options_.resume && (options_.checkpoint || file_exists(checkpoint_path_))) {
    Checkpoint c = options_.checkpoint ? std::move(*options_.checkpoint) : read_checkpoint(checkpoint_path_);
    options_.checkpoint.reset();
    RunConfig saved;
    try {
      saved = config_from_record(c.config);
    } catch (const ConfigError& e) {
      throw std::runtime_error(checkpoint_path_ + ": its configuration is invalid: " + e.what());
    }
    if (c.software_version != software_version() && !options_.force_version)
      throw std::runtime_error(checkpoint_path_ + ": written by robozoo " + c.software_version + ", this is robozoo " +
                               software_version() +
                               "; resume with that version (another version may grow, simulate or breed "
                               "differently), or --force to continue anyway");
    if (options_.generations > 0 && options_.generations < saved.generations)
      throw std::invalid_argument(checkpoint_path_ + ": the run was started for " + std::to_string(saved.generations) +
                                  " generations; it can be extended, not cut to " +
                                  std::to_string(options_.generations));
    const bool extend_finished = c.finished && options_.generations > saved.generations;
    if (options_.generations > 0) saved.generations = options_.generations;
    config_ = saved;
    run_id_ = c.run_id;
    rng_.set_state(c.rng_state);
    population_ = std::make_unique<Population>(config_.neat, config_.regime, layout, std::move(c.population));
    evaluations_ = c.evaluations;
    best_so_far_ = c.best_so_far;
    last_champion_hash_ = c.last_champion_hash;
    log_continues_ = c.log_continues;
    elapsed_before_ = c.elapsed_seconds;
    finished_ = c.finished && !extend_finished;
    resumed_ = true;
    if (extend_finished) {
      // A finished run's checkpoint holds its last generation, evaluated but not
      // bred (and the generator before breeding). Evaluation is deterministic, so
      // evaluating it again gives the fitnesses the uninterrupted run bred with.
      const std::vector<Genome> genomes = population_->genomes();
      const std::vector<EvalSummary> results = evaluator_.evaluate(genomes);
      if (results.size() != genomes.size())
        throw std::logic_error("evaluator returned " + std::to_string(results.size()) + " results for " +
                               std::to_string(genomes.size()) + " genomes");
      std::vector<double> fitness(results.size());
      for (size_t i = 0; i < results.size(); ++i) {
        if (results[i].genome_id != genomes[i].id) throw std::logic_error("evaluator returned results out of order");
        fitness[i] = results[i].fitness;
      }
      population_->advance(fitness, rng_);
    }
    checkpoint_writer_ =
        std::make_unique<CheckpointWriter>(checkpoint_path_, options_.background_checkpoint, generations_done());
    if (!finished_) {
      // A run continued on a machine without its log starts a new one (its
      // checkpoint, unpacked from a portable one, says the log holds nothing yet).
      if (log_continues_ && c.log_bytes == 0 && !file_exists(options_.log_path))
        log_.emplace(EventLogWriter::create(options_.log_path));
      else
        log_.emplace(EventLogWriter::resume(options_.log_path, c.log_bytes, c.log_events));
      // Stamps run ahead of the clock while messages wait for their turn: the
      // log's go on from its last one, never back.
      const int64_t last = timestamp_of_event_ending_at(options_.log_path, c.log_bytes);
      if (last >= 0) pacer_.not_before(last + 1);
    }
  } else {
    validate_config(config_);
    run_id_ = options_.run_id.empty() ? default_run_id(config_) : options_.run_id;
    rng_ = Rng(static_cast<uint64_t>(config_.seed));
    population_ = std::make_unique<Population>(config_.neat, config_.regime, layout, rng_);
    log_.emplace(EventLogWriter::create(options_.log_path));
    checkpoint_writer_ = std::make_unique<CheckpointWriter>(checkpoint_path_, options_.background_checkpoint);
    save_checkpoint();
  }
  if (!options_.lcm_url.empty() && !finished_) {
    bus_ = std::make_unique<Bus>(options_.lcm_url);
  }
  start_evaluations_ = evaluations_;
  start_generation_ = generations_done();
}

Evolution::~Evolution() = default;

int Evolution::generation() const { return population_->generation(); }

int64_t Evolution::messages_published() const { return bus_ ? bus_->published() - bus_statuses_ : -1; }

int64_t Evolution::publish_failures() const { return bus_ ? bus_->failures() : -1; }

int Evolution::generations_done() const { return finished_ ? config_.generations : population_->generation(); }

void Evolution::emit(const char* channel, const std::vector<uint8_t>& bytes, int64_t utime) {
  log_->write(channel, bytes, utime);
  if (bus_) bus_->publish(channel, bytes, utime);
}

template <class M>
void Evolution::emit_message(const char* channel, M m) {
  m.utime = pacer_.schedule(now_us(), static_cast<size_t>(m.getEncodedSize()));
  emit(channel, encode_message(m), m.utime);
}

void Evolution::save_checkpoint() { checkpoint_writer_->write(make_checkpoint(), generations_done()); }

Checkpoint Evolution::make_checkpoint() {
  log_->sync();
  Checkpoint c;
  c.run_id = run_id_;
  c.software_version = software_version();
  c.config = config_to_json(config_);
  c.population = population_->state();
  c.rng_state = rng_.state();
  c.evaluations = evaluations_;
  c.best_so_far = best_so_far_;
  c.last_champion_hash = last_champion_hash_;
  c.log_bytes = log_->bytes();
  c.log_events = log_->events();
  c.elapsed_seconds = elapsed_before_ + elapsed_;
  c.finished = finished_;
  c.log_continues = log_continues_;
  return c;
}

void Evolution::emit_poses(std::vector<pose_t>& poses) {
  for (pose_t& p : poses) {
    p.utime = pacer_.schedule(now_us(), static_cast<size_t>(p.getEncodedSize()));
    emit(kChannelPose, encode_message(p), p.utime);
  }
}

double Evolution::finish_trajectory() {
  if (!pending_poses_.valid()) return 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<pose_t> poses = pending_poses_.get();  // rethrows the re-simulation's failure
  emit_poses(poses);
  // The generation's checkpoint, now that its poses are in the log; written
  // at the end of this step unless this generation's own replaces it.
  held_checkpoint_ = make_checkpoint();
  held_generations_ = generations_done();
  return seconds_since(t0);
}

void Evolution::write_held_checkpoint() {
  if (!held_checkpoint_) return;
  Checkpoint c = std::move(*held_checkpoint_);
  held_checkpoint_.reset();
  checkpoint_writer_->write(std::move(c), held_generations_);
}

void Evolution::wait_for_checkpoint() {
  write_held_checkpoint();
  checkpoint_writer_->wait();
}

void Evolution::settle() {
  finish_trajectory();
  wait_for_checkpoint();
}

void Evolution::run(const std::function<void(const ProgressReport&)>& on_generation) {
  while (step(on_generation)) {
  }
}

std::vector<pose_t> Evolution::champion_trajectory(const Genome& champion, const Robot& robot, int32_t generation,
                                                   const EvalSummary& expected) const {
  PoseStream t = simulate_pose_stream(robot, config_.eval.sim, config_.pose_every, run_id_, generation, champion.id);
  const SimResult& r = t.result;
  // The trajectory must be exactly the evaluation the worker made.
  if (r.d != expected.d || static_cast<int>(r.outcome) != static_cast<int>(expected.outcome) ||
      r.steps_run != expected.steps_run)
    throw std::logic_error("determinism violated: re-simulating genome " + std::to_string(champion.id) +
                           " gave d = " + std::to_string(r.d) + " after " + std::to_string(r.steps_run) +
                           " steps, its evaluation gave d = " + std::to_string(expected.d) + " after " +
                           std::to_string(expected.steps_run));
  return std::move(t.poses);
}

std::vector<EvalSummary> Evolution::evaluate_generation(const std::vector<Genome>& genomes, StepTimings& timing) {
  auto tm = std::chrono::steady_clock::now();
  const auto emit_run = [&] {
    tm = std::chrono::steady_clock::now();
    const run_t run = make_run_message(run_id_, config_, 0);
    emit_message(kChannelRun, log_continues_ ? mark_continued(run, *log_continues_) : run);
    timing.messages += seconds_since(tm);
  };
  // With the previous generation's champion still simulating, its poses come
  // first in the log: this generation's run message follows them.
  const bool overlapped = pending_poses_.valid();
  if (!overlapped) emit_run();

  const auto te = std::chrono::steady_clock::now();
  std::vector<EvalSummary> results = evaluator_.evaluate(genomes);
  timing.evaluate = seconds_since(te);
  if (overlapped) {
    timing.trajectory += finish_trajectory();
    emit_run();
  }
  if (results.size() != genomes.size())
    throw std::logic_error("evaluator returned " + std::to_string(results.size()) + " results for " +
                           std::to_string(genomes.size()) + " genomes");
  return results;
}

Evolution::Published Evolution::grow_published(const std::vector<Genome>& genomes, size_t champ) const {
  Published p;
  p.index.push_back(champ);
  if (config_.publish_all)
    for (size_t i = 0; i < genomes.size(); ++i)
      if (i != champ) p.index.push_back(i);
  for (size_t i : p.index) {
    p.species_ids.push_back(population_->species_of(i));
    p.robots.push_back(grow_genome(genomes[i], config_.eval));
  }
  return p;
}

std::vector<pose_t> Evolution::new_champion_poses(const Genome& champion, const Robot& robot, int32_t gen,
                                                  const EvalSummary& result, bool last) {
  // The champion "changes" when its logged genes do (trajectory_key).
  const uint64_t champion_hash = trajectory_key(champion);
  std::vector<pose_t> poses;
  if (champion_hash != last_champion_hash_ && result.outcome != Outcome::NotSimulated) {
    if (options_.overlap_trajectory && !last) {
      // On a thread of its own, while the next generation is evaluated.
      pending_poses_ = std::async(std::launch::async, [this, c = champion, r = robot, gen, e = result] {
        return champion_trajectory(c, r, gen, e);
      });
    } else {
      poses = champion_trajectory(champion, robot, gen, result);
    }
  }
  last_champion_hash_ = champion_hash;
  return poses;
}

void Evolution::emit_generation(const GenerationSummary& s, const std::vector<Genome>& genomes,
                                const std::vector<EvalSummary>& results, const Published& published) {
  emit_message(kChannelGeneration, make_generation_message(run_id_, s, 0));
  for (size_t k = 0; k < published.index.size(); ++k) {
    const size_t i = published.index[k];
    const EvalSummary& r = results[i];
    emit_message(kChannelGenome, make_genome_message(run_id_, s.generation, genomes[i], published.species_ids[k],
                                                     GenomeScore{r.fitness, r.r, r.d, r.outcome}, 0));
    emit_message(kChannelMorphology,
                 make_morphology_message(run_id_, s.generation, genomes[i].id, published.robots[k], 0));
  }
}

void Evolution::publish_bus_status(int32_t gen) {
  if (!bus_) return;
  // How publishing went, on the bus only (the log is the record).
  bus_status_t b{};
  b.run_id = run_id_;
  b.generation = gen;
  b.messages_published = messages_published();
  b.bytes_published = bus_->bytes() - bus_status_bytes_;
  b.publish_failures = bus_->failures();
  b.utime = pacer_.schedule(now_us(), static_cast<size_t>(b.getEncodedSize()));  // it takes its turn too
  const std::vector<uint8_t> bytes = encode_message(b);
  if (bus_->publish(kChannelBus, bytes, b.utime)) {
    ++bus_statuses_;
    bus_status_bytes_ += static_cast<int64_t>(bytes.size());
  }
}

void Evolution::checkpoint_step(StepTimings& timing) {
  auto tm = std::chrono::steady_clock::now();
  // A generation whose poses are still to come is checkpointed once they are
  // in the log (finish_trajectory, in the next step or wait_for_checkpoint);
  // meanwhile the previous generation's is the last one whole.
  if (pending_poses_.valid()) {
    write_held_checkpoint();
  } else {
    held_checkpoint_.reset();
    save_checkpoint();
  }
  timing.checkpoint = seconds_since(tm);
  if (finished_) {
    tm = std::chrono::steady_clock::now();
    checkpoint_writer_->wait();  // a finished run's last checkpoint is on disk
    timing.final_checkpoint = seconds_since(tm);
  }
}

bool Evolution::step(const std::function<void(const ProgressReport&)>& on_generation) {
  if (finished_) return false;
  // Everything of the generation is computed first (evaluation, the published
  // robots, a new champion's trajectory, breeding), so that generation_t's
  // generation_seconds covers all of it; then its messages are written in
  // their usual order (generation, genome, morphology, poses) and the
  // checkpoint saved.
  const auto t0 = std::chrono::steady_clock::now();
  const int32_t gen = population_->generation();
  const std::vector<Genome> genomes = population_->genomes();  // advance() replaces them

  StepTimings timing;
  const std::vector<EvalSummary> results = evaluate_generation(genomes, timing);
  const double eval_seconds = timing.evaluate;

  ResultFigures figures = summarize_results(results, genomes, gen);
  GenerationSummary& s = figures.summary;
  const size_t champ = figures.champion;
  const double n = static_cast<double>(results.size());
  best_so_far_ = gen == 0 ? s.best_fitness : std::max(best_so_far_, s.best_fitness);
  s.best_so_far_fitness = best_so_far_;
  evaluations_ += static_cast<int64_t>(results.size());
  s.evaluations = evaluations_;
  s.num_species = static_cast<int32_t>(population_->species().size());
  // The threshold this generation was speciated with (advance() moves it on).
  s.compatibility_threshold = population_->speciation_threshold();
  s.eval_seconds = eval_seconds;

  // The published genomes with their species and robots.
  auto tm = std::chrono::steady_clock::now();
  const Published published = grow_published(genomes, champ);
  timing.messages += seconds_since(tm);

  tm = std::chrono::steady_clock::now();
  const bool last = gen + 1 >= config_.generations;
  // published.robots[0] is the champion's.
  std::vector<pose_t> poses = new_champion_poses(genomes[champ], published.robots.front(), gen, results[champ], last);
  timing.trajectory += seconds_since(tm);

  std::vector<double> fitness(results.size());
  for (size_t i = 0; i < results.size(); ++i) fitness[i] = results[i].fitness;
  tm = std::chrono::steady_clock::now();
  if (last) {
    finished_ = true;
  } else {
    population_->advance(fitness, rng_);
  }
  timing.breeding = seconds_since(tm);

  tm = std::chrono::steady_clock::now();
  s.generation_seconds = seconds_since(t0);
  emit_generation(s, genomes, results, published);
  timing.messages += seconds_since(tm);
  tm = std::chrono::steady_clock::now();
  emit_poses(poses);
  timing.trajectory += seconds_since(tm);
  publish_bus_status(gen);

  ProgressReport report;
  report.summary = s;
  elapsed_ += seconds_since(t0);
  checkpoint_step(timing);
  timing.total = seconds_since(t0);
  report.timings = timing;

  report.generations_total = config_.generations;
  report.elapsed_seconds = elapsed_before_ + elapsed_;
  report.evals_per_second = eval_seconds > 0 ? n / eval_seconds : 0.0;
  const int done = gen + 1;
  report.remaining_seconds = report.elapsed_seconds / done * (config_.generations - done);
  report.simulated_share = figures.simulated / n;
  report.messages_published = messages_published();
  report.publish_failures = publish_failures();
  if (on_generation) on_generation(report);
  return true;
}

}  // namespace robozoo
