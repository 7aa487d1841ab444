#include "reports/render/offscreen_context.hpp"

#include <GL/osmesa.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace feedflow::render {

namespace {
constexpr int kTokenSize = 16;
}

struct OffscreenContext::Handle {
  OSMesaContext context = nullptr;
};

OffscreenContext::OffscreenContext()
    : handle_(std::make_unique<Handle>()), token_buffer_(4 * kTokenSize * kTokenSize) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  handle_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (handle_->context == nullptr) {
    throw std::runtime_error(
        "OSMesa could not create an OpenGL 3.3 core context; snapshots need Mesa's gallium "
        "software rasteriser (llvmpipe, Debian package libosmesa6)");
  }
  make_current();
  gl_ = GlApi::load();
  const auto text = [this](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl_.GetString(name));
    return std::string(s != nullptr ? s : "?");
  };
  version_ = text(GL_VERSION);
  renderer_ = text(GL_RENDERER);
  GLint size = 0;
  gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &size);
  GLint viewport[2] = {0, 0};
  gl_.GetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  max_size_ = std::min({size, viewport[0], viewport[1]});
  check("context creation");
}

OffscreenContext::~OffscreenContext() {
  if (handle_->context != nullptr) OSMesaDestroyContext(handle_->context);
}

void OffscreenContext::make_current() {
  if (!OSMesaMakeCurrent(handle_->context, token_buffer_.data(), GL_UNSIGNED_BYTE, kTokenSize,
                         kTokenSize)) {
    throw std::runtime_error("OSMesa could not make the off-screen context current");
  }
}

void OffscreenContext::check(const char* during) const {
  const GLenum error = gl_.GetError();
  if (error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(error));
    throw std::runtime_error(std::string("OpenGL error ") + code + " during " + during);
  }
}

RenderTarget::RenderTarget(const OffscreenContext& context, int width, int height)
    : gl_(context.gl()), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > context.max_size() || height > context.max_size()) {
    throw std::invalid_argument("render target " + std::to_string(width) + "x" +
                                std::to_string(height) + " outside 1.." +
                                std::to_string(context.max_size()) + " pixels a side");
  }
  gl_.GenFramebuffers(1, &framebuffer_);
  gl_.GenRenderbuffers(1, &colour_);
  gl_.GenRenderbuffers(1, &depth_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, colour_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, depth_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    gl_.DeleteFramebuffers(1, &framebuffer_);
    gl_.DeleteRenderbuffers(1, &colour_);
    gl_.DeleteRenderbuffers(1, &depth_);
    throw std::runtime_error("off-screen framebuffer " + std::to_string(width) + "x" +
                             std::to_string(height) + " incomplete (status " +
                             std::to_string(status) + ")");
  }
  gl_.Viewport(0, 0, width, height);
}

RenderTarget::~RenderTarget() {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.DeleteFramebuffers(1, &framebuffer_);
  gl_.DeleteRenderbuffers(1, &colour_);
  gl_.DeleteRenderbuffers(1, &depth_);
}

void RenderTarget::bind() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.Viewport(0, 0, width_, height_);
}

RgbaImage RenderTarget::read() const {
  bind();
  RgbaImage image(width_, height_);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  // OpenGL's first row is the bottom one.
  const std::size_t row = 4 * static_cast<std::size_t>(width_);
  std::vector<std::uint8_t> swap(row);
  for (int y = 0; y < height_ / 2; ++y) {
    std::uint8_t* top = image.pixels.data() + row * y;
    std::uint8_t* bottom = image.pixels.data() + row * (height_ - 1 - y);
    std::memcpy(swap.data(), top, row);
    std::memcpy(top, bottom, row);
    std::memcpy(bottom, swap.data(), row);
  }
  return image;
}

}  // namespace feedflow::render
