// Foot locking's vocabulary and contact detection: settings, legs, planted spans and the lock
// weights around them. The lock itself is in foot_lock.cpp.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/kinematics/foot_lock.h"

namespace animkit {

namespace {

std::optional<Error> positive(const char* name, double value) {
  if (std::isfinite(value) && value > 0.0) return std::nullopt;
  return Error{std::string("foot lock ") + name + " must be > 0, got " + format_number(value)};
}

Result<LegJoints> find_leg(const Skeleton& skeleton, const std::string& side) {
  LegJoints leg;
  const std::string names[3] = {side + "Hip", side + "Knee", side + "Ankle"};
  int* joints[3] = {&leg.hip, &leg.knee, &leg.ankle};
  for (int i = 0; i < 3; ++i) {
    *joints[i] = skeleton.find_joint(names[i]);
    if (*joints[i] < 0) {
      return fail("no joint named " + names[i] +
                  ": a biped's legs are found by name (LeftHip, LeftKnee, LeftAnkle and the "
                  "same on the right)");
    }
  }
  for (int i = 1; i < 3; ++i) {
    if (skeleton.parents()[*joints[i]] != *joints[i - 1]) {
      return fail("a biped's leg needs " + names[i - 1] + " to be the parent of " + names[i]);
    }
  }
  return leg;
}

// Weights and lock points: 1 and the span's lock on a span; around it, ramps of smoothstep
// weight over `blend` frames toward its lock. A gap short enough for the ramps of its two spans
// to meet (at most 2 blend frames) has the larger of the two weights and a lock moving from the
// first span's to the second's by smoothstep across the gap: both continuous, so no pop.
void assign_weights(int blend, FootContacts& c) {
  const int n = static_cast<int>(c.planted.size());
  const auto ramp = [blend](int outside) {
    return outside > blend ? 0.0 : smoothstep(1.0 - static_cast<double>(outside) / (blend + 1));
  };
  const int spans = static_cast<int>(c.spans.size());
  for (int s = 0; s < spans; ++s) {
    const FootContactSpan& span = c.spans[s];
    for (int f = span.first; f <= span.last; ++f) {
      c.weight[f] = 1.0;
      c.lock[f] = span.lock;
    }
    const int next = s + 1 < spans ? c.spans[s + 1].first : n + blend + 1;
    const bool meet = s + 1 < spans && next - span.last - 1 <= 2 * blend;
    for (int f = span.last + 1; f < std::min(next, n); ++f) {
      if (meet) {
        const FootContactSpan& b = c.spans[s + 1];
        const double t = smoothstep(static_cast<double>(f - span.last) / (b.first - span.last));
        c.weight[f] = std::max(ramp(f - span.last), ramp(b.first - f));
        c.lock[f] = (1.0 - t) * span.lock + t * b.lock;
      } else if (f - span.last <= blend) {
        c.weight[f] = ramp(f - span.last);
        c.lock[f] = span.lock;
      } else if (next - f <= blend) {
        c.weight[f] = ramp(next - f);
        c.lock[f] = c.spans[s + 1].lock;
      }
    }
  }
  // Before the first span: its ramp in.
  if (spans > 0) {
    const FootContactSpan& first = c.spans.front();
    for (int f = std::max(first.first - blend, 0); f < first.first; ++f) {
      c.weight[f] = ramp(first.first - f);
      c.lock[f] = first.lock;
    }
  }
}

}  // namespace

Result<BipedLegs> find_biped_legs(const Skeleton& skeleton) {
  auto left = find_leg(skeleton, "Left");
  if (!left) return std::unexpected(left.error());
  auto right = find_leg(skeleton, "Right");
  if (!right) return std::unexpected(right.error());
  return BipedLegs{*left, *right};
}

std::string_view to_string(KneePole pole) {
  switch (pole) {
    case KneePole::pelvis_forward:
      return "pelvis-forward";
    case KneePole::original:
      return "original";
  }
  return "?";
}

std::optional<KneePole> parse_knee_pole(std::string_view text) {
  for (KneePole pole : {KneePole::pelvis_forward, KneePole::original}) {
    if (text == to_string(pole)) return pole;
  }
  return std::nullopt;
}

std::optional<Error> FootLockSettings::validate() const {
  if (auto e = positive("height threshold", height_threshold)) return e;
  if (auto e = positive("speed threshold", speed_threshold)) return e;
  if (min_contact_frames < 1) {
    return Error{"foot lock minimum contact length must be >= 1 frame, got " +
                 std::to_string(min_contact_frames)};
  }
  if (merge_gap_frames < 0) {
    return Error{"foot lock gap to merge must be >= 0 frames, got " +
                 std::to_string(merge_gap_frames)};
  }
  if (blend_frames < 0) {
    return Error{"foot lock blend must be >= 0 frames, got " + std::to_string(blend_frames)};
  }
  if (!(std::isfinite(soft_reach) && soft_reach >= 0.0)) {
    return Error{"foot lock soft reach must be >= 0 metres, got " + format_number(soft_reach)};
  }
  const bool range_ok = std::isfinite(min_knee_flexion) && std::isfinite(max_knee_flexion) &&
                        min_knee_flexion >= 0.0 && min_knee_flexion < max_knee_flexion &&
                        max_knee_flexion <= std::numbers::pi;
  if (!range_ok) {
    return Error{"foot lock knee flexion range must satisfy 0 <= min < max <= pi radians, got [" +
                 format_number(min_knee_flexion) + ", " + format_number(max_knee_flexion) + "]"};
  }
  return std::nullopt;
}

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double knee_flexion(const Vec3& hip, const Vec3& knee, const Vec3& ankle, const Vec3& forward) {
  const Vec3 thigh = knee - hip, shin = ankle - knee;
  const double angle = std::atan2(thigh.cross(shin).norm(), thigh.dot(shin));
  // The knee's offset from the hip-ankle line says on which side the leg bends.
  const Vec3 axis = ankle - hip;
  const double n2 = axis.squaredNorm();
  const Vec3 offset = n2 > 0.0 ? Vec3(thigh - thigh.dot(axis) / n2 * axis) : thigh;
  return offset.dot(forward) < 0.0 ? -angle : angle;
}

FootContacts detect_foot_contacts(const std::vector<Vec3>& ankle, double frame_time,
                                  double ground_height, const FootLockSettings& settings) {
  assert(!settings.validate());
  const int n = static_cast<int>(ankle.size());
  FootContacts c;
  c.planted.assign(n, 0);
  c.weight.assign(n, 0.0);
  c.lock.assign(n, Vec3::Zero());
  // Low and slow: central differences inside, one-sided at the ends.
  for (int f = 0; f < n; ++f) {
    const int a = std::max(f - 1, 0), b = std::min(f + 1, n - 1);
    const double speed = b > a ? (ankle[b] - ankle[a]).norm() / ((b - a) * frame_time) : 0.0;
    const double height = ankle[f].y() - ground_height;
    c.planted[f] = height <= settings.height_threshold && speed <= settings.speed_threshold;
  }
  // Short gaps between planted runs are filled: one contact, one lock.
  for (int f = 0, last_planted = -1; f < n; ++f) {
    if (!c.planted[f]) continue;
    if (last_planted >= 0 && f - last_planted - 1 <= settings.merge_gap_frames) {
      std::fill(c.planted.begin() + last_planted + 1, c.planted.begin() + f, 1);
    }
    last_planted = f;
  }
  // Runs long enough to be steps become spans, locked at the run's mean ankle position.
  for (int f = 0; f < n;) {
    if (!c.planted[f]) {
      ++f;
      continue;
    }
    int last = f;
    while (last + 1 < n && c.planted[last + 1]) ++last;
    if (last - f + 1 >= settings.min_contact_frames) {
      FootContactSpan span{f, last, Vec3::Zero()};
      for (int g = f; g <= last; ++g) span.lock += ankle[g];
      span.lock /= static_cast<double>(last - f + 1);
      c.spans.push_back(span);
    } else {
      std::fill(c.planted.begin() + f, c.planted.begin() + last + 1, 0);
    }
    f = last + 1;
  }
  assign_weights(settings.blend_frames, c);
  return c;
}

}  // namespace animkit
