#include "picture_output.h"

#include <cstdio>

#include "animkit/io/png.h"

namespace animkit::cli {

void add_picture_options(CLI::App& command, PictureArgs& args, const std::string& png_name) {
  command.add_flag("--no-picture", args.no_picture,
                   "Do not render " + png_name + " into the --out folder (no OpenGL needed)");
  command.add_option("--video", args.video,
                     "Also render every frame into FILE.mp4 or FILE.gif (needs ffmpeg)");
  command.add_option_function<std::string>(
      "--picture-size",
      [&args](const std::string& size) {
        int w = 0, h = 0;
        char tail = 0;
        if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 ||
            w > 8192 || h > 8192) {
          throw CLI::ValidationError("--picture-size",
                                     "must be WIDTHxHEIGHT, each 16..8192, got '" + size + "'");
        }
        args.width = w;
        args.height = h;
      },
      "Picture and video size in pixels, WIDTHxHEIGHT (default 960x720)");
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
    auto video = VideoWriter::open(args.video, args.width, args.height, fps);
    if (!video) return fail(video.error().message);
    output.video_.emplace(std::move(*video));
  }
  return output;
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
