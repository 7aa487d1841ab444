#include "reports/render/gl_api.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace feedflow::render {

GlApi GlApi::load() {
  GlApi api;
#define FEEDFLOW_GL_LOOKUP(name, gl_function)                                              \
  api.name = reinterpret_cast<decltype(api.name)>(OSMesaGetProcAddress(#gl_function));     \
  if (api.name == nullptr) {                                                               \
    throw std::runtime_error("OSMesa does not provide the OpenGL function " #gl_function); \
  }
  FEEDFLOW_GL_FUNCTIONS(FEEDFLOW_GL_LOOKUP)
#undef FEEDFLOW_GL_LOOKUP
  return api;
}

}  // namespace feedflow::render
