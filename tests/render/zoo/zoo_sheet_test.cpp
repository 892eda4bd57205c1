#include "render/zoo/zoo_sheet.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <cmath>

#include "render/gl/png_io.hpp"
#include "tests/render/fixtures.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::TempDir;

RobotCard known_card() {
  RobotCard c;
  c.run_id = "known-s1";
  c.regime = 1;
  c.generation = 3;
  c.genome_id = 1;
  c.fitness = 15.5;
  c.shape = shape_from_morphology(testing::known_robot());
  return c;
}

struct Disc {
  double x, y, r;  // pixels
  bool leaf;
};

// Where each sphere lands in the picture: its projected centre and radius.
std::vector<Disc> discs(const RobotCard& card, const Camera& cam, int w, int h) {
  std::vector<Disc> out;
  const double focal = h / (2.0 * std::tan(cam.fov_y_deg * M_PI / 360.0));
  for (size_t i = 0; i < card.shape.size(); ++i) {
    const Eigen::Vector3d p = project_to_pixel(cam, w, h, card.shape.start[i]);
    out.push_back({p.x(), p.y(), card.shape.radius[i] * focal / p.z(), card.shape.leaf[i]});
  }
  return out;
}

TEST(ZooSheet, RedLeavesAndBlueSpheresWhereTheyMustBe) {
  const RobotCard card = known_card();
  const int w = 320, h = 240;
  Stage stage(w, h, 4);
  const Camera cam = card_camera(card, w, h, ViewAngles{}, 0.07);
  const Image img = render_card(stage, card, cam);
  ASSERT_EQ(img.width(), w);
  ASSERT_EQ(img.height(), h);
  const std::vector<Disc> d = discs(card, cam, w, h);

  // The centre of every sphere shows its colour.
  for (const Disc& s : d) {
    const Rgb c = img.at(static_cast<int>(s.x), static_cast<int>(s.y));
    EXPECT_EQ(testing::is_red(c.r, c.g, c.b), s.leaf) << s.x << "," << s.y;
    EXPECT_EQ(testing::is_blue(c.r, c.g, c.b), !s.leaf) << s.x << "," << s.y;
  }
  // Count: red pixels only inside leaf discs, blue only inside the others,
  // and about as many as the discs' areas.
  double leaf_area = 0, other_area = 0;
  for (const Disc& s : d) (s.leaf ? leaf_area : other_area) += M_PI * s.r * s.r;
  int red = 0, blue = 0, stray = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb c = img.at(x, y);
      const bool r = testing::is_red(c.r, c.g, c.b), b = testing::is_blue(c.r, c.g, c.b);
      if (!r && !b) continue;
      bool inside = false;
      for (const Disc& s : d)
        if (s.leaf == r && std::hypot(x + 0.5 - s.x, y + 0.5 - s.y) <= s.r + 2.0) inside = true;
      red += r;
      blue += b;
      stray += !inside;
    }
  EXPECT_EQ(stray, 0);
  EXPECT_GT(red, 0.75 * leaf_area);
  EXPECT_LT(red, 1.1 * leaf_area);
  EXPECT_GT(blue, 0.75 * other_area);
  EXPECT_LT(blue, 1.1 * other_area);
}

TEST(ZooSheet, SheetSizeGridCaptionsAndPng) {
  TempDir dir;
  ZooOptions o;
  o.cell_width = 200;
  o.cell_height = 150;
  o.columns = 2;
  o.gap = 10;
  o.title = "three robots";
  const std::vector<RobotCard> cards(3, known_card());
  const Image sheet = render_zoo(cards, o);
  Fonts f = Fonts::load(o.font_size);
  Fonts title = Fonts::load(o.font_size * 3 / 2);
  const int caption = 2 * f.regular.line_height() + 10;
  const int title_h = title.bold.line_height() + o.gap;
  EXPECT_EQ(sheet.width(), 10 + 2 * (200 + 10));
  EXPECT_EQ(sheet.height(), 10 + title_h + 2 * (150 + caption + 10));
  write_png(dir / "zoo.png", sheet);
  const Image back = read_png(dir / "zoo.png");
  EXPECT_EQ(back.bytes(), sheet.bytes());
  // Every cell shows red and blue; the empty fourth cell shows neither.
  auto count = [&](int col, int row) {
    const int x0 = 10 + col * 210, y0 = 10 + title_h + row * (150 + caption + 10);
    int red = 0, blue = 0, ink = 0;
    for (int y = y0; y < y0 + 150; ++y)
      for (int x = x0; x < x0 + 200; ++x) {
        const Rgb c = back.at(x, y);
        red += testing::is_red(c.r, c.g, c.b);
        blue += testing::is_blue(c.r, c.g, c.b);
      }
    for (int y = y0 + 150; y < y0 + 150 + caption; ++y)
      for (int x = x0; x < x0 + 200; ++x) ink += back.at(x, y).r < 120;
    return std::array<int, 3>{red, blue, ink};
  };
  for (int i = 0; i < 3; ++i) {
    const auto c = count(i % 2, i / 2);
    EXPECT_GT(c[0], 200) << i;
    EXPECT_GT(c[1], 200) << i;
    EXPECT_GT(c[2], 100) << "caption of cell " << i;
  }
  const auto empty = count(1, 1);
  EXPECT_EQ(empty[0] + empty[1] + empty[2], 0);
}

TEST(ZooSheet, SameScaleGivesASmallRobotAMagnifiedInset) {
  // The known robot and a copy ten times as large, at one scale: the small one
  // gets an inset in its cell's top-right third; the large one does not.
  RobotCard small = known_card(), large = known_card();
  for (double& r : large.shape.radius) r *= 10;
  for (Eigen::Vector3d& c : large.shape.start) c *= 10;
  ZooOptions o;
  o.cell_width = 240;
  o.cell_height = 180;
  o.columns = 2;
  o.gap = 10;
  o.same_scale = true;
  const Image sheet = render_zoo({large, small}, o);
  auto corner = [&](int col) {
    int robot = 0;
    const int x0 = 10 + col * 250 + 240 * 2 / 3, y0 = 10;
    for (int y = y0; y < y0 + 180 / 3; ++y)
      for (int x = x0; x < x0 + 240 / 3; ++x) {
        const Rgb c = sheet.at(x, y);
        robot += testing::is_red(c.r, c.g, c.b) || testing::is_blue(c.r, c.g, c.b);
      }
    return robot;
  };
  EXPECT_EQ(corner(0), 0);
  EXPECT_GT(corner(1), 50);
  o.inset_below = 0;  // no insets
  const Image bare = render_zoo({large, small}, o);
  EXPECT_NE(bare.bytes(), sheet.bytes());
  o.inset_below = 1.5;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

TEST(ZooSheet, BadOptions) {
  ZooOptions o;
  EXPECT_THROW(render_zoo({}, o), std::invalid_argument);
  o.cell_width = 8;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = ZooOptions{};
  o.margin = 0.5;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

TEST(ZooSheet, CaptionSaysRunRegimeGenerationFitness) {
  const auto lines = card_caption(known_card());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "known-s1");
  EXPECT_EQ(lines[1], "recurrent \u00b7 generation 3 \u00b7 fitness 15.50");
}

}  // namespace
}  // namespace robozoo::render
