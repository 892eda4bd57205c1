#pragma once
// Contacts between the robot and the ground and between its own parts
// (docs/method.md section 2). Never between spheres of one body, nor between the
// spheres of two bodies joined directly by a joint. Contacts are found in a
// fixed order (ground contacts by sphere index, then sphere pairs (i, j), i < j,
// in lexicographic order), so that the constraint order handed to ODE never
// depends on pointers or on a space's internal lists.
#include <utility>
#include <vector>

#include <ode/ode.h>

#include "evolve/growth/robot.hpp"
#include "evolve/sim/params.hpp"
#include "evolve/sim/setup/world.hpp"

namespace robozoo {

struct Contact {
  dContactGeom geom;  ///< as dCollide reports it (g1, g2 and the normal's sense)
  int sphere_a = 0;   ///< the robot sphere of the contact
  int sphere_b = -1;  ///< the other sphere, -1 for the ground
};

class ContactFinder {
 public:
  /// Precomputes the sphere pairs that may collide.
  explicit ContactFinder(const Robot& robot);

  /// Finds this instant's contacts into `out` (cleared first) and marks, per
  /// sphere, touching (any contact) and on_ground (a ground contact).
  void find(const OdeWorld& world, const SimParams& params, std::vector<Contact>& out, std::vector<uint8_t>& touching,
            std::vector<uint8_t>& on_ground) const;

  /// The pairs (i, j), i < j, that may collide, in the order they are tested.
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }

 private:
  std::vector<std::pair<int, int>> pairs_;
  std::vector<double> radius_;
  mutable std::vector<double> center_;  // scratch: each sphere's centre, read once per find
};

/// Creates one soft contact joint per contact in the world's contact group
/// (dContactSoftERP | dContactSoftCFM | dContactApprox1, friction mu).
void add_contact_joints(const OdeWorld& world, const SimParams& params, const std::vector<Contact>& contacts);

}  // namespace robozoo
