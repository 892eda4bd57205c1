#pragma once
// Drawing one scene into the current OpenGL context: sky, a lit ground with a
// grid, soft-edged planar shadows, the robot's spheres (leaves red, all others
// blue, as in the paper's Figure 4) and the target marker. Shared by zoo
// sheets, videos and live mode; it knows nothing about growth or physics.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "render/gl/camera.hpp"
#include "render/gl/image.hpp"

namespace robozoo::render {

struct SceneStyle {
  Rgb leaf{214, 44, 36};                         ///< leaf spheres (no children)
  Rgb inner{40, 88, 204};                        ///< every other sphere
  Rgb ground{206, 204, 198};                     ///< ground colour under the grid
  Rgb sky_top{150, 180, 215};                    ///< top of the background gradient
  Rgb horizon{232, 236, 240};                    ///< bottom of the gradient, and the fog colour
  Rgb target{240, 176, 32};                      ///< target marker
  double grid_spacing = 0.5;                     ///< distance between grid lines (m); every other line is darker
  double shadow_opacity = 0.32;                  ///< darkness of shadows (0-1)
  Eigen::Vector3d key_light{-0.35, -0.55, 1.0};  ///< direction towards the key light (world); also casts shadows
  Eigen::Vector3d fill_light{0.6, 0.4, 0.35};    ///< direction towards the fill light (world)
  double target_height = 1.0;                    ///< height of the target's pole (m)
  double fog_start = 3.0;                        ///< fog starts at this many camera distances
  double fog_end = 9.0;                          ///< and is complete at this many
  double outline_width = 1.4;                    ///< anti-aliased outline on each sphere's silhouette (px at 720 lines;
                                                 ///< scaled with the image height); 0: none
  double outline_shade = 0.55;                   ///< outline colour = the sphere's colour times this
};

struct SphereDraw {
  Eigen::Vector3d center{0, 0, 0};  ///< (m)
  double radius = 0.1;              ///< (m)
  bool leaf = false;
};

struct SceneView {
  std::vector<SphereDraw> spheres;
  bool grid = true;  ///< grid lines on the ground
  bool shadows = true;
  bool outlines = true;  ///< smooth silhouettes (cheap anti-aliasing without multisampling)
  bool show_target = false;
  Eigen::Vector3d target{50, 0, 0};  ///< target position (m)
};

class SceneRenderer {
 public:
  /// Needs a current GlContext for its whole life (builds meshes, the shader
  /// program and the grid texture in it).
  explicit SceneRenderer(const SceneStyle& style = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  /// Draws `view` seen by `camera` into the bound framebuffer (width x height).
  void draw(const SceneView& view, const Camera& camera, int width, int height);
  const SceneStyle& style() const { return style_; }
  /// Triangles drawn by the last draw() (for the benchmark).
  size_t last_triangles() const { return last_triangles_; }
  /// Draws the background after the objects, only where none is (true, the
  /// default), or first under everything (false: the plain way, kept as the
  /// reference its tests compare with; both give the same pixels).
  void set_background_last(bool last) { background_last_ = last; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SceneStyle style_;
  size_t last_triangles_ = 0;
  bool background_last_ = true;
};

}  // namespace robozoo::render
