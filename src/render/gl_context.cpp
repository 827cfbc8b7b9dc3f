#include "animkit/render/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

#include "gl.h"

namespace animkit {

namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default:
      return "EGL error " + std::to_string(code);
  }
}

struct EglContext {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;
};

// Initializes `display` and creates a 3.3 core context on it, with a 16x16 pbuffer when
// `pbuffer` (displays without EGL_KHR_surfaceless_context need a surface to be current).
Result<EglContext> make_egl_context(EGLDisplay display, bool pbuffer) {
  if (display == EGL_NO_DISPLAY) return fail("no display");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return fail(egl_error_name(eglGetError()));
  EglContext egl{display};
  // The display stays initialized: it is shared by the whole process (see ~Impl).
  const auto give_up = [&](const std::string& what, EGLint code) {
    if (egl.surface != EGL_NO_SURFACE) eglDestroySurface(display, egl.surface);
    return fail(what + ": " + egl_error_name(code));
  };
  if (!eglBindAPI(EGL_OPENGL_API)) return give_up("eglBindAPI(OpenGL)", eglGetError());
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE,
                                      pbuffer ? EGL_PBUFFER_BIT : 0,
                                      EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_BIT,
                                      EGL_RED_SIZE,
                                      8,
                                      EGL_GREEN_SIZE,
                                      8,
                                      EGL_BLUE_SIZE,
                                      8,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs == 0) {
    return give_up("no RGB8 OpenGL config", eglGetError());
  }
  if (pbuffer) {
    const EGLint surface_attributes[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    egl.surface = eglCreatePbufferSurface(display, config, surface_attributes);
    if (egl.surface == EGL_NO_SURFACE) return give_up("eglCreatePbufferSurface", eglGetError());
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  egl.context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (egl.context == EGL_NO_CONTEXT) return give_up("eglCreateContext(3.3 core)", eglGetError());
  if (!eglMakeCurrent(display, egl.surface, egl.surface, egl.context)) {
    const EGLint code = eglGetError();  // before the clean-up overwrites it
    eglDestroyContext(display, egl.context);
    return give_up("eglMakeCurrent", code);
  }
  return egl;
}

std::string renderer_name() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "unknown renderer";
}

}  // namespace

struct OffscreenContext::Impl {
  EglContext egl;
  GLFWwindow* window = nullptr;
  std::string description;

  ~Impl() {
    if (egl.display != EGL_NO_DISPLAY) {
      // Another context may be current (a second renderer): leave it so.
      const bool current = eglGetCurrentContext() == egl.context;
      if (current) eglMakeCurrent(egl.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(egl.display, egl.context);
      if (egl.surface != EGL_NO_SURFACE) eglDestroySurface(egl.display, egl.surface);
      // The display is not terminated: EGL displays are shared by the whole process (another
      // context may use it), and terminating unloads Mesa's driver, which the next context
      // would load again. Its few driver allocations then stay reachable until exit.
      if (current) eglReleaseThread();
    }
    // GLFW is left initialized: terminating it would close every other GLFW window of the
    // process too.
    if (window) glfwDestroyWindow(window);
  }
};

OffscreenContext::OffscreenContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OffscreenContext::OffscreenContext(OffscreenContext&&) noexcept = default;
OffscreenContext& OffscreenContext::operator=(OffscreenContext&&) noexcept = default;
OffscreenContext::~OffscreenContext() = default;

const std::string& OffscreenContext::description() const {
  return impl_->description;
}

void OffscreenContext::make_current() const {
  if (impl_->window) {
    glfwMakeContextCurrent(impl_->window);
  } else {
    eglMakeCurrent(impl_->egl.display, impl_->egl.surface, impl_->egl.surface, impl_->egl.context);
  }
}

Result<OffscreenContext> OffscreenContext::create() {
  std::string attempts;
  auto impl = std::make_unique<Impl>();

  // 1. Mesa's surfaceless platform: no display server, no window system at all.
  const auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display) {
    auto egl = make_egl_context(
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), false);
    if (egl) {
      impl->egl = *egl;
      impl->description = "EGL surfaceless, " + renderer_name();
      return OffscreenContext(std::move(impl));
    }
    attempts += "EGL surfaceless: " + egl.error().message;
  } else {
    attempts += "EGL surfaceless: eglGetPlatformDisplayEXT missing";
  }

  // 2. EGL's default display (the window system's, when there is one) with a pbuffer.
  auto egl = make_egl_context(eglGetDisplay(EGL_DEFAULT_DISPLAY), true);
  if (egl) {
    impl->egl = *egl;
    impl->description = "EGL pbuffer, " + renderer_name();
    return OffscreenContext(std::move(impl));
  }
  attempts += "; EGL default display: " + egl.error().message;

  // 3. A hidden window, when a display exists.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display && *display) || (wayland && *wayland)) {
    if (glfwInit()) {
      glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
      glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
      glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
      glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
      impl->window = glfwCreateWindow(16, 16, "animkit offscreen", nullptr, nullptr);
      if (impl->window) {
        glfwMakeContextCurrent(impl->window);
        impl->description = "hidden GLFW window, " + renderer_name();
        return OffscreenContext(std::move(impl));
      }
    }
    attempts += "; hidden window: GLFW could not open one";
  } else {
    attempts += "; hidden window: no display (DISPLAY and WAYLAND_DISPLAY are unset)";
  }
  return fail("no OpenGL 3.3 context (" + attempts + ")");
}

}  // namespace animkit
