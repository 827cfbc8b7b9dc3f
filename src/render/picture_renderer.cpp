#include "animkit/render/picture_renderer.h"

namespace animkit {

PictureRenderer::PictureRenderer(OffscreenContext context, Renderer renderer,
                                 OffscreenTarget target)
    : context_(std::move(context)), renderer_(std::move(renderer)), target_(std::move(target)) {}

PictureRenderer::~PictureRenderer() {
  if (context_.valid()) context_.make_current();
}

Result<PictureRenderer> PictureRenderer::create(int width, int height) {
  auto context = OffscreenContext::create();
  if (!context) return fail(context.error().message);
  auto target = OffscreenTarget::create(width, height);
  if (!target) return fail(target.error().message);
  auto renderer = Renderer::create();
  if (!renderer) return fail(renderer.error().message);
  return PictureRenderer(std::move(*context), std::move(*renderer), std::move(*target));
}

Image PictureRenderer::render(const DrawList& list, const OrbitCamera& camera, Rgba background) {
  context_.make_current();
  target_.bind();
  const Viewport viewport{width(), height()};
  renderer_.clear(viewport, background);
  renderer_.draw(list, camera.view(), camera.projection(aspect()), viewport);
  return target_.read();
}

}  // namespace animkit
