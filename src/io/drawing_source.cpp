#include "animkit/io/drawing_source.h"

#include <cmath>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/curve_csv.h"
#include "animkit/io/image_input.h"
#include "animkit/trajectory/builtin_curves.h"
#include "animkit/trajectory/lab_shapes.h"

namespace animkit {

namespace {

constexpr double kDefaultSpacing = 0.01;

// World (x, 0, z) points as one plane stroke (x, z).
Stroke plane_stroke(const std::vector<Vec3>& points) {
  Stroke s;
  s.reserve(points.size());
  for (const Vec3& p : points) s.emplace_back(p.x(), p.z());
  return s;
}

Result<std::vector<Vec3>> builtin_shape(const std::string& name) {
  if (name == "spiral") return uneven_spiral_targets();
  if (const auto shape = parse_lab_shape(name)) return lab_shape_targets(*shape);
  std::string names;
  for (const std::string& n : builtin_shape_names()) names += (names.empty() ? "" : ", ") + n;
  return fail("unknown shape " + quote_input(name) + " (expected one of: " + names + ")");
}

// The source's strokes in its own frame (y up), a name for reports and, for images, the
// extent of the ink to fit.
Result<Strokes> read_strokes(const DrawingSource& source, std::string& name,
                             std::optional<Eigen::AlignedBox2d>& frame) {
  switch (source.kind) {
    case DrawingSourceKind::text:
      name = "text " + source.text;
      return text_strokes(source.text, source.text_options);
    case DrawingSourceKind::curve:
      name = "curve " + source.file.filename().string();
      return read_curve_csv(source.file);
    case DrawingSourceKind::image:
    case DrawingSourceKind::mnist: {
      const bool mnist = source.kind == DrawingSourceKind::mnist;
      name = (mnist ? "mnist " : "image ") + source.file.filename().string() +
             (mnist ? " #" + std::to_string(source.index) : "");
      auto image =
          mnist ? read_mnist_image(source.file, source.index) : read_gray_image(source.file);
      if (!image) return fail(image.error().message);
      auto strokes = image_to_strokes(*image, source.image);
      if (!strokes) return fail(source.file.string() + ": " + strokes.error().message);
      frame = strokes->extent;
      return std::move(strokes->strokes);
    }
    case DrawingSourceKind::shape:
      break;
  }
  return fail("not a file or text source");
}

}  // namespace

std::vector<std::string> builtin_shape_names() {
  std::vector<std::string> names;
  for (LabShape s : all_lab_shapes()) names.emplace_back(to_string(s));
  names.emplace_back("spiral");
  return names;
}

Result<PreparedDrawing> prepare_drawing(const DrawingSource& source, const DrawingLayout& layout,
                                        const Chain& chain) {
  if (layout.spacing && (!std::isfinite(*layout.spacing) || *layout.spacing <= 0.0)) {
    return fail("spacing must be a positive finite number, got " + format_number(*layout.spacing));
  }
  if (auto error = layout.travel.validate()) return fail(error->message);
  PreparedDrawing out;
  Strokes placed;
  if (source.kind == DrawingSourceKind::shape) {
    auto points = builtin_shape(source.shape);
    if (!points) return fail(points.error().message);
    out.name = source.shape;
    placed = {plane_stroke(*points)};
  } else {
    std::optional<Eigen::AlignedBox2d> frame;
    auto strokes = read_strokes(source, out.name, frame);
    if (!strokes) return fail(strokes.error().message);
    auto fitted = fit_to_box(
        *strokes, layout.box.value_or(reachable_box(chain.root_position(), chain.reach())), frame);
    if (!fitted) {
      // E.g. a curve of finite points too far apart to scale: the file is named too.
      const bool file = source.kind != DrawingSourceKind::text;
      return fail((file ? source.file.string() + ": " : "") + fitted.error().message);
    }
    placed = std::move(*fitted);
  }
  out.spacing_before = spacing_stats(placed);
  const std::optional<double> spacing = source.kind == DrawingSourceKind::shape
                                            ? layout.spacing
                                            : layout.spacing.value_or(kDefaultSpacing);
  if (spacing) {
    // Refuse before allocating: a tiny spacing on a long drawing would ask for billions.
    double length = 0.0;
    for (const Stroke& stroke : placed) length += stroke_length(stroke);
    double travel = 0.0;  // pen-up moves between strokes, cut at the travel spacing
    for (std::size_t i = 1; i < placed.size(); ++i) {
      if (!placed[i].empty() && !placed[i - 1].empty()) {
        travel += (placed[i].front() - placed[i - 1].back()).norm();
      }
    }
    const double samples = length / *spacing + travel / layout.travel.spacing +
                           3.0 * static_cast<double>(placed.size());
    if (samples > kMaxDrawingTargets) {
      return fail("spacing " + format_number(*spacing) + " would make about " +
                  format_number(samples) + " targets, more than the limit of " +
                  format_number(kMaxDrawingTargets));
    }
    placed = resample(placed, {.spacing = *spacing});
  }
  out.spacing_after = spacing_stats(placed);
  out.strokes = static_cast<int>(placed.size());
  auto trajectory = to_trajectory(placed, layout.travel);
  if (!trajectory) return fail(trajectory.error().message);
  out.trajectory = std::move(*trajectory);
  return out;
}

}  // namespace animkit
