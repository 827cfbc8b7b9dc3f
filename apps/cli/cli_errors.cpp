#include "cli_errors.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "animkit/core/quote.h"

namespace animkit::cli {

int report_error(std::string_view message) {
  // Messages may carry user input (a file name, a line of a file, a library's own text):
  // printed made safe, so the error stays one readable line whatever the input held.
  const std::string safe = sanitize_message(message);
  std::fprintf(stderr, "animkit: error: %s\n", safe.c_str());
  return kExitBadInput;
}

bool parse_vec3(std::string_view text, Vec3& out) {
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t comma = text.find(',');
    const bool last = axis == 2;
    if (last != (comma == std::string_view::npos)) return false;
    const std::string_view part = last ? text : text.substr(0, comma);
    // strtod rather than from_chars: it accepts "1e-3", "+2" and leading spaces users type.
    const std::string owned(part);
    char* end = nullptr;
    const double value = std::strtod(owned.c_str(), &end);
    if (owned.empty() || end != owned.c_str() + owned.size() || !std::isfinite(value)) {
      return false;
    }
    out[axis] = value;
    if (!last) text.remove_prefix(comma + 1);
  }
  return true;
}

}  // namespace animkit::cli
