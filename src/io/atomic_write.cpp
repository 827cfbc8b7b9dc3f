#include "animkit/io/atomic_write.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace animkit {

Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (file == nullptr) {
    return fail("cannot write " + path.string() + ": " + std::strerror(errno));
  }
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  const int saved_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !flushed || !closed) {
    std::remove(tmp.c_str());
    return fail("cannot write " + path.string() + ": " + std::strerror(saved_errno));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    return fail("cannot write " + path.string() + ": " + ec.message());
  }
  return {};
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
