#pragma once
// Triangle meshes (unit shapes, scaled when drawn) and their upload into
// OpenGL vertex buffers.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace robozoo::render {

struct Mesh {
  std::vector<float> positions;   ///< x, y, z per vertex
  std::vector<float> normals;     ///< unit normal per vertex
  std::vector<uint32_t> indices;  ///< three per triangle, counter-clockwise seen from outside
  size_t num_vertices() const { return positions.size() / 3; }
  size_t num_triangles() const { return indices.size() / 3; }
};

/// Unit sphere from a subdivided icosahedron: 20 * 4^level triangles.
Mesh make_icosphere(int level);
/// Cylinder of radius 1 from z = 0 to z = 1, with caps, `segments` around.
Mesh make_cylinder(int segments);
/// Flat ring in the z = 0 plane between radii `inner` and 1, facing +z.
Mesh make_ring(double inner, int segments);

/// A mesh in OpenGL vertex buffers; needs a current context for its whole life.
class GpuMesh {
 public:
  explicit GpuMesh(const Mesh& m);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;
  /// Draws it with the current matrices, colour and program.
  void draw() const;
  size_t num_triangles() const { return count_ / 3; }

 private:
  unsigned int vbo_ = 0, ibo_ = 0;
  size_t vertices_ = 0, count_ = 0;
};

}  // namespace robozoo::render
