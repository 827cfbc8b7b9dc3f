#include "animkit/io/metrics_sink.h"

#include "animkit/io/atomic_write.h"

namespace animkit {

Result<void> MetricsSink::finish(const ClothRun& run, const ClothFrame&) {
  ClothRunInfo info = info_;
  info.divergence = run.divergence;
  return write_file_atomic(dir_ / "metrics.json", cloth_metrics_json(info, run.steps));
}

}  // namespace animkit
