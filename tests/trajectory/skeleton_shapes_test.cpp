// Skeletons of awkward shapes: thin diagonals, short arms, filled blobs, mostly-ink images,
// and the Euler cover checked edge by edge on random drawings.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "animkit/trajectory/image_strokes.h"
#include "animkit/trajectory/stroke_cover.h"
#include "glyph_images.h"

namespace animkit {
namespace {

using namespace testing_support;

double total_length(const Strokes& strokes) {
  double length = 0.0;
  for (const Stroke& s : strokes) length += stroke_length(s);
  return length;
}

TEST(SkeletonShapes, ATwoPixelDiagonalLineKeepsItsLength) {
  for (ThinningMethod method : {ThinningMethod::zhang_suen, ThinningMethod::guo_hall}) {
    GrayImage image(64, 64);
    for (int i = 5; i < 55; ++i) image.at(i, i) = image.at(i + 1, i) = 0;  // x - y in {0, 1}
    const auto result = image_to_strokes(image, {.thinning = method});
    ASSERT_TRUE(result.has_value()) << result.error().message;
    ASSERT_EQ(result->strokes.size(), 1u);
    // Not eaten from its ends: the stroke still spans the line.
    const Stroke& s = result->strokes.front();
    EXPECT_NEAR((s.back() - s.front()).norm(), 49.0 * std::sqrt(2.0), 0.1 * 49.0 * std::sqrt(2.0))
        << to_string(method);
  }
}

TEST(SkeletonShapes, AShortArmedPlusKeepsAllFourArms) {
  GrayImage image(48, 48);
  paint_line(image, {12, 24}, {36, 24}, 3.0);
  paint_line(image, {24, 12}, {24, 36}, 3.0);
  for (ThinningMethod method : {ThinningMethod::zhang_suen, ThinningMethod::guo_hall}) {
    const auto result = image_to_strokes(image, {.thinning = method});
    ASSERT_TRUE(result.has_value()) << result.error().message;
    EXPECT_EQ(result->strokes.size(), 2u) << to_string(method);  // four ends: two strokes
    EXPECT_GT(total_length(result->strokes), 0.7 * 48.0) << to_string(method);
  }
}

TEST(SkeletonShapes, AFilledDiscIsADotOrATinyStrokeInItsOwnFrame) {
  GrayImage image(100, 100);
  paint_line(image, {50, 50}, {50, 50}, 20.0);  // a disc of radius 20
  const auto result = image_to_strokes(image);
  ASSERT_TRUE(result.has_value()) << result.error().message;
  EXPECT_LT(total_length(result->strokes), 8.0);
  EXPECT_NEAR(result->extent.sizes().x(), 41.0, 2.0);  // the ink's extent, for placement
}

TEST(SkeletonShapes, AnImageMostlyOfInkDrawsTheInkNotThePaper) {
  GrayImage image(100, 100);
  paint_line(image, {50, 50}, {50, 50}, 45.0);  // ink covers 64% of the image
  const BinaryImage ink = binarize(image, *otsu_threshold(image), InkPolarity::automatic);
  EXPECT_EQ(ink.get(50, 50), 1);
  EXPECT_EQ(ink.get(1, 1), 0);
}

TEST(SkeletonShapes, AOnePixelWideImage) {
  GrayImage image(1, 50);
  for (int y = 10; y < 40; ++y) image.at(0, y) = 0;
  const auto result = image_to_strokes(image);
  ASSERT_TRUE(result.has_value()) << result.error().message;
  ASSERT_EQ(result->strokes.size(), 1u);
  EXPECT_NEAR(total_length(result->strokes), 29.0, 3.0);
}

// Every edge of the graph is drawn exactly once: the unit steps of the strokes, as unordered
// pixel pairs, are the steps of the edges, counted with multiplicity.
TEST(StrokeCover, DrawsEveryEdgeExactlyOnceOnRandomDrawings) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(4.0, 60.0);
  for (int trial = 0; trial < 40; ++trial) {
    GrayImage image(64, 64);
    for (int k = 0; k < 1 + trial % 5; ++k)
      paint_line(image, {u(rng), u(rng)}, {u(rng), u(rng)}, 1.5);
    BinaryImage ink = binarize(image, 127, InkPolarity::dark);
    thin(ink, ThinningMethod::zhang_suen);
    const SkeletonGraph graph = skeleton_graph(ink);
    using Step = std::pair<std::pair<double, double>, std::pair<double, double>>;
    const auto key = [](const Point2& a, const Point2& b) {
      auto p = std::pair{a.x(), a.y()}, q = std::pair{b.x(), b.y()};
      return p < q ? Step{p, q} : Step{q, p};
    };
    std::map<Step, int> expected, drawn;
    for (const auto& e : graph.edges) {
      for (std::size_t i = 1; i < e.pixels.size(); ++i)
        ++expected[key(e.pixels[i - 1], e.pixels[i])];
    }
    for (const Stroke& s : cover_with_strokes(graph)) {
      for (std::size_t i = 1; i < s.size(); ++i) ++drawn[key(s[i - 1], s[i])];
    }
    ASSERT_EQ(drawn, expected) << "trial " << trial;
  }
}

}  // namespace
}  // namespace animkit
