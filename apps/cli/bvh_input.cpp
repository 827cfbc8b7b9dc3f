#include "bvh_input.h"

#include <cmath>

#include "animkit/core/validation.h"

namespace animkit::cli {

Result<MetricClip> read_input_clip(const std::string& in, double scale, bool scale_given) {
  if (!scale_given) {
    auto metric = read_bvh_in_metres(in, std::nullopt);
    if (!metric) return fail(metric.error().message + " with --scale");
    return metric;
  }
  if (!(std::isfinite(scale) && scale > 0.0)) {
    return fail("--scale must be a number > 0 (metres per file unit), got " + format_number(scale));
  }
  return read_bvh_in_metres(in, scale);
}

}  // namespace animkit::cli
