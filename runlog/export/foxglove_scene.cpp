#include "runlog/export/foxglove_scene.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "runlog/robots/leaf_spheres.hpp"

namespace robozoo {

namespace {

using nlohmann::json;

json vec3(double x, double y, double z) { return {{"x", x}, {"y", y}, {"z", z}}; }
json rgba(double r, double g, double b, double a = 1.0) { return {{"r", r}, {"g", g}, {"b", b}, {"a", a}}; }
json identity_pose(double x, double y, double z) {
  return {{"position", vec3(x, y, z)}, {"orientation", {{"x", 0.0}, {"y", 0.0}, {"z", 0.0}, {"w", 1.0}}}};
}
json time_of(uint64_t ns) { return {{"sec", ns / 1000000000ull}, {"nsec", ns % 1000000000ull}}; }

json entity(const std::string& id, uint64_t ns) {
  return {{"timestamp", time_of(ns)},
          {"frame_id", "world"},
          {"id", id},
          {"lifetime", {{"sec", 0}, {"nsec", 0}}},
          {"frame_locked", false},
          {"metadata", json::array()},
          {"arrows", json::array()},
          {"cubes", json::array()},
          {"spheres", json::array()},
          {"cylinders", json::array()},
          {"lines", json::array()},
          {"triangles", json::array()},
          {"texts", json::array()},
          {"models", json::array()}};
}

// Colours of robozoo-render's scene (render/scene.hpp), as fractions.
json leaf_colour() { return rgba(214 / 255.0, 44 / 255.0, 36 / 255.0); }
json inner_colour() { return rgba(40 / 255.0, 88 / 255.0, 204 / 255.0); }
json ground_colour() { return rgba(206 / 255.0, 204 / 255.0, 198 / 255.0); }
json target_colour() { return rgba(240 / 255.0, 176 / 255.0, 32 / 255.0); }

// Schema pieces, with Foxglove's titles and required fields.
json number() { return {{"type", "number"}}; }
json object(const std::string& title, const json& properties) {
  json required = json::array();
  for (const auto& [key, value] : properties.items()) required.push_back(key);
  return {{"title", title}, {"type", "object"}, {"properties", properties}, {"required", required}};
}
json vec3_schema() { return object("foxglove.Vector3", {{"x", number()}, {"y", number()}, {"z", number()}}); }
json pose_schema() {
  return object("foxglove.Pose",
                {{"position", vec3_schema()},
                 {"orientation", object("foxglove.Quaternion",
                                        {{"x", number()}, {"y", number()}, {"z", number()}, {"w", number()}})}});
}
json color_schema() {
  return object("foxglove.Color", {{"r", number()}, {"g", number()}, {"b", number()}, {"a", number()}});
}
json time_schema(bool duration) {
  json sec = {{"type", "integer"}};
  if (!duration) sec["minimum"] = 0;
  return object(duration ? "duration" : "time",
                {{"sec", sec}, {"nsec", {{"type", "integer"}, {"minimum", 0}, {"maximum", 999999999}}}});
}
json array_of(const json& items) { return {{"type", "array"}, {"items", items}}; }
json any_object_array() { return array_of({{"type", "object"}}); }

}  // namespace

json scene_update(const morphology_t& morphology, const pose_t& pose, const Eigen::Vector3d& target, uint64_t time_ns,
                  const SceneStyleParams& style) {
  if (pose.num_spheres != morphology.num_spheres ||
      static_cast<int32_t>(morphology.spheres.size()) != morphology.num_spheres)
    throw std::invalid_argument("pose of genome " + std::to_string(pose.genome_id) + " has " +
                                std::to_string(pose.num_spheres) + " spheres, its morphology " +
                                std::to_string(morphology.num_spheres));
  const std::vector<bool> leaves = leaf_spheres(morphology);
  json robot = entity("robot", time_ns);
  robot["metadata"] = json::array({{{"key", "run_id"}, {"value", pose.run_id}},
                                   {{"key", "generation"}, {"value", std::to_string(pose.generation)}},
                                   {{"key", "genome_id"}, {"value", std::to_string(pose.genome_id)}},
                                   {{"key", "step"}, {"value", std::to_string(pose.step)}}});
  for (int32_t i = 0; i < pose.num_spheres; ++i) {
    const double d = 2.0 * morphology.spheres[i].radius;
    const auto& c = pose.sphere_center[i];
    robot["spheres"].push_back({{"pose", identity_pose(c[0], c[1], c[2])},
                                {"size", vec3(d, d, d)},
                                {"color", leaves[i] ? leaf_colour() : inner_colour()}});
  }
  const double x0 = std::min(0.0, target.x()) - style.ground_margin,
               x1 = std::max(0.0, target.x()) + style.ground_margin;
  const double y0 = std::min(0.0, target.y()) - style.ground_margin,
               y1 = std::max(0.0, target.y()) + style.ground_margin;
  json ground = entity("ground", time_ns);
  ground["cubes"].push_back({{"pose", identity_pose((x0 + x1) / 2, (y0 + y1) / 2, -style.ground_thickness / 2)},
                             {"size", vec3(x1 - x0, y1 - y0, style.ground_thickness)},
                             {"color", ground_colour()}});
  json mark = entity("target", time_ns);
  const double td = 2.0 * style.target_radius;
  mark["spheres"].push_back({{"pose", identity_pose(target.x(), target.y(), target.z() + style.target_radius)},
                             {"size", vec3(td, td, td)},
                             {"color", target_colour()}});
  return {{"deletions", json::array()}, {"entities", json::array({robot, ground, mark})}};
}

json scene_update_schema() {
  const json primitive_array = any_object_array();
  json sphere =
      object("foxglove.SpherePrimitive", {{"pose", pose_schema()}, {"size", vec3_schema()}, {"color", color_schema()}});
  json cube =
      object("foxglove.CubePrimitive", {{"pose", pose_schema()}, {"size", vec3_schema()}, {"color", color_schema()}});
  json entity_schema = object(
      "foxglove.SceneEntity",
      {{"timestamp", time_schema(false)},
       {"frame_id", {{"type", "string"}}},
       {"id", {{"type", "string"}}},
       {"lifetime", time_schema(true)},
       {"frame_locked", {{"type", "boolean"}}},
       {"metadata",
        array_of(object("foxglove.KeyValuePair", {{"key", {{"type", "string"}}}, {"value", {{"type", "string"}}}}))},
       {"arrows", primitive_array},
       {"cubes", array_of(cube)},
       {"spheres", array_of(sphere)},
       {"cylinders", primitive_array},
       {"lines", primitive_array},
       {"triangles", primitive_array},
       {"texts", primitive_array},
       {"models", primitive_array}});
  json deletion =
      object("foxglove.SceneEntityDeletion",
             {{"timestamp", time_schema(false)}, {"type", {{"type", "integer"}}}, {"id", {{"type", "string"}}}});
  return object(kSceneUpdateSchemaName, {{"deletions", array_of(deletion)}, {"entities", array_of(entity_schema)}});
}

}  // namespace robozoo
