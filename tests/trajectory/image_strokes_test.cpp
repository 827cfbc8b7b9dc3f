#include "animkit/trajectory/image_strokes.h"

#include <gtest/gtest.h>

#include "animkit/trajectory/stroke_cover.h"
#include "glyph_images.h"

namespace animkit {
namespace {

using namespace testing_support;

// 4-connected pieces of paper: 1 + the number of holes (the paper touches the border).
int paper_pieces(const BinaryImage& ink) {
  BinaryImage paper(ink.width + 2, ink.height + 2);
  for (int y = 0; y < paper.height; ++y) {
    for (int x = 0; x < paper.width; ++x) paper.set(x, y, ink.get(x - 1, y - 1) ? 0 : 1);
  }
  std::vector<int> label(paper.pixels.size(), -1);
  int pieces = 0;
  for (int start = 0; start < static_cast<int>(paper.pixels.size()); ++start) {
    if (!paper.pixels[start] || label[start] >= 0) continue;
    std::vector<int> stack{start};
    label[start] = pieces;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % paper.width, y = p / paper.width;
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (!paper.get(x + dx, y + dy)) continue;
        const int q = (y + dy) * paper.width + x + dx;
        if (label[q] < 0) {
          label[q] = pieces;
          stack.push_back(q);
        }
      }
    }
    ++pieces;
  }
  return pieces;
}

bool one_pixel_thin(const BinaryImage& s) {
  for (int y = 0; y + 1 < s.height; ++y) {
    for (int x = 0; x + 1 < s.width; ++x) {
      if (s.get(x, y) && s.get(x + 1, y) && s.get(x, y + 1) && s.get(x + 1, y + 1)) return false;
    }
  }
  return true;
}

struct Glyph {
  const char* name;
  GrayImage (*make)();
  int strokes;  // an Euler cover: 1 for a path, a loop or an 8; 2 for a T (4 odd ends)
  int holes;
};

class Skeletons : public testing::TestWithParam<std::tuple<Glyph, ThinningMethod>> {};

TEST_P(Skeletons, AreThinKeepTheShapeAndGiveTheExpectedStrokes) {
  const auto& [glyph, method] = GetParam();
  const GrayImage image = glyph.make();
  ImageStrokeOptions options;
  options.thinning = method;
  const auto result = image_to_strokes(image, options);
  ASSERT_TRUE(result.has_value()) << result.error().message;
  const BinaryImage& skeleton = result->skeleton;
  EXPECT_TRUE(one_pixel_thin(skeleton));
  EXPECT_EQ(connected_components(skeleton).sizes.size(), 1u);  // one piece, as drawn
  EXPECT_EQ(paper_pieces(skeleton), 1 + glyph.holes);          // holes kept, none added
  EXPECT_EQ(static_cast<int>(result->strokes.size()), glyph.strokes) << glyph.name;
  // The skeleton runs inside the ink.
  for (int y = 0; y < skeleton.height; ++y) {
    for (int x = 0; x < skeleton.width; ++x) {
      if (skeleton.get(x, y)) {
        ASSERT_LT(image.at(x, y), 128) << x << "," << y;
      }
    }
  }
}

std::string glyph_case_name(const testing::TestParamInfo<std::tuple<Glyph, ThinningMethod>>& p) {
  return std::string(std::get<0>(p.param).name) + "_" +
         (std::get<1>(p.param) == ThinningMethod::zhang_suen ? "zhang_suen" : "guo_hall");
}

INSTANTIATE_TEST_SUITE_P(
    Glyphs, Skeletons,
    testing::Combine(testing::Values(Glyph{"seven", seven, 1, 0}, Glyph{"zero", zero, 1, 1},
                                     Glyph{"eight", eight, 1, 2}, Glyph{"tee", tee, 2, 0}),
                     testing::Values(ThinningMethod::zhang_suen, ThinningMethod::guo_hall)),
    glyph_case_name);

