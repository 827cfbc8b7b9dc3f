#include "animkit/render/offscreen_target.h"

#include <algorithm>
#include <string>

#include "gl.h"

namespace animkit {

namespace {
constexpr int kMaxSide = 8192;
}

struct OffscreenTarget::Impl {
  int width = 0, height = 0, samples = 1;
  GLuint multisampled = 0, resolved = 0;            // framebuffers
  GLuint color = 0, depth = 0, resolved_color = 0;  // renderbuffers

  ~Impl() {
    const GLuint framebuffers[] = {multisampled, resolved};
    const GLuint renderbuffers[] = {color, depth, resolved_color};
    glDeleteFramebuffers(2, framebuffers);
    glDeleteRenderbuffers(3, renderbuffers);
  }
};

OffscreenTarget::OffscreenTarget(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OffscreenTarget::OffscreenTarget(OffscreenTarget&&) noexcept = default;
OffscreenTarget& OffscreenTarget::operator=(OffscreenTarget&&) noexcept = default;
OffscreenTarget::~OffscreenTarget() = default;

int OffscreenTarget::width() const {
  return impl_->width;
}
int OffscreenTarget::height() const {
  return impl_->height;
}
int OffscreenTarget::samples() const {
  return impl_->samples;
}

Result<OffscreenTarget> OffscreenTarget::create(int width, int height, int samples) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    return fail("picture size must be between 1x1 and " + std::to_string(kMaxSide) + "x" +
                std::to_string(kMaxSide) + ", got " + std::to_string(width) + "x" +
                std::to_string(height));
  }
  auto impl = std::make_unique<Impl>();
  impl->width = width;
  impl->height = height;
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  impl->samples = std::clamp(samples, 1, std::max(1, static_cast<int>(max_samples)));

  glGenRenderbuffers(1, &impl->color);
  glBindRenderbuffer(GL_RENDERBUFFER, impl->color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, impl->samples, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &impl->depth);
  glBindRenderbuffer(GL_RENDERBUFFER, impl->depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, impl->samples, GL_DEPTH_COMPONENT24, width,
                                   height);
  glGenFramebuffers(1, &impl->multisampled);
  glBindFramebuffer(GL_FRAMEBUFFER, impl->multisampled);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, impl->color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, impl->depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return fail("the multisampled framebuffer is incomplete");
  }

  glGenRenderbuffers(1, &impl->resolved_color);
  glBindRenderbuffer(GL_RENDERBUFFER, impl->resolved_color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenFramebuffers(1, &impl->resolved);
  glBindFramebuffer(GL_FRAMEBUFFER, impl->resolved);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            impl->resolved_color);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return fail("the resolve framebuffer is incomplete");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, impl->multisampled);
  return OffscreenTarget(std::move(impl));
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->multisampled);
}

Image OffscreenTarget::read() const {
  const int w = impl_->width, h = impl_->height;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->multisampled);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, impl_->resolved);
  glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->resolved);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  Image bottom_up(w, h);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->multisampled);
  // OpenGL's rows run bottom to top; images run top to bottom.
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    std::copy_n(&bottom_up.at(0, h - 1 - y), w, &image.at(0, y));
  }
  for (Pixel& p : image.pixels) p.a = 255;  // pictures are opaque, whatever blending did

  return image;
}

}  // namespace animkit
