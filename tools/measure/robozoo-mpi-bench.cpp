// robozoo-mpi-bench: what an MPI run costs, measured on a real run, and what it
// would cost on a cluster. Under `mpirun -np N robozoo-mpi-bench ...` it
// runs an evolution exactly as `robozoo-evolve --mpi` does (rank 0: NEAT, log,
// checkpoints; ranks 1..N-1: evaluations over the MPI transport) and measures:
//   - per rank: jobs, time in the work function, evaluations per second;
//   - every job's evaluation time and message sizes, by outcome;
//   - rank 0's cost per generation: waiting for results, and its serial part
//     (messages and publishing, champion trajectory, breeding, checkpoint), and its
//     CPU time per job while the workers evaluate;
//   - messages and bytes exchanged per generation.
// From those it projects, with evolve/parallel/scaling_model.hpp, the time per
// generation, per run and for the paper's experiment on other rank counts, and
// names what bounds each: the evaluations, rank 0's messaging, or its serial part.
// With --resume LOG it measures the next generations of a logged, unfinished run
// (on a copy) instead of a new one: late-generation robots as evolution made them.
#include <time.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "evolve/config/run_config.hpp"
#include "evolve/core/cpu_time.hpp"
#include "evolve/core/rng.hpp"
#include "evolve/parallel/mpi/mpi_session.hpp"
#include "evolve/parallel/mpi/mpi_transport.hpp"
#include "evolve/parallel/mpi/mpi_worker.hpp"
#include "evolve/parallel/scaling_model.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/run/evolution.hpp"
#include "evolve/run/pool_evaluator.hpp"
#include "evolve/core/version.hpp"
#include "evolve/io/bus.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::string regime = "feedforward";
  int64_t seed = 7;
  int population = 150;
  int generations = 6;
  int steps = 2500;
  std::string config_file;
  std::string log_path;  // empty: a temporary folder, removed afterwards
  std::string lcm_url;
  std::vector<int> ranks = {8, 32, 128};
  double latency_us = 50.0;
  double bandwidth_gbit = 1.0;
  double core_speed = 1.0;
  int paper_runs = 60;
  int paper_generations = 500;
  int synthetic_generations = 50;
  int trial_ranks = 8;
  bool foreground_checkpoint = false;
  bool serial_trajectory = false;
  std::string json_path;
  std::string resume_log;  // continue this logged run (a copy) instead of starting one
  bool force_version = false;
};

struct JobRecord {
  double seconds = 0.0;  // as rank 0 saw it: hand-out to result
  double bytes_out = 0.0, bytes_in = 0.0;
  bool simulated = false;
  int steps = 0;
};

struct GenerationRecord {
  std::vector<JobRecord> jobs;  // in genome order
  double evaluate_wall = 0.0;
  double root_cpu = 0.0;  // rank 0's main-thread CPU time while the workers evaluated
  uint64_t messages = 0;  // sent + received
  uint64_t bytes = 0;     // sent + received
  StepTimings timings;    // from the progress report
};

