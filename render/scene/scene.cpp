#include "render/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "render/gl/gl.hpp"
#include "render/gl/mesh.hpp"
#include "render/gl/shader.hpp"

namespace robozoo::render {

namespace {

constexpr int kLods = 5;  // icosphere levels 0..4

void color(Rgb c, float alpha = 1.0f) { glColor4f(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, alpha); }

Eigen::Vector3f to_eye(const Eigen::Matrix4d& view, const Eigen::Vector3d& dir) {
  return (view.block<3, 3>(0, 0) * dir.normalized()).cast<float>();
}

Eigen::Vector3f rgbf(Rgb c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f}; }

/// Draws `mesh` scaled by (sx, sy, sz) and moved to `at`; returns its triangles.
size_t draw_placed(const GpuMesh& mesh, const Eigen::Vector3d& at, double sx, double sy, double sz) {
  glPushMatrix();
  glTranslated(at.x(), at.y(), at.z());
  glScaled(sx, sy, sz);
  mesh.draw();
  glPopMatrix();
  return mesh.num_triangles();
}

/// The target's pole and the ball on top of it, `h` high at (x, y) on the ground.
size_t draw_target_pole(const GpuMesh& cylinder, const GpuMesh& ball, double x, double y, double h) {
  return draw_placed(cylinder, {x, y, 0.0}, 0.025 * h, 0.025 * h, h) +
         draw_placed(ball, {x, y, h}, 0.08 * h, 0.08 * h, 0.08 * h);
}

/// Stencil bit of the pixels an opaque object covers (the background skips them).
constexpr GLuint kCovered = 0x80;

/// The background: a vertical gradient from the sky's top to the horizon
/// colour over the whole picture, drawn with identity matrices and no depth test.
void draw_background(const SceneStyle& st) {
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glBegin(GL_QUADS);
  color(st.horizon);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  color(st.sky_top);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
}

}  // namespace

struct SceneRenderer::Impl {
  LitProgram program;
  GroundProgram ground_program;
  std::vector<std::unique_ptr<GpuMesh>> spheres;  // by level of detail
  GpuMesh cylinder{make_cylinder(24)};
  GpuMesh ring{make_ring(0.78, 64)};

  Impl() {
    for (int l = 0; l < kLods; ++l) spheres.push_back(std::make_unique<GpuMesh>(make_icosphere(l)));
  }
};

SceneRenderer::SceneRenderer(const SceneStyle& style) : impl_(std::make_unique<Impl>()), style_(style) {}
SceneRenderer::~SceneRenderer() = default;

