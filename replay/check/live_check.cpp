#include "replay/check/live_check.hpp"

#include <lcm/lcm-cpp.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <deque>
#include <mutex>
#include <thread>

#include "evolve/config/run_config.hpp"
#include "evolve/io/bus.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/run/trajectory.hpp"
#include "replay/check/check_report.hpp"
#include "replay/log/logged_config.hpp"
#include "replay/compare/number_text.hpp"
#include "replay/check/recompute_cache.hpp"
#include "runlog/read/log_index.hpp"
#include "runlog/robots/regrow.hpp"

namespace robozoo::replay {

/// What one run has sent so far.
struct LiveChecker::Run {
  std::string id;
  bool usable = false;
  RunConfig config;
  run_t first{};
  std::vector<LogRecord> block;  ///< the open generation's messages (its run_t first)
  bool block_has_generation = false;
  int32_t block_generation = -1;
  int32_t next_generation = -1;  ///< -1: none seen yet
  bool key_known = false;        ///< the previous generation's champion was received
  uint64_t last_key = 0;
  int64_t received = 0;              ///< ROBOZOO_RUN/... messages of this run received (count)
  int64_t received_at_status = -1;   ///< `received` when the last ROBOZOO_BUS arrived
  int64_t published_at_status = -1;  ///< what that status said was published
  int64_t publish_failures = 0;
  RecomputeCache cache;
};

int64_t LiveCheckSummary::count(ChampionResult::Status s) const {
  int64_t n = 0;
  for (const auto& v : verdicts) n += v.result.status == s;
  return n;
}

int64_t LiveCheckSummary::champions_with_loss() const {
  int64_t n = 0;
  for (const auto& v : verdicts) n += !v.loss.empty();
  return n;
}

int LiveCheckSummary::exit_code() const {
  if (count(ChampionResult::Status::Diverged) > 0) return 1;
  if (runs.empty() || verdicts.empty() || !problems.empty() || !loss.empty() || champions_with_loss() > 0 ||
      count(ChampionResult::Status::Unusable) > 0)
    return 2;
  return 0;
}

LiveChecker::LiveChecker(LiveCheckOptions options, std::function<void(const std::string&)> on_line)
    : options_(std::move(options)), on_line_(std::move(on_line)) {}

LiveChecker::~LiveChecker() = default;

LiveChecker::Run* LiveChecker::run_of(const std::string& run_id) {
  const auto it = runs_.find(run_id);
  return it == runs_.end() ? nullptr : it->second.get();
}

void LiveChecker::ingest(const std::string& channel, const std::vector<uint8_t>& data) {
  if (channel.rfind("ROBOZOO_", 0) != 0) return;
  ++summary_.messages;
  auto bad = [&](const std::string& why) {
    ++summary_.bad;
    if (summary_.bad <= 5) on_line_("input: a " + channel + " message skipped: " + why);
  };
  std::string why;
  if (channel == kChannelBus) {
    bus_status_t s{};
    if (!safe_decode(data.data(), data.size(), s, &why)) return bad(why);
    if (Run* r = run_of(s.run_id)) {
      r->received_at_status = r->received;
      r->published_at_status = s.messages_published;
      r->publish_failures = s.publish_failures;
    }
    return;
  }
  const EventKind kind = kind_of_channel(channel);
  if (kind == EventKind::Foreign) return;
  // Which run is it? Every robozoo message names it.
  std::string run_id;
  int32_t generation = -1;
  bool ok = false;
  if (kind == EventKind::Run) {
    run_t m{};
    ok = safe_decode(data.data(), data.size(), m, &why);
    if (ok && !run_of(m.run_id)) {
      auto run = std::make_unique<Run>();
      run->id = m.run_id;
      run->first = m;
      summary_.runs.push_back(m.run_id);
      std::string refusal = version_refusal(m);
      if (!refusal.empty() && !options_.force) {
        summary_.problems.push_back(refusal);
        on_line_("UNUSABLE run " + m.run_id + ": " + refusal);
      } else {
        try {
          run->config = config_from_run_message(m);
          for (const auto& kv : options_.sets) run->config = config_from_json(config_assignment(kv), run->config);
          validate_config(run->config);
          run->usable = true;
          on_line_("run " + m.run_id + ": robozoo " + m.software_version + ", " +
                   (m.regime == 1 ? "recurrent" : "feedforward") + ", seed " + num(m.seed) + ", population " +
                   num(m.population) + ", " + num(m.generations) + " generations" +
                   (options_.sets.empty() ? "" : " (checked with --set changes)"));
        } catch (const std::exception& e) {
          summary_.problems.push_back(e.what());
          on_line_("UNUSABLE run " + m.run_id + ": " + e.what());
        }
      }
      runs_.emplace(m.run_id, std::move(run));
    }
    run_id = m.run_id;
  } else {
    LogRecord probe;
    probe.channel = channel;
    probe.data = data;
    LogContents one;
    one.records.push_back(probe);
    const LogIndex ix = index_log(one);
    ok = ix.events.size() == 1 && ix.events[0].kind != EventKind::Undecodable;
    if (!ok && !ix.problems.empty()) why = ix.problems[0].what;
    if (ok) {
      run_id = ix.events[0].run_id;
      generation = ix.events[0].generation;
    }
  }
  if (!ok) return bad(why);
  Run* run = run_of(run_id);
  if (!run) return;  // joined mid-run: wait for the run's next ROBOZOO_RUN
  ++run->received;
  if (kind == EventKind::Run) {
    if (run->block_has_generation) close_block(*run, false);
    run->block.clear();
  } else if (kind == EventKind::Generation) {
    if (run->block_has_generation) close_block(*run, false);  // its run_t was lost
    if (run->next_generation >= 0 && generation > run->next_generation)
      summary_.loss.push_back("run " + run_id + ": generations " + num(run->next_generation) + " to " +
                              num(generation - 1) + " never arrived");
    if (run->next_generation < 0 && generation > 0)
      on_line_("joined run " + run_id + " at generation " + num(generation));
    if (run->next_generation >= 0 && generation < run->next_generation)
      summary_.problems.push_back("run " + run_id + ": generation " + num(generation) + " arrived after generation " +
                                  num(run->next_generation - 1));
    if (run->next_generation >= 0 && generation > run->next_generation) run->key_known = false;
    run->next_generation = generation + 1;
    run->block_has_generation = true;
    run->block_generation = generation;
  }
  LogRecord r;
  r.eventnum = static_cast<int64_t>(run->block.size());
  r.channel = channel;
  r.data = data;
  run->block.push_back(std::move(r));
}

void LiveChecker::close_block(Run& run, bool at_end) {
  const int32_t gen = run.block_generation;
  run.block_has_generation = false;
  LogContents contents;
  contents.records = std::move(run.block);
  run.block.clear();
  if (!run.usable) return;
  const LogIndex index = index_log(contents);
  generation_t gm{};
  for (const auto& e : index.events)
    if (e.kind == EventKind::Generation) {
      const LogRecord& rec = contents.records[e.record];
      safe_decode(rec.data.data(), rec.data.size(), gm);
    }
  const LoggedGenome* champion = nullptr;
  for (const auto& g : index.genomes)
    if (g.genome_id == gm.champion_id && g.generation == gen) champion = &g;
  LiveVerdict v;
  if (!champion) {
    v.result.run_id = run.id;
    v.result.generation = gen;
    v.result.genome_id = gm.champion_id;
    v.result.status = ChampionResult::Status::Ok;
    v.loss.push_back("its genome never arrived" + std::string(at_end ? " (the input ended)" : ""));
    run.key_known = false;
  } else {
    // Was a trajectory due? As robozoo-evolve decides it (trajectory_key).
    cppn_genome_t m{};
    const LogRecord& rec = contents.records[index.events[champion->genome_event].record];
    safe_decode(rec.data.data(), rec.data.size(), m);
    uint64_t key = 0;
    bool key_ok = false;
    try {
      key = trajectory_key(logged_genes(m));
      key_ok = true;
    } catch (const std::exception&) {
    }
    const bool changed = !(run.key_known && key_ok && key == run.last_key);
    const bool simulated = m.outcome != static_cast<int8_t>(Outcome::NotSimulated);
    const bool due = changed && simulated;
    ChampionCheckParams params;
    params.tolerance = options_.tolerance;
    params.keep = options_.keep;
    v.result = check_champion(contents, index, *champion, run.config, params, &run.cache,
                              due || !champion->pose_events.empty() ? TrajectoryRule::Lossy : TrajectoryRule::None);
    run.last_key = key;
    run.key_known = key_ok;
    if (std::memcmp(&m.fitness, &gm.best_fitness, sizeof m.fitness) != 0 &&
        v.result.status != ChampionResult::Status::Unusable) {
      // generation_t's best fitness must be the champion's.
      v.result.status = ChampionResult::Status::Diverged;
      v.result.mismatches.insert(v.result.mismatches.begin(),
                                 Mismatch{"generation", -1, "", "best_fitness", exact_text(gm.best_fitness),
                                          exact_text(m.fitness), std::numeric_limits<double>::infinity()});
      ++v.result.mismatch_count;
    }
    // What the bus lost is loss, not a problem of the input.
    std::vector<std::string> problems;
    for (const auto& p : v.result.problems) {
      if (p.find("morphology is not in the log") != std::string::npos)
        v.loss.push_back("its morphology never arrived");
      else
        problems.push_back(p);
    }
    v.result.problems = problems;
    if (v.result.status == ChampionResult::Status::Unusable && problems.empty() && v.result.mismatch_count == 0)
      v.result.status = ChampionResult::Status::Ok;
    if (due && champion->pose_events.empty())
      v.loss.push_back("its trajectory never arrived");
    else if (v.result.poses_missing > 0)
      v.loss.push_back(num(v.result.poses_missing) + " of " + num(v.result.poses_expected) +
                       " poses of its trajectory never arrived");
  }
  std::string line = champion_line(v.result, runs_.size() > 1);
  if (!v.loss.empty()) {
    line += "  BUS LOSS:";
    for (const auto& l : v.loss) line += " " + l + ";";
    line.pop_back();
  }
  on_line_(line);
  summary_.verdicts.push_back(std::move(v));
}

void LiveChecker::finish() {
  for (auto& [id, run] : runs_) {
    if (run->block_has_generation) close_block(*run, true);
    if (run->published_at_status > run->received_at_status)
      summary_.loss.push_back("run " + id + ": the publisher had sent " + num(run->published_at_status) +
                              " messages at its last ROBOZOO_BUS status, " + num(run->received_at_status) +
                              " of them arrived");
    if (run->publish_failures > 0)
      summary_.loss.push_back("run " + id + ": the publisher counted " + num(run->publish_failures) +
                              " publish failures");
  }
}

LiveCheckSummary check_live(const std::string& url, const LiveCheckOptions& options, double idle_exit,
                            const std::function<bool()>& should_stop, std::ostream& out, std::ostream& log) {
  using Clock = std::chrono::steady_clock;
  Bus bus(url);  // throws naming the URL
  struct Queue {
    std::mutex m;
    std::condition_variable cv;
    std::deque<std::pair<std::string, std::vector<uint8_t>>> items;
    Clock::time_point last = Clock::now();
    bool any = false;
    // A plain function, not a member: LCM's pointer-to-member subscribe is
    // instrumented wrongly by GCC 12's sanitizers (see render/live.cpp).
    static void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Queue* self) {
      const auto* p = static_cast<const uint8_t*>(rbuf->data);
      std::lock_guard<std::mutex> lock(self->m);
      self->items.emplace_back(channel, std::vector<uint8_t>(p, p + rbuf->data_size));
      self->last = Clock::now();
      self->any = true;
      self->cv.notify_one();
    }
  } queue;
  lcm::Subscription* subscription = bus.lcm().subscribeFunction("ROBOZOO_.*", &Queue::on_message, &queue);
  if (subscription) subscription->setQueueCapacity(kSubscriberQueueMessages);
  log << "robozoo-replay: check --lcm-url: listening on " << url << std::endl;
  std::atomic<bool> stop{false};
  std::string receiver_error;
  std::thread receiver([&] {
    while (!stop.load()) {
      if (bus.lcm().handleTimeout(50) < 0) {
        receiver_error = "LCM stopped reading " + url;
        stop = true;
      }
    }
  });
  LiveChecker checker(options, [&](const std::string& line) { out << line << std::endl; });
  const auto started = Clock::now();
  for (;;) {
    std::deque<std::pair<std::string, std::vector<uint8_t>>> batch;
    Clock::time_point last;
    bool any;
    {
      std::unique_lock<std::mutex> lock(queue.m);
      queue.cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return !queue.items.empty(); });
      batch.swap(queue.items);
      last = queue.last;
      any = queue.any;
    }
    for (const auto& [channel, data] : batch) checker.ingest(channel, data);
    if (!batch.empty()) continue;
    if (stop.load() || should_stop()) break;
    const double quiet = std::chrono::duration<double>(Clock::now() - (any ? last : started)).count();
    if (idle_exit > 0 && !checker.summary().runs.empty() && quiet > idle_exit) {
      log << "robozoo-replay: no message for " << idle_exit << " s: finishing" << std::endl;
      break;
    }
  }
  stop = true;
  receiver.join();
  {
    // What arrived before the stop is still checked.
    std::lock_guard<std::mutex> lock(queue.m);
    for (const auto& [channel, data] : queue.items) checker.ingest(channel, data);
  }
  if (!receiver_error.empty()) throw std::runtime_error(receiver_error);
  checker.finish();
  return checker.summary();
}

std::string format_live_summary(const LiveCheckSummary& s) {
  std::string o = "summary: " + num(static_cast<int64_t>(s.verdicts.size())) +
                  " champions checked: " + num(s.count(ChampionResult::Status::Ok)) + " ok, " +
                  num(s.count(ChampionResult::Status::Diverged)) + " diverged, " +
                  num(s.count(ChampionResult::Status::Unusable)) + " unusable, " + num(s.champions_with_loss()) +
                  " with bus loss; " + num(s.messages) + " messages received, " + num(s.bad) + " bad";
  for (const auto& l : s.loss) o += "\nbus loss: " + l;
  for (const auto& p : s.problems) o += "\ninput: " + p;
  if (s.runs.empty()) o += "\ninput: no ROBOZOO_RUN arrived: nothing was checked";
  o += "\nexit " + num(s.exit_code()) + "\n";
  return o;
}

}  // namespace robozoo::replay