/// Forwards to the pool evaluator and records what each job cost.
class RecordingEvaluator : public Evaluator {
 public:
  RecordingEvaluator(PoolEvaluator& inner, MpiTransport& transport) : inner_(inner), transport_(transport) {}
  std::vector<EvalSummary> evaluate(const std::vector<Genome>& genomes) override {
    const MpiTransportStats& s = transport_.stats();
    const size_t k0 = s.timings.size();
    const uint64_t m0 = s.messages_sent + s.messages_received, b0 = s.bytes_sent + s.bytes_received;
    // CPU time of rank 0's main thread, which hands out and collects every job
    // (not the checkpoint thread, nor MPI's helper threads).
    const double cpu0 = thread_cpu_seconds();
    const auto t0 = Clock::now();
    std::vector<EvalSummary> results = inner_.evaluate(genomes);
    GenerationRecord g;
    g.evaluate_wall = std::chrono::duration<double>(Clock::now() - t0).count();
    g.root_cpu = thread_cpu_seconds() - cpu0;
    g.messages = s.messages_sent + s.messages_received - m0;
    g.bytes = s.bytes_sent + s.bytes_received - b0;
    g.jobs.resize(genomes.size());
    for (size_t k = k0; k < s.timings.size(); ++k) {
      const MpiJobTiming& t = s.timings[k];
      JobRecord& j = g.jobs.at(t.index);
      j.seconds = t.seconds;
      j.bytes_out = static_cast<double>(t.bytes_out);
      j.bytes_in = static_cast<double>(t.bytes_in);
    }
    for (size_t i = 0; i < results.size(); ++i) {
      g.jobs[i].simulated = results[i].outcome != Outcome::NotSimulated;
      g.jobs[i].steps = results[i].steps_run;
    }
    records.push_back(std::move(g));
    return results;
  }
  int parallelism() const override { return inner_.parallelism(); }
  bool simulates_in_process() const override { return inner_.simulates_in_process(); }
  std::vector<GenerationRecord> records;

 private:
  PoolEvaluator& inner_;
  MpiTransport& transport_;
};

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(std::min<double>(static_cast<double>(v.size() - 1), q * static_cast<double>(v.size())))];
}

std::string human(double s) {
  char buf[64];
  if (s < 1.0)
    std::snprintf(buf, sizeof buf, "%.0f ms", 1e3 * s);
  else if (s < 120.0)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 7200.0)
    std::snprintf(buf, sizeof buf, "%.1f min", s / 60.0);
  else if (s < 3 * 86400.0)
    std::snprintf(buf, sizeof buf, "%.1f h", s / 3600.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f days", s / 86400.0);
  return buf;
}

struct Projection {
  int ranks = 0;
  double seconds = 0.0, workers = 0.0, root_link = 0.0, serial = 0.0;
  std::map<std::string, int> bounds;
};

Projection project(const std::vector<GenerationCost>& gens, int ranks, const ClusterParams& k) {
  Projection p;
  p.ranks = ranks;
  for (const auto& g : gens) {
    const GenerationProjection gp = project_generation(g, ranks - 1, k);
    p.seconds += gp.seconds;
    p.workers += gp.workers;
    p.root_link += gp.root_link;
    p.serial += gp.serial;
    ++p.bounds[gp.bound];
  }
  const double n = static_cast<double>(gens.size());
  p.seconds /= n;
  p.workers /= n;
  p.root_link /= n;
  p.serial /= n;
  return p;
}

std::string main_bound(const Projection& p) {
  std::string best;
  int most = -1;
  for (const auto& [b, count] : p.bounds)
    if (count > most) {
      best = b;
      most = count;
    }
  return best;
}

/// Copies a logged run (LOG and LOG.checkpoint) to `dest` so that measuring its
/// next generations leaves the original untouched.
void copy_run(const std::string& log, const std::string& dest) {
  namespace fs = std::filesystem;
  const std::pair<std::string, std::string> files[] = {{log, dest},
                                                       {checkpoint_path_for(log), checkpoint_path_for(dest)}};
  for (const auto& [from, to] : files) {
    if (!fs::is_regular_file(from)) throw std::runtime_error("--resume: no file " + from);
    if (fs::exists(to))
      throw std::runtime_error("--log " + dest + ": " + to +
                               " exists already; --resume measures on a copy of the run and will not overwrite a file");
  }
  for (const auto& [from, to] : files) fs::copy_file(from, to);
}

/// The run measured: the configuration file, with the flags given (or every flag without a file).
RunConfig bench_config(const CLI::App& app, const Options& o) {
  RunConfig config;
  if (!o.config_file.empty()) config = load_config_file(o.config_file, config);
  if (app.count("--regime") || o.config_file.empty()) config.regime = regime_from_name(o.regime);
  if (app.count("--seed") || o.config_file.empty()) config.seed = o.seed;
  if (app.count("--population") || o.config_file.empty()) config.neat.population = o.population;
  if (app.count("--generations") || o.config_file.empty()) config.generations = o.generations;
  if (app.count("--steps") || o.config_file.empty()) config.eval.sim.steps = o.steps;
  validate_config(config);
  return config;
}

