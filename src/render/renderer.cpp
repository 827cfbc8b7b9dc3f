#include "animkit/render/renderer.h"

#include <vector>

#include "gl.h"
#include "shaders.h"

namespace animkit {

namespace {

// One program with its vertex array and a buffer re-filled every frame (scenes change every
// frame, so there is nothing to keep).
struct Batch {
  GLuint program = 0, vao = 0, vbo = 0;
  GLint view_projection = -1, viewport = -1, eye = -1;

  // `layout`: float count of each attribute, in location order.
  void set_up(GLuint linked, std::initializer_list<int> layout) {
    program = linked;
    view_projection = glGetUniformLocation(program, "view_projection");
    viewport = glGetUniformLocation(program, "viewport");
    eye = glGetUniformLocation(program, "eye");
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    int stride = 0;
    for (int count : layout) stride += count;
    GLuint location = 0;
    std::size_t offset = 0;
    for (int count : layout) {
      glEnableVertexAttribArray(location);
      glVertexAttribPointer(location, count, GL_FLOAT, GL_FALSE,
                            static_cast<GLsizei>(stride * sizeof(float)),
                            reinterpret_cast<const void*>(offset * sizeof(float)));
      ++location;
      offset += static_cast<std::size_t>(count);
    }
    glBindVertexArray(0);
  }

  void release() {
    if (vbo) glDeleteBuffers(1, &vbo);
    if (vao) glDeleteVertexArrays(1, &vao);
    if (program) glDeleteProgram(program);
    vbo = vao = program = 0;
  }

  void upload(const std::vector<float>& data) const {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                 GL_STREAM_DRAW);
  }
};

void push(std::vector<float>& out, const Vec3f& v) {
  out.insert(out.end(), {v.x(), v.y(), v.z()});
}
void push(std::vector<float>& out, const Rgba& c) {
  out.insert(out.end(), {c.r, c.g, c.b, c.a});
}

}  // namespace

struct Renderer::Impl {
  Batch lit, lines, points;
  std::vector<float> scratch;  // interleaved vertices, reused between frames

  ~Impl() {
    lit.release();
    lines.release();
    points.release();
  }
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Result<Renderer> Renderer::create() {
  auto impl = std::make_unique<Impl>();
  auto lit = build_program("lit", shaders::lit);
  if (!lit) return fail(lit.error().message);
  impl->lit.set_up(*lit, {3, 3, 4, 4});
  auto lines = build_program("line", shaders::line);
  if (!lines) return fail(lines.error().message);
  impl->lines.set_up(*lines, {3, 4, 1});
  auto points = build_program("point", shaders::point);
  if (!points) return fail(points.error().message);
  impl->points.set_up(*points, {3, 4, 1});
  return Renderer(std::move(impl));
}

void Renderer::clear(const Viewport& viewport, Rgba background) const {
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(viewport.x, viewport.y, viewport.width, viewport.height);
  glClearColor(background.r, background.g, background.b, background.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw(const DrawList& list, const Eigen::Matrix4d& view,
                    const Eigen::Matrix4d& projection, const Viewport& viewport) {
  const Eigen::Matrix4f view_projection = (projection * view).cast<float>();
  const Eigen::Vector3f eye =
      (-view.block<3, 3>(0, 0).transpose() * view.block<3, 1>(0, 3)).cast<float>();
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_MULTISAMPLE);
  std::vector<float>& data = impl_->scratch;

  const auto use = [&](const Batch& batch) {
    glUseProgram(batch.program);
    glUniformMatrix4fv(batch.view_projection, 1, GL_FALSE, view_projection.data());
    if (batch.viewport >= 0) {
      glUniform2f(batch.viewport, static_cast<float>(viewport.width),
                  static_cast<float>(viewport.height));
    }
    if (batch.eye >= 0) glUniform3f(batch.eye, eye.x(), eye.y(), eye.z());
    glBindVertexArray(batch.vao);
  };

  if (!list.triangles.empty()) {
    data.clear();
    for (const LitVertex& v : list.triangles) {
      push(data, v.position);
      push(data, v.normal);
      push(data, v.front);
      push(data, v.back);
    }
    use(impl_->lit);
    impl_->lit.upload(data);
    glDisable(GL_BLEND);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(list.triangles.size()));
  }
  // Lines and markers have soft edges: blend them, and keep them from writing depth so their
  // translucent rims never hide what is drawn after them.
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  if (!list.points.empty()) {
    data.clear();
    for (const PointMarker& p : list.points) {
      push(data, p.position);
      push(data, p.color);
      data.push_back(p.size_px);
    }
    use(impl_->points);
    impl_->points.upload(data);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(list.points.size()));
  }
  if (!list.lines.empty()) {
    data.clear();
    for (const LineSegment& l : list.lines) {
      push(data, l.a);
      push(data, l.color);
      data.push_back(l.width_px);
      push(data, l.b);
      push(data, l.color);
      data.push_back(l.width_px);
    }
    use(impl_->lines);
    impl_->lines.upload(data);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(2 * list.lines.size()));
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace animkit
