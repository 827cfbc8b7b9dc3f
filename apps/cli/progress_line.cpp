#include "progress_line.h"

#include <unistd.h>

#include <cstdio>

namespace animkit::cli {

ProgressLine::ProgressLine() : enabled_(::isatty(::fileno(stderr)) != 0) {}

Result<void> ProgressLine::begin(const ClothFrame&, int frames, double) {
  total_ = frames;
  return {};
}

Result<void> ProgressLine::frame(const ClothFrame& frame) {
  if (!enabled_) return {};
  const auto now = std::chrono::steady_clock::now();
  if (frame.frame < total_ && now - last_ < std::chrono::milliseconds(200)) return {};
  last_ = now;
  std::fprintf(stderr, "\rframe %d/%d, %.3f ms/step   ", frame.frame, total_, frame.step->ms);
  std::fflush(stderr);
  return {};
}

Result<void> ProgressLine::finish(const ClothRun&, const ClothFrame&) {
  if (enabled_) std::fprintf(stderr, "\n");
  return {};
}

}  // namespace animkit::cli
