#include "animkit/io/video_writer.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include "../support/temp_files.h"

namespace animkit {
namespace {

using testing_support::fresh_dir;

Image solid(int w, int h, std::uint8_t shade) {
  Image image(w, h);
  for (Pixel& p : image.pixels) p = {shade, 80, 160, 255};
  return image;
}

TEST(VideoWriter, WritesAnMp4AndAGifWhenFfmpegIsThere) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const auto dir = fresh_dir("video");
  for (const char* name : {"clip.mp4", "clip.gif"}) {
    auto video = VideoWriter::open(dir / name, 64, 48, 30.0);
    ASSERT_TRUE(video.has_value()) << video.error().message;
    for (int i = 0; i < 10; ++i) {
      ASSERT_TRUE(video->add_frame(solid(64, 48, static_cast<std::uint8_t>(20 * i))).has_value());
    }
    EXPECT_FALSE(std::filesystem::exists(dir / name));  // not before it is finished
    ASSERT_TRUE(video->finish().has_value());
    EXPECT_GT(std::filesystem::file_size(dir / name), 100u);
    EXPECT_FALSE(std::filesystem::exists(dir / (std::string(name) + ".tmp")));
    EXPECT_FALSE(std::filesystem::exists(dir / (std::string(name) + ".ffmpeg.log")));
  }
}

TEST(VideoWriter, AGifAbove50FpsIsResampledAndStillCheckedComplete) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const auto dir = fresh_dir("video_gif_55");
  for (double fps : {55.0, 60.0}) {
    auto video = VideoWriter::open(dir / "clip.gif", 64, 48, fps);
    ASSERT_TRUE(video.has_value()) << video.error().message;
    for (int i = 0; i < 120; ++i) {
      ASSERT_TRUE(video->add_frame(solid(64, 48, static_cast<std::uint8_t>(2 * i))).has_value());
    }
    const auto finished = video->finish();
    EXPECT_TRUE(finished.has_value()) << fps << " fps: " << finished.error().message;
  }
}

TEST(VideoWriter, AnAbandonedVideoLeavesNoFile) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const auto dir = fresh_dir("video_abandoned");
  {
    auto video = VideoWriter::open(dir / "gone.mp4", 64, 48, 30.0);
    ASSERT_TRUE(video.has_value());
    ASSERT_TRUE(video->add_frame(solid(64, 48, 10)).has_value());
    const auto wrong = video->add_frame(solid(32, 48, 10));
    ASSERT_FALSE(wrong.has_value());
    EXPECT_EQ(wrong.error().message,
              (dir / "gone.mp4").string() + ": frame is 32x48 but the video is 64x48");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(VideoWriter, RefusesWhatItCannotWrite) {
  const auto dir = fresh_dir("video_refused");
  const auto avi = VideoWriter::open(dir / "a.avi", 64, 48, 30.0);
  ASSERT_FALSE(avi.has_value());
  EXPECT_EQ(avi.error().message,
            (dir / "a.avi").string() + ": video files must end in .mp4 or .gif");
  const auto odd = VideoWriter::open(dir / "a.mp4", 63, 48, 30.0);
  ASSERT_FALSE(odd.has_value());
  EXPECT_EQ(odd.error().message,
            (dir / "a.mp4").string() + ": H.264 needs an even width and height, got 63x48");
}

TEST(VideoWriter, MissingFfmpegIsAClearError) {
  const std::string saved = getenv("PATH") ? getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const auto video = VideoWriter::open("x.mp4", 64, 48, 30.0);
  setenv("PATH", saved.c_str(), 1);
  ASSERT_FALSE(video.has_value());
  EXPECT_EQ(video.error().message,
            "cannot write x.mp4: ffmpeg is not installed (on Debian: apt-get install ffmpeg)");
}

}  // namespace
}  // namespace animkit
