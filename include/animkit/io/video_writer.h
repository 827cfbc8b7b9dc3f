#pragma once
// Videos (.mp4 H.264 or .gif) through the ffmpeg program, fed raw frames on a pipe. Written
// whole or not at all: ffmpeg writes a temporary file that is renamed when it succeeds.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// Where the ffmpeg program is on PATH, or nothing.
std::optional<std::filesystem::path> find_ffmpeg();

class VideoWriter {
 public:
  /// Starts ffmpeg for a width x height video at `fps` frames per second. The format follows
  /// the extension: .mp4 or .gif. Errors: another extension, a folder that does not exist,
  /// ffmpeg not installed (the message says how to install it), odd sizes for .mp4, ffmpeg
  /// failing to start. While the video is open SIGPIPE is ignored, so a crashing ffmpeg is an
  /// error, not a killed caller; the previous handler is restored when it finishes.
  static Result<VideoWriter> open(const std::filesystem::path& path, int width, int height,
                                  double fps);

  VideoWriter(VideoWriter&& other) noexcept;
  VideoWriter& operator=(VideoWriter&&) = delete;
  /// Abandons an unfinished video: stops ffmpeg and removes the temporary file.
  ~VideoWriter();

  /// Sends one frame; it must have the size given to open(). Errors: a wrong size, ffmpeg gone.
  Result<void> add_frame(const Image& frame);
  /// Waits for ffmpeg and renames the finished file into place. Errors quote ffmpeg's log.
  Result<void> finish();
  int frames() const { return frames_; }

 private:
  VideoWriter(std::FILE* pipe, std::filesystem::path path, std::filesystem::path temporary,
              std::filesystem::path log, int width, int height);
  void abandon();
  void restore_sigpipe();

  std::FILE* pipe_ = nullptr;
  std::filesystem::path path_, temporary_, log_;
  int width_ = 0, height_ = 0, frames_ = 0;
  void (*previous_sigpipe_)(int) = SIG_ERR;
};

}  // namespace animkit
