#include "animkit/io/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "animkit/core/quote.h"

namespace animkit {

Result<std::string> read_file_bytes(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  const std::string name = shown_path(path.string());  // a NUL or escape shown escaped
  // The operating system reads a path up to its first NUL: "scene.json\0x" would open
  // scene.json, and a message would show only that part.
  if (path.native().find('\0') != std::string::npos)
    return fail(name + ": a path cannot hold a NUL byte");
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) return fail(name + ": no such file");
  if (std::filesystem::is_directory(status)) return fail(name + ": is a folder, not a file");
  // A device (/dev/zero, /dev/urandom) never ends: it would be read up to the limit first.
  // Regular files and pipes (`--scene <(generate)`) are read.
  if (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status) ||
      std::filesystem::is_socket(status))
    return fail(name + ": is a device, not a file");
  // fopen and fread rather than streams: their errno says why (permissions, I/O errors).
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) return fail(name + ": cannot read it (" + std::strerror(errno) + ")");
  const auto size = std::filesystem::file_size(path, error);
  if (!error && size > max_bytes) {
    return fail(name + ": " + std::to_string(size) + " bytes, larger than the limit of " +
                std::to_string(max_bytes) + " bytes");
  }
  std::string bytes;
  // Read in chunks up to the limit: the size above is a hint (a pipe or /proc file has none).
  char chunk[65536];
  while (true) {
    const std::size_t got = std::fread(chunk, 1, sizeof chunk, file.get());
    bytes.append(chunk, got);
    if (bytes.size() > max_bytes) {
      return fail(name + ": larger than the limit of " + std::to_string(max_bytes) + " bytes");
    }
    if (got < sizeof chunk) break;
  }
  if (std::ferror(file.get()))
    return fail(name + ": cannot read it (" + std::strerror(errno) + ")");
  return bytes;
}

}  // namespace animkit
