#include "animkit/io/video_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "child_process.h"

namespace animkit {

namespace {

// The last non-empty line of what ffmpeg printed, or "".
std::string last_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

// Creates `path` exclusively (never through a link): reserves a temporary's name and proves
// the folder can be written before ffmpeg starts. The descriptor, or -1 with errno.
int create_exclusive(const std::filesystem::path& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
}

std::string cannot_write(const std::filesystem::path& path, const std::string& why) {
  return "cannot write " + path.string() + ": " + why;
}

}  // namespace

std::optional<std::filesystem::path> find_program(std::string_view name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
  }
  return std::nullopt;
}

std::optional<std::filesystem::path> find_ffmpeg() {
  return find_program("ffmpeg");
}

struct VideoWriter::ErrorLog {
  detail::PipeCollector collector;
};

VideoWriter::VideoWriter() = default;

VideoWriter::VideoWriter(VideoWriter&& other) noexcept
    : pipe_(std::exchange(other.pipe_, -1)),
      ffmpeg_(std::exchange(other.ffmpeg_, 0)),
      path_(std::move(other.path_)),
      temporary_(std::move(other.temporary_)),
      temporary_cleanup_(std::move(other.temporary_cleanup_)),
      errors_(std::move(other.errors_)),
      child_(std::move(other.child_)),
      ffprobe_(std::move(other.ffprobe_)),
      width_(other.width_),
      height_(other.height_),
      frames_(other.frames_),
      gif_resampled_from_(other.gif_resampled_from_),
      previous_sigpipe_(std::exchange(other.previous_sigpipe_, SIG_ERR)) {}

VideoWriter::~VideoWriter() {
  abandon();
}

void VideoWriter::restore_sigpipe() {
  if (previous_sigpipe_ != SIG_ERR) std::signal(SIGPIPE, previous_sigpipe_);
  previous_sigpipe_ = SIG_ERR;
}

void VideoWriter::abandon() {
  if (pipe_ >= 0) ::close(std::exchange(pipe_, -1));
  if (ffmpeg_ != 0) {
    ::kill(ffmpeg_, SIGKILL);  // an abandoned video is not worth finishing
    detail::wait_program(std::exchange(ffmpeg_, 0));
  }
  child_.release();
  restore_sigpipe();
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_cleanup_.release();
  errors_.reset();
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
    return fail(cannot_write(path, "no folder " + folder.string()));
  }
  const auto ffmpeg = find_ffmpeg();
  const auto ffprobe = find_program("ffprobe");
  if (!ffmpeg || !ffprobe) {
    return fail(cannot_write(path, std::string(ffmpeg ? "ffprobe" : "ffmpeg") +
                                       " is not installed (on Debian: apt-get install ffmpeg)"));
  }
  remove_stale_temporaries(folder);

  VideoWriter writer;
  writer.path_ = path;
  writer.width_ = width;
  writer.height_ = height;
  writer.ffprobe_ = *ffprobe;
  const bool gif = extension == ".gif";
  if (gif && fps > 50.0) writer.gif_resampled_from_ = fps;
  // Both names reserved here: a read-only folder or a name too long is one clear error now,
  // not ffmpeg's complaint later.
  const std::filesystem::path temporary = unique_sibling(path, "tmp");
  const int video_fd = create_exclusive(temporary);
  if (video_fd < 0) return fail(cannot_write(path, std::strerror(errno)));
  ::close(video_fd);
  writer.temporary_ = temporary;
  writer.temporary_cleanup_ = CleanupHandle(temporary);
  auto errors = detail::PipeCollector::open();
  if (!errors) return fail(cannot_write(path, errors.error().message));
  writer.errors_ = std::make_unique<ErrorLog>(ErrorLog{std::move(*errors)});

  std::vector<std::string> argv = {ffmpeg->string(),
                                   "-hide_banner",
                                   "-loglevel",
                                   "error",
                                   "-nostdin",
                                   "-y",
                                   "-f",
                                   "rawvideo",
                                   "-pix_fmt",
                                   "rgba",
                                   "-s",
                                   std::to_string(width) + "x" + std::to_string(height),
                                   "-r",
                                   format_number(fps),
                                   "-i",
                                   "pipe:0"};
  if (gif) {
    // GIF delays are whole hundredths of a second and players stretch 1/100 s to 1/10 s, so
    // above 50 fps frames are dropped to 50 fps (2/100 s each) to keep the timing. One
    // palette for the whole animation, made from its own frames.
    argv.insert(argv.end(), {"-vf",
                             std::string(writer.gif_resampled_from_ > 0.0 ? "fps=50," : "") +
                                 "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse",
                             "-f", "gif"});
  } else {
    argv.insert(argv.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags",
                             "+faststart", "-f", "mp4"});
  }
  argv.push_back("file:" + temporary.string());  // "file:": a name is never a protocol
  int frames_pipe[2];
  if (::pipe2(frames_pipe, O_CLOEXEC) != 0) return fail(cannot_write(path, std::strerror(errno)));
  auto pid = detail::spawn_program(argv, frames_pipe[0], -1, writer.errors_->collector.child_end());
  ::close(frames_pipe[0]);
  writer.errors_->collector.start();
  if (!pid) {
    ::close(frames_pipe[1]);
    return fail(cannot_write(path, pid.error().message));
  }
  writer.pipe_ = frames_pipe[1];
  writer.ffmpeg_ = *pid;
  writer.child_ = ChildHandle(*pid);
  // A pipe to an ffmpeg that died would raise SIGPIPE and kill the caller; while the video is
  // open, a failed write is an error instead (the previous handler comes back after).
  writer.previous_sigpipe_ = std::signal(SIGPIPE, SIG_IGN);
  return writer;
}

