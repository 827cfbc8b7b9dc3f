#pragma once
// Runs a command line through the shell and captures what it printed, for behaviour tests.
#include <string>

namespace animkit::testing_support {

struct CommandOutput {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `command` with /bin/sh; stdout and stderr are captured separately.
CommandOutput run_command(const std::string& command);

}  // namespace animkit::testing_support
