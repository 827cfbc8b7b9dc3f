#pragma once
// Output files are written whole or not at all: the bytes go to a temporary file beside the
// destination with a name no other run can take (temporary_files.h), created exclusively and
// never through a symbolic link, then flushed, synced and renamed over the destination.
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/io/temporary_files.h"

namespace animkit {

/// A file being written whole or not at all: a temporary beside the destination that commit()
/// renames over it, and the destructor removes if it was never committed.
class AtomicFile {
 public:
  /// Creates the temporary for `path` (O_CREAT | O_EXCL | O_NOFOLLOW) after removing stale
  /// temporaries of dead runs from its folder. Errors name `path` and the reason.
  static Result<AtomicFile> create(const std::filesystem::path& path);

  /// Takes over `other`'s open temporary; `other` is left owning nothing.
  AtomicFile(AtomicFile&& other) noexcept;
  /// Not assignable: an AtomicFile stays bound to the destination it was created for.
  AtomicFile& operator=(AtomicFile&&) = delete;
  /// An uncommitted file is abandoned: the temporary is removed, `path` stays as it was.
  ~AtomicFile();

  /// Where to write (binary). Valid until commit().
  std::FILE* stream() const { return file_; }
  /// The destination: where the file appears once commit() succeeds.
  const std::filesystem::path& path() const { return path_; }

  /// Ends the write: flushes, syncs and closes, then renames the temporary over path(). `ok`
  /// false (an earlier write failed) or any failure here removes the temporary instead, leaving
  /// path() as it was. Errors name the path and the reason (e.g. "No space left on device").
  Result<void> commit(bool ok = true);

 private:
  AtomicFile(std::FILE* file, std::filesystem::path path, std::filesystem::path temporary);
  void abandon();

  std::FILE* file_ = nullptr;
  std::filesystem::path path_, temporary_;
  CleanupHandle cleanup_;
};

/// Writes `content` to `path` atomically. Errors name the path and the reason.
Result<void> write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Creates `dir` (and parents) if needed and checks that it is a writable directory.
Result<void> ensure_output_directory(const std::filesystem::path& dir);

}  // namespace animkit
