#include "evolve/run/champion_log.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/run/trajectory.hpp"

namespace robozoo {

namespace {

std::string g17(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

/// A generation of a compact result as its run logged it.
GenerationSummary summary_of(const GenerationRecord& r) {
  GenerationSummary g;
  g.generation = r.generation;
  g.evaluations = r.evaluations;
  g.best_fitness = r.best_fitness;
  g.mean_fitness = r.mean_fitness;
  g.stderr_fitness = r.stderr_fitness;
  g.best_so_far_fitness = r.best_so_far_fitness;
  g.champion_id = r.champion_id;
  g.num_species = r.num_species;
  g.compatibility_threshold = r.compatibility_threshold;
  for (size_t k = 0; k < r.outcomes.size(); ++k) g.outcome_counts[k] = r.outcomes[k];
  return g;
}

}  // namespace

ChampionReplay replay_champion(const RunResults& results, bool with_poses) {
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

  // This build must give the committed evaluation, or it would show another robot.
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

  // The generation it won, as generation 0 of a one-generation run with the champion's fitness.
  GenerationSummary g = summary_of(*gen);
  g.generation = 0;
  g.evaluations = config.neat.population;
  g.best_fitness = logged.fitness;
  g.best_so_far_fitness = logged.fitness;
  g.champion_id = genome.id;

  ChampionReplay r;
  r.generation = best->generation;
  r.generations = s.generations_requested;
  r.run = make_run_message(s.run_id, config, now_us());
  r.summary = make_generation_message(s.run_id, g, now_us());
  r.genome = make_genome_message(s.run_id, 0, genome, logged.species_id, GenomeScore{e.fitness, e.r, e.d, e.outcome},
                                 now_us());
  r.morphology = make_morphology_message(s.run_id, 0, genome.id, robot, now_us());
  if (with_poses && e.outcome != Outcome::NotSimulated)
    r.poses = simulate_pose_stream(robot, config.eval.sim, config.pose_every, s.run_id, 0, genome.id).poses;
  return r;
}

namespace {

// Parallel replays run in child processes: ODE steps every world of a process
// through one default threading implementation, which two threads must not share.

void put(std::string& out, const void* data, size_t size) { out.append(static_cast<const char*>(data), size); }

template <class T>
void put_message(std::string& out, const T& m) {
  const std::vector<uint8_t> bytes = encode_message(m);
  const uint64_t n = bytes.size();
  put(out, &n, sizeof n);
  put(out, bytes.data(), bytes.size());
}

/// A replay as bytes: the generation, then each message with its size, the poses counted.
std::string replay_bytes(const ChampionReplay& r) {
  std::string out;
  put(out, &r.generation, sizeof r.generation);
  put(out, &r.generations, sizeof r.generations);
  put_message(out, r.run);
  put_message(out, r.summary);
  put_message(out, r.genome);
  put_message(out, r.morphology);
  const uint64_t poses = r.poses.size();
  put(out, &poses, sizeof poses);
  for (const pose_t& p : r.poses) put_message(out, p);
  return out;
}

class Reader {
 public:
  explicit Reader(const std::string& bytes) : s_(bytes) {}
  void get(void* out, size_t size) {
    if (at_ + size > s_.size()) throw std::runtime_error("a replay's child process returned a short answer");
    std::memcpy(out, s_.data() + at_, size);
    at_ += size;
  }
  template <class T>
  void message(T& m) {
    uint64_t n = 0;
    get(&n, sizeof n);
    if (at_ + n > s_.size() || !safe_decode(s_.data() + at_, n, m))
      throw std::runtime_error("a replay's child process returned a message that does not decode");
    at_ += n;
  }

