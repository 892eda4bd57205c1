#pragma once
// The page of one trial of robozoo-view --experiment (/trial?name=T), as one
// self-contained replay: the trial's newest champion from its log (a growing
// log's complete events), or, for a trial known only from its compact result
// (finished on another machine), its best-of-run robot grown, evaluated and
// simulated again by this build in memory (evolve/run/champion_log's replay_champion, the code
// robozoo-evolve champion writes its logs with). When this build does not give the
// committed fitness, r, d or outcome, the answer says so and shows nothing.
#include <string>

#include "view/serve/assets.hpp"
#include "view/feed/experiment_watch.hpp"
#include "view/serve/server.hpp"

namespace robozoo::view {

/// 200 with the page; 404 with one line for an unknown trial, or a log or
/// result that gives no champion (the reason).
HttpReply trial_page(const ExperimentWatch& watch, const AssetDirs& dirs, const std::string& name);

}  // namespace robozoo::view
