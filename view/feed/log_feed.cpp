#include "view/feed/log_feed.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "runlog/play/player.hpp"
#include "runlog/read/log_index.hpp"
#include "runlog/read/log_reader.hpp"

namespace robozoo::view {

namespace {

struct Stopped {};

/// Real time that gives up its sleeps (by throwing Stopped) when told to stop.
class StoppableClock : public SteadyPlayClock {
 public:
  explicit StoppableClock(const std::function<bool()>& should_stop) : should_stop_(should_stop) {}
  void sleep_until(double t) override {
    for (;;) {
      if (should_stop_()) throw Stopped{};
      const double now_s = now();
      if (now_s >= t) return;
      SteadyPlayClock::sleep_until(std::min(t, now_s + 0.1));
    }
  }

 private:
  const std::function<bool()>& should_stop_;
};

/// Pacing of appended poses (--follow): a genome's poses at real speed.
struct Pace {
  int64_t genome = -1;
  double sim_time = 0.0;  // (s)
  double wall = 0.0;      // when that pose went in (s, clock)
};

void feed_appended(const ScannedLog& chunk, double speed, StoppableClock& clock, Pace& pace, ViewState& state) {
  const LogIndex ix = index_log(chunk.contents);
  for (const IndexedEvent& e : ix.events) {
    if (e.kind == EventKind::Pose) {
      if (e.genome_id == pace.genome && e.sim_time > pace.sim_time) {
        pace.wall += (e.sim_time - pace.sim_time) / speed;
        clock.sleep_until(pace.wall);
      } else {
        pace.wall = clock.now();
      }
      pace.genome = e.genome_id;
      pace.sim_time = e.sim_time;
    }
    const LogRecord& r = chunk.contents.records[e.record];
    state.ingest(r.channel, r.data.data(), r.data.size());
  }
}

void warn_damage(const ScannedLog& s, const std::string& path, bool growing, std::ostream& log) {
  for (const LogDamage& d : s.damage)
    if (!(growing && d.kind == LogDamage::Kind::Truncated))  // a growing log ends inside its newest event
      log << "robozoo-view: warning: " << path << ": " << d.describe() << "\n";
}

}  // namespace

void play_log(const LogFeedOptions& o, ViewState& state, const std::function<bool()>& should_stop, std::ostream& log) {
  if (!(o.speed > 0.0) || !std::isfinite(o.speed)) throw std::invalid_argument("--speed must be a positive number");
  if (o.generation < 0) throw std::invalid_argument("--generation must be >= 0");
  const ScannedLog scanned = scan_event_log(o.path);  // throws naming the path
  warn_damage(scanned, o.path, o.follow, log);
  const LogContents& contents = scanned.contents;
  const LogIndex index = index_log(contents);
  if (contents.records.empty() && !o.follow)
    throw std::runtime_error(o.path + ": no LCM events: not a robozoo-evolve log");
  StoppableClock clock(should_stop);
  const PublishFn publish = [&](const std::string& channel, const std::vector<uint8_t>& data) {
    state.ingest(channel, data.data(), data.size());
    return true;
  };
  PlayOptions po;
  po.speed = o.speed;
  po.start_generation = o.generation;
  try {
    for (int pass = 0; !contents.records.empty(); ++pass) {
      if (pass > 0) state.restart();
      if (o.generation > 0) {  // the generations before G at once: the chart starts with them
        const std::vector<PlannedEvent> plan = plan_pass(contents, index, po);
        size_t first = contents.records.size();
        for (const PlannedEvent& e : plan)
          if (!e.state) {
            first = e.record;
            break;
          }
        state.set_quiet(true);  // pages get the result at once, not every pose of it
        for (size_t i = 0; i < first; ++i) publish(contents.records[i].channel, contents.records[i].data);
        state.set_quiet(false);
      }
      log << "robozoo-view: playing " << o.path << (pass > 0 ? " again" : "") << std::endl;
      play(contents, index, po, clock, publish);
      if (!o.loop) break;
    }
    if (!o.follow) {
      state.end_of_input();
      log << "robozoo-view: end of " << o.path << std::endl;
      if (o.exit_at_end) return;
      for (;;) clock.sleep_until(clock.now() + 3600);  // until told to stop
    }
    log << "robozoo-view: following " << o.path << " as it grows" << std::endl;
    int64_t offset = scanned.end_of_events;
    Pace pace;
    for (;;) {
      clock.sleep_until(clock.now() + o.poll_seconds);
      const ScannedLog chunk = scan_event_log_from(o.path, offset);
      if (chunk.contents.records.empty()) continue;
      warn_damage(chunk, o.path, true, log);
      feed_appended(chunk, o.speed, clock, pace, state);
      offset += chunk.end_of_events;
    }
  } catch (const Stopped&) {
  }
}

}  // namespace robozoo::view
