#pragma once
// Internal to animkit_io: reading a picture or MNIST file whole for the decoders, with the
// errors every image reader shares: missing, a folder, empty, too large to be a picture we
// accept.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "animkit/core/result.h"

namespace animkit::io_detail {

/// Largest image file read into memory: above any picture within kMaxImageSide (a 4096x4096
/// 16-bit ASCII PPM is about 300 MB) and any MNIST file (47 MB).
constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{512} << 20;

/// The bytes of `path`. Errors, each starting with the path: "no such file", "is a folder,
/// not a file", "the file is empty", "the file is N bytes, larger than the limit of 512 MiB",
/// or the system's reason.
Result<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path);

}  // namespace animkit::io_detail
