#pragma once
// A BVH clip read in metres, whatever its file's unit: the scale given, or one detected from
// the skeleton's legs (body_scale.h), and a sentence that says which, for the shells to print.
#include <filesystem>
#include <optional>
#include <string>

#include "animkit/io/bvh.h"

namespace animkit {

/// A BVH clip scaled to metres, with the scale used and how it was chosen.
struct MetricClip {
  BvhClip clip;                  ///< offsets and positions in metres
  double metres_per_unit = 1.0;  ///< of the file
  /// "scale 0.056444 m per file unit (detected: CMU's unit (inch / 0.45), legs 14.2 units
  /// long)" or "scale 0.01 m per file unit (given)".
  std::string description;
};

/// Reads `path` at `scale` metres per file unit, or, without one, at the unit its legs show
/// (legs named as find_biped_legs wants them). Errors: the reader's, a skeleton without such
/// legs or of no recognizable size (each saying to give the scale).
Result<MetricClip> read_bvh_in_metres(const std::filesystem::path& path,
                                      std::optional<double> scale);

}  // namespace animkit
