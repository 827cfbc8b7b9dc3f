#include "animkit/io/png.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/temp_files.h"

namespace animkit {
namespace {

using testing_support::fresh_dir;

TEST(Png, WrittenPixelsReadBackExactly) {
  Image image(7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      image.at(x, y) = {static_cast<std::uint8_t>(30 * x), static_cast<std::uint8_t>(40 * y), 200,
                        255};
    }
  }
  const auto dir = fresh_dir("png_roundtrip");
  ASSERT_TRUE(write_png(dir / "a.png", image).has_value());
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png.tmp"));
  const auto back = read_image(dir / "a.png");
  ASSERT_TRUE(back.has_value()) << back.error().message;
  ASSERT_EQ(back->width, 7);
  ASSERT_EQ(back->height, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      EXPECT_EQ(back->at(x, y).r, image.at(x, y).r);
      EXPECT_EQ(back->at(x, y).g, image.at(x, y).g);
      EXPECT_EQ(back->at(x, y).b, 200);
    }
  }
}

TEST(Png, EmptyImageIsRefusedAndNothingIsWritten) {
  const auto dir = fresh_dir("png_empty");
  const auto written = write_png(dir / "e.png", Image{});
  ASSERT_FALSE(written.has_value());
  EXPECT_EQ(written.error().message,
            (dir / "e.png").string() + ": cannot encode an empty image as PNG");
  EXPECT_FALSE(std::filesystem::exists(dir / "e.png"));
}

TEST(Png, UnreadableFilesNameTheFileAndTheReason) {
  const auto dir = fresh_dir("png_bad");
  const auto missing = read_image(dir / "missing.png");
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().message, (dir / "missing.png").string() + ": no such file");
  std::ofstream(dir / "text.png") << "not a picture";
  const auto text = read_image(dir / "text.png");
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().message,
            (dir / "text.png").string() +
                ": not an image format animkit reads (supported: PNG, JPEG, BMP, PNM/PGM/PPM/PBM)");
}

}  // namespace
}  // namespace animkit
