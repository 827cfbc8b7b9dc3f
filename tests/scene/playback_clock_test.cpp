#include "animkit/scene/playback_clock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace animkit {
namespace {

TEST(PlaybackClock, ShowsTheFrameTheSecondsReach) {
  PlaybackClock clock(10, 0.1);
  EXPECT_EQ(clock.frame(), 0);
  clock.advance(0.35);
  EXPECT_EQ(clock.frame(), 3);
  clock.speed = 2.0;
  clock.advance(0.1);  // 0.2 s of clip
  EXPECT_EQ(clock.frame(), 5);
  EXPECT_DOUBLE_EQ(clock.duration(), 1.0);
}

TEST(PlaybackClock, PausedItStays) {
  PlaybackClock clock(10, 0.1);
  clock.advance(0.25);
  clock.playing = false;
  clock.advance(5.0);
  EXPECT_EQ(clock.frame(), 2);
}

TEST(PlaybackClock, LoopsAtTheEndBothWays) {
  PlaybackClock clock(10, 0.1);
  clock.advance(1.0 + 0.15);  // one lap and a frame and a half
  EXPECT_EQ(clock.frame(), 1);
  clock.speed = -1.0;
  clock.advance(0.3);  // back past the start
  EXPECT_EQ(clock.frame(), 8);
  EXPECT_GE(clock.time(), 0.0);
  EXPECT_LT(clock.time(), clock.duration());
}

TEST(PlaybackClock, NonFiniteStepsAndSpeedsLeaveItWhereItIs) {
  PlaybackClock clock(10, 0.1);
  clock.seek(3);
  const double before = clock.time();
  clock.advance(std::numeric_limits<double>::infinity());
  clock.advance(std::nan(""));
  clock.speed = std::numeric_limits<double>::infinity();
  clock.advance(0.1);
  EXPECT_EQ(clock.time(), before);
  EXPECT_EQ(clock.frame(), 3);
}

TEST(PlaybackClock, SeekClampsToTheClip) {
  PlaybackClock clock(10, 0.1);
  clock.seek(7);
  EXPECT_EQ(clock.frame(), 7);
  clock.seek(-3);
  EXPECT_EQ(clock.frame(), 0);
  clock.seek(1000);
  EXPECT_EQ(clock.frame(), 9);
  clock.playing = false;
  clock.seek(4);  // scrubbing works while paused
  EXPECT_EQ(clock.frame(), 4);
}

TEST(PlaybackClock, EveryFrameIsShownOnceAtTheCapturedRate) {
  // 1/120 s frames advanced by exactly one frame time: no frame skipped or shown twice.
  PlaybackClock clock(50, 1.0 / 120.0);
  clock.seek(0);
  for (int f = 1; f < 50; ++f) {
    clock.advance(1.0 / 120.0);
    EXPECT_EQ(clock.frame(), f);
  }
  clock.advance(1.0 / 120.0);
  EXPECT_EQ(clock.frame(), 0);
}

}  // namespace
}  // namespace animkit
