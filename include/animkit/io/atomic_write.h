#pragma once
// Output files are written whole or not at all: the bytes go to "<name>.tmp", are flushed,
// and the temporary file is renamed over the destination.
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"

namespace animkit {

/// "<path>.tmp": where an atomic write puts its bytes until they are complete.
std::filesystem::path temporary_path(const std::filesystem::path& path);

/// Opens "<path>.tmp" for writing (binary); nullptr (with errno) on failure.
std::FILE* open_temporary(const std::filesystem::path& path);

/// Ends an atomic write: flushes, syncs and closes `file` (open on temporary_path(path)), then
/// renames it over `path`. `ok` false (an earlier write failed) or any failure here removes
/// the temporary instead, leaving `path` as it was. Errors name the path and the reason.
Result<void> commit_temporary(std::FILE* file, const std::filesystem::path& path, bool ok = true);

/// Writes `content` to `path` atomically. Errors name the path and the reason.
Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Creates `dir` (and parents) if needed and checks that it is a writable directory.
Result<void> ensure_output_directory(const std::filesystem::path& dir);

}  // namespace animkit
