#pragma once
// Compiling and linking GLSL programs, with the driver's log in the error.
#include <string>

#include "animkit/core/result.h"
#include "gl.h"

namespace animkit {

struct ShaderSources {
  const char* vertex = nullptr;
  const char* geometry = nullptr;  ///< optional
  const char* fragment = nullptr;
};

/// A linked program, or an error naming the stage and quoting the compiler's log.
Result<GLuint> build_program(const char* name, const ShaderSources& sources);

}  // namespace animkit
