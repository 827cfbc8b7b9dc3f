#include "animkit/io/bvh_units.h"

#include <cstdio>

#include "animkit/io/bvh_motion.h"
#include "animkit/kinematics/body_scale.h"

namespace animkit {

namespace {

std::string shortest(double value, int digits = 6) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace

Result<MetricClip> read_bvh_in_metres(const std::filesystem::path& path,
                                      std::optional<double> scale) {
  if (scale) {
    auto clip = read_bvh_file(path, {.scale = *scale});
    if (!clip) return fail(clip.error().message);
    return MetricClip{.clip = std::move(*clip),
                      .metres_per_unit = *scale,
                      .description = "scale " + shortest(*scale) + " m per file unit (given)"};
  }
  auto clip = read_bvh_file(path);
  if (!clip) return fail(clip.error().message);
  const std::string name = path.string();
  const auto with_hint = [&](const std::string& why) {
    return fail(name + ": " + why + "; give the file's scale (metres per unit)");
  };
  const auto skeleton = build_skeleton(clip->skeleton);
  if (!skeleton) return fail(name + ": " + skeleton.error().message);
  const auto legs = find_biped_legs(*skeleton);
  if (!legs) return with_hint("cannot tell its units: " + legs.error().message);
  const auto body = detect_body_scale(*skeleton, *legs);
  if (!body) return with_hint(body.error().message);
  if (auto ok = scale_bvh_clip(*clip, body->unit.metres); !ok) return fail(ok.error().message);
  return MetricClip{.clip = std::move(*clip),
                    .metres_per_unit = body->unit.metres,
                    .description = "scale " + shortest(body->unit.metres) +
                                   " m per file unit (detected: " + std::string(body->unit.name) +
                                   ", legs " + shortest(body->leg_units, 3) + " units long)"};
}

}  // namespace animkit
