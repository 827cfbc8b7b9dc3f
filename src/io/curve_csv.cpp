#include "animkit/io/curve_csv.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "animkit/core/quote.h"
#include "animkit/io/file_bytes.h"
#include "held_fp_exceptions.h"
#include "text_lines.h"

namespace animkit {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// One number, all of `field` (spaces around it allowed), as strtod reads it ("1e-3", "+2").
// Copied first: strtod needs a NUL terminator and the field is a view into the file.
bool parse_number(std::string_view field, double& value) {
  const std::string owned(trim(field));
  char* end = nullptr;
  value = std::strtod(owned.c_str(), &end);
  return !owned.empty() && end == owned.c_str() + owned.size();
}

}  // namespace

Result<Strokes> parse_curve_csv(std::string_view text, std::string_view name) {
  const std::string file(name);
  const HeldFloatingPointExceptions held;
  Strokes strokes(1);
  TextLines lines(text, file);
  while (auto next = lines.next()) {
    if (!*next) return fail(next->error().message);
    const std::string_view line = **next;
    const std::string& where = lines.where();
    const std::string_view content = trim(line);
    if (content.empty()) {
      if (!strokes.back().empty()) strokes.emplace_back();  // pen up
      continue;
    }
    if (content.front() == '#') continue;
    const std::size_t comma = content.find(',');
    double x = 0.0, z = 0.0;
    if (comma == std::string_view::npos || !parse_number(content.substr(0, comma), x) ||
        !parse_number(content.substr(comma + 1), z)) {
      return fail(where + ": expected two finite numbers x,z, got " + quote_input(line));
    }
    if (!std::isfinite(x) || !std::isfinite(z)) {
      return fail(where + ": the point is not finite, got " + quote_input(line));
    }
    strokes.back().emplace_back(x, -z);
  }
  if (strokes.back().empty()) strokes.pop_back();
  if (strokes.empty()) return fail(file + ": no points (expected lines of x,z)");
  return strokes;
}

Result<Strokes> read_curve_csv(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxCurveFileBytes);
  if (!bytes) return fail(bytes.error().message);
  return parse_curve_csv(*bytes, path.string());
}

}  // namespace animkit
