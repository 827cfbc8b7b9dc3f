#pragma once
// Output files are written whole or not at all: the bytes go to "<name>.tmp", are flushed,
// and the temporary file is renamed over the destination.
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"

namespace animkit {

/// Writes `content` to `path` atomically. Errors name the path and the reason.
Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Creates `dir` (and parents) if needed and checks that it is a writable directory.
Result<void> ensure_output_directory(const std::filesystem::path& dir);

}  // namespace animkit
