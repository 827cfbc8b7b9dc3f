#include "drawing_args.h"

#include <cstdio>

#include "animkit/core/quote.h"

namespace animkit::apps {

CLI::Option* add_drawing_options(CLI::App& command, DrawingArgs& args) {
  std::string names;
  for (const std::string& n : builtin_shape_names()) names += (names.empty() ? "" : ", ") + n;
  CLI::Option* shape =
      command.add_option("--shape", args.shape, "Built-in shape to draw: " + names)
          ->capture_default_str();
  CLI::Option* text = command.add_option(
      "--text", args.text, "Draw this text (glyph outlines; '\\n' in the text starts a line)");
  CLI::Option* image = command.add_option(
      "--image", args.image, "Draw the skeleton of this picture (PNG, JPEG, BMP, ...)");
  CLI::Option* mnist = command.add_option(
      "--mnist", args.mnist, "Draw the skeleton of a digit from this MNIST IDX image file");
  CLI::Option* curve =
      command.add_option("--curve", args.curve,
                         "Draw your own points: a CSV of x,z lines, a blank line lifts the pen");
  const std::vector<CLI::Option*> sources{shape, text, image, mnist, curve};
  for (CLI::Option* a : sources) {
    for (CLI::Option* b : sources) {
      if (a != b) a->excludes(b);
    }
  }
  command.add_option("--font", args.font, "Font file for --text (default DejaVu Sans)")
      ->needs(text);
  command
      .add_flag("--centerline", args.centerline,
                "With --text: draw each glyph's centre line instead of its outline")
      ->needs(text);
  command.add_option("--index", args.index, "With --mnist: which image of the file (from 0)")
      ->needs(mnist)
      ->capture_default_str();
  command.add_option("--threshold", args.threshold,
                     "With --image/--mnist: gray level 0..254 splitting ink from paper "
                     "(default: Otsu's)");
  command.add_option("--thinning", args.thinning, "With --image/--mnist: zhang-suen or guo-hall")
      ->capture_default_str();
  command.add_option("--spacing", args.spacing,
                     "Resample strokes by arc length to this spacing (scene units; default "
                     "0.01 for text, images and curves, the lab's own sampling for shapes)");
  command.add_option("--box", args.box,
                     "Fit text, images and curves in the square X,Z,HALF on the plane y = 0 "
                     "(default: the largest comfortable square in the arm's reach)");
  return shape;
}

Result<std::pair<DrawingSource, DrawingLayout>> drawing_request(const DrawingArgs& args) {
  DrawingSource source;
  DrawingLayout layout;
  source.shape = args.shape;
  if (args.text) {
    source.kind = DrawingSourceKind::text;
    source.text = *args.text;
    // "\n" typed on a command line arrives as two characters: make it a line break.
    for (std::size_t at = source.text.find("\\n"); at != std::string::npos;
         at = source.text.find("\\n", at + 1)) {
      source.text.replace(at, 2, "\n");
    }
  } else if (!args.image.empty()) {
    source.kind = DrawingSourceKind::image;
    source.file = args.image;
  } else if (!args.mnist.empty()) {
    source.kind = DrawingSourceKind::mnist;
    source.file = args.mnist;
    source.index = args.index;
  } else if (!args.curve.empty()) {
    source.kind = DrawingSourceKind::curve;
    source.file = args.curve;
  }
  if (!args.font.empty()) source.text_options.font = args.font;
  source.text_options.centerline = args.centerline;
  const bool image = !args.image.empty() || !args.mnist.empty();
  if ((args.threshold || args.thinning) && !image) {
    return fail(std::string(args.threshold ? "--threshold" : "--thinning") +
                " applies to --image and --mnist only");
  }
  if (args.thinning) {
    const auto thinning = parse_thinning(*args.thinning);
    if (!thinning) {
      return fail("unknown --thinning " + quote_input(*args.thinning) +
                  " (expected zhang-suen or guo-hall)");
    }
    source.image.thinning = *thinning;
  }
  source.image.threshold = args.threshold;
  if (auto error = source.image.validate()) return fail(error->message);
  layout.spacing = args.spacing;
  if (!args.box.empty()) {
    if (source.kind == DrawingSourceKind::shape) {
      return fail(
          "--box applies to --text, --image, --mnist and --curve; the built-in shapes keep "
          "the lab's placement");
    }
    DrawingBox box;
    char tail = 0;
    if (std::sscanf(args.box.c_str(), "%lf,%lf,%lf%c", &box.center_x, &box.center_z,
                    &box.half_extent, &tail) != 3 ||
        !std::isfinite(box.center_x) || !std::isfinite(box.center_z) ||
        !std::isfinite(box.half_extent) || box.half_extent <= 0.0) {
      return fail("--box must be X,Z,HALF with HALF > 0, got " + quote_input(args.box));
    }
    layout.box = box;
  }
  return std::pair{source, layout};
}

}  // namespace animkit::apps
