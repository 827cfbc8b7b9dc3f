#pragma once
// An output folder replaced whole. A run writes its files into a fresh folder beside the
// target ("<target>.animkit-<pid>-<hex>.staging") and commit() swaps that folder in with one
// atomic rename (renameat2 RENAME_EXCHANGE). So the target holds the previous complete set of
// results or the new complete set, never a mix, whatever stops the run: an error, a diverging
// simulation, a full disk, a signal, or another run into the same folder (the last to finish
// wins, whole).
//
// Replacing a folder whole must never take a user's own files with it, so the target must be
// new, empty or a folder of animkit results: every entry is listed in its ".animkit-outputs"
// file (written by commit()) or is a name earlier versions wrote.
#include <filesystem>

#include "animkit/core/result.h"
#include "animkit/io/temporary_files.h"

namespace animkit {

/// The list of a results folder's entries, written into it by StagedFolder::commit().
inline constexpr const char* kOutputListName = ".animkit-outputs";

/// An output folder being filled beside its target and swapped in whole by commit(); removed,
/// leaving the target untouched, if it is never committed.
class StagedFolder {
 public:
  /// Checks the target and creates the staging folder beside it (creating the target's parent
  /// folders if needed), after removing stale temporaries of dead runs there. Errors: the target
  /// is a file; it holds something animkit did not write (named); it is the current folder or
  /// contains it; its parent cannot be written.
  static Result<StagedFolder> begin(const std::filesystem::path& target);

  /// Takes over `other`'s staging folder; `other` is left owning nothing.
  StagedFolder(StagedFolder&& other) noexcept;
  /// Not assignable: a staged folder stays bound to the target it was begun for.
  StagedFolder& operator=(StagedFolder&&) = delete;
  /// Uncommitted: the staging folder and everything in it are removed; the target is untouched.
  ~StagedFolder();

  /// Where the run writes its files.
  const std::filesystem::path& dir() const { return staging_; }
  /// The folder the user asked for (absolute, symbolic links resolved).
  const std::filesystem::path& target() const { return target_; }

  /// A file the user named that lies directly in the target folder (e.g. --video out/v.mp4
  /// with --out out) goes into the staging folder instead, so it arrives with the rest; other
  /// paths are returned as they are. Error: a path in a subfolder of the target.
  Result<std::filesystem::path> redirect(const std::filesystem::path& path) const;

  /// Lists the files in ".animkit-outputs", syncs the folder and swaps it in; the previous
  /// results are then removed. Errors name the target and the reason; the target is then as it
  /// was.
  Result<void> commit();

 private:
  StagedFolder(std::filesystem::path target, std::filesystem::path staging);
  void abandon();

  std::filesystem::path target_, staging_;
  CleanupHandle cleanup_;
  bool open_ = false;
};

}  // namespace animkit
