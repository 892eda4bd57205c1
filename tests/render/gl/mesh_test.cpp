#include "render/gl/mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo::render {
namespace {

TEST(Mesh, IcosphereHasTheExpectedTrianglesOnTheUnitSphere) {
  for (int level = 0; level <= 4; ++level) {
    const Mesh m = make_icosphere(level);
    EXPECT_EQ(m.num_triangles(), 20u << (2 * level)) << level;
    // Euler: V - E + F = 2 with E = 3F/2.
    EXPECT_EQ(m.num_vertices(), m.num_triangles() / 2 + 2) << level;
    for (size_t v = 0; v < m.num_vertices(); ++v) {
      const float* p = &m.positions[3 * v];
      EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-6);
    }
  }
  EXPECT_THROW(make_icosphere(7), std::invalid_argument);
}

TEST(Mesh, IcosphereTrianglesFaceOutwards) {
  // Back-face culling relies on counter-clockwise triangles seen from outside.
  const Mesh m = make_icosphere(2);
  for (size_t t = 0; t < m.num_triangles(); ++t) {
    const float* a = &m.positions[3 * m.indices[3 * t]];
    const float* b = &m.positions[3 * m.indices[3 * t + 1]];
    const float* c = &m.positions[3 * m.indices[3 * t + 2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    EXPECT_GT(n[0] * a[0] + n[1] * a[1] + n[2] * a[2], 0.0) << "triangle " << t;
  }
}

TEST(Mesh, CylinderAndRing) {
  const Mesh c = make_cylinder(12);
  EXPECT_EQ(c.num_triangles(), 12u * 2 + 12u * 2);
  for (size_t v = 0; v < c.num_vertices(); ++v) {
    EXPECT_GE(c.positions[3 * v + 2], 0.0f);
    EXPECT_LE(c.positions[3 * v + 2], 1.0f);
  }
  const Mesh r = make_ring(0.5, 10);
  EXPECT_EQ(r.num_triangles(), 20u);
  EXPECT_THROW(make_ring(1.0, 10), std::invalid_argument);
  EXPECT_THROW(make_cylinder(2), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::render
