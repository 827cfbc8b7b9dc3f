#pragma once
// The BVH clip of a command's --in, in metres: at --scale when given, else at the unit its
// legs show (io/bvh_units.h). Shared by footlock and reach.
#include <string>

#include "animkit/io/bvh_units.h"

namespace animkit::cli {

/// Errors are the command's one line: a --scale that is not > 0, the reader's, or a unit that
/// cannot be told (ending "with --scale").
Result<MetricClip> read_input_clip(const std::string& in, double scale, bool scale_given);

}  // namespace animkit::cli
