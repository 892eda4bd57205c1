#include "runlog/export/foxglove_scene.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace robozoo {
namespace {

// A root with two children, the second of which has a child: leaves are 1 and 3.
morphology_t robot() {
  morphology_t m{};
  m.num_spheres = 4;
  m.spheres.resize(4);
  const int parents[] = {-1, 0, 0, 2};
  for (int i = 0; i < 4; ++i) {
    m.spheres[i].index = i;
    m.spheres[i].parent = parents[i];
    m.spheres[i].radius = 0.1 * (i + 1);
  }
  return m;
}

pose_t pose() {
  pose_t p{};
  p.run_id = "r";
  p.genome_id = 9;
  p.step = 40;
  p.num_spheres = 4;
  p.sphere_center = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {0, 2, 3}};
  return p;
}

TEST(FoxgloveScene, OneSpherePerRobotSphereAtItsCentreAndSize) {
  const nlohmann::json s = scene_update(robot(), pose(), {20, -4, 0}, 3'500'000'123ull);
  ASSERT_EQ(s["entities"].size(), 3u);
  const auto& r = s["entities"][0];
  EXPECT_EQ(r["id"], "robot");
  EXPECT_EQ(r["frame_id"], "world");
  EXPECT_EQ(r["timestamp"]["sec"], 3);
  EXPECT_EQ(r["timestamp"]["nsec"], 500'000'123);
  ASSERT_EQ(r["spheres"].size(), 4u);
  EXPECT_EQ(r["spheres"][3]["pose"]["position"]["y"], 2.0);
  EXPECT_EQ(r["spheres"][3]["pose"]["position"]["z"], 3.0);
  EXPECT_DOUBLE_EQ(r["spheres"][2]["size"]["x"].get<double>(), 0.6);  // diameter of radius 0.3
  EXPECT_EQ(r["spheres"][0]["pose"]["orientation"]["w"], 1.0);
}

TEST(FoxgloveScene, LeavesRedOthersBlue) {
  const nlohmann::json scene = scene_update(robot(), pose(), {50, 0, 0}, 0);
  const auto& spheres = scene["entities"][0]["spheres"];
  auto red = [&](int i) { return spheres[i]["color"]["r"].get<double>() > spheres[i]["color"]["b"].get<double>(); };
  EXPECT_FALSE(red(0));
  EXPECT_TRUE(red(1));
  EXPECT_FALSE(red(2));
  EXPECT_TRUE(red(3));
}

TEST(FoxgloveScene, GroundUnderStartAndTargetAndTargetOnIt) {
  SceneStyleParams style;
  style.ground_margin = 2.0;
  style.target_radius = 0.5;
  const nlohmann::json s = scene_update(robot(), pose(), {20, -4, 0}, 0, style);
  const auto& ground = s["entities"][1]["cubes"][0];
  // x from -2 to 22, y from -6 to 2
  EXPECT_DOUBLE_EQ(ground["pose"]["position"]["x"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(ground["pose"]["position"]["y"].get<double>(), -2.0);
  EXPECT_DOUBLE_EQ(ground["size"]["x"].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(ground["size"]["y"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(ground["pose"]["position"]["z"].get<double>() + ground["size"]["z"].get<double>() / 2, 0.0);
  const auto& target = s["entities"][2]["spheres"][0];
  EXPECT_EQ(target["pose"]["position"]["x"], 20.0);
  EXPECT_DOUBLE_EQ(target["pose"]["position"]["z"].get<double>(), 0.5);
}

TEST(FoxgloveScene, EveryEntityHasEveryFieldTheSchemaRequires) {
  const nlohmann::json schema = scene_update_schema();
  EXPECT_EQ(schema["title"], kSceneUpdateSchemaName);
  const auto& entity = schema["properties"]["entities"]["items"];
  const nlohmann::json s = scene_update(robot(), pose(), {50, 0, 0}, 0);
  for (const auto& e : s["entities"])
    for (const auto& field : entity["required"]) EXPECT_TRUE(e.contains(field.get<std::string>())) << field;
  EXPECT_EQ(entity["required"].size(), 14u);  // Foxglove's SceneEntity has 14 fields
}

TEST(FoxgloveScene, PoseOfAnotherRobotIsAnError) {
  pose_t p = pose();
  p.num_spheres = 3;
  p.sphere_center.pop_back();
  EXPECT_THROW(scene_update(robot(), p, {50, 0, 0}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
