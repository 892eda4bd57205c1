#include "study/analysis/read/continued_results.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "runlog/read/log_reader.hpp"
#include "study/analysis/read/log_results.hpp"

namespace robozoo {

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The run object of `r`'s JSON without the generations requested (there and in its
/// configuration), flattened: "/run_id", "/config/neat/population", ...
nlohmann::json identity_of(const RunResults& r) {
  RunResults bare;
  bare.run = r.run;
  bare.run.generations.clear();
  bare.run.champions.clear();
  bare.run.min_center_z.clear();
  nlohmann::json run = run_results_to_json(bare).at("run");
  run.erase("generations");
  if (run.contains("config") && run["config"].is_object()) run["config"].erase("generations");
  return run.flatten();
}

/// The first field where two runs' identities differ, as "run/seed: 7 != 8"; empty when none.
/// Compared as JSON text: doubles bit for bit.
std::string identity_difference(const RunResults& a, const RunResults& b) {
  const nlohmann::json ia = identity_of(a), ib = identity_of(b);
  const nlohmann::json none;
  for (auto it = ia.begin(); it != ia.end(); ++it) {
    const nlohmann::json& o = ib.contains(it.key()) ? ib.at(it.key()) : none;
    if (it->dump() != o.dump()) return "run" + it.key() + ": " + it->dump() + " != " + o.dump();
  }
  for (auto it = ib.begin(); it != ib.end(); ++it)
    if (!ia.contains(it.key())) return "run" + it.key() + ": null != " + it->dump();
  return "";
}

/// Generation numbers from..from + n - 1 in order; the first that is not, or -1.
int64_t first_out_of_order(const std::vector<GenerationRecord>& gens, int32_t from) {
  for (size_t i = 0; i < gens.size(); ++i)
    if (gens[i].generation != from + static_cast<int32_t>(i)) return static_cast<int64_t>(i);
  return -1;
}

/// `later` merged with the earlier result beside `log_path` when it continues a run.
RunResults with_earlier_generations(RunResults later, const std::string& log_path) {
  if (!later.run.continues) return later;
  const std::string earlier_path = earlier_results_path_for(log_path);
  if (!std::filesystem::exists(earlier_path))
    throw std::invalid_argument(log_path + " continues run " + later.run.run_id + " from generation " +
                                std::to_string(later.run.continues->from_generation) +
                                ", but its earlier generations' compact result " + earlier_path + " is missing");
  const RunResults earlier = read_run_results(earlier_path);
  return merge_run_results(earlier, later, earlier_path + " and " + log_path);
}

}  // namespace

std::string earlier_results_path_for(const std::string& log_path) { return log_path + ".earlier.json"; }

