#include "animkit/io/atomic_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>

namespace animkit {

namespace {

std::string cannot_write(const std::filesystem::path& path, int error) {
  return "cannot write " + path.string() + ": " + std::strerror(error != 0 ? error : EIO);
}

}  // namespace

AtomicFile::AtomicFile(std::FILE* file, std::filesystem::path path, std::filesystem::path temporary)
    : file_(file), path_(std::move(path)), temporary_(std::move(temporary)), cleanup_(temporary_) {}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : file_(std::exchange(other.file_, nullptr)),
      path_(std::move(other.path_)),
      temporary_(std::move(other.temporary_)),
      cleanup_(std::move(other.cleanup_)) {}

AtomicFile::~AtomicFile() {
  abandon();
}

void AtomicFile::abandon() {
  if (file_ == nullptr) return;
  std::fclose(std::exchange(file_, nullptr));
  ::unlink(temporary_.c_str());
  cleanup_.release();
}

Result<AtomicFile> AtomicFile::create(const std::filesystem::path& path) {
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  remove_stale_temporaries(folder);
  const std::filesystem::path temporary = unique_sibling(path, "tmp");
  // O_EXCL and O_NOFOLLOW: a file or link planted at the temporary's name is never written
  // through; the name is unique, so a clash is an attack or a bug, and an error either way.
  const int fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) return fail(cannot_write(path, errno));
  std::FILE* file = ::fdopen(fd, "wb");
  if (file == nullptr) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    return fail(cannot_write(path, error));
  }
  return AtomicFile(file, path, temporary);
}

Result<void> AtomicFile::commit(bool ok) {
  if (file_ == nullptr) return fail(cannot_write(path_, EBADF));
  std::FILE* file = std::exchange(file_, nullptr);
  int error = ok ? 0 : (errno != 0 ? errno : EIO);
  if (ok && (std::ferror(file) || std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0)) {
    error = errno != 0 ? errno : EIO;
  }
  if (std::fclose(file) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary_.c_str(), path_.c_str()) != 0) error = errno;
  if (error != 0) ::unlink(temporary_.c_str());
  cleanup_.release();
  if (error != 0) return fail(cannot_write(path_, error));
  return {};
}

Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  auto file = AtomicFile::create(path);
  if (!file) return fail(file.error().message);
  errno = 0;
  const bool written =
      std::fwrite(content.data(), 1, content.size(), file->stream()) == content.size();
  return file->commit(written);
}

Result<void> ensure_output_directory(const std::filesystem::path& dir) {
  const std::string name = dir.string();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail("cannot create output folder " + name + ": " + ec.message());
  if (!std::filesystem::is_directory(dir)) {
    return fail("output folder " + name + " is not a directory");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    return fail("output folder " + name + " is not writable");
  }
  return {};
}

}  // namespace animkit