/// What a measured run left: its configuration, options, per-generation records and the ranks' figures.
struct MeasuredRun {
  RunConfig config;
  EvolveOptions opts;
  std::vector<GenerationRecord> records;  // with the progress reports' timings
  int resumed_at = -1;                    // the generation a --resume run continued at; -1: a new run
  MpiTransportStats transport_stats;
  std::vector<MpiWorkerStats> workers;  // by rank
};

/// Runs the evolution as robozoo-evolve --mpi does (or continues --resume's copy) on the worker
/// ranks, recording every job; then gathers the worker ranks' figures.
MeasuredRun measure_run(const MpiSession& session, const CLI::App& app, const Options& o) {
  MeasuredRun m;
  RunConfig& config = m.config;
  config = bench_config(app, o);
  std::string folder;
  EvolveOptions& opts = m.opts;
  if (o.log_path.empty()) {
    char tmpl[] = "/tmp/robozoo-mpi-bench-XXXXXX";
    if (!::mkdtemp(tmpl)) throw std::runtime_error("cannot create a temporary folder");
    folder = tmpl;
    opts.log_path = folder + "/bench.lcmlog";
  } else {
    opts.log_path = o.log_path;
  }
  opts.lcm_url = o.lcm_url;
  opts.background_checkpoint = !o.foreground_checkpoint;  // as robozoo-evolve --mpi, unless asked
  opts.overlap_trajectory = !o.serial_trajectory;         // the same
  if (!o.resume_log.empty()) {
    copy_run(o.resume_log, opts.log_path);
    opts.resume = true;
    opts.force_version = o.force_version;
  }

  MpiTransportParams tp;
  tp.record_jobs = true;
  auto owned = std::make_unique<MpiTransport>(tp);
  MpiTransport& transport = *owned;
  std::vector<ProgressReport> reports;
  {
    PoolEvaluator pool(std::move(owned), 600.0);
    RecordingEvaluator evaluator(pool, transport);
    Evolution evo(config, opts, evaluator);
    if (!o.resume_log.empty()) {
      if (!evo.resumed() || evo.finished())
        throw std::runtime_error("--resume: " + o.resume_log + " is a finished run; nothing left to measure");
      config = evo.config();
    }
    transport.start(config_to_json(evo.config()).dump());
    std::cerr << "robozoo-mpi-bench: " << session.size() << " ranks (" << transport.size() << " evaluating) on "
              << session.host() << ": " << regime_name(config.regime) << ", population " << config.neat.population
              << ", " << config.generations << " generations of " << config.eval.sim.steps << " steps"
              << (o.resume_log.empty()
                      ? std::string()
                      : ", continuing " + o.resume_log + " at generation " + std::to_string(evo.start_generation()) +
                            " for " + std::to_string(o.generations) + " generations")
              << "\n";
    const auto report = [&](const ProgressReport& r) {
      reports.push_back(r);
      std::cerr << format_progress(r) << std::endl;
    };
    if (o.resume_log.empty()) {
      evo.run(report);
    } else {
      for (int g = 0; g < o.generations && evo.step(report); ++g) {
      }
      evo.settle();
    }
    m.resumed_at = evo.resumed() ? evo.start_generation() : -1;
    m.records = evaluator.records;
    m.transport_stats = transport.stats();
  }  // Shutdown to the worker ranks
  m.workers = gather_worker_stats(MpiWorkerStats{});
  if (!folder.empty()) std::filesystem::remove_all(folder);
  for (size_t g = 0; g < m.records.size() && g < reports.size(); ++g) m.records[g].timings = reports[g].timings;
  return m;
}

