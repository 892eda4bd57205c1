#include "render/gl/camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace robozoo::render {

namespace {
double rad(double deg) { return deg * M_PI / 180.0; }
}  // namespace

Eigen::Vector3d view_direction(const ViewAngles& a) {
  const double az = rad(a.azimuth_deg), el = rad(a.elevation_deg);
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

Eigen::Matrix4d view_matrix(const Camera& c) {
  const Eigen::Vector3d f = (c.target - c.eye).normalized();
  const Eigen::Vector3d s = f.cross(c.up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(c.eye);
  m(1, 3) = -u.dot(c.eye);
  m(2, 3) = f.dot(c.eye);
  return m;
}

Eigen::Matrix4d projection_matrix(const Camera& c, double aspect) {
  const double f = 1.0 / std::tan(rad(c.fov_y_deg) / 2.0);
  const double n = c.near_m, fa = c.far_m;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (fa + n) / (n - fa);
  m(2, 3) = 2.0 * fa * n / (n - fa);
  m(3, 2) = -1.0;
  return m;
}

Eigen::Vector3d project_to_pixel(const Camera& c, int width, int height, const Eigen::Vector3d& p) {
  const Eigen::Vector4d e = view_matrix(c) * p.homogeneous();
  const Eigen::Vector4d clip = projection_matrix(c, static_cast<double>(width) / height) * e;
  const double x = clip.x() / clip.w(), y = clip.y() / clip.w();
  return {(x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height, -e.z()};
}

Camera frame_spheres(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii, double aspect,
                     const ViewAngles& angles, double margin) {
  if (centers.empty() || centers.size() != radii.size())
    throw std::invalid_argument("frame_spheres: need one radius per centre and at least one sphere");
  if (!(aspect > 0) || !(margin >= 0 && margin < 0.5))
    throw std::invalid_argument("frame_spheres: aspect must be > 0 and margin in [0, 0.5)");
  // Camera basis: back (towards the eye), right, up.
  const Eigen::Vector3d back = view_direction(angles);
  const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(back).normalized();
  const Eigen::Vector3d up = back.cross(right);
  const double half_v = rad(angles.fov_y_deg) / 2.0;
  // Shrink the usable field by the margin.
  const double tan_v = std::tan(half_v) * (1.0 - 2.0 * margin);
  const double tan_h = std::tan(half_v) * aspect * (1.0 - 2.0 * margin);
  const double ang_v = std::atan(tan_v), ang_h = std::atan(tan_h);

  // Aim at the middle of the spheres' extent across the view, twice: the
  // second pass re-centres on the extent the first one found.
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  for (const auto& c : centers) target += c;
  target /= static_cast<double>(centers.size());
  double distance = 1.0;
  for (int pass = 0; pass < 2; ++pass) {
    // For a sphere at lateral offset x and depth z (along the view axis) from
    // the eye, a plane through the eye at angle a from the axis clears it when
    // z >= (|x| + r / cos a) / tan a. Depth z = distance - (offset . back).
    double need = 0.0;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (size_t i = 0; i < centers.size(); ++i) {
      const Eigen::Vector3d o = centers[i] - target;
      const double x = o.dot(right), y = o.dot(up), zb = o.dot(back), r = radii[i];
      need = std::max(need, (std::abs(x) + r / std::cos(ang_h)) / tan_h + zb);
      need = std::max(need, (std::abs(y) + r / std::cos(ang_v)) / tan_v + zb);
      lo_x = std::min(lo_x, x - r);
      hi_x = std::max(hi_x, x + r);
      lo_y = std::min(lo_y, y - r);
      hi_y = std::max(hi_y, y + r);
    }
    distance = std::max(need, 1e-3);
    if (pass == 0) target += right * (lo_x + hi_x) / 2.0 + up * (lo_y + hi_y) / 2.0;
  }
  double max_r = 0.0;
  for (double r : radii) max_r = std::max(max_r, r);
  Camera cam;
  cam.fov_y_deg = angles.fov_y_deg;
  cam.target = target;
  cam.eye = target + back * distance;
  cam.near_m = std::max(1e-3, 0.05 * distance);
  cam.far_m = 40.0 * distance + 10.0 * max_r;
  return cam;
}

FollowCamera::FollowCamera(const Camera& framing, const Eigen::Vector3d& start, double smoothing)
    : camera_(framing), offset_(framing.eye - framing.target), position_(start), smoothing_(smoothing) {
  if (!(smoothing >= 0)) throw std::invalid_argument("FollowCamera: smoothing must be >= 0 s");
  camera_.target = position_;
  camera_.eye = position_ + offset_;
}

const Camera& FollowCamera::update(const Eigen::Vector3d& point, double dt) {
  if (smoothing_ <= 0 || dt <= 0) {
    if (smoothing_ <= 0) position_ = point;
  } else {
    // Critically damped spring (closed form over dt, stable for any dt).
    const double omega = 2.0 / smoothing_;
    const double x = omega * dt;
    const double decay = 1.0 / (1.0 + x + 0.48 * x * x + 0.235 * x * x * x);
    const Eigen::Vector3d change = position_ - point;
    const Eigen::Vector3d temp = (velocity_ + omega * change) * dt;
    velocity_ = (velocity_ - omega * temp) * decay;
    position_ = point + (change + temp) * decay;
  }
  camera_.target = position_;
  camera_.eye = position_ + offset_;
  return camera_;
}

}  // namespace robozoo::render
