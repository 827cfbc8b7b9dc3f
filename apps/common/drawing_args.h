#pragma once
// The options that choose what the arm draws, shared by `animkit ik` and `animkit-viewer` so
// both accept the same sources: --shape, --text (--font, --centerline), --image, --mnist
// (--index), --curve, and how they are laid out (--spacing, --box, --threshold, --thinning).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "animkit/io/drawing_source.h"

namespace animkit::apps {

struct DrawingArgs {
  std::string shape = "circle";
  std::optional<std::string> text;  // set (even to "") when --text is given
  std::string font, image, mnist, curve;
  int index = 0;
  bool centerline = false;
  std::optional<int> threshold;         // nothing: Otsu
  std::optional<std::string> thinning;  // nothing: zhang-suen
  std::optional<double> spacing;        // nothing: the source's default
  std::string box;                      // "X,Z,HALF"; empty: in the arm's reach
};

/// Adds the options to `command`; returns the --shape option (for excludes).
CLI::Option* add_drawing_options(CLI::App& command, DrawingArgs& args);

/// The source and layout the options ask for. Errors: bad --thinning, --threshold, --box,
/// --spacing values; --threshold or --thinning without an image to apply them to.
Result<std::pair<DrawingSource, DrawingLayout>> drawing_request(const DrawingArgs& args);

}  // namespace animkit::apps
