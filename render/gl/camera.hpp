#pragma once
// Cameras: where the eye is, what it looks at, and how a robot is framed.
// z is up (docs/method.md section 2). Every camera of robozoo-render looks from the
// same direction (azimuth and elevation), so robots are seen alike.
#include <vector>

#include <Eigen/Core>

namespace robozoo::render {

struct Camera {
  Eigen::Vector3d eye{-3, -6, 3};   ///< (m)
  Eigen::Vector3d target{0, 0, 0};  ///< point looked at (m)
  Eigen::Vector3d up{0, 0, 1};      ///< world up
  double fov_y_deg = 30.0;          ///< vertical field of view (degrees)
  double near_m = 0.05;             ///< near clipping distance (m)
  double far_m = 200.0;             ///< far clipping distance (m)
};

/// The direction cameras look from.
struct ViewAngles {
  double azimuth_deg = -62.0;   ///< of the eye around the target, from +x towards +y (degrees);
                                ///< -62: in front of the robot's path to +x, a little behind its start
  double elevation_deg = 24.0;  ///< of the eye above the horizontal (degrees)
  double fov_y_deg = 30.0;      ///< vertical field of view (degrees)
};

/// Unit vector from the target towards the eye for these angles.
Eigen::Vector3d view_direction(const ViewAngles& a);

/// Column-major OpenGL matrices (gluLookAt and gluPerspective conventions).
Eigen::Matrix4d view_matrix(const Camera& c);
Eigen::Matrix4d projection_matrix(const Camera& c, double aspect);

/// Where a world point lands in a width x height image (pixels, origin top
/// left, y down); z of the result is the eye-space depth (m, > 0 in front).
Eigen::Vector3d project_to_pixel(const Camera& c, int width, int height, const Eigen::Vector3d& p);

/// The camera at `angles` that shows every sphere (centre, radius) whole, as
/// large as possible with `margin` (fraction of the image kept free on each
/// side); near/far set from the distance. Throws std::invalid_argument when
/// there are no spheres or the sizes differ.
Camera frame_spheres(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii, double aspect,
                     const ViewAngles& angles, double margin = 0.08);

/// A camera that follows a moving point smoothly: the eye keeps a fixed offset
/// (direction and distance) from a target that trails the point like a
/// critically damped spring. Deterministic: a pure function of the points and
/// time steps it is given.
class FollowCamera {
 public:
  /// Starts looking at `start`, the eye keeping `framing`'s offset from its
  /// target (and its field of view and clipping); `smoothing` is the spring's
  /// time constant (s; 0: follow rigidly).
  FollowCamera(const Camera& framing, const Eigen::Vector3d& start, double smoothing);
  /// Advances by dt (s) towards `point` and returns the camera.
  const Camera& update(const Eigen::Vector3d& point, double dt);
  const Camera& camera() const { return camera_; }

 private:
  Camera camera_;
  Eigen::Vector3d offset_;    // eye - target
  Eigen::Vector3d position_;  // the smoothed target
  Eigen::Vector3d velocity_{0, 0, 0};
  double smoothing_;
};

}  // namespace robozoo::render