namespace {

/// Loads the camera's matrices (depth test on) and returns the lighting of a
/// picture seen by it.
LightingUniforms set_camera(const Camera& camera, int width, int height, const SceneStyle& st) {
  const double aspect = static_cast<double>(width) / height;
  const Eigen::Matrix4d proj = projection_matrix(camera, aspect);
  const Eigen::Matrix4d mv = view_matrix(camera);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(proj.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(mv.data());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);

  const double distance = (camera.eye - camera.target).norm();
  LightingUniforms lu;
  lu.key_dir_eye = to_eye(mv, st.key_light);
  lu.fill_dir_eye = to_eye(mv, st.fill_light);
  lu.up_eye = to_eye(mv, Eigen::Vector3d::UnitZ());
  lu.fog_color = rgbf(st.horizon);
  lu.fog_start = static_cast<float>(st.fog_start * distance);
  lu.fog_end = static_cast<float>(st.fog_end * distance);
  return lu;
}

/// The spheres, lit, nearest first: llvmpipe tests depth before shading, so
/// hidden parts of overlapping spheres cost little. Leaves GL_RESCALE_NORMAL
/// on. Returns the triangles drawn.
size_t draw_spheres(const std::vector<SphereDraw>& spheres, const Camera& camera, double focal_px,
                    const std::vector<std::unique_ptr<GpuMesh>>& lods, LitProgram& prog, const SceneStyle& st) {
  // Level of detail: the coarsest icosphere whose silhouette stays within
  // ~0.4 px of the true circle (edge angle 1.107 / 2^level rad; chord error
  // r * angle^2 / 8). llvmpipe transforms vertices on one thread, so this is
  // what keeps large robots fast.
  auto lod = [&](const SphereDraw& s) {
    const double depth = std::max(1e-6, (camera.eye - s.center).norm());
    const double px = s.radius * focal_px / depth;
    return px < 10 ? 1 : px < 42 ? 2 : px < 166 ? 3 : 4;
  };
  std::vector<const SphereDraw*> order;
  for (const SphereDraw& s : spheres) order.push_back(&s);
  std::stable_sort(order.begin(), order.end(), [&](const SphereDraw* a, const SphereDraw* b) {
    return (a->center - camera.eye).squaredNorm() < (b->center - camera.eye).squaredNorm();
  });
  glEnable(GL_RESCALE_NORMAL);
  glEnable(GL_CULL_FACE);  // closed meshes: back faces are never seen
  glCullFace(GL_BACK);
  prog.material(0.45f, 48.0f, 0.10f);
  size_t triangles = 0;
  for (const SphereDraw* sp : order) {
    const SphereDraw& s = *sp;
    color(s.leaf ? st.leaf : st.inner);
    triangles += draw_placed(*lods[static_cast<size_t>(lod(s))], s.center, s.radius, s.radius, s.radius);
  }
  glDisable(GL_CULL_FACE);
  return triangles;
}

/// The ground: a square around the point looked at, reaching past the fog,
/// with the grid (or none). Returns the triangles drawn.
size_t draw_ground(GroundProgram& program, const LightingUniforms& lu, bool grid, const Camera& camera,
                   const SceneStyle& st) {
  const double distance = (camera.eye - camera.target).norm();
  const double half = std::max(st.fog_end * distance * 1.5, 20.0);
  const double cx = camera.target.x(), cy = camera.target.y();
  program.use(lu, grid);
  const double tex_scale = 1.0 / st.grid_spacing;  // grid lines at integer coordinates
  const Eigen::Vector3f lit = rgbf(st.ground).cwiseProduct(lu.up_facing_light()).cwiseMin(1.0f);
  glColor3f(lit.x(), lit.y(), lit.z());
  glBegin(GL_QUADS);
  for (const auto& c :
       {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1), Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)}) {
    const double x = cx + c.x() * half, y = cy + c.y() * half;
    glTexCoord2d(x * tex_scale, y * tex_scale);
    glVertex3d(x, y, 0);
  }
  glEnd();
  return 2;
}

/// Shadows: every object flattened onto the ground along the key light, each
/// ground pixel darkened once (stencil); drawn after the spheres so the depth
/// test hides shadow under a sphere's own silhouette.
void draw_shadows(const SceneView& view, const SceneStyle& st, const GpuMesh& sphere, const GpuMesh& cylinder) {
  const Eigen::Vector3d L = st.key_light.normalized();
  // Projection onto z = 0 along L: p' = p - (p.z / L.z) L.
  Eigen::Matrix4d shadow = Eigen::Matrix4d::Identity();
  shadow(0, 2) = -L.x() / L.z();
  shadow(1, 2) = -L.y() / L.z();
  shadow(2, 2) = 0.0;
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, kCovered - 1);  // the low bits count shadows
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-2.0f, -2.0f);
  glColor4f(0.05f, 0.06f, 0.1f, static_cast<float>(st.shadow_opacity));
  // A flattened closed mesh covers its shadow twice, once in each winding:
  // draw one of them.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glPushMatrix();
  glMultMatrixd(shadow.data());
  for (const SphereDraw& s : view.spheres) {
    draw_placed(sphere, s.center, s.radius, s.radius, s.radius);
  }
  if (view.show_target) draw_target_pole(cylinder, sphere, view.target.x(), view.target.y(), st.target_height);
  glPopMatrix();
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
}

