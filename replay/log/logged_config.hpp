#pragma once
// The configuration of a logged run comes from its ROBOZOO_RUN and nowhere
// else: every key must be in run_t.config_json (none is filled in from this
// build's defaults, which may have changed), and run_t's own fields must agree
// with it.
#include <string>

#include "evolve/config/run_config.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo::replay {

/// Throws std::invalid_argument naming the run and the problem: config_json is
/// not JSON, lacks a key, holds an invalid value, or disagrees with run_t's
/// seed, regime, population, generations, steps or dt.
RunConfig config_from_run_message(const run_t& m);

/// Empty when `m` was written by this build's software version; otherwise the
/// sentence that refuses it (a different version may grow or simulate differently).
std::string version_refusal(const run_t& m);

}  // namespace robozoo::replay
