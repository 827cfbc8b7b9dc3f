#pragma once
// The clock of a motion clip on screen: play, pause, scrub and speed, looping at the clip's
// end. Kept apart from the scene so its arithmetic (which frame shows after how many seconds)
// is tested without a skeleton.
namespace animkit {

/// Play, pause, scrub and speed for a clip of equal-length frames, looping at its end.
class PlaybackClock {
 public:
  /// A clip of `frame_count` frames (>= 1) of `frame_time` seconds (> 0) each, at frame 0,
  /// playing at speed 1 (both asserted).
  PlaybackClock(int frame_count, double frame_time);

  /// When playing, moves the time on by `seconds` (>= 0) x speed, wrapping round the clip's
  /// duration (a negative speed plays backwards and wraps too). Paused: nothing changes.
  void advance(double seconds);
  /// Shows frame `frame`, clamped to [0, frame_count - 1]; the clock keeps playing or paused.
  void seek(int frame);

  /// The frame on screen: floor(time / frame_time), in [0, frame_count - 1].
  int frame() const;
  /// Seconds into the clip, in [0, duration()).
  double time() const { return time_; }
  /// frame_count x frame_time, seconds.
  double duration() const { return frame_count_ * frame_time_; }
  /// Frames in the clip, >= 1.
  int frame_count() const { return frame_count_; }
  /// Seconds per frame, > 0.
  double frame_time() const { return frame_time_; }

  /// Whether advance() moves the time on; false pauses.
  bool playing = true;
  /// Clip seconds per real second; 1 plays at the captured rate.
  double speed = 1.0;

 private:
  int frame_count_;
  double frame_time_;
  double time_ = 0.0;
};

}  // namespace animkit