/// Outlines: an anti-aliased line along each sphere's silhouette, over the
/// finished picture. It smooths the edges llvmpipe draws without
/// multisampling (which costs it 3x) and gives the drawing a crisp look.
void draw_outlines(const std::vector<SphereDraw>& spheres, const Camera& camera, double focal_px, int height,
                   const SceneStyle& st) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_LINE_SMOOTH);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glLineWidth(static_cast<float>(std::max(1.0, st.outline_width * height / 720.0)));
  glDepthMask(GL_FALSE);
  for (const SphereDraw& s : spheres) {
    const Eigen::Vector3d to_eye = camera.eye - s.center;
    const double d = to_eye.norm();
    if (d <= s.radius * 1.001) continue;  // the eye is inside the sphere
    const Eigen::Vector3d u = to_eye / d;
    const Eigen::Vector3d a = u.unitOrthogonal(), b = u.cross(a);
    // The silhouette circle, nudged towards the eye so the sphere's own
    // surface does not hide its inner half.
    const double rho = s.radius * std::sqrt(1.0 - (s.radius * s.radius) / (d * d));
    const Eigen::Vector3d c = s.center + u * (s.radius * s.radius / d + 0.004 * d);
    const Rgb base = s.leaf ? st.leaf : st.inner;
    glColor4f(static_cast<float>(base.r / 255.0 * st.outline_shade),
              static_cast<float>(base.g / 255.0 * st.outline_shade),
              static_cast<float>(base.b / 255.0 * st.outline_shade), 1.0f);
    const double px = s.radius * focal_px / d;
    const int segments = std::clamp(static_cast<int>(px * 0.5), 12, 96);
    glBegin(GL_LINE_LOOP);
    for (int k = 0; k < segments; ++k) {
      const double t = 2.0 * M_PI * k / segments;
      const Eigen::Vector3d p = c + rho * (std::cos(t) * a + std::sin(t) * b);
      glVertex3d(p.x(), p.y(), p.z());
    }
    glEnd();
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_BLEND);
}

}  // namespace

void SceneRenderer::draw(const SceneView& view, const Camera& camera, int width, int height) {
  const SceneStyle& st = style_;
  last_triangles_ = 0;
  glClearColor(st.horizon.r / 255.0f, st.horizon.g / 255.0f, st.horizon.b / 255.0f, 1.0f);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  glDisable(GL_LIGHTING);
  if (!background_last_) draw_background(st);

  const LightingUniforms lu = set_camera(camera, width, height, st);
  LitProgram& prog = impl_->program;
  prog.use(lu);
  const double focal_px = height / (2.0 * std::tan(camera.fov_y_deg * M_PI / 360.0));

  // Every opaque object marks the pixels it covers, so that the background
  // is drawn afterwards only where nothing is: the same picture as drawing it
  // first under everything, without shading the pixels the ground covers twice.
  if (background_last_) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kCovered, kCovered);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  }

  // Target marker: a ring on the ground and a pole with a ball on top.
  if (view.show_target) {
    prog.material(0.4f, 30.0f, 0.1f);
    color(st.target);
    const double h = st.target_height;
    last_triangles_ += draw_placed(impl_->ring, {view.target.x(), view.target.y(), 0.004}, 0.5 * h, 0.5 * h, 1);
    last_triangles_ += draw_target_pole(impl_->cylinder, *impl_->spheres[3], view.target.x(), view.target.y(), h);
  }

  last_triangles_ += draw_spheres(view.spheres, camera, focal_px, impl_->spheres, prog, st);
  // The ground after the robot, so the depth test skips shading what the robot hides.
  last_triangles_ += draw_ground(impl_->ground_program, lu, view.grid, camera, st);

  ShaderProgram::unuse();
  if (background_last_) {
    glStencilFunc(GL_EQUAL, 0, kCovered);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    draw_background(st);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
  }

  if (view.shadows && (!view.spheres.empty() || view.show_target))
    draw_shadows(view, st, *impl_->spheres[2], impl_->cylinder);
  glDisable(GL_RESCALE_NORMAL);

  if (view.outlines && st.outline_width > 0 && !view.spheres.empty())
    draw_outlines(view.spheres, camera, focal_px, height, st);
}

}  // namespace robozoo::render
