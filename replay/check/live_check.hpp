#pragma once
// `robozoo-replay check --lcm-url`: a replay process that joins a running
// evolution on the bus and proves each champion while the run goes on. As each generation's messages are complete (the next ROBOZOO_RUN
// or ROBOZOO_GENERATION of its run arrives, or the input ends), its champion is
// re-grown, re-simulated and re-evaluated with the configuration of the run's
// ROBOZOO_RUN, exactly as `check` does for a log, and a verdict line is printed.
//
// UDP multicast loses messages; loss is not divergence. What never arrived is
// reported as bus loss: a generation whose messages are missing, a champion's
// genome, morphology or whole trajectory, poses missing from a trajectory (the
// ones received must still be in order and agree bit for bit), and the
// difference between the ROBOZOO_RUN/... messages the publisher says it sent
// (ROBOZOO_BUS, bus_status_t) and those received. A value that differs is a
// divergence.
//
// Exit status as `check`: 0 every champion received agrees and nothing was lost;
// 1 a divergence; 2 unusable input (no run seen, a refused version or
// configuration) or bus loss.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/io/event_log.hpp"
#include "replay/check/champion_check.hpp"

namespace robozoo::replay {

struct LiveCheckOptions {
  double tolerance = 0.0;  ///< 0: bit for bit; else the largest value_error allowed (dimensionless)
  bool force = false;      ///< check runs written by another software version
  /// KEY=VALUE configuration assignments applied over each run's logged
  /// configuration before re-computing (robozoo-evolve's --set syntax): a what-if
  /// tool, and how the tests make a replay whose physics differs.
  std::vector<std::string> sets;
  size_t keep = 20;  ///< mismatches kept per champion (count)
};

/// One champion's verdict.
struct LiveVerdict {
  ChampionResult result;
  std::vector<std::string> loss;  ///< what of it never arrived (empty: all of it did)
};

struct LiveCheckSummary {
  int64_t messages = 0;           ///< ROBOZOO_* messages received (count)
  int64_t bad = 0;                ///< messages that do not decode (count), skipped
  std::vector<std::string> runs;  ///< run ids seen
  std::vector<LiveVerdict> verdicts;
  std::vector<std::string> loss;      ///< bus loss outside any champion (missing generations, the publisher's count)
  std::vector<std::string> problems;  ///< unusable input: refused versions, bad configurations, bad messages
  int64_t count(ChampionResult::Status s) const;
  int64_t champions_with_loss() const;
  int exit_code() const;
};

/// Feeds received messages in order and checks each champion as its generation
/// completes. No bus here: the tests feed it directly.
class LiveChecker {
 public:
  /// `on_line` gets each verdict line and notice as it happens.
  LiveChecker(LiveCheckOptions options, std::function<void(const std::string&)> on_line);
  ~LiveChecker();
  void ingest(const std::string& channel, const std::vector<uint8_t>& data);
  /// The input ended: checks what is still open (its missing parts are loss).
  void finish();
  const LiveCheckSummary& summary() const { return summary_; }

 private:
  struct Run;
  void close_block(Run& run, bool at_end);
  Run* run_of(const std::string& run_id);
  LiveCheckOptions options_;
  std::function<void(const std::string&)> on_line_;
  std::map<std::string, std::unique_ptr<Run>> runs_;
  LiveCheckSummary summary_;
};

/// Subscribes to ROBOZOO_.* on `url` (a thread that only queues what arrives, so
/// that checking never makes the socket overflow) and checks until
/// `should_stop()` or, once a run was seen, `idle_exit` seconds without a message
/// (0: never). Verdict lines go to `out`, notices to `log`. Throws
/// std::runtime_error naming the URL when LCM cannot start.
LiveCheckSummary check_live(const std::string& url, const LiveCheckOptions& options, double idle_exit,
                            const std::function<bool()>& should_stop, std::ostream& out, std::ostream& log);

/// The summary line: champions ok / diverged / unusable / with loss, loss, exit.
std::string format_live_summary(const LiveCheckSummary& s);

}  // namespace robozoo::replay
