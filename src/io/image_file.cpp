#include "image_file.h"

#include <string>

#include "animkit/io/file_bytes.h"

namespace animkit::io_detail {

Result<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxInputFileBytes) {
    return fail(name + ": the file is " + std::to_string(size) +
                " bytes, larger than the limit of " + std::to_string(kMaxInputFileBytes >> 20) +
                " MiB");
  }
  auto bytes = animkit::read_file_bytes(path, kMaxInputFileBytes);
  if (!bytes) return fail(bytes.error().message);
  if (bytes->empty()) return fail(name + ": the file is empty");
  return std::vector<std::uint8_t>(bytes->begin(), bytes->end());
}

}  // namespace animkit::io_detail
