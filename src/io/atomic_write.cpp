#include "animkit/io/atomic_write.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace animkit {

std::filesystem::path temporary_path(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  return tmp;
}

std::FILE* open_temporary(const std::filesystem::path& path) {
  return std::fopen(temporary_path(path).c_str(), "wb");
}

Result<void> commit_temporary(std::FILE* file, const std::filesystem::path& path, bool ok) {
  const std::filesystem::path tmp = temporary_path(path);
  int error = ok ? 0 : errno;
  if (ok && (std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0)) error = errno;
  if (std::fclose(file) != 0 && error == 0) error = errno;
  if (!ok || error != 0) {
    std::remove(tmp.c_str());
    return fail("cannot write " + path.string() + ": " + std::strerror(error != 0 ? error : EIO));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    return fail("cannot write " + path.string() + ": " + ec.message());
  }
  return {};
}

Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  std::FILE* file = open_temporary(path);
  if (file == nullptr) {
    return fail("cannot write " + path.string() + ": " + std::strerror(errno));
  }
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  return commit_temporary(file, path, written);
}

Result<void> ensure_output_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail("cannot create output folder " + dir.string() + ": " + ec.message());
  if (!std::filesystem::is_directory(dir)) {
    return fail("output folder " + dir.string() + " is not a directory");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    return fail("output folder " + dir.string() + " is not writable");
  }
  return {};
}

}  // namespace animkit