/// Every job's time and message sizes as rank 0 saw them.
struct JobFigures {
  std::vector<double> all, sim, nosim, msg_out, msg_in;  // (s), (s), (s), (bytes), (bytes)
  double simulated_share = 0.0;
};

/// Per-rank evaluation throughput.
void report_ranks(const MpiSession& session, const MeasuredRun& m, nlohmann::json& j) {
  const std::vector<MpiWorkerStats>& workers = m.workers;
  const MpiTransportStats& transport_stats = m.transport_stats;
  std::printf("Per-rank evaluation throughput (time in the work function, on the worker rank)\n");
  std::printf("  rank  jobs  busy s  evals/s   rank 0 saw: s  overhead/job\n");
  nlohmann::json per_rank = nlohmann::json::array();
  for (int r = 1; r < session.size(); ++r) {
    const MpiWorkerStats& w = workers[static_cast<size_t>(r)];
    const double seen = transport_stats.busy_seconds[static_cast<size_t>(r - 1)];
    const double rate = w.busy_seconds > 0 ? static_cast<double>(w.jobs) / w.busy_seconds : 0.0;
    const double overhead = w.jobs ? (seen - w.busy_seconds) / static_cast<double>(w.jobs) : 0.0;
    std::printf("  %4d  %4llu  %6.2f  %7.2f   %13.2f  %9.3f ms\n", r, static_cast<unsigned long long>(w.jobs),
                w.busy_seconds, rate, seen, 1e3 * overhead);
    per_rank.push_back({{"rank", r},
                        {"jobs", w.jobs},
                        {"busy_seconds", w.busy_seconds},
                        {"evaluations_per_second", rate},
                        {"seen_by_rank0_seconds", seen},
                        {"overhead_per_job_seconds", overhead}});
  }
  j["per_rank"] = per_rank;
}

/// Job times, simulated or not.
JobFigures report_jobs(const std::vector<GenerationRecord>& records, nlohmann::json& j) {
  JobFigures f;
  std::vector<double>& all = f.all;
  std::vector<double>& sim = f.sim;
  std::vector<double>& nosim = f.nosim;
  std::vector<double>& msg_out = f.msg_out;
  std::vector<double>& msg_in = f.msg_in;
  for (const auto& g : records)
    for (const auto& job : g.jobs) {
      all.push_back(job.seconds);
      (job.simulated ? sim : nosim).push_back(job.seconds);
      msg_out.push_back(job.bytes_out);
      msg_in.push_back(job.bytes_in);
    }
  f.simulated_share = all.empty() ? 0.0 : static_cast<double>(sim.size()) / static_cast<double>(all.size());
  std::printf("\nJob times as rank 0 saw them (hand-out to result), %zu jobs, %.0f%% simulated\n", all.size(),
              100.0 * f.simulated_share);
  std::printf("  all: mean %.1f ms, median %.1f ms, 90%% %.1f ms, max %.1f ms\n", 1e3 * mean(all),
              1e3 * quantile(all, 0.5), 1e3 * quantile(all, 0.9), 1e3 * quantile(all, 1.0));
  std::printf("  simulated: %zu, mean %.1f ms, max %.1f ms; not simulated: %zu, mean %.2f ms\n", sim.size(),
              1e3 * mean(sim), 1e3 * quantile(sim, 1.0), nosim.size(), 1e3 * mean(nosim));
  j["jobs"] = {{"count", all.size()},
               {"simulated_share", f.simulated_share},
               {"mean_seconds", mean(all)},
               {"median_seconds", quantile(all, 0.5)},
               {"p90_seconds", quantile(all, 0.9)},
               {"max_seconds", quantile(all, 1.0)},
               {"simulated_mean_seconds", mean(sim)},
               {"not_simulated_mean_seconds", mean(nosim)},
               {"job_message_mean_bytes", mean(msg_out)},
               {"result_message_mean_bytes", mean(msg_in)}};
  return f;
}

