// Drawings from every source, placed in the arm's reach and drawn: the arm converges on every
// target, strokes are evenly sampled, and pen-up travel is left out of the drawn path.
#include "animkit/io/drawing_source.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/temp_files.h"
#include "../trajectory/glyph_images.h"
#include "animkit/io/png.h"
#include "animkit/kinematics/drawing_session.h"

namespace animkit {
namespace {

using testing_support::fresh_dir;

const Chain& arm() {
  static const Chain chain = *build_chain(lab_arm());
  return chain;
}

// Runs the drawing with both solvers and checks every target converged.
void expect_drawn_everywhere(const PreparedDrawing& d) {
  for (IkSolverKind solver : all_ik_solvers()) {
    DrawingOptions options;
    options.solver = solver;
    const auto run = run_drawing(arm(), d.trajectory.targets, options, d.trajectory.pen_down);
    ASSERT_TRUE(run.has_value()) << run.error().message;
    const DrawingSummary s = summarize(*run);
    EXPECT_EQ(s.converged_fraction, 1.0) << d.name << " with " << to_string(solver);
    EXPECT_EQ(s.unreachable_targets, 0) << d.name;
    // The drawn path has one polyline per stroke: travel is not drawn.
    EXPECT_EQ(static_cast<int>(drawn_strokes(run->frames).size()), d.strokes) << d.name;
  }
}

void expect_inside(const PreparedDrawing& d, const DrawingBox& box) {
  for (std::size_t i = 0; i < d.trajectory.targets.size(); ++i) {
    if (!d.trajectory.pen_down[i]) continue;
    const Vec3& t = d.trajectory.targets[i];
    EXPECT_LE(std::abs(t.x() - box.center_x), box.half_extent + 1e-9);
    EXPECT_LE(std::abs(t.z() - box.center_z), box.half_extent + 1e-9);
    EXPECT_EQ(t.y(), 0.0);
  }
}

TEST(PrepareDrawing, TextFitsTheReachableAreaAndIsDrawnEverywhere) {
  DrawingSource source;
  source.kind = DrawingSourceKind::text;
  source.text = "QD";
  const auto d = prepare_drawing(source, {}, arm());
  ASSERT_TRUE(d.has_value()) << d.error().message;
  EXPECT_EQ(d->name, "text QD");
  EXPECT_EQ(d->strokes, 4);
  expect_inside(*d, reachable_box(arm().root_position(), arm().reach()));
  EXPECT_LT(d->spacing_after.cv, 0.05);
  EXPECT_LE(d->spacing_after.max, 0.01 + 1e-9);
  EXPECT_GT(d->spacing_before.cv, 0.5);  // outlines: long straight edges, dense curves
  expect_drawn_everywhere(*d);
}

TEST(PrepareDrawing, ImagesOfDigitsAreDrawnAsTheirSkeletons) {
  const auto dir = fresh_dir("drawing_images");
  const std::pair<const char*, GrayImage (*)()> digits[] = {{"seven", testing_support::seven},
                                                            {"zero", testing_support::zero},
                                                            {"eight", testing_support::eight},
                                                            {"tee", testing_support::tee}};
  for (const auto& [name, make] : digits) {
    const GrayImage gray = make();
    Image image(gray.width, gray.height);
    for (std::size_t i = 0; i < gray.pixels.size(); ++i) {
      image.pixels[i] = {gray.pixels[i], gray.pixels[i], gray.pixels[i], 255};
    }
    const auto path = dir / (std::string(name) + ".png");
    ASSERT_TRUE(write_png(path, image).has_value());
    DrawingSource source;
    source.kind = DrawingSourceKind::image;
    source.file = path;
    const DrawingBox box{0.2, -0.1, 0.5};
    const auto d = prepare_drawing(source, {.box = box}, arm());
    ASSERT_TRUE(d.has_value()) << d.error().message;
    EXPECT_EQ(d->strokes, std::string(name) == "tee" ? 2 : 1) << name;
    expect_inside(*d, box);
    EXPECT_LT(d->spacing_after.cv, 0.05) << name;
    expect_drawn_everywhere(*d);
  }
}

TEST(PrepareDrawing, TheUnevenSpiralIsEvenedOutOnRequest) {
  DrawingSource source;
  source.shape = "spiral";
  const auto raw = prepare_drawing(source, {}, arm());
  ASSERT_TRUE(raw.has_value());
  EXPECT_GT(raw->spacing_after.cv, 1.0);  // the built-in sampling, kept
  const auto even = prepare_drawing(source, {.spacing = 0.01}, arm());
  ASSERT_TRUE(even.has_value());
  EXPECT_GT(even->spacing_before.cv, 1.0);
  EXPECT_LT(even->spacing_after.cv, 0.05);
  expect_drawn_everywhere(*even);
}

TEST(PrepareDrawing, CurvesKeepTheirStrokes) {
  const auto dir = fresh_dir("drawing_curve");
  std::ofstream(dir / "ab.csv") << "0,0\n0,1\n1,1\n\n2,0\n3,1\n";
  DrawingSource source;
  source.kind = DrawingSourceKind::curve;
  source.file = dir / "ab.csv";
  const auto d = prepare_drawing(source, {}, arm());
  ASSERT_TRUE(d.has_value()) << d.error().message;
  EXPECT_EQ(d->strokes, 2);
  expect_drawn_everywhere(*d);
}

TEST(PrepareDrawing, BadRequestsAreClearErrors) {
  DrawingSource source;
  source.shape = "hexagon";
  EXPECT_EQ(prepare_drawing(source, {}, arm()).error().message,
            "unknown shape 'hexagon' (expected one of: circle, square, heart, triangle, star, "
            "spiral)");
  source.shape = "circle";
  EXPECT_EQ(prepare_drawing(source, {.spacing = -1.0}, arm()).error().message,
            "spacing must be a positive finite number, got -1");
  EXPECT_EQ(prepare_drawing(source, {.spacing = 1e-9}, arm()).error().message,
            "spacing 1e-09 would make about 3.7445e+09 targets, more than the limit of 1e+06");
  DrawingSource text;
  text.kind = DrawingSourceKind::text;
  text.text = "QD";
  // A box a million units wide: millions of samples and pen-up steps, refused up front.
  const auto far = prepare_drawing(text, {.box = DrawingBox{0.0, 0.0, 1e6}}, arm());
  ASSERT_FALSE(far.has_value());
  EXPECT_EQ(far.error().message.rfind("spacing 0.01 would make about ", 0), 0u)
      << far.error().message;
  source.kind = DrawingSourceKind::image;
  source.file = "/nonexistent/seven.png";
  EXPECT_EQ(prepare_drawing(source, {}, arm()).error().message,
            "/nonexistent/seven.png: no such file");
  const auto dir = fresh_dir("drawing_white");
  // Fully transparent pixels are paper: composited over white.
  ASSERT_TRUE(write_png(dir / "white.png", Image(20, 20)).has_value());  // all (0,0,0,0)
  source.file = dir / "white.png";
  EXPECT_EQ(
      prepare_drawing(source, {}, arm()).error().message,
      (dir / "white.png").string() + ": the image is a single shade (gray 255): nothing to draw");
}

}  // namespace
}  // namespace animkit
