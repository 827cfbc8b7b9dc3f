#include "animkit/scene/playback_clock.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace animkit {

PlaybackClock::PlaybackClock(int frame_count, double frame_time)
    : frame_count_(frame_count), frame_time_(frame_time) {
  assert(frame_count >= 1 && frame_time > 0.0);
}

void PlaybackClock::advance(double seconds) {
  // Nothing to advance by unless both are finite (fmod of inf is NaN, which frame() could not
  // turn into an index).
  // (isfinite first: an ordered comparison with NaN raises FE_INVALID.)
  if (!playing || !std::isfinite(seconds) || !std::isfinite(speed) || !(seconds > 0.0)) return;
  const double wrapped = std::fmod(time_ + seconds * speed, duration());
  time_ = wrapped < 0.0 ? wrapped + duration() : wrapped;
  // fmod of a value just below a multiple can round up to the duration itself.
  if (time_ >= duration()) time_ = 0.0;
}

void PlaybackClock::seek(int frame) {
  // The middle of the frame, so rounding in time / frame_time cannot land on its predecessor.
  time_ = (std::clamp(frame, 0, frame_count_ - 1) + 0.5) * frame_time_;
}

int PlaybackClock::frame() const {
  const int f = static_cast<int>(std::floor(time_ / frame_time_));
  return std::clamp(f, 0, frame_count_ - 1);
}

}  // namespace animkit
