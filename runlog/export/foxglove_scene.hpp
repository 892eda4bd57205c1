#pragma once
// A robot's pose as a Foxglove foxglove.SceneUpdate (JSON, for Foxglove's 3D
// panel): one entity "robot" with one sphere per robot sphere (leaves red,
// others blue, as robozoo-render draws them), one "ground" (a thin cube) and
// one "target" (a sphere); and the JSON Schema of that message, with
// Foxglove's names and fields (SceneUpdate, SceneEntity, SpherePrimitive, ...).
#include <cstdint>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"

namespace robozoo {

struct SceneStyleParams {
  double ground_margin = 10.0;     ///< ground reaches this far beyond the start and the target (m)
  double ground_thickness = 0.02;  ///< thickness of the ground cube, its top at z = 0 (m)
  double target_radius = 0.25;     ///< radius of the target's sphere (m)
};

/// Schema name and encoding as Foxglove expects them.
inline constexpr const char* kSceneUpdateSchemaName = "foxglove.SceneUpdate";

/// The SceneUpdate of `pose` of the robot `morphology` (same sphere count, else
/// std::invalid_argument), at `time_ns`, with the run's target.
nlohmann::json scene_update(const morphology_t& morphology, const pose_t& pose, const Eigen::Vector3d& target,
                            uint64_t time_ns, const SceneStyleParams& style = {});

/// The JSON Schema of foxglove.SceneUpdate.
nlohmann::json scene_update_schema();

}  // namespace robozoo
