#include "animkit/trajectory/strokes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "animkit/trajectory/trajectory.h"

namespace animkit {
namespace {

// A spiral sampled at equal steps of a parameter that runs slowly at first and fast later:
// the points bunch up near the centre and spread out at the rim.
Stroke uneven_spiral() {
  Stroke s;
  for (int i = 0; i <= 300; ++i) {
    const double t = std::pow(i / 300.0, 3.0);
    const double angle = 6.0 * std::numbers::pi * t;
    s.emplace_back((0.1 + t) * std::cos(angle), (0.1 + t) * std::sin(angle));
  }
  return s;
}

TEST(Resample, EvensOutAnUnevenCurve) {
  const Stroke raw = uneven_spiral();
  const SpacingStats before = spacing_stats({raw});
  EXPECT_GT(before.cv, 1.0);
  const Stroke even = resample(raw, {.spacing = 0.01});
  const SpacingStats after = spacing_stats({even});
  EXPECT_LT(after.cv, 0.05);
  EXPECT_LE(after.max, 0.01 + 1e-12);
  EXPECT_EQ(even.front(), raw.front());
  EXPECT_EQ(even.back(), raw.back());
  EXPECT_NEAR(stroke_length(even), stroke_length(raw), 0.01 * stroke_length(raw));
}

TEST(Resample, KeepsCorners) {
  const Stroke square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  const Stroke even = resample(square, {.spacing = 0.3});
  for (const Point2& corner : square) {
    bool kept = false;
    for (const Point2& p : even) kept = kept || (p - corner).norm() < 1e-12;
    EXPECT_TRUE(kept) << corner.transpose();
  }
  // Each side of length 1 is cut into 4 parts of 0.25: no sample cuts a corner.
  EXPECT_EQ(even.size(), 17u);
  EXPECT_NEAR(spacing_stats({even}).cv, 0.0, 1e-12);
  EXPECT_EQ(find_corners(square, 0.5).size(), 4u);  // the start of a closed stroke included
}

TEST(Resample, KeepsCornersCloserThanTheSpacing) {
  Stroke wave;  // a square wave of steps 0.2, resampled at 0.3
  for (int i = 0; i < 10; ++i) {
    wave.emplace_back(0.2 * i, (i % 2) * 0.2);
    wave.emplace_back(0.2 * (i + 1), (i % 2) * 0.2);
  }
  const Stroke even = resample(wave, {.spacing = 0.3});
  for (std::size_t i = 1; i + 1 < wave.size(); ++i) {
    bool kept = false;
    for (const Point2& p : even) kept = kept || (p - wave[i]).norm() < 1e-12;
    EXPECT_TRUE(kept) << "corner " << i;
  }
}

TEST(Resample, DegenerateStrokesStayPoints) {
  EXPECT_EQ(resample(Stroke{{1, 2}, {1, 2}, {1, 2}}, {}).size(), 1u);
  EXPECT_TRUE(resample(Stroke{}, {}).empty());
  EXPECT_EQ(ResampleOptions{.spacing = 0.0}.validate()->message,
            "spacing must be a positive finite number, got 0");
}

TEST(FitToBox, ScalesUniformlyAndTurnsThePictureUpright) {
  const Strokes drawing{{{0, 0}, {4, 0}, {4, 2}}};
  const auto fitted = fit_to_box(drawing, {.center_x = 0.5, .center_z = -0.2, .half_extent = 0.6});
  ASSERT_TRUE(fitted.has_value());
  const Stroke& s = fitted->front();
  EXPECT_NEAR(s[1].x() - s[0].x(), 1.2, 1e-12);   // the 4-wide side spans 2 * 0.6
  EXPECT_NEAR(s[2].y() - s[1].y(), -0.6, 1e-12);  // up in the picture is -z
  EXPECT_NEAR(0.5 * (s[0].x() + s[1].x()), 0.5, 1e-12);
  EXPECT_FALSE(fit_to_box({}, {}).has_value());
  EXPECT_EQ(fit_to_box({{{0, 0}, {std::nan(""), 1}}}, {}).error().message,
            "stroke 0 point 1 is not finite");
}

TEST(Trajectory, StrokesAreJoinedByPenUpTravel) {
  const Strokes plane{{{0, 0}, {0.1, 0}}, {{0.5, 0}, {0.6, 0}}};
  const auto t = to_trajectory(plane, {.pen_lift = 0.05, .spacing = 0.1});
  ASSERT_TRUE(t.has_value());
  ASSERT_EQ(t->targets.size(), t->pen_down.size());
  int up = 0;
  for (std::size_t i = 0; i < t->targets.size(); ++i) {
    if (!t->pen_down[i]) {
      ++up;
      EXPECT_NEAR(t->targets[i].y(), 0.05, 1e-12);
    } else {
      EXPECT_EQ(t->targets[i].y(), 0.0);
    }
  }
  EXPECT_EQ(up, 5);  // lift, 3 points across 0.4 at 0.1, drop
  const Strokes drawn = pen_down_strokes(*t);
  ASSERT_EQ(drawn.size(), 2u);
  EXPECT_EQ(drawn[1].front(), Point2(0.5, 0.0));
}

TEST(Trajectory, ReachableBoxLiesInsideTheArmsReach) {
  const DrawingBox box = reachable_box(Vec3(0.0, 1.7, 0.0), 2.6);
  const double corner = std::hypot(box.half_extent, box.half_extent);
  EXPECT_LT(std::hypot(corner, 1.7), 2.6);
  EXPECT_GT(box.half_extent, 0.6);  // at least the lab's drawings fit
}

}  // namespace
}  // namespace animkit
