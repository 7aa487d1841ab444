#pragma once
// The OpenGL entry points the snapshot renderer uses, looked up through OSMesaGetProcAddress.
// Looking them up (rather than linking them by name) keeps the calls on Mesa's off-screen
// context even when a program also links the system libGL (GLVND), whose same-named functions
// would dispatch to a GLX context that does not exist. Internal to reports/render.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

namespace feedflow::render {

// Name in the table, GL function.
#define FEEDFLOW_GL_FUNCTIONS(X)                        \
  X(GetString, glGetString)                             \
  X(GetError, glGetError)                               \
  X(GetIntegerv, glGetIntegerv)                         \
  X(Viewport, glViewport)                               \
  X(ClearColor, glClearColor)                           \
  X(ClearDepth, glClearDepth)                           \
  X(Clear, glClear)                                     \
  X(Enable, glEnable)                                   \
  X(Disable, glDisable)                                 \
  X(DepthFunc, glDepthFunc)                             \
  X(DepthMask, glDepthMask)                             \
  X(PixelStorei, glPixelStorei)                         \
  X(ReadPixels, glReadPixels)                           \
  X(Finish, glFinish)                                   \
  X(GenFramebuffers, glGenFramebuffers)                 \
  X(DeleteFramebuffers, glDeleteFramebuffers)           \
  X(BindFramebuffer, glBindFramebuffer)                 \
  X(FramebufferRenderbuffer, glFramebufferRenderbuffer) \
  X(CheckFramebufferStatus, glCheckFramebufferStatus)   \
  X(GenRenderbuffers, glGenRenderbuffers)               \
  X(DeleteRenderbuffers, glDeleteRenderbuffers)         \
  X(BindRenderbuffer, glBindRenderbuffer)               \
  X(RenderbufferStorage, glRenderbufferStorage)         \
  X(CreateShader, glCreateShader)                       \
  X(DeleteShader, glDeleteShader)                       \
  X(ShaderSource, glShaderSource)                       \
  X(CompileShader, glCompileShader)                     \
  X(GetShaderiv, glGetShaderiv)                         \
  X(GetShaderInfoLog, glGetShaderInfoLog)               \
  X(CreateProgram, glCreateProgram)                     \
  X(DeleteProgram, glDeleteProgram)                     \
  X(AttachShader, glAttachShader)                       \
  X(LinkProgram, glLinkProgram)                         \
  X(GetProgramiv, glGetProgramiv)                       \
  X(GetProgramInfoLog, glGetProgramInfoLog)             \
  X(UseProgram, glUseProgram)                           \
  X(GetUniformLocation, glGetUniformLocation)           \
  X(Uniform1f, glUniform1f)                             \
  X(Uniform3f, glUniform3f)                             \
  X(UniformMatrix4fv, glUniformMatrix4fv)               \
  X(GenVertexArrays, glGenVertexArrays)                 \
  X(DeleteVertexArrays, glDeleteVertexArrays)           \
  X(BindVertexArray, glBindVertexArray)                 \
  X(GenBuffers, glGenBuffers)                           \
  X(DeleteBuffers, glDeleteBuffers)                     \
  X(BindBuffer, glBindBuffer)                           \
  X(BufferData, glBufferData)                           \
  X(VertexAttribPointer, glVertexAttribPointer)         \
  X(EnableVertexAttribArray, glEnableVertexAttribArray) \
  X(VertexAttribDivisor, glVertexAttribDivisor)         \
  X(DrawArrays, glDrawArrays)                           \
  X(DrawArraysInstanced, glDrawArraysInstanced)

struct GlApi {
#define FEEDFLOW_GL_MEMBER(name, gl_function) decltype(&::gl_function) name = nullptr;
  FEEDFLOW_GL_FUNCTIONS(FEEDFLOW_GL_MEMBER)
#undef FEEDFLOW_GL_MEMBER

  // Looks every entry point up; throws std::runtime_error naming the first one missing.
  static GlApi load();
};

}  // namespace feedflow::render
