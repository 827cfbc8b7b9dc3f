#pragma once
// An OpenGL 3.3 core context for drawing without a window: EGL on Mesa (a surfaceless display,
// then the default display with a pbuffer), falling back to a hidden GLFW window when a display
// exists. Works with no display and no GPU (Mesa's llvmpipe).
#include <memory>
#include <string>

#include "animkit/core/result.h"

namespace animkit {

/// An OpenGL 3.3 core context with no window (or a hidden one), owned by this object: made
/// current by create() and destroyed with it. Move-only.
class OffscreenContext {
 public:
  /// Creates the context and makes it current on this thread. Errors say what each way of
  /// getting a context answered, e.g. "no OpenGL 3.3 context: EGL surfaceless: ...; ...".
  static Result<OffscreenContext> create();

  /// Takes over the context; `other` is left invalid.
  OffscreenContext(OffscreenContext&&) noexcept;
  /// Destroys this context (if any) and takes over `other`'s; `other` is left invalid.
  OffscreenContext& operator=(OffscreenContext&&) noexcept;
  /// Destroys the context (releasing it first if it is current on this thread); the EGL
  /// display and GLFW stay initialized, as other contexts of the process may use them.
  ~OffscreenContext();

  /// Makes the context current on this thread.
  void make_current() const;
  /// False once moved from.
  bool valid() const { return impl_ != nullptr; }
  /// How the context was made and by which renderer, e.g. "EGL surfaceless, llvmpipe (LLVM 15)".
  const std::string& description() const;

 private:
  struct Impl;
  explicit OffscreenContext(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
