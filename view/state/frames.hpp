#pragma once
// The messages robozoo-view sends to its page, as JSON text frames. Every
// frame is an object whose "t" names its kind:
//   hello      mode ("live" or "log"), source, version
//   run        the run's facts: id, regime, seed, population, generations, steps, dt, target, version
//   gen        one generation: best, mean, best-so-far, species, evaluations, timings, outcome counts
//   history    {"gens": [gen...]}: every generation so far (sent to a joining page)
//   champions  {"list": [{id, gen, fitness}...]}: the run's distinct champions so far
//   champion   one more distinct champion {id, gen, fitness}
//   robot      the robot now shown: id, gen, fitness, radius[], leaf[], start[] (x,y,z per sphere),
//              sensor_type[], sensor_sphere[], neurons, sensors, live (its poses are still coming),
//              replay (asked for), cppn {nodes: [{id, kind, act, pos}], links: [{inn, from, to, w, on}]}
//              (the genome's nodes with kind, activation code and drawing position as in
//              cppn_node_t; its links, disabled ones with on = false)
//   pose       one sample: id, step, time (s), utime (us, when it was published), c[] (x,y,z per
//              sphere), n[] neuron outputs, s[] sensor values
//   poses      {"id", "list": [pose...], "done", "resimulated"}: many samples at once
//   stats      counters: dropped poses (this page), bad bus messages, messages, pages connected
//   error      {"what"}: a request the server could not answer
// Positions are rounded to 0.1 mm and neuron/sensor values to 1e-4: the page
// draws, it does not check.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "robozoo/generation_t.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"
#include "runlog/robots/trajectory.hpp"

namespace robozoo::view {

/// A frame as sent: shared by every page it goes to.
using Frame = std::shared_ptr<const std::string>;

Frame make_frame(const nlohmann::json& j);

nlohmann::json hello_json(const std::string& mode, const std::string& source);
/// `target`: the run's target position (m).
nlohmann::json run_json(const run_t& run, const double target[3]);
nlohmann::json generation_json(const generation_t& g);
nlohmann::json champion_json(const cppn_genome_t& g);
nlohmann::json robot_json(const cppn_genome_t& g, const morphology_t& m, bool live, bool replay);
nlohmann::json pose_json(const pose_t& p);
/// Samples of a trajectory (no utime: not published live).
nlohmann::json trajectory_json(int64_t genome_id, const Trajectory& t);

}  // namespace robozoo::view
