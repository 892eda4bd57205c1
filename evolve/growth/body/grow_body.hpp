#pragma once
// Growth steps 1-4 (paper 2.3; docs/method.md section 2): the root, then clouds cast
// around spheres taken from a max-priority queue, spheres placed by rules
// (a)-(d), each with its joint, motor neuron and sensors.
#include "evolve/growth/body/cppn_probe.hpp"
#include "evolve/growth/body/grown_body.hpp"
#include "evolve/growth/params.hpp"

namespace robozoo {

/// 1. Root at the origin, radius r_init; its sensors (never proprioceptive) from a
///    query at its centre with r_parent = r_init; its density from that query's m
///    (sphere_density: rho_min when m <= T_matter, since the root exists regardless).
/// 2. Pop the sphere with the largest m (ties: earliest created); query the CPPN at
///    its cloud points (r_parent = its radius, no one-hot).
/// 3. Visit the points with m > T_matter by m descending, ties by k ascending (the
///    stable order of the cloud); for each: r = sphere_radius, jointed iff
///    j > T_joint, placed iff Placement::admissible (rules (b), (c), (d)).
/// 4. A placed sphere gets density, joint (axis, range) and motor neuron when
///    jointed, sensors, its cloud_angle_index, and enters the queue. Stops as soon
///    as max_spheres are placed, or when the queue is empty.
/// Assumes validated params (see validate_growth_params).
GrownBody grow_body(CppnProbe& probe, const GrowthParams& params);

}  // namespace robozoo
