#include "animkit/io/curve_csv.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace animkit {

namespace {

// "x,z" (spaces allowed around each number) as two finite numbers.
bool parse_pair(const std::string& line, double& x, double& z) {
  const char* text = line.c_str();
  char* end = nullptr;
  x = std::strtod(text, &end);
  if (end == text) return false;
  while (*end == ' ' || *end == '\t') ++end;
  if (*end != ',') return false;
  const char* second = end + 1;
  z = std::strtod(second, &end);
  if (end == second) return false;
  while (*end == ' ' || *end == '\t' || *end == '\r') ++end;
  return *end == '\0' && std::isfinite(x) && std::isfinite(z);
}

}  // namespace

Result<Strokes> read_curve_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return fail(path.string() + ": cannot open the file");
  Strokes strokes(1);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) {
      if (!strokes.back().empty()) strokes.emplace_back();  // pen up
      continue;
    }
    if (line[first] == '#') continue;
    double x = 0.0, z = 0.0;
    if (!parse_pair(line.substr(first), x, z)) {
      return fail(path.string() + " line " + std::to_string(number) +
                  ": expected two finite numbers x,z, got '" + line + "'");
    }
    strokes.back().emplace_back(x, -z);
  }
  if (strokes.back().empty()) strokes.pop_back();
  if (strokes.empty()) return fail(path.string() + ": no points (expected lines of x,z)");
  return strokes;
}

}  // namespace animkit
