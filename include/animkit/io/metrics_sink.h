#pragma once
// metrics.json of a cloth run (cloth_report.h): the settings, a summary and every step's report,
// written at the end of every run, a diverged one included (where and how it failed).
#include <filesystem>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/cloth_report.h"

namespace animkit {

class MetricsSink final : public ClothSink {
 public:
  MetricsSink(std::filesystem::path dir, ClothRunInfo info)
      : dir_(std::move(dir)), info_(std::move(info)) {}

  Result<void> begin(const ClothFrame&, int, double) override { return {}; }
  Result<void> frame(const ClothFrame&) override { return {}; }
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  std::filesystem::path dir_;
  ClothRunInfo info_;
};

}  // namespace animkit
