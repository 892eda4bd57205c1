#include "evolve/growth/finish/vertical_shift.hpp"

namespace robozoo {

double rest_on_ground(Robot& robot) {
  if (robot.spheres.empty()) return 0.0;
  const Sphere* largest = &robot.spheres.front();
  for (const Sphere& s : robot.spheres)
    if (s.radius > largest->radius) largest = &s;  // strict: ties keep the earlier
  const double dz = largest->radius - largest->center.z();
  for (Sphere& s : robot.spheres) s.center.z() += dz;
  robot.vertical_shift += dz;
  return dz;
}

}  // namespace robozoo
