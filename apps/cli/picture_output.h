#pragma once
// The pictures a CLI run leaves: a PNG of its end and, with --video, every frame through
// ffmpeg. Rendering needs an OpenGL context; it is made only when a picture is asked for.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

#include "animkit/io/video_writer.h"
#include "animkit/render/picture_renderer.h"

namespace animkit::cli {

struct PictureArgs {
  bool no_picture = false;  ///< --no-picture: no PNG in the output folder
  std::string video;        ///< --video FILE.mp4|.gif: empty for none
  int width = 960, height = 720;
};

/// Adds --no-picture, --video and --picture-size to a subcommand; `png_name` is the picture's
/// file name in the --out folder.
void add_picture_options(CLI::App& command, PictureArgs& args, const std::string& png_name);

/// Adds an option `name` taking WIDTHxHEIGHT (each 16..8192 pixels) into args.width and height.
void add_size_option(CLI::App& command, const std::string& name, PictureArgs& args,
                     const std::string& help);

class PictureOutput {
 public:
  /// Opens what `args` asks for: the renderer when a PNG (with an --out folder) or a video is
  /// wanted, and the video. Errors: no OpenGL context (with a hint to pass --no-picture), a bad
  /// size, ffmpeg missing.
  static Result<PictureOutput> open(const PictureArgs& args, bool has_out_folder, double fps);

  bool wants_video() const { return video_.has_value(); }
  /// Whether the next simulation frame goes into the video: all of them up to 60 frames per
  /// second, every k-th one beyond (a cloth run with --dt 0.001 is not a 1000 fps video).
  bool take_video_frame();
  bool wants_png() const { return wants_png_; }
  double aspect() const;

  /// Renders one video frame (nothing when no video was asked for).
  Result<void> add_video_frame(const DrawList& list, const OrbitCamera& camera);
  /// Finishes the video (nothing when none was asked for).
  Result<void> finish_video();
  /// Renders and writes the PNG (nothing when no PNG was asked for).
  Result<void> write_png(const std::filesystem::path& path, const DrawList& list,
                         const OrbitCamera& camera);

 private:
  std::optional<PictureRenderer> renderer_;
  std::optional<VideoWriter> video_;
  bool wants_png_ = false;
  int stride_ = 1;         // simulation frames per video frame
  long long offered_ = 0;  // simulation frames offered to take_video_frame()
};

}  // namespace animkit::cli
