#pragma once
// Reading a whole input file into memory, so every parser works on bytes (and can be fuzzed
// without files) and every reader reports missing, folder, unreadable and oversized files alike.
#include <cstdint>
#include <filesystem>
#include <string>

#include "animkit/core/result.h"

namespace animkit {

/// The file's bytes. Errors name the file (control bytes escaped): "<path>: no such file",
/// "<path>: is a folder, not a file", "<path>: is a device, not a file" (/dev/zero would never
/// end), "<path>: a path cannot hold a NUL byte", "<path>: cannot read it (<reason>)",
/// "<path>: N bytes, larger than the limit of M bytes" (checked before reading, so a huge file
/// is never loaded; a pipe is read up to the limit).
Result<std::string> read_file_bytes(const std::filesystem::path& path, std::uintmax_t max_bytes);

}  // namespace animkit