TEST(ImageStrokes, TheRingIsOneClosedStroke) {
  const auto result = image_to_strokes(zero());
  ASSERT_TRUE(result.has_value());
  const Stroke& ring = result->strokes.front();
  EXPECT_LT((ring.front() - ring.back()).norm(), 1e-9);
  EXPECT_NEAR(stroke_length(ring), 2.0 * 3.14159 * 20.0, 12.0);
}

TEST(ImageStrokes, SpecksAreDropped) {
  GrayImage image = seven();
  for (auto [x, y] : {std::pair{4, 60}, {60, 60}, {4, 30}}) image.at(x, y) = 0;  // 1-pixel dust
  image.at(60, 40) = image.at(61, 40) = image.at(60, 41) = 0;                    // a 3-pixel fleck
  const auto result = image_to_strokes(image);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->specks_removed, 4);
  EXPECT_EQ(result->strokes.size(), 1u);
  EXPECT_EQ(result->skeleton.get(4, 60), 0);
  EXPECT_EQ(result->skeleton.get(60, 40), 0);
}

TEST(ImageStrokes, LightInkOnDarkPaperLikeMnist) {
  GrayImage image(64, 64, 0);
  paint_line(image, {14, 12}, {50, 12}, 3.0, 255);
  paint_line(image, {50, 12}, {26, 54}, 3.0, 255);
  const auto result = image_to_strokes(image);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->strokes.size(), 1u);
  EXPECT_GT(stroke_length(result->strokes.front()), 60.0);
}

TEST(ImageStrokes, OtsuSplitsTwoShadesBetweenThem) {
  GrayImage image(10, 10, 200);
  for (int x = 0; x < 10; ++x) image.at(x, 5) = 40;
  const auto t = otsu_threshold(image);
  ASSERT_TRUE(t.has_value());
  EXPECT_GE(*t, 40);
  EXPECT_LT(*t, 200);
  EXPECT_FALSE(otsu_threshold(GrayImage(5, 5, 17)).has_value());
}

TEST(ImageStrokes, ImagesWithNothingToDrawAreErrors) {
  const auto white = image_to_strokes(GrayImage(20, 20, 255));
  ASSERT_FALSE(white.has_value());
  EXPECT_EQ(white.error().message, "the image is a single shade (gray 255): nothing to draw");
  const auto black = image_to_strokes(GrayImage(20, 20, 0));
  ASSERT_FALSE(black.has_value());
  EXPECT_EQ(black.error().message, "the image is a single shade (gray 0): nothing to draw");
  GrayImage dust(40, 40, 255);
  dust.at(3, 3) = 0;
  const auto specks = image_to_strokes(dust);
  ASSERT_FALSE(specks.has_value());
  EXPECT_EQ(specks.error().message,
            "the image has no ink to draw after thresholding at gray 0 and removing specks");
  const auto huge = image_to_strokes(GrayImage(5000, 2, 255));
  ASSERT_FALSE(huge.has_value());
  EXPECT_EQ(huge.error().message, "the image is 5000x2 pixels, larger than the limit of 4096x4096");
  EXPECT_EQ(image_to_strokes(GrayImage{}).error().message, "the image is empty");
}

TEST(SkeletonStrokes, OrderingShortensTravel) {
  // Four short dashes in a scrambled order along a line.
  Strokes dashes{{{30, 0}, {31, 0}}, {{0, 0}, {1, 0}}, {{21, 0}, {20, 0}}, {{10, 0}, {11, 0}}};
  const double before = travel_length(dashes);
  const Strokes ordered = order_for_short_travel(dashes);
  EXPECT_EQ(ordered.size(), 4u);
  EXPECT_LT(travel_length(ordered), before);
  // From 31: the dash at 21 (10 away), reversed ends at 20; then 11 (9), reversed; then 1 (9).
  EXPECT_NEAR(travel_length(ordered), 10.0 + 9.0 + 9.0, 1e-9);
}

}  // namespace
}  // namespace animkit
