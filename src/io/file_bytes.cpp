#include "file_bytes.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

namespace animkit::io_detail {

Result<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) return fail(name + ": no such file");
  if (std::filesystem::is_directory(status)) return fail(name + ": is a folder, not a file");
  const auto size = std::filesystem::file_size(path, error);
  if (error) return fail(name + ": " + error.message());
  if (size == 0) return fail(name + ": the file is empty");
  if (size > kMaxInputFileBytes) {
    return fail(name + ": the file is " + std::to_string(size) + " bytes, larger than the limit of " +
                std::to_string(kMaxInputFileBytes >> 20) + " MiB");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(name + ": cannot open the file (" + std::strerror(errno) + ")");
  std::vector<std::uint8_t> bytes(size);
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  // The file may shrink between the size query and the read: keep what was really read.
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.empty()) return fail(name + ": the file is empty");
  return bytes;
}

}  // namespace animkit::io_detail
