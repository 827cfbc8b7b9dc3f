#pragma once
// metrics.json of a cloth run (cloth_report.h): the settings, a summary and every step's report,
// written at the end of every run, a diverged one included (where and how it failed).
#include <filesystem>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/cloth_report.h"

namespace animkit {

/// Writes DIR/metrics.json at the end of every run, a diverged one included.
class MetricsSink final : public ClothSink {
 public:
  /// Writes into `dir`; `info` gives the run's settings (its divergence is taken from the run).
  MetricsSink(std::filesystem::path dir, ClothRunInfo info)
      : dir_(std::move(dir)), info_(std::move(info)) {}

  /// Does nothing: the file needs only the run's reports.
  Result<void> begin(const ClothFrame&, int, double) override { return {}; }
  /// Does nothing: the step reports arrive with finish().
  Result<void> frame(const ClothFrame&) override { return {}; }
  /// Writes metrics.json from the run's step reports and divergence, atomically.
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  std::filesystem::path dir_;
  ClothRunInfo info_;
};

}  // namespace animkit
