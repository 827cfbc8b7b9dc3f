#pragma once
// Temporary files and folders that a run must never leave behind.
//
// Every temporary gets a name no other run can take, "<name>.animkit-<pid>-<hex>.<kind>",
// beside the file it becomes, and is registered here until it is renamed into place or removed.
// If the process is stopped by SIGINT, SIGTERM or SIGHUP (with install_signal_cleanup()), what
// is registered is removed and child processes (ffmpeg) are killed before it dies of the
// signal. What a killed process (SIGKILL, power loss) leaves is found by the pid in its name and
// removed by the next run that writes into the same folder (remove_stale_temporaries()).
#include <sys/types.h>

#include <filesystem>
#include <string_view>

namespace animkit {

/// "<path>.animkit-<pid>-<12 hex digits>.<kind>": a name beside `path` unique to this process
/// and call. `kind` says what it is: "tmp" (a file being written), "log", "staging" (a folder
/// being filled), "old" (a folder being replaced).
std::filesystem::path unique_sibling(const std::filesystem::path& path, std::string_view kind);

/// Whether `name` (a file name, no folder) is one unique_sibling() made; if so, `pid` is the
/// process that made it.
bool is_animkit_temporary(std::string_view name, pid_t& pid);

/// Registered paths are removed (folders with everything in them) if a signal stops the
/// process. A handle unregisters on destruction or release(); moves transfer it.
class CleanupHandle {
 public:
  /// A handle that registers nothing.
  CleanupHandle() = default;
  /// Registers `path` for removal if a signal stops the process.
  explicit CleanupHandle(const std::filesystem::path& path);
  /// Takes over `other`'s registration; `other` is left holding none.
  CleanupHandle(CleanupHandle&& other) noexcept;
  /// Releases this handle's registration, then takes over `other`'s.
  CleanupHandle& operator=(CleanupHandle&& other) noexcept;
  /// Releases the registration (the path itself is left alone).
  ~CleanupHandle();

  /// Stops watching the path (it was renamed into place or removed).
  void release();

 private:
  int id_ = 0;
};

/// A child process to kill (SIGKILL, then reaped) if a signal stops this one; the same
/// handle semantics as CleanupHandle.
class ChildHandle {
 public:
  /// A handle that registers nothing.
  ChildHandle() = default;
  /// Registers the child process `pid` to be killed if a signal stops this process.
  explicit ChildHandle(pid_t pid);
  /// Takes over `other`'s registration; `other` is left holding none.
  ChildHandle(ChildHandle&& other) noexcept;
  /// Releases this handle's registration, then takes over `other`'s.
  ChildHandle& operator=(ChildHandle&& other) noexcept;
  /// Releases the registration (the child itself is left alone).
  ~ChildHandle();
  /// Stops watching the child (it has ended and been waited for).
  void release();

 private:
  pid_t pid_ = 0;
};

/// For programs (the CLI), not the library: SIGINT, SIGTERM and SIGHUP no longer interrupt the
/// calling thread; a thread of their own waits for them, kills registered children, removes
/// registered temporaries and then ends the process by the same signal (the exit status a
/// shell expects). Call it once, first thing in main, before any other thread exists, so every
/// thread inherits the blocked signals.
void install_signal_cleanup();

/// Removes from `folder` the temporaries of animkit processes that no longer run (files and
/// folders named by unique_sibling() whose pid is gone). An "old" folder whose original is
/// missing (a run died between the two renames of a swap) is renamed back instead. Errors are
/// ignored: this is housekeeping.
void remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace animkit
