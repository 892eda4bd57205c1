// grow(): growth steps 1-7 of docs/method.md section 2, one stage per file.
#include "evolve/growth/growth.hpp"

#include "evolve/growth/finish/assemble.hpp"
#include "evolve/growth/body/cppn_probe.hpp"
#include "evolve/growth/body/grow_body.hpp"
#include "evolve/growth/finish/prune.hpp"
#include "evolve/growth/finish/vertical_shift.hpp"
#include "evolve/growth/finish/weights.hpp"

namespace robozoo {

Robot grow(Network& cppn, const GrowthParams& params) {
  validate_growth_params(params);
  CppnProbe probe(cppn, params.bias_input);
  GrownBody body = grow_body(probe, params);  // steps 1-4
  prune_leaf_joints(body);                    // step 5
  Robot robot = assemble_robot(body);
  set_ctrnn_weights(robot, probe, params);  // step 6, in the growth frame
  score_r_term(robot);                      // paper 2.4
  rest_on_ground(robot);                    // step 7
  return robot;
}

}  // namespace robozoo
