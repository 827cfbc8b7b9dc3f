#include "picture_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "animkit/io/png.h"
#include "size_arg.h"

namespace animkit::cli {

void add_picture_options(CLI::App& command, PictureArgs& args, const std::string& png_name) {
  command.add_flag("--no-picture", args.no_picture,
                   "Do not render " + png_name + " into the --out folder (no OpenGL needed)");
  command.add_option("--video", args.video,
                     "Also render every frame into FILE.mp4 or FILE.gif (needs ffmpeg)");
  add_size_option(command, "--picture-size", args,
                  "Picture and video size in pixels, WIDTHxHEIGHT (default 960x720)");
}

void add_size_option(CLI::App& command, const std::string& name, PictureArgs& args,
                     const std::string& help) {
  command.add_option_function<std::string>(
      name,
      [&args, name](const std::string& text) {
        const auto size = apps::parse_pixel_size(text, 16);
        if (!size) {
          throw CLI::ValidationError(name,
                                     "must be WIDTHxHEIGHT, each 16..8192, got '" + text + "'");
        }
        args.width = size->width;
        args.height = size->height;
      },
      help);
}

Result<PictureOutput> PictureOutput::open(const PictureArgs& args, bool has_out_folder,
                                          double fps) {
  PictureOutput output;
  output.wants_png_ = has_out_folder && !args.no_picture;
  if (!output.wants_png_ && args.video.empty()) return output;
  auto renderer = PictureRenderer::create(args.width, args.height);
  if (!renderer) {
    return fail("cannot render pictures: " + renderer.error().message +
                (args.video.empty() ? "; pass --no-picture to run without them" : ""));
  }
  output.renderer_.emplace(std::move(*renderer));
  if (!args.video.empty()) {
    constexpr double kMaxFps = 60.0;
    output.stride_ = std::max(1, static_cast<int>(std::ceil(fps / kMaxFps - 1e-9)));
    auto video = VideoWriter::open(args.video, args.width, args.height, fps / output.stride_);
    if (!video) return fail(video.error().message);
    output.video_.emplace(std::move(*video));
  }
  return output;
}

bool PictureOutput::take_video_frame() {
  return video_ && offered_++ % stride_ == 0;
}

double PictureOutput::aspect() const {
  return renderer_ ? renderer_->aspect() : 4.0 / 3.0;
}

Result<void> PictureOutput::add_video_frame(const DrawList& list, const OrbitCamera& camera) {
  if (!video_) return {};
  return video_->add_frame(renderer_->render(list, camera));
}

Result<void> PictureOutput::finish_video() {
  if (!video_) return {};
  return video_->finish();
}

Result<void> PictureOutput::write_png(const std::filesystem::path& path, const DrawList& list,
                                      const OrbitCamera& camera) {
  if (!wants_png_) return {};
  return animkit::write_png(path, renderer_->render(list, camera));
}

}  // namespace animkit::cli
