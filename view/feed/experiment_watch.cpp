#include "view/feed/experiment_watch.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>
#include <tuple>

#include "study/analysis/compare/nan.hpp"
#include "study/analysis/compare/ttest.hpp"
#include "study/experiment/trial_plan.hpp"
#include "evolve/messages/build.hpp"
#include "robozoo/generation_t.hpp"
#include "robozoo/run_t.hpp"
#include "runlog/read/log_reader.hpp"
#include "evolve/record/run_results.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace robozoo::view {

namespace fs = std::filesystem;

namespace {

/// Where the page says a trial comes from: "log", "result" or "checkpoint" (a portable checkpoint).
std::string source_of(const TrialProgress& t) {
  if (t.results_path.empty()) return "log";
  const std::string ext = kPortableCheckpointExtension;
  const std::string& p = t.results_path;
  return p.size() >= ext.size() && p.compare(p.size() - ext.size(), ext.size(), ext) == 0 ? "checkpoint" : "result";
}

/// The values of an arm's trials at generation g.
std::vector<double> at_generation(const std::vector<TrialProgress>& trials, const std::string& arm, size_t g) {
  std::vector<double> v;
  for (const TrialProgress& t : trials)
    if (t.arm == arm && g < t.best_so_far.size()) v.push_back(t.best_so_far[g]);
  return v;
}

size_t longest(const std::vector<TrialProgress>& trials, const std::string& arm) {
  size_t n = 0;
  for (const TrialProgress& t : trials)
    if (t.arm == arm) n = std::max(n, t.best_so_far.size());
  return n;
}

std::set<std::string> arm_names(const std::vector<TrialProgress>& trials) {
  std::set<std::string> arms;
  for (const TrialProgress& t : trials) arms.insert(t.arm);
  return arms;
}

/// Seconds since the file last changed (infinity when it does not exist).
double age_seconds(const fs::path& p) {
  std::error_code ec;
  const fs::file_time_type m = fs::last_write_time(p, ec);
  if (ec) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(fs::file_time_type::clock::now() - m).count();
}

/// The bytes [from, to) of the file at `path`; fewer when the file is shorter.
std::string bytes_between(const std::string& path, int64_t from, int64_t to) {
  std::ifstream in(path, std::ios::binary);
  std::string out(static_cast<size_t>(std::max<int64_t>(0, to - from)), '\0');
  if (!in.seekg(from)) return {};
  in.read(out.data(), static_cast<std::streamsize>(out.size()));
  out.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  return out;
}

constexpr int64_t kTailBytes = 256;

/// Sets a trial's best-so-far at generation `generation`; false (nothing set) when the number
/// is negative or beyond what the trial may hold (its planned generations, when known).
bool set_best_so_far(TrialProgress& t, int64_t generation, double value) {
  const int64_t limit = t.planned > 0 ? std::min<int64_t>(t.planned, kMaxWatchedGenerations) : kMaxWatchedGenerations;
  if (generation < 0 || generation >= limit) return false;
  const size_t at = static_cast<size_t>(generation);
  if (t.best_so_far.size() <= at) t.best_so_far.resize(at + 1, kNaN);
  t.best_so_far[at] = value;
  return true;
}

}  // namespace

