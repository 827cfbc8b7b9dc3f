#pragma once
// `animkit footlock --video`: the walk before (thin orange lines) and after foot locking (blue
// bones), planted feet's locks as green points, over the ground, from one fixed camera.
#include "animkit/kinematics/foot_lock.h"
#include "picture_output.h"

namespace animkit::cli {

/// Renders every video frame PictureOutput takes (up to 60 per second of the clip) and
/// finishes the video. `before` and `after` are the clip's motion and its locked one.
Result<void> render_foot_lock_video(const Skeleton& skeleton, const SkeletalMotion& before,
                                    const SkeletalMotion& after, const FootLockResult& result,
                                    PictureOutput& pictures);

}  // namespace animkit::cli
