#pragma once
// The GLSL programs of the renderer, on top of the compatibility profile's
// fixed matrices:
//  - LitProgram: per-pixel Blinn-Phong with two directional lights,
//    hemispheric ambient, a rim term and distance fog (spheres, the target);
//  - GroundProgram: a flat colour (a plane under directional light is evenly
//    lit, so the caller lights it once per frame) with anti-aliased grid lines
//    computed per pixel (cheaper than a filtered texture on llvmpipe) and fog.
#include <Eigen/Core>

namespace robozoo::render {

struct LightingUniforms {
  Eigen::Vector3f key_dir_eye{0, 0, 1};   ///< towards the key light, eye space (unit)
  Eigen::Vector3f fill_dir_eye{0, 0, 1};  ///< towards the fill light, eye space (unit)
  Eigen::Vector3f up_eye{0, 1, 0};        ///< world up in eye space (unit)
  Eigen::Vector3f key_color{0.78f, 0.76f, 0.72f};
  Eigen::Vector3f fill_color{0.22f, 0.24f, 0.28f};
  Eigen::Vector3f sky_ambient{0.36f, 0.38f, 0.42f};
  Eigen::Vector3f ground_ambient{0.16f, 0.15f, 0.14f};
  Eigen::Vector3f fog_color{0.9f, 0.92f, 0.95f};
  float fog_start = 50.0f;  ///< eye distance where fog starts (m)
  float fog_end = 100.0f;   ///< eye distance of full fog (m)
  /// The light an upward-facing surface receives (ambient + diffuse), per channel.
  Eigen::Vector3f up_facing_light() const;
};

/// A linked vertex + fragment program; throws std::runtime_error with the GLSL
/// log when compiling or linking fails.
class ShaderProgram {
 public:
  ShaderProgram(const char* vertex, const char* fragment);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;
  void use() const;
  static void unuse();
  int uniform(const char* name) const;

 private:
  unsigned int program_ = 0;
};

class LitProgram {
 public:
  LitProgram();
  void use(const LightingUniforms& u) const;
  /// Surface of what is drawn next: specular strength, shininess and rim strength.
  void material(float specular, float shininess, float rim) const;

 private:
  ShaderProgram program_;
  int key_, fill_, up_, key_color_, fill_color_, sky_, ground_, fog_color_, fog_range_, material_;
};

class GroundProgram {
 public:
  GroundProgram();
  /// `grid`: lines at integer texture coordinates (s, t), a lighter one at
  /// every integer and a darker one at every even integer.
  void use(const LightingUniforms& u, bool grid) const;

 private:
  ShaderProgram program_;
  int fog_color_, fog_range_, grid_;
};

}  // namespace robozoo::render
