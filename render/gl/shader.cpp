#include "render/gl/shader.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "render/gl/gl.hpp"

namespace robozoo::render {

namespace {

const char* kVertex = R"(#version 120
varying vec3 v_normal;
varying vec3 v_eye;
void main() {
  vec4 e = gl_ModelViewMatrix * gl_Vertex;
  v_eye = e.xyz;
  v_normal = gl_NormalMatrix * gl_Normal;
  gl_TexCoord[0] = gl_MultiTexCoord0;
  gl_FrontColor = gl_Color;
  gl_Position = gl_ProjectionMatrix * e;
}
)";

const char* kLitFragment = R"(#version 120
varying vec3 v_normal;
varying vec3 v_eye;
uniform vec3 u_key, u_fill, u_up, u_key_color, u_fill_color, u_sky, u_ground, u_fog_color;
uniform vec2 u_fog_range;
uniform vec3 u_material;   // specular, shininess, rim
void main() {
  vec3 n = normalize(v_normal);
  float dist = length(v_eye);
  vec3 v = -v_eye / dist;
  float nv = dot(n, v);
  if (nv < 0.0) { n = -n; nv = -nv; }
  vec3 ambient = mix(u_ground, u_sky, 0.5 + 0.5 * dot(n, u_up));
  vec3 diffuse = max(dot(n, u_key), 0.0) * u_key_color + max(dot(n, u_fill), 0.0) * u_fill_color;
  float spec = u_material.x * pow(max(dot(n, normalize(u_key + v)), 0.0), u_material.y);
  float edge = 1.0 - nv;
  float rim = u_material.z * edge * edge * edge;
  vec3 c = gl_Color.rgb * (ambient + diffuse) + vec3(spec + rim);
  float fog = clamp((u_fog_range.y - dist) / (u_fog_range.y - u_fog_range.x), 0.0, 1.0);
  gl_FragColor = vec4(mix(u_fog_color, c, fog), 1.0);
}
)";

const char* kGroundFragment = R"(#version 120
varying vec3 v_eye;
uniform vec3 u_fog_color;
uniform vec2 u_fog_range;
uniform float u_grid;
// Anti-aliased lines about a pixel wide at any distance, fading out where
// cells shrink to a few pixels (no moire towards the horizon). w: fwidth(c),
// at least 1e-5.
float grid_lines(vec2 c, vec2 w) {
  vec2 d = abs(fract(c - 0.5) - 0.5) / w;
  float line = 1.0 - clamp(min(d.x, d.y) - 0.2, 0.0, 1.0);
  return line * clamp(1.6 - 8.0 * max(w.x, w.y), 0.0, 1.0);
}
void main() {
  vec3 c = gl_Color.rgb;
  if (u_grid > 0.5) {
    vec2 t = gl_TexCoord[0].st;
    vec2 f = fwidth(t);
    // fwidth(t * 0.5) is 0.5 * fwidth(t) to the bit (halving is exact), so
    // the coarse grid reuses the fine grid's derivatives.
    c *= 1.0 - 0.16 * grid_lines(t, max(f, vec2(1e-5))) - 0.20 * grid_lines(t * 0.5, max(0.5 * f, vec2(1e-5)));
  }
  float fog = clamp((u_fog_range.y - length(v_eye)) / (u_fog_range.y - u_fog_range.x), 0.0, 1.0);
  gl_FragColor = vec4(mix(u_fog_color, c, fog), 1.0);
}
)";

GLuint compile(GLenum type, const char* src) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<size_t>(len > 0 ? len : 1));
    glGetShaderInfoLog(s, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(s);
    throw std::runtime_error(std::string("GLSL compilation failed: ") + log.data());
  }
  return s;
}

void set3(int loc, const Eigen::Vector3f& v) { glUniform3f(loc, v.x(), v.y(), v.z()); }

}  // namespace

Eigen::Vector3f LightingUniforms::up_facing_light() const {
  // What the lit program computes for n = up: ambient = sky, diffuse from both lights.
  return sky_ambient + std::max(0.0f, up_eye.dot(key_dir_eye)) * key_color +
         std::max(0.0f, up_eye.dot(fill_dir_eye)) * fill_color;
}

ShaderProgram::ShaderProgram(const char* vertex, const char* fragment) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string("GLSL link failed: ") + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }
void ShaderProgram::unuse() { glUseProgram(0); }
int ShaderProgram::uniform(const char* name) const { return glGetUniformLocation(program_, name); }

LitProgram::LitProgram() : program_(kVertex, kLitFragment) {
  key_ = program_.uniform("u_key");
  fill_ = program_.uniform("u_fill");
  up_ = program_.uniform("u_up");
  key_color_ = program_.uniform("u_key_color");
  fill_color_ = program_.uniform("u_fill_color");
  sky_ = program_.uniform("u_sky");
  ground_ = program_.uniform("u_ground");
  fog_color_ = program_.uniform("u_fog_color");
  fog_range_ = program_.uniform("u_fog_range");
  material_ = program_.uniform("u_material");
}

void LitProgram::use(const LightingUniforms& u) const {
  program_.use();
  set3(key_, u.key_dir_eye);
  set3(fill_, u.fill_dir_eye);
  set3(up_, u.up_eye);
  set3(key_color_, u.key_color);
  set3(fill_color_, u.fill_color);
  set3(sky_, u.sky_ambient);
  set3(ground_, u.ground_ambient);
  set3(fog_color_, u.fog_color);
  glUniform2f(fog_range_, u.fog_start, u.fog_end);
}

void LitProgram::material(float specular, float shininess, float rim) const {
  glUniform3f(material_, specular, shininess, rim);
}

GroundProgram::GroundProgram() : program_(kVertex, kGroundFragment) {
  fog_color_ = program_.uniform("u_fog_color");
  fog_range_ = program_.uniform("u_fog_range");
  grid_ = program_.uniform("u_grid");
}

void GroundProgram::use(const LightingUniforms& u, bool grid) const {
  program_.use();
  set3(fog_color_, u.fog_color);
  glUniform2f(fog_range_, u.fog_start, u.fog_end);
  glUniform1f(grid_, grid ? 1.0f : 0.0f);
}

}  // namespace robozoo::render