std::vector<ArmCurve> arm_curves(const std::vector<TrialProgress>& trials) {
  std::vector<ArmCurve> out;
  for (const std::string& arm : arm_names(trials)) {
    ArmCurve c;
    c.arm = arm;
    for (size_t g = 0, n = longest(trials, arm); g < n; ++g) {
      const std::vector<double> v = at_generation(trials, arm, g);
      double sum = 0;
      for (double x : v) sum += x;
      const double mean = sum / static_cast<double>(v.size());
      double ss = 0;
      for (double x : v) ss += (x - mean) * (x - mean);
      c.mean.push_back(mean);
      c.se.push_back(v.size() > 1 ? std::sqrt(ss / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))
                                  : kNaN);
      c.n.push_back(static_cast<int>(v.size()));
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<double> generation_p_values(const std::vector<TrialProgress>& trials, const std::string& a,
                                        const std::string& b) {
  std::vector<double> p;
  for (size_t g = 0, n = std::min(longest(trials, a), longest(trials, b)); g < n; ++g) {
    const std::vector<double> va = at_generation(trials, a, g), vb = at_generation(trials, b, g);
    p.push_back(va.size() >= 2 && vb.size() >= 2 ? ttest_ind(va, vb).p : kNaN);
  }
  return p;
}

ExperimentWatch::ExperimentWatch(std::string dir, ExperimentWatchOptions options)
    : dir_(std::move(dir)), options_(options) {
  std::error_code ec;
  if (!fs::is_directory(dir_, ec)) throw std::runtime_error(dir_ + ": not a folder");
  poll();
  if (trials_.empty())
    throw std::runtime_error(
        dir_ +
        ": no experiment here (no trial log <arm>-s<seed>.lcmlog, as robozoo-experiment "
        "writes" +
        (options_.results_dirs.empty() ? std::string(")") : std::string(", nor a compact result in --results)")));
}

bool ExperimentWatch::poll() {
  static const std::regex name_re(R"(([a-z-]+)-s([0-9]{1,18})\.lcmlog)");
  std::vector<fs::path> logs;
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) logs.push_back(it->path());
  std::sort(logs.begin(), logs.end());
  std::vector<TrialProgress> work;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const fs::path& p : logs) {
      std::smatch m;
      const std::string file = p.filename().string();
      if (!std::regex_match(file, m, name_re)) continue;
      try {
        arm_from_name(m[1].str());
      } catch (const std::invalid_argument&) {
        continue;  // not a trial log
      }
      const std::string name = file.substr(0, file.size() - 7);
      auto it = trials_.find(name);
      if (it == trials_.end() || !it->second.results_path.empty()) {  // new, or known from a result until now
        TrialProgress t;
        t.name = name;
        t.arm = m[1].str();
        t.seed = std::stoll(m[2].str());
        t.log_path = p.string();
        work.push_back(t);
      } else {
        work.push_back(it->second);
      }
    }
  }
  // Reading happens off the lock: the server keeps answering with the last summary.
  bool changed = false;
  for (TrialProgress& t : work) {
    const TrialProgress before = t;
    std::string problem;
    try {
      read_trial(t);
    } catch (const std::exception& e) {  // gone or unreadable since it was listed: shown as it was
      t = before;
      t.state = "stopped";
      problem = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    changed |= problem.empty() ? unreadable_.erase(t.log_path) > 0 : unreadable_[t.log_path] != problem;
    if (!problem.empty()) unreadable_[t.log_path] = problem;
    changed |= t.best_so_far != before.best_so_far || t.state != before.state || t.planned != before.planned ||
               t.checkpoint != before.checkpoint || before.state.empty();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (TrialProgress& t : work) trials_[t.name] = std::move(t);
  }
  changed |= poll_results();
  std::lock_guard<std::mutex> lock(mutex_);
  if (changed || summary_.empty()) summary_ = summary_json_locked().dump();
  return changed;
}

bool ExperimentWatch::poll_results() {
  // Compact results, and portable checkpoints (trials in progress: the result of their finished generations).
  static const std::regex name_re(R"((([a-z-]+)-s[0-9]{1,18})\.(results\.json|portable-checkpoint))");
  // The result files, by trial; of two files of one trial, the one with more generations is shown.
  std::map<std::string, std::vector<fs::path>> files;
  for (const std::string& d : options_.results_dirs) {
    std::error_code ec;
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
      std::smatch m;
      const std::string file = it->path().filename().string();
      if (!it->is_regular_file(ec) || !std::regex_match(file, m, name_re)) continue;
      try {
        arm_from_name(m[2].str());
      } catch (const std::invalid_argument&) {
        continue;
      }
      files[m[1].str()].push_back(it->path());
    }
  }
  bool changed = false;
  for (const auto& [name, paths] : files) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = trials_.find(name);
      if (it != trials_.end() && it->second.results_path.empty()) continue;  // its log is here
    }
    std::string stamp;
    for (const fs::path& p : paths) {
      std::error_code ec;
      stamp += p.string() + ":" + std::to_string(fs::file_size(p, ec)) + ":" +
               std::to_string(fs::last_write_time(p, ec).time_since_epoch().count()) + ";";
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = trials_.find(name);
      if (it != trials_.end() && it->second.results_stamp == stamp) continue;  // read, and unchanged
    }
    std::optional<TrialProgress> best;
    for (const fs::path& p : paths) {
      RunResults r;
      try {
        r = read_results_or_portable_checkpoint(p.string());
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        changed |= unreadable_.emplace(p.string(), e.what()).second;
        continue;
      }
      TrialProgress t;
      t.name = name;
      t.arm = r.run.arm;
      t.seed = r.run.seed;
      t.planned = r.run.generations_requested;
      bool fits = true;
      for (const GenerationRecord& g : r.run.generations)
        fits = fits && set_best_so_far(t, g.generation, g.best_so_far_fitness);
      if (!fits || (!r.run.generations.empty() && r.run.generations.front().generation != 0)) {
        std::lock_guard<std::mutex> lock(mutex_);
        changed |= unreadable_
                       .emplace(p.string(), p.string() + ": its generations are not 0, 1, ... within the run's " +
                                                std::to_string(t.planned))
                       .second;
        continue;
      }
      {
        std::lock_guard<std::mutex> lock(mutex_);
        changed |= unreadable_.erase(p.string()) > 0;
      }
      const int32_t done = static_cast<int32_t>(t.best_so_far.size());
      t.state = t.planned > 0 && done >= t.planned ? "finished" : "stopped";
      t.results_path = p.string();
      t.results_stamp = stamp;
      if (!best || t.best_so_far.size() > best->best_so_far.size()) best = std::move(t);
    }
    if (!best) continue;
    std::lock_guard<std::mutex> lock(mutex_);
    trials_[name] = std::move(*best);
    changed = true;
  }
  return changed;
}

