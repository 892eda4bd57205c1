#include "replay/check/full_check.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include "evolve/core/wall_time.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/record/checkpoint.hpp"
#include "replay/log/logged_config.hpp"
#include "replay/compare/message_diff.hpp"
#include "runlog/read/log_index.hpp"
#include "runlog/read/log_reader.hpp"

namespace robozoo::replay {

namespace {

/// A folder made for the re-run and removed with everything in it.
class WorkDir {
 public:
  explicit WorkDir(const std::string& given) {
    if (!given.empty()) {
      path_ = given;
      return;
    }
    const char* tmp = std::getenv("TMPDIR");
    std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/robozoo-full-check-XXXXXX";
    if (!::mkdtemp(templ.data())) throw std::runtime_error("cannot make a temporary folder in " + templ);
    path_ = templ;
    owned_ = true;
  }
  ~WorkDir() {
    if (!owned_) return;
    const std::string log = path_ + "/rerun.lcmlog";
    for (const std::string& f : {log, checkpoint_path_for(log), checkpoint_path_for(log) + ".tmp"}) ::unlink(f.c_str());
    ::rmdir(path_.c_str());
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool owned_ = false;
};

/// The message as compared: normalised (clock fields zeroed); with `force`,
/// run_t's software_version blanked too. False with `why` when it does not decode.
bool comparable(const LogRecord& r, bool force, std::vector<uint8_t>& out, std::string& why) {
  if (!normalize_message(r.channel, r.data, out, &why)) return false;
  if (force && r.channel == kChannelRun) {
    run_t m{};
    if (!safe_decode(out.data(), out.size(), m, &why)) return false;
    m.software_version.clear();
    out = encode_message(m);
  }
  return true;
}

}  // namespace

std::string FullDifference::describe() const {
  std::ostringstream o;
  o << "generation " << generation << ", robozoo event " << index << ": ";
  if (logged_eventnum < 0) {
    o << "the re-run wrote event " << rerun_eventnum << " (" << rerun_channel << ") where the log ends";
    return o.str();
  }
  if (rerun_eventnum < 0) {
    o << "the log holds event " << logged_eventnum << " (" << channel << ") that the re-run never wrote";
    return o.str();
  }
  o << "log event " << logged_eventnum << " (" << channel << ")";
  if (rerun_channel != channel) {
    o << ", the re-run wrote " << rerun_channel << " (its event " << rerun_eventnum << ")";
    return o.str();
  }
  o << " " << (field.empty() ? "(bytes)" : field) << ": logged " << logged << ", re-run " << rerun;
  return o.str();
}

int FullCheckReport::exit_code() const {
  if (!fatal.empty()) return 2;
  if (diverged) return 1;
  return input_problems.empty() ? 0 : 2;
}

FullCheckReport full_check(const std::string& log_path, const EvaluatorFactory& make_evaluator,
                           const FullCheckOptions& options, const FullCheckProgress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  FullCheckReport r;
  r.log_path = log_path;
  auto finish = [&]() -> FullCheckReport& {
    r.seconds = seconds_since(t0);
    return r;
  };
  ScannedLog scanned;
  try {
    scanned = scan_event_log(log_path);
  } catch (const std::exception& e) {
    r.fatal = e.what();
    return finish();
  }
  for (const auto& d : scanned.damage) r.input_problems.push_back(d.describe());
  const LogContents& log = scanned.contents;
  const LogIndex index = index_log(log);
  for (const auto& p : index.problems)
    r.input_problems.push_back("event " + std::to_string(p.eventnum) + " (" + p.channel + "): " + p.what);
  if (index.run_events.empty()) {
    r.fatal = "the log holds no ROBOZOO_RUN, so the run to re-run is unknown";
    return finish();
  }
  std::set<std::string> runs;
  for (size_t e : index.run_events) runs.insert(index.events[e].run_id);
  if (runs.size() > 1) {
    r.fatal = "the log holds " + std::to_string(runs.size()) + " runs; check --full re-runs the one run of a log";
    return finish();
  }
  run_t first{};
  {
    const LogRecord& rec = log.records[index.events[index.run_events.front()].record];
    safe_decode(rec.data.data(), rec.data.size(), first);  // the index decoded it already
  }
  r.run_id = first.run_id;
  r.software_version = first.software_version;
  r.seed = first.seed;
  r.regime = first.regime == 1 ? "recurrent" : "feedforward";
  const std::string refusal = version_refusal(first);
  if (!refusal.empty() && !options.force) {
    r.fatal = refusal;
    return finish();
  }
  RunConfig config;
  try {
    config = config_from_run_message(first);
  } catch (const std::invalid_argument& e) {
    r.fatal = e.what();
    return finish();
  }
  // The log's robozoo events, in order (a record that does not decode stays: it equals nothing).
  std::vector<const LogRecord*> logged;
  for (const auto& e : index.events) {
    if (e.kind == EventKind::Foreign) continue;
    logged.push_back(&log.records[e.record]);
    r.generations_logged += e.kind == EventKind::Generation;
  }
  int target = r.generations_logged;
  if (options.max_generations >= 0) target = std::min(target, options.max_generations);
  if (target == 0) {
    r.fatal = "the log holds no ROBOZOO_GENERATION: no generation to re-run";
    return finish();
  }

  try {
    WorkDir dir(options.work_dir);
    EvolveOptions eo;
    eo.run_id = first.run_id;
    eo.log_path = dir.path() + "/rerun.lcmlog";
    Evolution evo(config, eo, make_evaluator(config));
    int64_t offset = 0;
    size_t next = 0;
    for (int g = 0; g < target && !r.diverged; ++g) {
      evo.step();
      ++r.generations_rerun;
      const ScannedLog fresh = scan_event_log_from(eo.log_path, offset);
      offset += fresh.end_of_events;
      for (const LogRecord& mine : fresh.contents.records) {
        if (mine.channel.rfind("ROBOZOO_", 0) != 0) continue;
        FullDifference d;
        d.index = static_cast<int64_t>(next);
        d.generation = g;
        d.rerun_eventnum = mine.eventnum;
        d.rerun_channel = mine.channel;
        if (next >= logged.size()) {
          d.channel = mine.channel;
          r.diverged = true;
          r.difference = d;
          break;
        }
        const LogRecord& theirs = *logged[next];
        d.logged_eventnum = theirs.eventnum;
        d.channel = theirs.channel;
        std::vector<uint8_t> a, b;
        std::string why_a, why_b;
        const bool ok_a = comparable(theirs, options.force, a, why_a);
        const bool ok_b = comparable(mine, options.force, b, why_b);
        if (!ok_a || !ok_b || theirs.channel != mine.channel || a != b) {
          if (!ok_a || !ok_b) {
            d.field = "(bytes)";
            d.logged = ok_a ? "a valid message" : "not a valid " + theirs.channel + " message: " + why_a;
            d.rerun = ok_b ? "a valid message" : "not a valid " + mine.channel + " message: " + why_b;
          } else if (theirs.channel == mine.channel) {
            const FieldDifference f = first_field_difference(theirs.channel, a, b);
            d.field = f.field.empty() ? "(bytes: the same values, other bits, e.g. -0 and 0)" : f.field;
            d.logged = f.a;
            d.rerun = f.b;
          }
          r.diverged = true;
          r.difference = d;
          break;
        }
        ++r.events_compared;
        ++next;
      }
      if (progress) progress(g + 1, target, seconds_since(t0));
    }
    if (!r.diverged && target == r.generations_logged && next < logged.size()) {
      FullDifference d;
      d.index = static_cast<int64_t>(next);
      d.generation = target - 1;
      d.logged_eventnum = logged[next]->eventnum;
      d.channel = logged[next]->channel;
      r.diverged = true;
      r.difference = d;
    }
  } catch (const std::exception& e) {
    r.fatal = std::string("the re-run failed: ") + e.what();
  }
  return finish();
}

std::string format_full_text(const FullCheckReport& r) {
  std::ostringstream o;
  o << "robozoo-replay check --full " << r.log_path;
  if (!r.run_id.empty())
    o << ": run " << r.run_id << " (robozoo " << r.software_version << ", " << r.regime << ", seed " << r.seed << "), "
      << r.generations_logged << " generations logged";
  o << "\n";
  if (!r.fatal.empty()) o << "UNUSABLE: " << r.fatal << "\n";
  for (const auto& p : r.input_problems) o << "input: " << p << "\n";
  if (r.diverged) o << "DIVERGED " << r.difference.describe() << "\n";
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.1f", r.seconds);
  o << "summary: " << r.generations_rerun << " generations re-run, " << r.events_compared
    << " messages equal (utime and timings left out)" << (r.diverged ? " before the first difference" : "") << "; "
    << secs << " s; exit " << r.exit_code() << "\n";
  return o.str();
}

nlohmann::json to_json(const FullCheckReport& r) {
  using nlohmann::json;
  json j;
  j["log"] = r.log_path;
  j["run_id"] = r.run_id;
  j["software_version"] = r.software_version;
  j["seed"] = r.seed;
  j["regime"] = r.regime;
  j["generations_logged"] = r.generations_logged;
  j["generations_rerun"] = r.generations_rerun;
  j["events_equal"] = r.events_compared;
  j["left_out"] = {"utime", "generation_t.eval_seconds", "generation_t.generation_seconds"};
  j["fatal"] = r.fatal.empty() ? json(nullptr) : json(r.fatal);
  j["input_problems"] = r.input_problems;
  if (r.diverged) {
    const FullDifference& d = r.difference;
    j["difference"] = {{"generation", d.generation},
                       {"index", d.index},
                       {"logged_eventnum", d.logged_eventnum >= 0 ? json(d.logged_eventnum) : json(nullptr)},
                       {"rerun_eventnum", d.rerun_eventnum >= 0 ? json(d.rerun_eventnum) : json(nullptr)},
                       {"channel", d.channel},
                       {"rerun_channel", d.rerun_channel},
                       {"field", d.field},
                       {"logged", d.logged},
                       {"rerun", d.rerun},
                       {"text", d.describe()}};
  } else {
    j["difference"] = nullptr;
  }
  j["seconds"] = r.seconds;
  j["exit_code"] = r.exit_code();
  return j;
}

}  // namespace robozoo::replay
