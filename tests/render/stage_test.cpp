#include "render/stage.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace robozoo::render
