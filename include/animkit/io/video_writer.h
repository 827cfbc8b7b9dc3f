#pragma once
// Videos (.mp4 H.264 or .gif) through the ffmpeg program, fed raw frames on a pipe. Written
// whole or not at all: ffmpeg writes a temporary file beside the video (temporary_files.h),
// which is checked (ffmpeg's exit status, its error output, and ffprobe counting the frames in
// the finished file) and only then renamed into place. The check matters: ffmpeg 5.1 exits 0
// after "Error writing trailer: No space left on device", leaving an MP4 without its index.
#include <sys/types.h>

#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>

#include "animkit/core/image.h"
#include "animkit/core/result.h"
#include "animkit/io/temporary_files.h"

namespace animkit {

/// Where the program `name` (e.g. "ffmpeg") is on PATH, or nothing.
std::optional<std::filesystem::path> find_program(std::string_view name);
/// find_program("ffmpeg").
std::optional<std::filesystem::path> find_ffmpeg();

/// A video being encoded by an ffmpeg child process, renamed into place by finish() once checked
/// complete.
class VideoWriter {
 public:
  /// Starts ffmpeg (no shell in between) for a width x height video at `fps` frames per
  /// second. The format follows the extension: .mp4 or .gif. Errors, all before any frame:
  /// another extension, a folder that does not exist or cannot be written, a name too long,
  /// ffmpeg or ffprobe not installed (the message says how to install them), odd sizes for
  /// .mp4, ffmpeg failing to start. While the video is open SIGPIPE is ignored, so a crashing
  /// ffmpeg is an error, not a killed caller; the previous handler is restored when it ends.
  static Result<VideoWriter> open(const std::filesystem::path& path, int width, int height,
                                  double fps);

  /// Takes over `other`'s ffmpeg process and temporary file; `other` is left owning nothing.
  VideoWriter(VideoWriter&& other) noexcept;
  /// Not assignable: a writer stays bound to the video it opened.
  VideoWriter& operator=(VideoWriter&&) = delete;
  /// Abandons an unfinished video: stops ffmpeg and removes the temporary file.
  ~VideoWriter();

  /// Sends one frame; it must have the size given to open(). Errors: a wrong size, ffmpeg gone.
  Result<void> add_frame(const Image& frame);
  /// Waits for ffmpeg, checks the file is complete and renames it into place. Errors quote
  /// ffmpeg's log (e.g. "No space left on device") or say what the file lacks.
  Result<void> finish();
  /// Frames sent so far by add_frame().
  int frames() const { return frames_; }

 private:
  VideoWriter();
  void abandon();
  void restore_sigpipe();
  Result<void> check_complete() const;

  int pipe_ = -1;  // ffmpeg's standard input
  pid_t ffmpeg_ = 0;
  std::filesystem::path path_, temporary_;
  CleanupHandle temporary_cleanup_;
  struct ErrorLog;  // ffmpeg's standard error, collected in memory
  std::unique_ptr<ErrorLog> errors_;
  ChildHandle child_;
  std::filesystem::path ffprobe_;
  int width_ = 0, height_ = 0, frames_ = 0;
  double gif_resampled_from_ = 0.0;  // a GIF's fps above 50, resampled to 50; else 0
  void (*previous_sigpipe_)(int) = SIG_ERR;
};

}  // namespace animkit
