#include "render/gl/camera.hpp"

#include <gtest/gtest.h>

namespace robozoo::render {
namespace {

TEST(Camera, TargetProjectsToTheImageCentre) {
  Camera c;
  c.eye = {3, -4, 2};
  c.target = {0.5, 0.2, 0.1};
  const Eigen::Vector3d p = project_to_pixel(c, 640, 480, c.target);
  EXPECT_NEAR(p.x(), 320, 1e-6);
  EXPECT_NEAR(p.y(), 240, 1e-6);
  EXPECT_NEAR(p.z(), (c.eye - c.target).norm(), 1e-9);
  // Up in the world is up in the image.
  EXPECT_LT(project_to_pixel(c, 640, 480, c.target + Eigen::Vector3d(0, 0, 0.5)).y(), 240);
}

TEST(Camera, FramedSpheresFitInsideTheMargin) {
  const std::vector<Eigen::Vector3d> centers = {{0, 0, 0.3}, {1.5, 0.4, 0.3}, {-0.7, -1.1, 0.1}, {0.2, 1.8, 0.5}};
  const std::vector<double> radii = {0.3, 0.25, 0.1, 0.5};
  for (double aspect : {4.0 / 3.0, 16.0 / 9.0, 0.8}) {
    const int w = static_cast<int>(600 * aspect), h = 600;
    const double margin = 0.08;
    const Camera cam = frame_spheres(centers, radii, aspect, ViewAngles{}, margin);
    double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
    for (size_t i = 0; i < centers.size(); ++i) {
      // Sample the sphere's surface and project it.
      for (int a = 0; a < 24; ++a)
        for (int b = 0; b <= 12; ++b) {
          const double th = a * 2 * M_PI / 24, ph = b * M_PI / 12;
          const Eigen::Vector3d p = centers[i] + radii[i] * Eigen::Vector3d(std::sin(ph) * std::cos(th),
                                                                            std::sin(ph) * std::sin(th), std::cos(ph));
          const Eigen::Vector3d q = project_to_pixel(cam, w, h, p);
          lo_x = std::min(lo_x, q.x());
          hi_x = std::max(hi_x, q.x());
          lo_y = std::min(lo_y, q.y());
          hi_y = std::max(hi_y, q.y());
        }
    }
    EXPECT_GE(lo_x, margin * w - 1) << aspect;
    EXPECT_LE(hi_x, (1 - margin) * w + 1) << aspect;
    EXPECT_GE(lo_y, margin * h - 1) << aspect;
    EXPECT_LE(hi_y, (1 - margin) * h + 1) << aspect;
    // Tight along at least one axis: the robot fills the cell.
    EXPECT_TRUE(lo_x < margin * w + 0.05 * w || lo_y < margin * h + 0.05 * h) << aspect;
  }
  EXPECT_THROW(frame_spheres({}, {}, 1.0, ViewAngles{}), std::invalid_argument);
  EXPECT_THROW(frame_spheres(centers, {0.1}, 1.0, ViewAngles{}), std::invalid_argument);
}

TEST(Camera, SameDirectionForEveryRobot) {
  const Camera a = frame_spheres({{0, 0, 0.1}}, {0.1}, 1.5, ViewAngles{});
  const Camera b = frame_spheres({{5, 3, 1}, {6, 3, 1}}, {0.5, 0.5}, 1.5, ViewAngles{});
  EXPECT_TRUE((a.eye - a.target).normalized().isApprox((b.eye - b.target).normalized(), 1e-12));
}

TEST(Camera, FollowCameraTrailsSmoothlyAndDeterministically) {
  Camera framing;
  framing.target = {0, 0, 0};
  framing.eye = {-2, -5, 3};
  FollowCamera f1(framing, {0, 0, 0}, 0.5), f2(framing, {0, 0, 0}, 0.5);
  double last = 0;
  for (int i = 1; i <= 100; ++i) {
    const Eigen::Vector3d point(0.04 * i, 0, 0);  // 1 m/s
    const Camera& c = f1.update(point, 0.04);
    EXPECT_EQ(c.eye - c.target, framing.eye - framing.target);  // fixed offset
    EXPECT_GE(c.target.x(), last);                              // never goes back
    EXPECT_LE(c.target.x(), point.x());                         // trails
    last = c.target.x();
    EXPECT_EQ(f2.update(point, 0.04).target, c.target);  // same inputs, same camera
  }
  EXPECT_NEAR(last, 4.0, 0.6);  // caught up to within the smoothing lag
  FollowCamera rigid(framing, {0, 0, 0}, 0.0);
  EXPECT_EQ(rigid.update({3, 2, 1}, 0.04).target, Eigen::Vector3d(3, 2, 1));
}

}  // namespace
}  // namespace robozoo::render