/// Rank 0's cost per generation, in means over the generations.
struct RootFigures {
  double serial = 0.0;       // serial part (s)
  double cpu_per_job = 0.0;  // main-thread CPU while the workers evaluate (s per job)
};

/// Rank 0's cost per generation and the traffic.
RootFigures report_root(const MeasuredRun& m, const JobFigures& jf, nlohmann::json& j) {
  const std::vector<GenerationRecord>& records = m.records;
  const MpiTransportStats& transport_stats = m.transport_stats;
  const std::vector<double>& msg_out = jf.msg_out;
  const std::vector<double>& msg_in = jf.msg_in;
  std::vector<double> total, wait, serial, messages, trajectory, breeding, checkpoint, cpu_per_job, msgs, bytes;
  double final_checkpoint = 0.0;  // the run's last generation's wait for its last checkpoint (once a run)
  for (const auto& g : records) {
    total.push_back(g.timings.total);
    wait.push_back(g.timings.evaluate);
    total.back() -= g.timings.final_checkpoint;
    serial.push_back(g.timings.serial());
    final_checkpoint += g.timings.final_checkpoint;
    messages.push_back(g.timings.messages);
    trajectory.push_back(g.timings.trajectory);
    breeding.push_back(g.timings.breeding);
    checkpoint.push_back(g.timings.checkpoint);
    cpu_per_job.push_back(g.jobs.empty() ? 0.0 : g.root_cpu / static_cast<double>(g.jobs.size()));
    msgs.push_back(static_cast<double>(g.messages));
    bytes.push_back(static_cast<double>(g.bytes));
  }
  std::printf("\nRank 0 per generation (mean of %zu)\n", records.size());
  std::printf(
      "  waiting for results %.3f s; serial part %.1f ms: messages and publishing %.1f ms, champion "
      "trajectory %.1f ms, breeding (selection, speciation, reproduction) %.1f ms, checkpoint %.1f ms\n",
      mean(wait), 1e3 * mean(serial), 1e3 * mean(messages), 1e3 * mean(trajectory), 1e3 * mean(breeding),
      1e3 * mean(checkpoint));
  const double serial_share = mean(total) > 0 ? mean(serial) / mean(total) : 0.0;
  std::printf("  the serial part is %.2f%% of the generation (%.3f s)\n", 100.0 * serial_share, mean(total));
  if (final_checkpoint > 0)
    std::printf(
        "  (not counted: the run's last generation waited %.1f ms for its last checkpoint to be on disk, once a "
        "run)\n",
        1e3 * final_checkpoint);
  std::printf("  rank 0 CPU while the workers evaluate: %.3f ms per job\n", 1e3 * mean(cpu_per_job));
  j["rank0_per_generation"] = {{"waiting_seconds", mean(wait)},
                               {"serial_seconds", mean(serial)},
                               {"generation_seconds", mean(total)},
                               {"serial_share", serial_share},
                               {"messages_seconds", mean(messages)},
                               {"trajectory_seconds", mean(trajectory)},
                               {"breeding_seconds", mean(breeding)},
                               {"checkpoint_seconds", mean(checkpoint)},
                               {"final_checkpoint_seconds_once", final_checkpoint},
                               {"cpu_per_job_seconds", mean(cpu_per_job)}};
  std::printf(
      "\nExchanged per generation: %.0f messages, %.0f kB (jobs %.0f B, results %.0f B on average); "
      "setup broadcast once: %llu B\n",
      mean(msgs), mean(bytes) / 1e3, mean(msg_out), mean(msg_in),
      static_cast<unsigned long long>(transport_stats.setup_bytes));
  j["per_generation_traffic"] = {
      {"messages", mean(msgs)}, {"bytes", mean(bytes)}, {"setup_bytes", transport_stats.setup_bytes}};
  return RootFigures{mean(serial), mean(cpu_per_job)};
}

