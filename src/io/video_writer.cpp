#include "animkit/io/video_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

#include "animkit/core/validation.h"

namespace animkit {

namespace {

// 'text' with every ' escaped, for /bin/sh.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string last_lines(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last.empty() ? "no message" : last;
}

}  // namespace

std::optional<std::filesystem::path> find_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / "ffmpeg";
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return std::nullopt;
}

VideoWriter::VideoWriter(std::FILE* pipe, std::filesystem::path path,
                         std::filesystem::path temporary, std::filesystem::path log, int width,
                         int height)
    : pipe_(pipe),
      path_(std::move(path)),
      temporary_(std::move(temporary)),
      log_(std::move(log)),
      width_(width),
      height_(height) {}

VideoWriter::VideoWriter(VideoWriter&& other) noexcept
    : pipe_(std::exchange(other.pipe_, nullptr)),
      path_(std::move(other.path_)),
      temporary_(std::move(other.temporary_)),
      log_(std::move(other.log_)),
      width_(other.width_),
      height_(other.height_),
      frames_(other.frames_),
      previous_sigpipe_(std::exchange(other.previous_sigpipe_, SIG_ERR)) {}

VideoWriter::~VideoWriter() {
  abandon();
}

void VideoWriter::restore_sigpipe() {
  if (previous_sigpipe_ != SIG_ERR) std::signal(SIGPIPE, previous_sigpipe_);
  previous_sigpipe_ = SIG_ERR;
}

void VideoWriter::abandon() {
  if (!pipe_) return;
  pclose(pipe_);
  pipe_ = nullptr;
  restore_sigpipe();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
  std::filesystem::remove(log_, ignored);
}

Result<VideoWriter> VideoWriter::open(const std::filesystem::path& path, int width, int height,
                                      double fps) {
  const std::string extension = path.extension().string();
  if (extension != ".mp4" && extension != ".gif") {
    return fail(path.string() + ": video files must end in .mp4 or .gif");
  }
  if (width < 2 || height < 2 || !std::isfinite(fps) || fps <= 0.0) {
    return fail(path.string() + ": bad video size " + std::to_string(width) + "x" +
                std::to_string(height) + " at " + format_number(fps) + " fps");
  }
  if (extension == ".mp4" && (width % 2 || height % 2)) {
    return fail(path.string() + ": H.264 needs an even width and height, got " +
                std::to_string(width) + "x" + std::to_string(height));
  }
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code folder_error;
  if (!std::filesystem::is_directory(folder, folder_error)) {
    return fail("cannot write " + path.string() + ": no folder " + folder.string());
  }
  const auto ffmpeg = find_ffmpeg();
  if (!ffmpeg) {
    return fail("cannot write " + path.string() +
                ": ffmpeg is not installed (on Debian: apt-get install ffmpeg)");
  }
  const std::filesystem::path temporary = path.string() + ".tmp";
  const std::filesystem::path log = path.string() + ".ffmpeg.log";
  std::ostringstream command;
  command << shell_quote(ffmpeg->string()) << " -hide_banner -loglevel error -nostdin -y"
          << " -f rawvideo -pix_fmt rgba -s " << width << "x" << height << " -r " << fps << " -i -";
  if (extension == ".mp4") {
    command << " -c:v libx264 -pix_fmt yuv420p -crf 20 -movflags +faststart -f mp4";
  } else {
    // GIF delays are whole hundredths of a second and players stretch 1/100 s to 1/10 s, so
    // above 50 fps frames are dropped to 50 fps (2/100 s each) to keep the timing. One
    // palette for the whole animation, made from its own frames.
    command << " -vf '" << (fps > 50.0 ? "fps=50," : "")
            << "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse' -f gif";
  }
  command << " " << shell_quote(temporary.string()) << " 2> " << shell_quote(log.string());
  std::FILE* pipe = popen(command.str().c_str(), "w");
  if (!pipe) {
    return fail("cannot write " + path.string() + ": ffmpeg did not start (" +
                std::generic_category().message(errno) + ")");
  }
  VideoWriter writer(pipe, path, temporary, log, width, height);
  // A pipe to an ffmpeg that died would raise SIGPIPE and kill the caller; while the video is
  // open, a failed write is an error instead (the previous handler comes back after).
  writer.previous_sigpipe_ = std::signal(SIGPIPE, SIG_IGN);
  return writer;
}

Result<void> VideoWriter::add_frame(const Image& frame) {
  if (!pipe_) return fail(path_.string() + ": the video is already finished");
  if (frame.width != width_ || frame.height != height_) {
    return fail(path_.string() + ": frame is " + std::to_string(frame.width) + "x" +
                std::to_string(frame.height) + " but the video is " + std::to_string(width_) + "x" +
                std::to_string(height_));
  }
  const std::size_t bytes = frame.pixels.size() * sizeof(Pixel);
  if (std::fwrite(frame.pixels.data(), 1, bytes, pipe_) != bytes) {
    const std::string reason = last_lines(log_);
    abandon();
    return fail(path_.string() + ": ffmpeg stopped taking frames (" + reason + ")");
  }
  ++frames_;
  return {};
}

Result<void> VideoWriter::finish() {
  if (!pipe_) return fail(path_.string() + ": the video is already finished");
  const int status = pclose(std::exchange(pipe_, nullptr));
  restore_sigpipe();
  const std::string reason = last_lines(log_);
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
  if (status != 0) {
    std::filesystem::remove(temporary_, ignored);
    return fail(path_.string() + ": ffmpeg failed (" + reason + ")");
  }
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) {
    std::filesystem::remove(temporary_, ignored);
    return fail(path_.string() + ": " + error.message());
  }
  return {};
}

}  // namespace animkit
