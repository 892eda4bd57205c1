#include "runlog/play/player.hpp"

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>

namespace robozoo {

namespace {

bool has_generation(EventKind k) {
  return k == EventKind::Generation || k == EventKind::Genome || k == EventKind::Morphology || k == EventKind::Pose;
}

/// First event of the pass: the first of generation >= g, with the run and
/// foreign events just before it (a generation opens with its ROBOZOO_RUN).
size_t start_event(const LogIndex& index, int32_t g) {
  if (g <= 0) return 0;
  size_t i = 0;
  int32_t last = -1;
  while (i < index.events.size() && !(has_generation(index.events[i].kind) && index.events[i].generation >= g)) {
    if (has_generation(index.events[i].kind)) last = std::max(last, index.events[i].generation);
    ++i;
  }
  if (i == index.events.size())
    throw std::invalid_argument("--start-generation " + std::to_string(g) + ": the log's last generation is " +
                                std::to_string(last));
  while (i > 0 && !has_generation(index.events[i - 1].kind)) --i;
  return i;
}

}  // namespace

std::vector<PlannedEvent> plan_pass(const LogContents& log, const LogIndex& index, const PlayOptions& o) {
  if (!(o.speed > 0.0) || !std::isfinite(o.speed)) throw std::invalid_argument("--speed must be a positive number");
  std::regex channels;
  try {
    channels = std::regex(o.channels, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument("--channels '" + o.channels + "' is not a regular expression: " + e.what());
  }
  const size_t start = start_event(index, o.start_generation);

  using Key = std::pair<std::string, int64_t>;
  std::map<std::string, size_t> latest_run;
  std::map<Key, size_t> latest_genome, latest_morphology;
  std::set<std::string> sent_run;
  std::set<Key> sent_genome, sent_morphology;
  struct LastPose {
    double t;
    double sim_time;
  };
  std::map<Key, LastPose> last_pose;
  std::map<std::string, bool> matches;  // channel -> selected (one regex match per channel name)

  std::vector<PlannedEvent> plan;
  double t = 0.0;  // play time of the current event, before the speed (s)
  int64_t prev_ts = 0;
  bool first = true;
  for (size_t i = 0; i < index.events.size(); ++i) {
    const IndexedEvent& e = index.events[i];
    const LogRecord& r = log.records[e.record];
    const Key key{e.run_id, e.genome_id};
    if (i >= start) {
      if (!first) t += std::max<int64_t>(0, r.timestamp - prev_ts) * 1e-6;
      first = false;
      prev_ts = r.timestamp;
      if (e.kind == EventKind::Pose && o.pace_poses_by_sim_time) {
        const auto lp = last_pose.find(key);
        if (lp != last_pose.end() && e.sim_time > lp->second.sim_time)
          t = std::max(t, lp->second.t + (e.sim_time - lp->second.sim_time));
        last_pose[key] = {t, e.sim_time};
      }
      auto m = matches.find(r.channel);
      if (m == matches.end())
        m = matches.emplace(r.channel, r.channel != "LCM_SELF_TEST" && std::regex_match(r.channel, channels)).first;
      const bool selected = e.kind != EventKind::Undecodable && m->second;
      if (selected) {
        if (e.kind == EventKind::Pose) {  // state first
          auto send_state = [&](auto& latest, auto& sent, const auto& k) {
            if (sent.count(k)) return;
            const auto it = latest.find(k);
            if (it == latest.end()) return;
            plan.push_back({index.events[it->second].record, t / o.speed, true});
            sent.insert(k);
          };
          send_state(latest_run, sent_run, e.run_id);
          send_state(latest_genome, sent_genome, key);
          send_state(latest_morphology, sent_morphology, key);
        }
        plan.push_back({e.record, t / o.speed, false});
        if (e.kind == EventKind::Run) sent_run.insert(e.run_id);
        if (e.kind == EventKind::Genome) sent_genome.insert(key);
        if (e.kind == EventKind::Morphology) sent_morphology.insert(key);
      }
    }
    if (e.kind == EventKind::Run) latest_run[e.run_id] = i;
    if (e.kind == EventKind::Genome) latest_genome[key] = i;
    if (e.kind == EventKind::Morphology) latest_morphology[key] = i;
  }
  if (plan.empty())
    throw std::invalid_argument(
        "no event of the log matches --channels '" + o.channels + "'" +
        (o.start_generation > 0 ? " from generation " + std::to_string(o.start_generation) : ""));
  return plan;
}

PlayStats play(const LogContents& log, const LogIndex& index, const PlayOptions& o, PlayClock& clock,
               const PublishFn& publish) {
  const std::vector<PlannedEvent> plan = plan_pass(log, index, o);
  PlayStats stats;
  do {
    const double t0 = clock.now();
    for (const auto& p : plan) {
      clock.sleep_until(t0 + p.at);
      const LogRecord& r = log.records[p.record];
      if (!publish(r.channel, r.data)) ++stats.publish_failures;
      ++stats.events_sent;
      stats.state_events_sent += p.state;
    }
    ++stats.passes;
  } while (o.loop && (o.max_passes <= 0 || stats.passes < o.max_passes));
  return stats;
}

}  // namespace robozoo
