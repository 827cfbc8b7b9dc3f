#pragma once
// "frame 120/600, 1.23 ms/step" on one rewritten line of stderr while a cloth run works, only
// when stderr is a terminal (a log or a pipe gets nothing).
#include <chrono>

#include "animkit/cloth/cloth_run.h"

namespace animkit::cli {

class ProgressLine final : public ClothSink {
 public:
  ProgressLine();

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  int total_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace animkit::cli
