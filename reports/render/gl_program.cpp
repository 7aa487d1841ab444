#include "reports/render/gl_program.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace feedflow::render {

namespace {

GLuint compile(const GlApi& gl, const std::string& program, GLenum kind, const char* source) {
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    gl.DeleteShader(shader);
    throw std::runtime_error("shader " + program +
                             (kind == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                             " does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const GlApi& gl, const char* name, const char* vertex_source,
                     const char* fragment_source)
    : gl_(gl), name_(name) {
  const GLuint vertex = compile(gl, name_, GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = compile(gl, name_, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vertex);
  gl.AttachShader(program_, fragment);
  gl.LinkProgram(program_);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::vector<char> log(1024, '\0');
    gl.GetProgramInfoLog(program_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    gl.DeleteProgram(program_);
    throw std::runtime_error("shader program " + name_ + " does not link: " + log.data());
  }
}

GlProgram::~GlProgram() { gl_.DeleteProgram(program_); }

GLint GlProgram::uniform(const char* uniform_name) const {
  const GLint location = gl_.GetUniformLocation(program_, uniform_name);
  if (location < 0) {
    throw std::runtime_error("shader program " + name_ + " has no uniform " + uniform_name);
  }
  return location;
}

}  // namespace feedflow::render