void ExperimentWatch::read_trial(TrialProgress& t) {
  // A log cut back or rewritten under what was read is read again from its start.
  if (t.offset > 0 && bytes_between(t.log_path, t.offset - static_cast<int64_t>(t.tail.size()), t.offset) != t.tail) {
    t.offset = 0;
    t.tail.clear();
    t.best_so_far.clear();
    t.planned = 0;
  }
  if (t.offset == 0) {
    // A log continued here from a portable checkpoint: its earlier generations are beside it.
    const std::string earlier = earlier_results_path_for(t.log_path);
    std::error_code ec;
    if (fs::exists(earlier, ec)) {
      const RunResults r = read_run_results(earlier);
      t.planned = r.run.generations_requested;
      for (const GenerationRecord& g : r.run.generations)
        if (!set_best_so_far(t, g.generation, g.best_so_far_fitness))
          throw std::runtime_error(earlier + ": generation " + std::to_string(g.generation) + " is beyond the run's " +
                                   std::to_string(t.planned));
    }
  }
  const ScannedLog chunk = scan_event_log_from(t.log_path, t.offset);
  for (const LogRecord& r : chunk.contents.records) {
    if (r.channel == kChannelGeneration) {
      generation_t g;
      if (g.decode(r.data.data(), 0, static_cast<int>(r.data.size())) < 0) continue;
      set_best_so_far(t, g.generation, g.best_so_far_fitness);  // a number beyond the run is damage: skipped
    } else if (r.channel == kChannelRun) {
      run_t run;
      if (run.decode(r.data.data(), 0, static_cast<int>(r.data.size())) >= 0) t.planned = run.generations;
    }
  }
  t.offset += chunk.end_of_events;
  t.tail = bytes_between(t.log_path, std::max<int64_t>(0, t.offset - kTailBytes), t.offset);
  const fs::path checkpoint = t.log_path + ".checkpoint";
  std::error_code ec;
  t.checkpoint = fs::exists(checkpoint, ec);
  const double age = std::min(age_seconds(t.log_path), age_seconds(checkpoint));
  const int32_t done = static_cast<int32_t>(t.best_so_far.size());
  if (t.planned > 0 && done >= t.planned)
    t.state = "finished";
  else
    t.state = age <= options_.running_seconds ? "running" : "stopped";
}

nlohmann::json ExperimentWatch::summary_json_locked() const {
  std::vector<TrialProgress> all;
  for (const auto& [name, t] : trials_) all.push_back(t);
  std::sort(all.begin(), all.end(), [](const TrialProgress& a, const TrialProgress& b) {
    return std::tie(a.arm, a.seed) < std::tie(b.arm, b.seed);  // recurrent-s2 before recurrent-s10
  });
  nlohmann::json trials = nlohmann::json::array();
  for (const TrialProgress& t : all) {
    const double best = t.best_so_far.empty() ? kNaN : t.best_so_far.back();
    trials.push_back({{"name", t.name},
                      {"arm", t.arm},
                      {"seed", t.seed},
                      {"state", t.state},
                      {"generations", t.best_so_far.size()},
                      {"planned", t.planned},
                      {"best", best},
                      {"checkpoint", t.checkpoint},
                      {"source", source_of(t)},
                      {"bsf", t.best_so_far}});
  }
  nlohmann::json arms = nlohmann::json::array();
  const std::vector<ArmCurve> curves = arm_curves(all);
  for (const ArmCurve& c : curves) arms.push_back({{"arm", c.arm}, {"mean", c.mean}, {"se", c.se}, {"n", c.n}});
  nlohmann::json tests = nlohmann::json::array();
  for (size_t i = 0; i < curves.size(); ++i)
    for (size_t j = i + 1; j < curves.size(); ++j) {
      const std::vector<double> p = generation_p_values(all, curves[i].arm, curves[j].arm);
      nlohmann::json sig = nlohmann::json::array();
      for (size_t g = 0; g < p.size(); ++g)
        if (p[g] < options_.alpha) sig.push_back(g);
      tests.push_back({{"a", curves[i].arm}, {"b", curves[j].arm}, {"p", p}, {"significant", sig}});
    }
  nlohmann::json unreadable = nlohmann::json::array();
  for (const auto& [file, why] : unreadable_) unreadable.push_back(why);
  return {{"t", "experiment"},
          {"dir", dir_},
          {"results_dirs", options_.results_dirs},
          {"alpha", options_.alpha},
          {"test", "Student's t-test, two-sided"},
          {"trials", trials},
          {"arms", arms},
          {"tests", tests},
          {"unreadable_results", unreadable}};
}

std::string ExperimentWatch::summary() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return summary_;
}

std::vector<TrialProgress> ExperimentWatch::trials() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<TrialProgress> out;
  for (const auto& [name, t] : trials_) out.push_back(t);
  return out;
}

std::string ExperimentWatch::log_of(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = trials_.find(name);
  return it == trials_.end() ? "" : it->second.log_path;
}

std::string ExperimentWatch::results_of(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = trials_.find(name);
  return it == trials_.end() ? "" : it->second.results_path;
}

}  // namespace robozoo::view
