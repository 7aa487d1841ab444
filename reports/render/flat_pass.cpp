#include "reports/render/flat_pass.hpp"

#include <cstddef>

#include "reports/render/view_transform.hpp"

namespace feedflow::render {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;  // relative to the camera centre
layout(location = 1) in vec4 colour;
uniform mat4 view_projection;
out vec4 vertex_colour;
void main() {
  gl_Position = view_projection * vec4(position, 1.0);
  vertex_colour = colour;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 vertex_colour;
out vec4 fragment;
void main() { fragment = vertex_colour; }
)";

using Vertex = FlatTriangles::Vertex;

}  // namespace

FlatPass::FlatPass(const OffscreenContext& context)
    : gl_(context.gl()), program_(context.gl(), "flat", kVertexShader, kFragmentShader) {
  gl_.GenVertexArrays(1, &vertex_array_);
  gl_.GenBuffers(1, &buffer_);
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, x)));
  gl_.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, r)));
  gl_.EnableVertexAttribArray(0);
  gl_.EnableVertexAttribArray(1);
  gl_.BindVertexArray(0);
  context.check("flat pass set-up");
}

FlatPass::~FlatPass() {
  gl_.DeleteBuffers(1, &buffer_);
  gl_.DeleteVertexArrays(1, &vertex_array_);
}

void FlatPass::draw(const FlatTriangles& triangles, const Camera& camera) {
  if (triangles.empty()) return;
  program_.use();
  const std::array<float, 16> m = view_projection(camera);
  gl_.UniformMatrix4fv(program_.uniform("view_projection"), 1, GL_TRUE, m.data());
  gl_.BindVertexArray(vertex_array_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  const auto& v = triangles.vertices();
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
                 GL_STREAM_DRAW);
  gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
  gl_.BindVertexArray(0);
}

}  // namespace feedflow::render
