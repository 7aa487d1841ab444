#pragma once
// A linked GLSL program (vertex + fragment shader) on the current context. Internal to
// reports/render.
#include <string>

#include "reports/render/gl_api.hpp"

namespace feedflow::render {

class GlProgram {
 public:
  // Throws std::runtime_error with the compiler's log when a shader does not compile or link.
  GlProgram(const GlApi& gl, const char* name, const char* vertex_source,
            const char* fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { gl_.UseProgram(program_); }
  // The location of a uniform; throws std::runtime_error if the program has no such uniform.
  GLint uniform(const char* uniform_name) const;

 private:
  const GlApi& gl_;
  std::string name_;
  GLuint program_ = 0;
};

}  // namespace feedflow::render