Result<void> VideoWriter::add_frame(const Image& frame) {
  if (pipe_ < 0) return fail(path_.string() + ": the video is already finished");
  if (frame.width != width_ || frame.height != height_) {
    return fail(path_.string() + ": frame is " + std::to_string(frame.width) + "x" +
                std::to_string(frame.height) + " but the video is " + std::to_string(width_) + "x" +
                std::to_string(height_));
  }
  const char* bytes = reinterpret_cast<const char*>(frame.pixels.data());
  std::size_t left = frame.pixels.size() * sizeof(Pixel);
  while (left > 0) {
    const ssize_t n = ::write(pipe_, bytes, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(std::exchange(pipe_, -1));
      detail::wait_program(std::exchange(ffmpeg_, 0));
      const std::string reason = last_line(errors_->collector.finish());
      abandon();
      return fail(path_.string() + ": ffmpeg stopped taking frames (" +
                  sanitize_message(reason.empty() ? "no message" : reason, 300) + ")");
    }
    bytes += n;
    left -= static_cast<std::size_t>(n);
  }
  ++frames_;
  return {};
}

Result<void> VideoWriter::check_complete() const {
  // ffprobe decodes the container's index and counts the video packets: a file cut short
  // (no MP4 moov atom, a GIF missing frames) either fails here or counts short.
  auto counted = detail::run_program_output(
      {ffprobe_.string(), "-v", "error", "-count_packets", "-select_streams", "v:0",
       "-show_entries", "stream=nb_read_packets", "-of", "csv=p=0", "file:" + temporary_.string()});
  if (!counted) return fail(path_.string() + ": the finished file cannot be read back");
  char* end = nullptr;
  const long packets = std::strtol(counted->c_str(), &end, 10);
  // Resampling to 50 fps keeps 50 frames of every `fps` sent, give or take one at the ends.
  const bool resampled = gif_resampled_from_ > 0.0;
  const long expected = resampled ? std::lround(frames_ * 50.0 / gif_resampled_from_) : frames_;
  const long slack = resampled ? 2 : 0;
  if (end == counted->c_str() || std::labs(packets - expected) > slack) {
    return fail(path_.string() + ": the finished file holds " + std::to_string(packets) +
                " frames of the " + std::to_string(expected) + " sent");
  }
  return {};
}

Result<void> VideoWriter::finish() {
  if (pipe_ < 0) return fail(path_.string() + ": the video is already finished");
  ::close(std::exchange(pipe_, -1));
  const int status = detail::wait_program(std::exchange(ffmpeg_, 0));
  child_.release();
  restore_sigpipe();
  // With -loglevel error, anything printed is an error, even when ffmpeg exits 0.
  const std::string reason = last_line(errors_->collector.finish());
  Result<void> outcome;
  if (status != 0 || !reason.empty()) {
    outcome = fail(
        path_.string() + ": ffmpeg failed (" +
        sanitize_message(reason.empty() ? "exit status " + std::to_string(status) : reason, 300) +
        ")");
  } else {
    outcome = check_complete();
  }
  if (outcome) {
    // Synced before the rename, like every other output file.
    const int fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) outcome = fail(cannot_write(path_, std::strerror(errno)));
    if (fd >= 0) ::close(fd);
  }
  if (outcome && ::rename(temporary_.c_str(), path_.c_str()) != 0) {
    outcome = fail(cannot_write(path_, std::strerror(errno)));
  } else if (outcome) {
    temporary_.clear();  // renamed into place: not ours to remove any more
  }
  abandon();  // removes the temporary unless it became the video
  return outcome;
}

}  // namespace animkit
