#pragma once
// How the CLI reports failure: one line on stderr and exit code 2.
#include <string_view>

#include "animkit/core/types.h"

namespace animkit::cli {

constexpr int kExitBadInput = 2;

/// Prints "animkit: error: <message>" on stderr and returns kExitBadInput.
int report_error(std::string_view message);

/// Parses "X,Y,Z" into a vector; false if it is not three finite numbers.
bool parse_vec3(std::string_view text, Vec3& out);

}  // namespace animkit::cli