 private:
  const std::string& s_;
  size_t at_ = 0;
};

ChampionReplay replay_from_bytes(const std::string& bytes) {
  Reader in(bytes);
  ChampionReplay r;
  in.get(&r.generation, sizeof r.generation);
  in.get(&r.generations, sizeof r.generations);
  in.message(r.run);
  in.message(r.summary);
  in.message(r.genome);
  in.message(r.morphology);
  uint64_t poses = 0;
  in.get(&poses, sizeof poses);
  r.poses.resize(poses);
  for (pose_t& p : r.poses) in.message(p);
  return r;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_all(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// A temporary folder, removed with its object.
struct TemporaryDir {
  std::string path;
  TemporaryDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "robozoo-replay-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder " + tmpl);
    path = tmpl;
  }
  ~TemporaryDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TemporaryDir(const TemporaryDir&) = delete;
  TemporaryDir& operator=(const TemporaryDir&) = delete;
};

}  // namespace

std::vector<ChampionReplay> replay_champions(const std::vector<RunResults>& results, bool poses, int jobs,
                                             const std::function<void(size_t, size_t)>& done) {
  const size_t n = results.size();
  std::vector<ChampionReplay> out(n);
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (jobs == 1 || n <= 1) {
    for (size_t i = 0; i < n; ++i) {
      out[i] = replay_champion(results[i], poses);
      if (done) done(i + 1, n);
    }
    return out;
  }
  // Each replay in a child process that writes it (or its error) to a file of a temporary folder.
  TemporaryDir dir;
  std::vector<std::string> failed(n);  // "A" + message (std::invalid_argument) or "R" + message
  std::map<pid_t, size_t> running;
  size_t next = 0, finished = 0;
  auto wait_one = [&] {
    for (;;) {
      for (auto it = running.begin(); it != running.end(); ++it) {
        int status = 0;
        const pid_t got = ::waitpid(it->first, &status, WNOHANG);
        if (got == 0) continue;
        const pid_t pid = it->first;
        const size_t i = it->second;
        running.erase(it);  // `it` is gone from here on
        const std::string file = dir.path + "/" + std::to_string(i);
        if (got == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
          try {
            out[i] = replay_from_bytes(read_all(file));
          } catch (const std::exception& e) {
            failed[i] = std::string("R") + results[i].run.path + ": " + e.what();
          }
        } else {
          failed[i] = read_all(file + ".error");
          if (failed[i].empty())
            failed[i] = "R" + results[i].run.path + ": the replay's child process ended abnormally (status " +
                        std::to_string(status) + ")";
        }
        if (done) done(++finished, n);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  };
  while (next < n || !running.empty()) {
    if (next < n && running.size() < static_cast<size_t>(jobs)) {
      const size_t i = next++;
      const std::string file = dir.path + "/" + std::to_string(i);
      std::cout.flush();
      std::cerr.flush();
      const pid_t pid = ::fork();
      if (pid < 0) throw std::runtime_error("cannot start a process for a replay");
      if (pid == 0) {
        int code = 0;
        try {
          write_all(file, replay_bytes(replay_champion(results[i], poses)));
        } catch (const std::invalid_argument& e) {
          write_all(file + ".error", std::string("A") + e.what());
          code = 1;
        } catch (const std::exception& e) {
          write_all(file + ".error", std::string("R") + e.what());
          code = 1;
        }
        ::_exit(code);
      }
      running[pid] = i;
    } else {
      wait_one();
    }
  }
  for (const std::string& f : failed) {
    if (f.empty()) continue;
    if (f[0] == 'A') throw std::invalid_argument(f.substr(1));
    throw std::runtime_error(f.substr(1));
  }
  return out;
}

generation_t generation_message_of(const GenerationRecord& r, const std::string& run_id, int64_t utime) {
  return make_generation_message(run_id, summary_of(r), utime);
}

ChampionLogInfo write_champion_log(const RunResults& results, const std::string& log_path) {
  ChampionReplay r = replay_champion(results, true);
  EventLogWriter log = EventLogWriter::create(log_path);
  log.write(kChannelRun, encode_message(r.run), r.run.utime);
  log.write(kChannelGeneration, encode_message(r.summary), r.summary.utime);
  log.write(kChannelGenome, encode_message(r.genome), r.genome.utime);
  log.write(kChannelMorphology, encode_message(r.morphology), r.morphology.utime);
  for (pose_t& p : r.poses) {
    p.utime = now_us();
    log.write(kChannelPose, encode_message(p), p.utime);
  }
  log.sync();
  ChampionLogInfo info;
  info.generation = r.generation;
  info.genome_id = r.genome.genome_id;
  info.fitness = r.genome.fitness;
  info.poses = r.poses.size();
  return info;
}

}  // namespace robozoo
