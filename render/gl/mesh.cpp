#include "render/gl/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/gl/gl.hpp"

namespace robozoo::render {

namespace {

uint32_t add_vertex(Mesh& m, double x, double y, double z, double nx, double ny, double nz) {
  m.positions.insert(m.positions.end(), {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
  m.normals.insert(m.normals.end(), {static_cast<float>(nx), static_cast<float>(ny), static_cast<float>(nz)});
  return static_cast<uint32_t>(m.num_vertices() - 1);
}
}  // namespace

Mesh make_icosphere(int level) {
  if (level < 0 || level > 6)
    throw std::invalid_argument("make_icosphere: level must be in [0, 6], got " + std::to_string(level));
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  const double v[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : v) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    add_vertex(m, p[0] / n, p[1] / n, p[2] / n, p[0] / n, p[1] / n, p[2] / n);
  }
  m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
               3, 9,  4, 3, 4, 2, 3, 2, 6, 3, 6, 8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      double x = m.positions[3 * a] + m.positions[3 * b], y = m.positions[3 * a + 1] + m.positions[3 * b + 1],
             z = m.positions[3 * a + 2] + m.positions[3 * b + 2];
      const double n = std::sqrt(x * x + y * y + z * z);
      x /= n;
      y /= n;
      z /= n;
      const uint32_t i = add_vertex(m, x, y, z, x, y, z);
      mid.emplace(key, i);
      return i;
    };
    std::vector<uint32_t> next;
    next.reserve(m.indices.size() * 4);
    for (size_t k = 0; k < m.indices.size(); k += 3) {
      const uint32_t a = m.indices[k], b = m.indices[k + 1], c = m.indices[k + 2];
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.indices = std::move(next);
  }
  return m;
}

Mesh make_cylinder(int segments) {
  if (segments < 3) throw std::invalid_argument("make_cylinder: need at least 3 segments");
  Mesh m;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2.0 * M_PI * i / segments, c = std::cos(a), s = std::sin(a);
    add_vertex(m, c, s, 0, c, s, 0);
    add_vertex(m, c, s, 1, c, s, 0);
  }
  for (int i = 0; i < segments; ++i) {
    const uint32_t b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * i + 2, t1 = 2 * i + 3;
    m.indices.insert(m.indices.end(), {b0, b1, t1, b0, t1, t0});
  }
  for (int cap = 0; cap < 2; ++cap) {
    const double z = cap, nz = cap ? 1 : -1;
    const uint32_t centre = add_vertex(m, 0, 0, z, 0, 0, nz);
    const uint32_t first = static_cast<uint32_t>(m.num_vertices());
    for (int i = 0; i <= segments; ++i) {
      const double a = 2.0 * M_PI * i / segments;
      add_vertex(m, std::cos(a), std::sin(a), z, 0, 0, nz);
    }
    for (int i = 0; i < segments; ++i) {
      if (cap)
        m.indices.insert(m.indices.end(), {centre, first + i, first + i + 1});
      else
        m.indices.insert(m.indices.end(), {centre, first + i + 1, first + i});
    }
  }
  return m;
}

Mesh make_ring(double inner, int segments) {
  if (!(inner >= 0 && inner < 1) || segments < 3)
    throw std::invalid_argument("make_ring: inner radius must be in [0, 1) and segments >= 3");
  Mesh m;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2.0 * M_PI * i / segments, c = std::cos(a), s = std::sin(a);
    add_vertex(m, inner * c, inner * s, 0, 0, 0, 1);
    add_vertex(m, c, s, 0, 0, 0, 1);
  }
  for (int i = 0; i < segments; ++i) {
    const uint32_t i0 = 2 * i, o0 = 2 * i + 1, i1 = 2 * i + 2, o1 = 2 * i + 3;
    m.indices.insert(m.indices.end(), {i0, o0, o1, i0, o1, i1});
  }
  return m;
}

GpuMesh::GpuMesh(const Mesh& m) : vertices_(m.num_vertices()), count_(m.indices.size()) {
  if (m.positions.size() != m.normals.size() || m.positions.size() % 3 != 0)
    throw std::invalid_argument("GpuMesh: positions and normals must have 3 floats per vertex each");
  std::vector<float> interleaved;
  interleaved.reserve(m.positions.size() * 2);
  for (size_t v = 0; v < vertices_; ++v) {
    interleaved.insert(interleaved.end(), m.positions.begin() + 3 * v, m.positions.begin() + 3 * v + 3);
    interleaved.insert(interleaved.end(), m.normals.begin() + 3 * v, m.normals.begin() + 3 * v + 3);
  }
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &ibo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(uint32_t)), m.indices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

GpuMesh::~GpuMesh() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (ibo_) glDeleteBuffers(1, &ibo_);
}

void GpuMesh::draw() const {
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(0));
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count_), GL_UNSIGNED_INT, nullptr);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

}  // namespace robozoo::render