/// The projection to other rank counts, as measured and for a late-run generation.
void report_projection(const MpiSession& session, const Options& o, const MeasuredRun& m, const JobFigures& jf,
                       const RootFigures& root, nlohmann::json& j) {
  const std::vector<GenerationRecord>& records = m.records;
  const RunConfig& config = m.config;
  const std::vector<double>& sim = jf.sim;
  const double simulated_share = jf.simulated_share;
  ClusterParams cluster;
  cluster.latency_s = o.latency_us * 1e-6;
  cluster.bandwidth_bytes_per_s = o.bandwidth_gbit * 1e9 / 8.0;
  cluster.core_speed = o.core_speed;
  const double root_per_job = root.cpu_per_job;
  // Rank 0's serial part, without its champion re-simulation: that runs as often
  // as the champion's genes change, which the measured mean already reflects.
  const double serial_mean = root.serial;
  std::vector<GenerationCost> measured;
  for (const auto& g : records) {
    GenerationCost c;
    for (const auto& job : g.jobs) {
      c.job_seconds.push_back(job.seconds);
      c.job_bytes.push_back(job.bytes_out + job.bytes_in);
    }
    c.serial_seconds = g.timings.serial();
    c.root_seconds_per_job = root_per_job;
    measured.push_back(std::move(c));
  }
  // A late-run generation: every robot simulated, costs drawn from the measured
  // simulated jobs (seeded; the mean serial part of the measured generations).
  std::vector<GenerationCost> late;
  if (!sim.empty()) {
    std::vector<const JobRecord*> pool;
    for (const auto& g : records)
      for (const auto& job : g.jobs)
        if (job.simulated) pool.push_back(&job);
    Rng rng(1);
    for (int k = 0; k < o.synthetic_generations; ++k) {
      GenerationCost c;
      for (int i = 0; i < config.neat.population; ++i) {
        const JobRecord* job = pool[rng.index(pool.size())];
        c.job_seconds.push_back(job->seconds);
        c.job_bytes.push_back(job->bytes_out + job->bytes_in);
      }
      c.serial_seconds = serial_mean;
      c.root_seconds_per_job = root_per_job;
      late.push_back(std::move(c));
    }
  }
  std::printf(
      "\nProjection (evolve/parallel/scaling_model.hpp): latency %.0f us, rank 0's link %.1f Gbit/s, "
      "cores %.2fx this machine's; paper: %d runs of %d generations\n",
      o.latency_us, o.bandwidth_gbit, o.core_speed, o.paper_runs, o.paper_generations);
  nlohmann::json proj = nlohmann::json::object();
  for (const auto& [name, gens] : {std::pair<std::string, const std::vector<GenerationCost>*>{"as measured", &measured},
                                   {"all simulated", &late}}) {
    if (gens->empty()) continue;
    const Projection one = project(*gens, 2, cluster);
    std::printf("  %s (%s):\n", name.c_str(),
                name == "as measured" ? (std::to_string(static_cast<int>(100 * simulated_share + 0.5)) +
                                         "% simulated, the measured generations")
                                            .c_str()
                                      : "every robot simulated, late in a run");
    const Projection per_trial = project(*gens, o.trial_ranks, cluster);
    const double trial_run = per_trial.seconds * o.paper_generations;
    std::printf(
        "    ranks  s/generation  workers  rank0 link  serial  bound              speedup  efficiency  one run    "
        "experiment: trials one after another | %d-rank trials side by side\n",
        o.trial_ranks);
    std::vector<int> counts = {session.size()};
    for (int r : o.ranks) counts.push_back(r);
    nlohmann::json rows = nlohmann::json::array();
    for (int r : counts) {
      if (r < 2) continue;
      const Projection p = project(*gens, r, cluster);
      const double run = p.seconds * o.paper_generations;
      const double speedup = one.seconds / p.seconds;
      const double efficiency = speedup / (r - 1);
      // The same ranks as a job array: floor(r / trial_ranks) trials at a time.
      const int at_once = std::max(1, r / o.trial_ranks);
      const double array_time =
          r < o.trial_ranks ? run * o.paper_runs : std::ceil(static_cast<double>(o.paper_runs) / at_once) * trial_run;
      std::printf("    %5d  %12.3f  %7.3f  %10.4f  %6.3f  %-17s  %7.1f  %9.0f%%  %-9s  %-37s | %s\n", r, p.seconds,
                  p.workers, p.root_link, p.serial, main_bound(p).c_str(), speedup, 100.0 * efficiency,
                  human(run).c_str(), human(run * o.paper_runs).c_str(), human(array_time).c_str());
      rows.push_back({{"ranks", r},
                      {"seconds_per_generation", p.seconds},
                      {"workers_seconds", p.workers},
                      {"root_link_seconds", p.root_link},
                      {"serial_seconds", p.serial},
                      {"bound", main_bound(p)},
                      {"speedup_vs_one_worker", speedup},
                      {"efficiency", efficiency},
                      {"one_run_seconds", run},
                      {"experiment_seconds_sequential", run * o.paper_runs},
                      {"experiment_seconds_job_array", array_time}});
    }
    proj[name] = rows;
  }
  j["projection"] = {{"latency_s", cluster.latency_s},
                     {"bandwidth_bytes_per_s", cluster.bandwidth_bytes_per_s},
                     {"core_speed", cluster.core_speed},
                     {"paper_runs", o.paper_runs},
                     {"paper_generations", o.paper_generations},
                     {"trial_ranks", o.trial_ranks},
                     {"rows", proj}};
}

