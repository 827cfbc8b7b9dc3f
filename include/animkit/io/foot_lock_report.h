#pragma once
// The files of a foot-locking run (`animkit footlock --out DIR`): metrics.json (contacts,
// sliding before and after, IK error, joint steps, timing, the settings) and compare.png (the
// ankle trails seen from above, then the planted feet's sliding per frame, before and after).
#include <filesystem>
#include <string>
#include <string_view>

#include "animkit/core/image.h"
#include "animkit/core/result.h"
#include "animkit/kinematics/foot_lock.h"

namespace animkit {

/// The clip a foot lock ran on, as its report names it.
struct FootLockClip {
  std::string_view input;        ///< its path, as given
  int frames = 0;                ///< frames in the clip
  double frame_time = 0.0;       ///< seconds per frame
  double metres_per_unit = 1.0;  ///< the scale it was read at
  /// That scale and how it was found (MetricClip::description): "scale 0.056444 m per file
  /// unit (detected: CMU's unit (inch / 0.45), legs 14.2 units long)" or "... (given)".
  std::string_view scale_description;
};

/// The run's facts as JSON: {"input", "frames", "frame_time", "scale": {"metres_per_unit",
/// "description"}, "contacts": {"left", "right"}, "planted_frames": {...}, "sliding_cm_per_frame":
/// {"before": {"mean", "max"}, "after": {...}}, "ik_error_cm": {"mean", "max"},
/// "max_joint_step_cm": {"before", "after"}, "max_leg_step_cm": {...},
/// "max_correction_step_cm", "ms_per_frame", "settings": {...}}.
std::string foot_lock_metrics_json(const FootLockResult& result, const FootLockSettings& settings,
                                   const FootLockClip& clip);

/// Width and height of compare.png: two plots of kFootLockPlotWidth x kFootLockPlotHeight,
/// one above the other.
constexpr int kFootLockPlotWidth = 1000, kFootLockPlotHeight = 620;

/// compare.png: above, the ankles' XZ trails before (orange) and after (blue), planted spans
/// bold green; below, each planted ankle's horizontal motion per frame (cm) against the frame,
/// before and after. Errors: the font's (text_strokes.h).
Result<Image> foot_lock_compare_image(const FootLockResult& result, int frames);

/// Writes metrics.json and compare.png into `dir` (which must exist), each atomically.
Result<void> write_foot_lock_report(const std::filesystem::path& dir, const FootLockResult& result,
                                    const FootLockSettings& settings, const FootLockClip& clip);

}  // namespace animkit
