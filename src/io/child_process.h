#pragma once
// Internal to animkit_io: starting a program without a shell (posix_spawn), so no file name
// is ever parsed by /bin/sh, and the child starts with default signal handling whatever the
// caller blocked or ignored (install_signal_cleanup() blocks SIGINT, SIGTERM and SIGHUP).
#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "animkit/core/result.h"

namespace animkit::detail {

/// Starts argv[0] (a full path) with argv. Its standard input, output and error become the
/// given descriptors; -1 means /dev/null. Errors: the program could not be started.
Result<pid_t> spawn_program(const std::vector<std::string>& argv, int stdin_fd, int stdout_fd,
                            int stderr_fd);

/// Waits for `pid`; its exit code, or 128 + the signal that killed it.
int wait_program(pid_t pid);

/// Runs argv to the end and returns what it printed on standard output (at most 64 KiB).
/// Errors: it could not be started or did not exit 0.
Result<std::string> run_program_output(const std::vector<std::string>& argv);

/// What a child writes on a pipe (e.g. its standard error), read on a thread of its own so a
/// chatty child never blocks on a full pipe. Kept in memory, not in a file beside the output:
/// on a full disk that file could not hold the reason ("No space left on device") either.
class PipeCollector {
 public:
  /// Creates the pipe. Errors: the system's.
  static Result<PipeCollector> open();
  PipeCollector(PipeCollector&&) noexcept;
  PipeCollector& operator=(PipeCollector&&) noexcept;
  ~PipeCollector();

  /// The end to hand to the child (spawn_program); valid until start().
  int child_end() const;
  /// After the child started: closes the child's end here and starts reading.
  void start();
  /// Waits until the child's end is closed (the child exited) and returns what it wrote (the
  /// last 16 KiB).
  std::string finish();

 private:
  struct State;
  PipeCollector();
  std::unique_ptr<State> state_;
};

}  // namespace animkit::detail
