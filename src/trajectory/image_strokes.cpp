#include "animkit/trajectory/image_strokes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/trajectory/stroke_cover.h"

namespace animkit {

std::optional<Error> ImageStrokeOptions::validate() const {
  if (threshold && (*threshold < 0 || *threshold > 254)) {
    return Error{"threshold must be a gray level from 0 to 254, got " + std::to_string(*threshold)};
  }
  if (!std::isfinite(speck_fraction) || speck_fraction < 0.0 || speck_fraction >= 1.0) {
    return Error{"speck fraction must be in [0, 1), got " + format_number(speck_fraction)};
  }
  if (smoothing_radius < 0) {
    return Error{"smoothing radius must be >= 0, got " + std::to_string(smoothing_radius)};
  }
  return std::nullopt;
}

Result<ImageStrokes> image_to_strokes(const GrayImage& image, const ImageStrokeOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  if (image.empty() || image.width <= 0 || image.height <= 0) return fail("the image is empty");
  if (image.width > kMaxImageSide || image.height > kMaxImageSide) {
    return fail("the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " pixels, larger than the limit of " + std::to_string(kMaxImageSide) + "x" +
                std::to_string(kMaxImageSide));
  }
  ImageStrokes out;
  if (options.threshold) {
    out.threshold = *options.threshold;
  } else {
    const auto otsu = otsu_threshold(image);
    if (!otsu) {
      return fail("the image is a single shade (gray " + std::to_string(image.pixels.front()) +
                  "): nothing to draw");
    }
    out.threshold = *otsu;
  }
  BinaryImage ink = binarize(image, out.threshold, options.polarity);
  const Components pieces = connected_components(ink);
  const int largest =
      pieces.sizes.empty() ? 0 : *std::max_element(pieces.sizes.begin(), pieces.sizes.end());
  const int min_pixels = std::max(4, static_cast<int>(std::ceil(options.speck_fraction * largest)));
  out.specks_removed = remove_specks(ink, min_pixels);
  if (ink.count() == 0) {
    return fail("the image has no ink to draw after thresholding at gray " +
                std::to_string(out.threshold) + " and removing specks");
  }
  const int ink_pixels = ink.count();
  // The drawing's frame is the ink's extent, not the skeleton's: a dot stays a dot in a frame
  // as big as the ink, instead of a point blown up to the whole box.
  for (int y = 0; y < ink.height; ++y) {
    for (int x = 0; x < ink.width; ++x) {
      if (ink.get(x, y)) {
        out.extent.extend(Point2(x - 0.5, -(y - 0.5)));
        out.extent.extend(Point2(x + 0.5, -(y + 0.5)));
      }
    }
  }
  thin(ink, options.thinning);
  SkeletonGraph graph = skeleton_graph(ink);
  // Ink per skeleton pixel is about the pen's width. Thinning grows a spur at a corner about
  // half a width long (from the skeleton out to the corner of the ink); a branch up to 0.75
  // widths is taken for one, anything longer is a stroke.
  const double pen_width = static_cast<double>(ink_pixels) / std::max(1, ink.count());
  out.spurs_removed = prune_spurs(graph, 0.75 * pen_width);
  Strokes strokes = cover_with_strokes(graph);
  for (Stroke& s : strokes) {
    // Smooth in pixels, corners held (a "7" keeps its corner; judged over 3 pixels, so the
    // staircase of a slanted line is no corner), then flip y to point up.
    s = smooth(s, options.smoothing_radius, find_corners(s, 1.0, 3.0));
    for (Point2& p : s) p = Point2(p.x(), -p.y());
  }
  out.strokes = order_for_short_travel(std::move(strokes));
  out.skeleton = std::move(ink);
  if (out.strokes.empty()) return fail("the image's skeleton has no strokes to draw");
  return out;
}

}  // namespace animkit