RunResults merge_run_results(const RunResults& earlier, const RunResults& later, const std::string& what) {
  auto refuse = [&what](const std::string& why) { throw std::invalid_argument(what + ": not one run: " + why); };
  const RunSummary& a = earlier.run;
  const RunSummary& b = later.run;
  if (!b.continues) refuse("the later log does not say it continues a run");
  if (a.continues) refuse("the earlier result does not begin at generation 0");
  const LogContinuation& c = *b.continues;
  if (const std::string why = identity_difference(earlier, later); !why.empty()) refuse(why);
  if (a.generations_requested > b.generations_requested)
    refuse("the earlier result was requested for " + std::to_string(a.generations_requested) +
           " generations, the later log for " + std::to_string(b.generations_requested));
  if (a.generations.size() != static_cast<size_t>(c.from_generation))
    refuse("the later log continues from generation " + std::to_string(c.from_generation) +
           ", the earlier result has " + std::to_string(a.generations.size()) + " generations");
  if (const int64_t i = first_out_of_order(a.generations, 0); i >= 0)
    refuse("the earlier result's generation record " + std::to_string(i) + " is generation " +
           std::to_string(a.generations[static_cast<size_t>(i)].generation));
  if (b.generations.empty()) refuse("the later log holds no generation");
  if (const int64_t i = first_out_of_order(b.generations, c.from_generation); i >= 0)
    refuse("the later log's generation record " + std::to_string(i) + " is generation " +
           std::to_string(b.generations[static_cast<size_t>(i)].generation) + ", not " +
           std::to_string(c.from_generation + i));
  const GenerationRecord& last = a.generations.back();
  const GenerationRecord& next = b.generations.front();
  if (last.evaluations != c.evaluations_before || next.evaluations != last.evaluations + b.population)
    refuse("evaluations go from " + std::to_string(last.evaluations) + " to " + std::to_string(next.evaluations) +
           " (population " + std::to_string(b.population) + ", the log continues after " +
           std::to_string(c.evaluations_before) + ")");
  if (!same_bits(last.best_so_far_fitness, c.best_so_far_before) ||
      !same_bits(next.best_so_far_fitness, std::max(last.best_so_far_fitness, next.best_fitness)))
    refuse("the best-so-far fitness does not go on from generation " + std::to_string(last.generation) +
           "'s to generation " + std::to_string(next.generation) + "'s");
  for (const auto& ch : a.champions)
    if (ch.generation >= c.from_generation) refuse("the earlier result has a champion of a later generation");
  for (const auto& ch : b.champions)
    if (ch.generation < c.from_generation) refuse("the later log has a champion of an earlier generation");

  // The merged run before its compact reduction: compact_summary picks the
  // best-of-run among both parts' champions (each part's best is whole) and
  // reduces every other champion as the uninterrupted run's result has it.
  RunSummary m = b;
  m.continues.reset();
  m.generations = a.generations;
  m.generations.insert(m.generations.end(), b.generations.begin(), b.generations.end());
  m.champions = a.champions;
  m.champions.insert(m.champions.end(), b.champions.begin(), b.champions.end());
  m.min_center_z = a.min_center_z;
  for (const auto& [id, z] : b.min_center_z) {
    auto [it, inserted] = m.min_center_z.emplace(id, z);
    if (!inserted && it->second.size() == z.size())
      for (size_t i = 0; i < z.size(); ++i) it->second[i] = std::min(it->second[i], z[i]);
  }
  m.max_d = std::max(a.max_d, b.max_d);
  m.undecodable = a.undecodable + b.undecodable;
  m.truncated = a.truncated || b.truncated;
  RunResults out;
  out.run = compact_summary(m);
  out.has_evolve_seconds = later.has_evolve_seconds;
  out.evolve_seconds = later.evolve_seconds;
  return out;
}

RunResults run_results_of_log(const std::string& log_path) {
  return with_earlier_generations(results_from_log(log_path), log_path);
}

RunResults run_results_up_to(const std::string& log_path, const Checkpoint& c) {
  if (c.log_continues && c.log_bytes == 0) {
    // Continued here, no generation finished yet: the earlier result is all there is.
    RunResults r = read_run_results(earlier_results_path_for(log_path));
    r.has_evolve_seconds = true;
    r.evolve_seconds = c.elapsed_seconds;
    return r;
  }
  std::error_code ec;
  const auto size = std::filesystem::file_size(log_path, ec);
  if (ec) throw std::runtime_error(log_path + ": cannot read the log (" + ec.message() + ")");
  if (c.log_bytes < 0 || static_cast<uintmax_t>(c.log_bytes) > size)  // checked before anything is allocated
    throw std::runtime_error(log_path + ": the log is shorter (" + std::to_string(size) +
                             " bytes) than its checkpoint says (" + std::to_string(c.log_bytes) + ")");
  std::ifstream in(log_path, std::ios::binary);
  if (!in) throw std::runtime_error(log_path + ": cannot read the log");
  std::vector<uint8_t> bytes(static_cast<size_t>(c.log_bytes));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (in.gcount() != static_cast<std::streamsize>(bytes.size()))
    throw std::runtime_error(log_path + ": the log is shorter (" + std::to_string(in.gcount()) +
                             " bytes) than its checkpoint says (" + std::to_string(c.log_bytes) + ")");
  RunResults r;
  r.run = compact_summary(summarize_run(scan_event_log_bytes(bytes).contents, log_path));
  r.has_evolve_seconds = true;
  r.evolve_seconds = c.elapsed_seconds;
  return with_earlier_generations(std::move(r), log_path);
}

}  // namespace robozoo
