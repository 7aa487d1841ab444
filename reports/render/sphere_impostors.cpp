#include "reports/render/sphere_impostors.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "reports/render/sphere_shading.hpp"
#include "reports/render/view_transform.hpp"

namespace feedflow::render {

namespace {

struct Instance {
  float x, y, z, radius;
  std::uint8_t r, g, b, a;
};
static_assert(sizeof(Instance) == 20);

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 sphere;   // centre relative to the camera centre, radius
layout(location = 1) in vec4 colour;
uniform mat4 view_projection;
uniform vec3 right;
uniform vec3 up;
uniform float depth_per_metre;         // window depth per metre along the view direction
out vec2 disc;
flat out vec3 base_colour;
flat out float depth_radius;
void main() {
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, (gl_VertexID & 2) == 0 ? -1.0 : 1.0);
  vec3 p = sphere.xyz + sphere.w * (corner.x * right + corner.y * up);
  gl_Position = view_projection * vec4(p, 1.0);
  disc = corner;
  base_colour = colour.rgb;
  depth_radius = sphere.w * depth_per_metre;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 disc;
flat in vec3 base_colour;
flat in float depth_radius;
uniform vec3 light;
uniform vec3 half_vector;
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float shininess;
out vec4 fragment;
void main() {
  float d2 = dot(disc, disc);
  if (d2 > 1.0) discard;
  vec3 n = vec3(disc, sqrt(1.0 - d2));
  float lambert = max(dot(n, light), 0.0);
  float highlight = specular * pow(max(dot(n, half_vector), 0.0), shininess);
  fragment = vec4(min(base_colour * (ambient + diffuse * lambert) + vec3(highlight), vec3(1.0)),
                  1.0);
  gl_FragDepth = gl_FragCoord.z - n.z * depth_radius;
}
)";

}  // namespace

SphereImpostors::SphereImpostors(const OffscreenContext& context)
    : gl_(context.gl()), program_(context.gl(), "sphere impostor", kVertexShader, kFragmentShader) {
  gl_.GenVertexArrays(1, &vertex_array_);
  gl_.GenBuffers(1, &buffer_);
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  gl_.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(offsetof(Instance, x)));
  gl_.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Instance),
                          reinterpret_cast<const void*>(offsetof(Instance, r)));
  gl_.EnableVertexAttribArray(0);
  gl_.EnableVertexAttribArray(1);
  gl_.VertexAttribDivisor(0, 1);
  gl_.VertexAttribDivisor(1, 1);
  gl_.BindVertexArray(0);
  context.check("sphere impostor set-up");
}

SphereImpostors::~SphereImpostors() {
  gl_.DeleteBuffers(1, &buffer_);
  gl_.DeleteVertexArrays(1, &vertex_array_);
}

void SphereImpostors::draw(const ParticleSet& particles, std::span<const Rgb8> colours,
                           const Camera& camera) {
  const std::size_t n = particles.size();
  if (n == 0) return;
  std::vector<Instance> instances(n);
  const Vec3 c = camera.centre;
  for (std::size_t i = 0; i < n; ++i) {
    instances[i] = {static_cast<float>(particles.x[i] - c.x),
                    static_cast<float>(particles.y[i] - c.y),
                    static_cast<float>(particles.z[i] - c.z),
                    static_cast<float>(particles.radius[i]),
                    colours[i].r,
                    colours[i].g,
                    colours[i].b,
                    255};
  }
  program_.use();
  const std::array<float, 16> m = view_projection(camera);
  gl_.UniformMatrix4fv(program_.uniform("view_projection"), 1, GL_TRUE, m.data());
  const Vec3 r = camera.right();
  const Vec3 u = camera.up;
  gl_.Uniform3f(program_.uniform("right"), static_cast<float>(r.x), static_cast<float>(r.y),
                static_cast<float>(r.z));
  gl_.Uniform3f(program_.uniform("up"), static_cast<float>(u.x), static_cast<float>(u.y),
                static_cast<float>(u.z));
  gl_.Uniform1f(program_.uniform("depth_per_metre"), static_cast<float>(0.5 / camera.half_depth));
  const Vec3 l = SphereShading::light();
  const Vec3 h = SphereShading::half_vector();
  gl_.Uniform3f(program_.uniform("light"), static_cast<float>(l.x), static_cast<float>(l.y),
                static_cast<float>(l.z));
  gl_.Uniform3f(program_.uniform("half_vector"), static_cast<float>(h.x), static_cast<float>(h.y),
                static_cast<float>(h.z));
  gl_.Uniform1f(program_.uniform("ambient"), static_cast<float>(SphereShading::ambient));
  gl_.Uniform1f(program_.uniform("diffuse"), static_cast<float>(SphereShading::diffuse));
  gl_.Uniform1f(program_.uniform("specular"), static_cast<float>(SphereShading::specular));
  gl_.Uniform1f(program_.uniform("shininess"), static_cast<float>(SphereShading::shininess));

  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(Instance)), instances.data(),
                 GL_STREAM_DRAW);
  gl_.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(n));
  gl_.BindVertexArray(0);
}

}  // namespace feedflow::render
