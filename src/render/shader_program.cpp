#include "shader_program.h"

#include <vector>

namespace animkit {

namespace {

std::string log_of(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::vector<char> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  if (is_program) {
    glGetProgramInfoLog(object, length, nullptr, text.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, text.data());
  }
  // Drivers write several lines; errors are reported on one.
  std::string log = text.data();
  while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) log.pop_back();
  for (char& c : log) {
    if (c == '\n') c = ';';
  }
  return log;
}

Result<GLuint> compile(GLenum stage, const char* source, const std::string& what) {
  const GLuint shader = glCreateShader(stage);
  if (shader == 0) return fail(what + ": glCreateShader failed (is a context current?)");
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = log_of(shader, false);
    glDeleteShader(shader);
    return fail(what + " does not compile: " + log);
  }
  return shader;
}

}  // namespace

Result<GLuint> build_program(const char* name, const ShaderSources& sources) {
  const std::string base = std::string("shader '") + name + "'";
  std::vector<GLuint> shaders;
  const auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  const std::pair<GLenum, const char*> stages[] = {{GL_VERTEX_SHADER, sources.vertex},
                                                   {GL_GEOMETRY_SHADER, sources.geometry},
                                                   {GL_FRAGMENT_SHADER, sources.fragment}};
  static constexpr const char* stage_names[] = {"vertex", "geometry", "fragment"};
  for (int k = 0; k < 3; ++k) {
    if (!stages[k].second) continue;
    auto shader =
        compile(stages[k].first, stages[k].second, base + " " + stage_names[k] + " stage");
    if (!shader) {
      cleanup();
      return fail(shader.error().message);
    }
    shaders.push_back(*shader);
  }
  const GLuint program = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = log_of(program, true);
    glDeleteProgram(program);
    return fail(base + " does not link: " + log);
  }
  return program;
}

}  // namespace animkit
