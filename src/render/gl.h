#pragma once
// The one place animkit includes OpenGL. Core-profile 3.3 entry points are declared by the
// Khronos header and resolved at link time by glvnd's libOpenGL, which forwards each call to
// whichever context (EGL or GLX) is current, so no loader is needed.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
