#include "render/scene/stage.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "render/gl/gl.hpp"

#include "tests/render/fixtures.hpp"

namespace robozoo::render {
namespace {

Camera looking_at_origin() {
  Camera c;
  c.target = {0, 0, 0.3};
  c.eye = {-2.5, -4.0, 2.0};
  c.near_m = 0.1;
  c.far_m = 100;
  return c;
}

TEST(Stage, DrawsWithLlvmpipe) {
  Stage stage(160, 120, 4);
  EXPECT_FALSE(stage.context().renderer().empty());
  EXPECT_EQ(stage.context().samples(), 4);  // llvmpipe's multisampling
  SceneView view;
  view.spheres.push_back({{0, 0, 0.3}, 0.3, false});
  const Image img = stage.render(view, looking_at_origin());
  ASSERT_EQ(img.width(), 160);
  ASSERT_EQ(img.height(), 120);
  const Rgb c = img.at(80, 60);  // the sphere's centre is the image's
  EXPECT_TRUE(testing::is_blue(c.r, c.g, c.b)) << int(c.r) << " " << int(c.g) << " " << int(c.b);
  view.spheres[0].leaf = true;
  const Rgb l = stage.render(view, looking_at_origin()).at(80, 60);
  EXPECT_TRUE(testing::is_red(l.r, l.g, l.b));
}

TEST(Stage, EmptySceneIsGroundAndSkyAndResizes) {
  Stage stage(64, 48, 0);
  EXPECT_EQ(stage.context().samples(), 0);
  SceneView empty;
  Camera c = looking_at_origin();
  const Image a = stage.render(empty, c);
  // The bottom shows the light ground, neither red nor blue.
  const Rgb g = a.at(32, 46);
  EXPECT_GT(g.r, 150);
  EXPECT_FALSE(testing::is_blue(g.r, g.g, g.b));
  stage.resize(32, 24);
  const Image b = stage.render(empty, c);
  EXPECT_EQ(b.width(), 32);
  EXPECT_EQ(b.height(), 24);
}

TEST(Stage, SameSceneSamePixels) {
  Stage stage(96, 64, 4);
  SceneView v;
  v.spheres = {{{0, 0, 0.3}, 0.3, false}, {{0.5, 0.1, 0.2}, 0.2, true}};
  v.show_target = true;
  v.target = {1, 1, 0};
  EXPECT_EQ(stage.render(v, looking_at_origin()).bytes(), stage.render(v, looking_at_origin()).bytes());
}

/// Scenes that put the background next to every kind of object: spheres near
/// and far, the target, shadows, outlines, with and without the grid, seen
/// from low (horizon and the ground's far edge in view) and from above.
std::vector<std::pair<SceneView, Camera>> varied_scenes() {
  std::vector<std::pair<SceneView, Camera>> out;
  SceneView robot;
  for (int i = 0; i < 12; ++i)
    robot.spheres.push_back({{0.15 * i - 0.8, 0.1 * (i % 3), 0.1 + 0.05 * (i % 4)}, 0.08 + 0.02 * (i % 5), i % 3 == 0});
  robot.show_target = true;
  robot.target = {3, 1, 0};
  out.push_back({robot, looking_at_origin()});
  Camera low = looking_at_origin();
  low.eye = {-3.0, -0.5, 0.25};  // nearly level: sky over most of the picture
  out.push_back({robot, low});
  Camera far = low;
  far.far_m = 6;  // the ground ends at the far plane, short of the fog
  out.push_back({robot, far});
  SceneView bare = robot;
  bare.grid = false;
  bare.shadows = false;
  bare.outlines = false;
  out.push_back({bare, low});
  Camera above = looking_at_origin();
  above.eye = {0.01, 0.0, 6.0};  // the ground fills the picture
  out.push_back({robot, above});
  SceneView sky_only;
  Camera up = looking_at_origin();
  up.eye = {0, 0, 0.5};
  up.target = {1, 0, 3};  // looking up: no object at all
  out.push_back({sky_only, up});
  return out;
}

TEST(Stage, BackgroundDrawnLastGivesTheSamePixelsAsDrawnFirst) {
  // The scene draws the background after the objects, only where none is;
  // drawing it first under everything (the plain way) must give the same bytes.
  for (const int samples : {0, 4}) {
    Stage stage(200, 120, samples);
    int scene = 0;
    for (const auto& [view, camera] : varied_scenes()) {
      stage.scene().set_background_last(true);
      const Image last = stage.render(view, camera);
      stage.scene().set_background_last(false);
      const Image first = stage.render(view, camera);
      EXPECT_EQ(last.bytes(), first.bytes()) << "scene " << scene << ", " << samples << " samples";
      ++scene;
    }
  }
}

TEST(Stage, ReadBackIsTheFramebufferTopRowFirst) {
  // An odd width, so the last pixel of each row is read on its own.
  Stage stage(63, 47, 0);
  const auto scenes = varied_scenes();
  const Image img = stage.render(scenes[0].first, scenes[0].second);
  std::vector<unsigned char> gl(63 * 47 * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 63, 47, GL_RGB, GL_UNSIGNED_BYTE, gl.data());
  for (int y = 0; y < 47; ++y)
    for (int x = 0; x < 63; ++x) {
      const unsigned char* p = gl.data() + 3 * (static_cast<size_t>(46 - y) * 63 + x);
      ASSERT_EQ(img.at(x, y), (Rgb{p[0], p[1], p[2]})) << x << ", " << y;
    }
}

}  // namespace
}  // namespace robozoo::render
