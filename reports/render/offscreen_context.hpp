#pragma once
// An OpenGL 3.3 core context on Mesa's off-screen software rasteriser (OSMesa; llvmpipe on
// Debian 12): no display, no GPU. Drawing goes to framebuffer objects (RenderTarget), so the
// context's own buffer is a token 16 x 16 pixels. Internal to reports/render.
#include <memory>
#include <string>
#include <vector>

#include "reports/render/gl_api.hpp"
#include "reports/render/rgba_image.hpp"

namespace feedflow::render {

class OffscreenContext {
 public:
  // Loads libOSMesa on first use: throws NotAvailable when it cannot be loaded
  // (osmesa_library.cpp), std::runtime_error when OSMesa cannot create or bind a 3.3 core context.
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // Binds the context to the calling thread; call before drawing on a new thread.
  void make_current();
  const GlApi& gl() const { return gl_; }
  // "4.5 (Core Profile) Mesa 22.3.6" and "llvmpipe (LLVM 15.0.6, 256 bits)" here.
  const std::string& version() const { return version_; }
  const std::string& renderer() const { return renderer_; }
  int max_size() const { return max_size_; }
  // Throws std::runtime_error naming `during` if OpenGL has recorded an error.
  void check(const char* during) const;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
  std::vector<unsigned char> token_buffer_;
  GlApi gl_;
  std::string version_;
  std::string renderer_;
  int max_size_ = 0;
};

// A colour (RGBA8) and depth framebuffer of a given size on the current context.
class RenderTarget {
 public:
  // Throws std::invalid_argument for a size beyond the context's limit, std::runtime_error when
  // the framebuffer is incomplete.
  RenderTarget(const OffscreenContext& context, int width, int height);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  // The pixels, top row first.
  RgbaImage read() const;

 private:
  const GlApi& gl_;
  int width_;
  int height_;
  GLuint framebuffer_ = 0;
  GLuint colour_ = 0;
  GLuint depth_ = 0;
};

}  // namespace feedflow::render