int run_root(const MpiSession& session, const CLI::App& app, const Options& o) {
  const MeasuredRun m = measure_run(session, app, o);
  const RunConfig& config = m.config;
  const std::vector<GenerationRecord>& records = m.records;
  const int resumed_at = m.resumed_at;

  // ---- measured
  nlohmann::json j;
  j["setup"] = {{"ranks", session.size()},
                {"host", session.host()},
                {"regime", regime_name(config.regime)},
                {"population", config.neat.population},
                {"generations", static_cast<int>(records.size())},
                {"resumed_log", o.resume_log},
                {"resumed_at_generation", resumed_at},
                {"steps", config.eval.sim.steps},
                {"seed", config.seed},
                {"background_checkpoint", m.opts.background_checkpoint},
                {"overlap_trajectory", m.opts.overlap_trajectory}};
  std::printf(
      "robozoo-mpi-bench: %d ranks on %s (1 evolving, %d evaluating); %s, population %d, %zu generations "
      "of up to %d steps, seed %lld",
      session.size(), session.host().c_str(), session.size() - 1, regime_name(config.regime).c_str(),
      config.neat.population, records.size(), config.eval.sim.steps, static_cast<long long>(config.seed));
  if (resumed_at >= 0)
    std::printf("; generations %d-%d of %s", resumed_at, resumed_at + static_cast<int>(records.size()) - 1,
                o.resume_log.c_str());
  std::printf("\n\n");

  report_ranks(session, m, j);
  const JobFigures jobs = report_jobs(records, j);
  const RootFigures root = report_root(m, jobs, j);

  // ---- projected
  report_projection(session, o, m, jobs, root, j);
  if (!o.json_path.empty()) std::ofstream(o.json_path) << j.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<MpiSession> session;
  try {
    session = std::make_unique<MpiSession>(&argc, &argv);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-mpi-bench: " << e.what() << "\n";
    return 2;
  }
  const bool root = session->rank() == 0;
  CLI::App app{
      "robozoo-mpi-bench: run an evolution over MPI as robozoo-evolve --mpi does, measure per-rank\n"
      "throughput, rank 0's cost per generation and the traffic, and project the time per generation\n"
      "and for the paper's experiment on more ranks. Start it with mpirun -np N (N >= 2)."};
  Options o;
  std::string ranks_text = "8,32,128";
  app.add_option("--regime", o.regime, "feedforward or recurrent")->check(CLI::IsMember({"feedforward", "recurrent"}));
  app.add_option("--seed", o.seed, "seed of the run (default 7)");
  app.add_option("--population", o.population, "genomes per generation (default 150, the paper's)")
      ->check(CLI::Range(2, 1000000));
  app.add_option("--generations", o.generations, "generations to measure (default 6)")->check(CLI::Range(1, 100000));
  app.add_option("--steps", o.steps, "physics steps per evaluation (default 2500, the paper's)")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--config", o.config_file, "configuration file (.json or .toml); flags given override it");
  app.add_option("--log", o.log_path,
                 "keep the run's log here (default: a temporary folder, removed); with --resume, where the copy goes "
                 "(must not exist)");
  app.add_option(
         "--lcm-url", o.lcm_url,
         "publish live on this LCM URL while measuring (given alone: LCM's default URL; default: no publishing)")
      ->expected(0, 1)
      ->default_str(robozoo::kDefaultLcmUrl);
  app.add_option("--project", ranks_text, "rank counts to project to, comma-separated (default 8,32,128)");
  app.add_option("--latency-us", o.latency_us, "one-way message latency of the cluster (us, default 50: TCP)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--bandwidth-gbit", o.bandwidth_gbit, "rank 0's link (Gbit/s, default 1)")->check(CLI::PositiveNumber);
  app.add_option("--core-speed", o.core_speed, "a cluster core's speed relative to this machine's (default 1)")
      ->check(CLI::PositiveNumber);
  app.add_option("--paper-runs", o.paper_runs, "runs of the experiment (default 60)")->check(CLI::Range(1, 100000));
  app.add_option("--paper-generations", o.paper_generations, "generations per run (default 500)")
      ->check(CLI::Range(1, 100000000));
  app.add_option("--trial-ranks", o.trial_ranks,
                 "ranks per trial when a budget of N ranks runs several trials at once (default 8)")
      ->check(CLI::Range(2, 1000000));
  app.add_flag("--foreground-checkpoint", o.foreground_checkpoint,
               "write checkpoints within the generation, as a local run does (to compare)");
  app.add_flag("--serial-trajectory", o.serial_trajectory,
               "re-simulate a new champion for its poses within the generation, as a local run does, instead "
               "of while the next generation is evaluated (to compare)");
  app.add_option("--json", o.json_path, "also write every figure to this JSON file");
  auto* resume = app.add_option(
      "--resume", o.resume_log,
      "measure the next --generations generations of this logged, unfinished run (a copy of LOG and "
      "LOG.checkpoint; the run's own configuration): late-generation costs, robots as evolution made them");
  app.add_flag("--force", o.force_version, "with --resume: continue a checkpoint another robozoo version wrote")
      ->needs(resume);
  for (const char* name : {"--regime", "--seed", "--population", "--steps", "--config"})
    resume->excludes(app.get_option(name));
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-mpi-bench", !root)) return *stop;
  try {
    o.ranks.clear();
    std::stringstream ss(ranks_text);
    for (std::string item; std::getline(ss, item, ',');) {
      const int r = std::stoi(item);
      if (r < 2) throw std::invalid_argument("rank counts must be >= 2, got " + item);
      o.ranks.push_back(r);
    }
  } catch (const std::exception& e) {
    if (root) std::cerr << "robozoo-mpi-bench: --project: " << e.what() << "\n";
    return 2;
  }
  if (session->size() < 2) {
    std::cerr << "robozoo-mpi-bench: needs at least 2 ranks: mpirun -np N robozoo-mpi-bench (N >= 2)\n";
    return 2;
  }
  try {
    if (root) return run_root(*session, app, o);
    MpiWorkerStats stats;
    serve_mpi_session(
        [](const std::string& setup) {
          const RunConfig c = config_from_record(nlohmann::json::parse(setup));
          return WorkFn([eval = c.eval](const Bytes& job) { return run_eval_job(job, eval); });
        },
        &stats);
    gather_worker_stats(stats);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-mpi-bench: rank " << session->rank() << ": " << e.what() << "\n";
    session->abort(1);
  }
}
