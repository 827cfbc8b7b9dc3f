// Bindings of the drawings the arm follows: the lab's shapes and the spiral, text, image and
// MNIST skeletons, CSV curves, resampling and spacing statistics, placement on the plane and
// pen-up travel (Trajectory), and prepare_drawing(), which turns any source into the arm's
// targets as `animkit ik` does. Strokes are lists of (k, 2) float64 arrays.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/curve_csv.h"
#include "animkit/io/drawing_source.h"
#include "animkit/io/image_input.h"
#include "animkit/io/text_strokes.h"
#include "animkit/kinematics/ik_types.h"
#include "animkit/trajectory/builtin_curves.h"
#include "animkit/trajectory/image_strokes.h"
#include "animkit/trajectory/lab_shapes.h"
#include "animkit/trajectory/strokes.h"
#include "animkit/trajectory/trajectory.h"
#include "bind_kin_common.h"
#include "bindings.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {

namespace {

namespace py = pybind11;

std::string joined(const std::vector<std::string>& names, const char* separator = ", ") {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

std::vector<std::string> lab_names() {
  std::vector<std::string> names;
  for (LabShape s : all_lab_shapes()) names.emplace_back(to_string(s));
  return names;
}

std::vector<Vec3> builtin_points(const std::string& name, bool lab_only) {
  if (const auto shape = parse_lab_shape(name)) return lab_shape_targets(*shape);
  if (!lab_only && name == "spiral") return uneven_spiral_targets();
  const std::vector<std::string> names = lab_only ? lab_names() : builtin_shape_names();
  raise(std::string(lab_only ? "unknown lab shape " : "unknown shape ") + quote_input(name) +
        " (expected one of: " + joined(names) + ")");
}

// ---- strokes <-> numpy -------------------------------------------------------------------

Stroke to_stroke(const py::handle& value, const std::string& what) {
  std::vector<Eigen::Vector2d> points = to_points2(value, what);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      raise(what + " point " + std::to_string(i) + " has a non-finite coordinate");
    }
    // The bound of IK targets: lengths and spacings of such points stay finite (a point at
    // 1e300 made stroke_length return inf).
    if (points[i].cwiseAbs().maxCoeff() > kMaxTargetCoordinate) {
      raise(what + " point " + std::to_string(i) + " has a coordinate beyond " +
            format_number(kMaxTargetCoordinate));
    }
  }
  return Stroke(points.begin(), points.end());
}

/// True when `value` is one stroke: an array (or nested list) of shape (k, 2).
bool is_one_stroke(const py::handle& value) {
  if (value.is_none() || py::isinstance<py::str>(value)) return false;
  DoubleArray array = DoubleArray::ensure(value);
  if (!array) {
    PyErr_Clear();  // ragged: a list of strokes of different lengths
    return false;
  }
  return array.ndim() == 2;
}

Strokes to_strokes(const py::handle& value, const char* what) {
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
      !py::isinstance<py::sequence>(value)) {
    if (!py::isinstance<py::array>(value)) {
      raise(std::string(what) + " must be a list of (k, 2) arrays, got " +
            std::string(py::str(py::type::of(value).attr("__name__"))));
    }
  }
  Strokes strokes;
  std::size_t s = 0;
  for (const py::handle& item : value) {
    strokes.push_back(to_stroke(item, std::string(what) + " " + std::to_string(s)));
    ++s;
  }
  return strokes;
}

py::list strokes_to_list(const Strokes& strokes) {
  py::list out;
  for (const Stroke& s : strokes) out.append(points2_to_array(s));
  return out;
}

// ---- images --------------------------------------------------------------------------------

GrayImage to_gray_image(const py::handle& value) {
  const DoubleArray array = as_double_array(value, "image");
  if (array.ndim() != 2 || array.shape(0) == 0 || array.shape(1) == 0) {
    raise("image must be a non-empty 2-D array of gray levels (height, width), got " +
          std::to_string(array.ndim()) + " dimensions");
  }
  if (array.shape(0) > kMaxImageSide || array.shape(1) > kMaxImageSide) {
    raise("image is " + std::to_string(array.shape(1)) + "x" + std::to_string(array.shape(0)) +
          " pixels, larger than " + std::to_string(kMaxImageSide) + " on a side");
  }
  GrayImage image(static_cast<int>(array.shape(1)), static_cast<int>(array.shape(0)));
  const double* data = array.data();
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const double v = data[i];
    if (!(v >= 0.0 && v <= 255.0) || v != std::floor(v)) {
      raise("image pixel " + std::to_string(i) + " is " + format_number(v) +
            ", not a gray level 0..255");
    }
    image.pixels[i] = static_cast<std::uint8_t>(v);
  }
  return image;
}

py::array_t<std::uint8_t> gray_to_array(int width, int height,
                                        const std::vector<std::uint8_t>& pixels) {
  py::array_t<std::uint8_t> array(
      {static_cast<py::ssize_t>(height), static_cast<py::ssize_t>(width)});
  std::copy(pixels.begin(), pixels.end(), array.mutable_data());
  return array;
}

InkPolarity polarity_kind(const std::string& name) {
  if (name == "automatic") return InkPolarity::automatic;
  if (name == "dark") return InkPolarity::dark;
  if (name == "light") return InkPolarity::light;
  raise("unknown polarity " + quote_input(name) + " (expected automatic, dark or light)");
}

ThinningMethod thinning_kind(const std::string& name) {
  if (const auto method = parse_thinning(name)) return *method;
  raise("unknown thinning " + quote_input(name) + " (expected zhang-suen or guo-hall)");
}

ImageStrokeOptions image_options(const std::optional<int>& threshold, const std::string& polarity,
                                 const std::string& thinning, double speck_fraction,
                                 int smoothing_radius) {
  ImageStrokeOptions options;
  options.threshold = threshold;
  options.polarity = polarity_kind(polarity);
  options.thinning = thinning_kind(thinning);
  options.speck_fraction = speck_fraction;
  options.smoothing_radius = smoothing_radius;
  check(options.validate());
  return options;
}

py::array_t<double> box_to_array(const Eigen::AlignedBox2d& box) {
  py::array_t<double> array({py::ssize_t{2}, py::ssize_t{2}});
  double* out = array.mutable_data();
  out[0] = box.min().x();
  out[1] = box.min().y();
  out[2] = box.max().x();
  out[3] = box.max().y();
  return array;
}

std::optional<Eigen::AlignedBox2d> to_frame(const py::object& value) {
  if (value.is_none()) return std::nullopt;
  const DoubleArray array = as_double_array(value, "frame");
  if (array.ndim() != 2 || array.shape(0) != 2 || array.shape(1) != 2) {
    raise("frame must be a (2, 2) array [[u_min, v_min], [u_max, v_max]]");
  }
  const double* d = array.data();
  return Eigen::AlignedBox2d(Eigen::Vector2d(d[0], d[1]), Eigen::Vector2d(d[2], d[3]));
}

// ---- classes ---------------------------------------------------------------------------------

std::string stats_repr(const SpacingStats& s) {
  return "SpacingStats(segments=" + std::to_string(s.segments) + ", mean=" + repr_number(s.mean) +
         ", min=" + repr_number(s.min) + ", max=" + repr_number(s.max) +
         ", cv=" + repr_number(s.cv) + ")";
}

std::string box_repr(const DrawingBox& b) {
  return "DrawingBox(center_x=" + repr_number(b.center_x) +
         ", center_z=" + repr_number(b.center_z) + ", half_extent=" + repr_number(b.half_extent) +
         ")";
}

Trajectory make_trajectory(const py::object& targets, const py::object& pen_down) {
  Trajectory t;
  t.targets = to_vec3s(targets, "targets");
  if (pen_down.is_none()) {
    t.pen_down.assign(t.targets.size(), 1);
    return t;
  }
  const DoubleArray flags = as_double_array(pen_down, "pen_down");
  if (flags.ndim() != 1 || static_cast<std::size_t>(flags.shape(0)) != t.targets.size()) {
    raise("pen_down must have one flag per target (" + std::to_string(t.targets.size()) + ")");
  }
  for (py::ssize_t i = 0; i < flags.shape(0); ++i) {
    const double v = flags.data()[i];
    if (!std::isfinite(v)) raise("pen_down " + std::to_string(i) + " is not a finite number");
    t.pen_down.push_back(v != 0.0 ? 1 : 0);
  }
  return t;
}

void bind_classes(py::module_& m) {
  py::class_<SpacingStats>(m, "SpacingStats",
                           "How evenly a drawing is sampled: statistics of the distances between "
                           "consecutive points of each stroke (pen-up gaps excluded).")
      .def_readonly("segments", &SpacingStats::segments, "Number of segments measured.")
      .def_readonly("mean", &SpacingStats::mean, "Mean segment length (drawing units).")
      .def_readonly("min", &SpacingStats::min, "Shortest segment.")
      .def_readonly("max", &SpacingStats::max, "Longest segment.")
      .def_readonly("cv", &SpacingStats::cv,
                    "Coefficient of variation: standard deviation / mean (0: even).")
      .def("__repr__", &stats_repr);

  const DrawingBox box_defaults;
  py::class_<DrawingBox>(m, "DrawingBox",
                         "Where a drawing goes on the plane y = 0: a square centred at "
                         "(center_x, 0, center_z), its larger side 2 * half_extent.")
      .def(py::init([](double cx, double cz, double half) {
             return DrawingBox{cx, cz, half};
           }),
           py::kw_only(), py::arg("center_x") = box_defaults.center_x,
           py::arg("center_z") = box_defaults.center_z,
           py::arg("half_extent") = box_defaults.half_extent,
           "A box (scene units); checked when used (half_extent > 0, finite).")
      .def_readwrite("center_x", &DrawingBox::center_x, "Centre's x (scene units).")
      .def_readwrite("center_z", &DrawingBox::center_z, "Centre's z (scene units).")
      .def_readwrite("half_extent", &DrawingBox::half_extent,
                     "Half the drawing's larger side (scene units), > 0.")
      .def("__repr__", &box_repr);

  py::class_<Trajectory>(m, "Trajectory",
                         "The arm's targets in drawing order, one per frame, each with the pen "
                         "state (down draws, up travels between strokes).")
      .def(py::init(&make_trajectory), py::arg("targets"), py::arg("pen_down") = py::none(),
           "targets: (n, 3) world points; pen_down: None (all down) or n flags.")
      .def_property_readonly(
          "targets", [](const Trajectory& t) { return vec3s_to_array(t.targets); },
          "(n, 3) targets (world); a copy.")
      .def_property_readonly(
          "pen_down", [](const Trajectory& t) { return pen_flags_to_array(t.pen_down); },
          "(n,) bool: True draws, False travels; a copy.")
      .def(
          "__len__", [](const Trajectory& t) { return t.targets.size(); }, "Number of targets.")
      .def(
          "pen_down_strokes",
          [](const Trajectory& t) { return strokes_to_list(pen_down_strokes(t)); },
          "The strokes it draws: runs of pen-down targets as (k, 2) arrays of plane (x, z).")
      .def("__repr__", [](const Trajectory& t) {
        std::size_t up = 0;
        for (char f : t.pen_down) up += f ? 0 : 1;
        return "Trajectory(targets=" + std::to_string(t.targets.size()) +
               ", pen_up=" + std::to_string(up) + ")";
      });

  py::class_<ImageStrokes>(m, "ImageStrokes",
                           "An image's skeleton as pen strokes, with what the pipeline found "
                           "(threshold, specks and spurs removed, the thinned ink).")
      .def_property_readonly(
          "strokes", [](const ImageStrokes& s) { return strokes_to_list(s.strokes); },
          "The strokes, (k, 2) arrays in drawing coordinates (x right, y up, one unit a pixel).")
      .def_property_readonly(
          "extent", [](const ImageStrokes& s) { return box_to_array(s.extent); },
          "(2, 2) [[x_min, y_min], [x_max, y_max]]: the ink's extent, the frame to fit.")
      .def_readonly("threshold", &ImageStrokes::threshold, "The gray level used.")
      .def_readonly("specks_removed", &ImageStrokes::specks_removed, "Ink pieces dropped as noise.")
      .def_readonly("spurs_removed", &ImageStrokes::spurs_removed,
                    "Short skeleton branches dropped.")
      .def_property_readonly(
          "skeleton",
          [](const ImageStrokes& s) {
            return gray_to_array(s.skeleton.width, s.skeleton.height, s.skeleton.pixels);
          },
          "(height, width) uint8: the thinned ink (1) on paper (0).")
      .def("__repr__", [](const ImageStrokes& s) {
        return "ImageStrokes(strokes=" + std::to_string(s.strokes.size()) +
               ", threshold=" + std::to_string(s.threshold) +
               ", specks_removed=" + std::to_string(s.specks_removed) +
               ", spurs_removed=" + std::to_string(s.spurs_removed) + ")";
      });

  py::class_<PreparedDrawing>(m, "PreparedDrawing",
                              "A drawing source made into the arm's targets, as `animkit ik` "
                              "prepares it.")
      .def_readonly("name", &PreparedDrawing::name, "E.g. 'star', 'text QD', 'image a.png'.")
      .def_readonly("trajectory", &PreparedDrawing::trajectory, "The Trajectory (targets, pens).")
      .def_property_readonly(
          "targets", [](const PreparedDrawing& d) { return vec3s_to_array(d.trajectory.targets); },
          "(n, 3) the trajectory's targets (world).")
      .def_property_readonly(
          "pen_down",
          [](const PreparedDrawing& d) { return pen_flags_to_array(d.trajectory.pen_down); },
          "(n,) bool: the trajectory's pen flags.")
      .def_readonly("stroke_count", &PreparedDrawing::strokes, "Number of pen-down strokes.")
      .def_readonly("spacing_before", &PreparedDrawing::spacing_before,
                    "SpacingStats of the placed strokes before resampling (scene units).")
      .def_readonly("spacing_after", &PreparedDrawing::spacing_after,
                    "SpacingStats of the strokes the arm is given (scene units).")
      .def("__repr__", [](const PreparedDrawing& d) {
        return "PreparedDrawing(name=" + py::repr(py::str(d.name)).cast<std::string>() +
               ", targets=" + std::to_string(d.trajectory.targets.size()) +
               ", stroke_count=" + std::to_string(d.strokes) + ")";
      });
}

// ---- sources -------------------------------------------------------------------------------

void bind_sources(py::module_& m) {
  m.def(
      "lab_shape",
      [](const std::string& name) { return vec3s_to_array(builtin_points(name, true)); },
      py::arg("name"),
      "The lab's shape `name` as (n, 3) targets in drawing order on the plane y = 0 (circle,\n"
      "square, heart, triangle: 150 points; star: 400). Raises animkit.Error for other names.");
  m.def("lab_shape_names", &lab_names,
        "The lab's five shapes, in its menu order: circle, square, heart, triangle, star.");
  m.def(
      "builtin_shape",
      [](const std::string& name) { return vec3s_to_array(builtin_points(name, false)); },
      py::arg("name"),
      "A built-in shape as (n, 3) targets: a lab shape or 'spiral' (three turns, sampled\n"
      "unevenly on purpose). Raises animkit.Error for other names.");
  m.def("builtin_shape_names", &builtin_shape_names,
        "Every built-in shape, in menu order: the lab's five, then 'spiral'.");

  const TextOptions text_defaults;
  m.def(
      "text_strokes",
      [](const std::string& text, const std::filesystem::path& font, double tolerance,
         bool centerline) {
        TextOptions options;
        options.font = font;
        options.tolerance = tolerance;
        options.centerline = centerline;
        check(options.validate());
        Result<Strokes> strokes = fail("not read");
        {
          py::gil_scoped_release release;
          strokes = text_strokes(text, options);
        }
        return strokes_to_list(unwrap(std::move(strokes)));
      },
      py::arg("text"), py::arg("font") = text_defaults.font,
      py::arg("tolerance") = text_defaults.tolerance,
      py::arg("centerline") = text_defaults.centerline,
      "The strokes of `text` (one line per '\\n') as (k, 2) arrays, an em of 1 (x right, y up,\n"
      "the first baseline at y = 0): glyph outlines flattened to `tolerance` (fraction of the\n"
      "em, in (0, 0.1]), or each glyph's centre line. Raises animkit.Error for empty text, a\n"
      "missing or bad font file, a character the font lacks, nothing visible.");

  m.def(
      "read_gray_image",
      [](const std::filesystem::path& path) {
        const GrayImage image = unwrap(animkit::read_gray_image(path));
        return gray_to_array(image.width, image.height, image.pixels);
      },
      py::arg("path"),
      "Reads an image (PNG, JPEG, BMP, PGM/PPM/PBM) as a (height, width) uint8 gray array.\n"
      "Raises animkit.Error naming the file when it is missing, unreadable or too large.");
  m.def(
      "read_mnist_image",
      [](const std::filesystem::path& path, int index) {
        const GrayImage image = unwrap(animkit::read_mnist_image(path, index));
        return gray_to_array(image.width, image.height, image.pixels);
      },
      py::arg("path"), py::arg("index") = 0,
      "Image `index` (from 0) of an MNIST IDX image file as a (rows, columns) uint8 array\n"
      "(white digit on black). Raises animkit.Error for a missing or malformed file or an\n"
      "index out of range.");

  const ImageStrokeOptions image_defaults;
  m.def(
      "image_strokes",
      [](const py::object& image, std::optional<int> threshold, const std::string& polarity,
         const std::string& thinning, double speck_fraction, int smoothing_radius) {
        const ImageStrokeOptions options =
            image_options(threshold, polarity, thinning, speck_fraction, smoothing_radius);
        GrayImage gray;
        std::string name;
        if (py::isinstance<py::str>(image) || py::hasattr(image, "__fspath__")) {
          const auto path = image.cast<std::filesystem::path>();
          gray = unwrap(animkit::read_gray_image(path));
          name = path.string() + ": ";
        } else {
          gray = to_gray_image(image);
        }
        Result<ImageStrokes> strokes = fail("not run");
        {
          py::gil_scoped_release release;
          strokes = image_to_strokes(gray, options);
        }
        if (!strokes) raise(name + strokes.error().message);
        return std::move(*strokes);
      },
      py::arg("image"), py::arg("threshold") = py::none(), py::arg("polarity") = "automatic",
      py::arg("thinning") = std::string(to_string(image_defaults.thinning)),
      py::arg("speck_fraction") = image_defaults.speck_fraction,
      py::arg("smoothing_radius") = image_defaults.smoothing_radius,
      "An image's skeleton as pen strokes (ImageStrokes): threshold (None: Otsu's; else\n"
      "0..254), speck removal, thinning ('zhang-suen' or 'guo-hall'), strokes covering the\n"
      "skeleton, smoothing. image: a file path or a (height, width) array of gray levels\n"
      "0..255. polarity: 'automatic', 'dark' (ink <= threshold) or 'light'. Raises\n"
      "animkit.Error for a missing file, an image of one gray level, no ink, bad options.");

  m.def(
      "read_curve_csv",
      [](const std::filesystem::path& path) {
        return strokes_to_list(unwrap(animkit::read_curve_csv(path)));
      },
      py::arg("path"),
      "The strokes of a CSV curve file: one 'x,z' point per line, a blank line lifts the pen,\n"
      "'#' starts a comment. Drawing coordinates (u = x, v = -z). Raises animkit.Error naming\n"
      "the file and line.");
  m.def(
      "parse_curve_csv",
      [](const std::string& text, const std::string& name) {
        return strokes_to_list(unwrap(animkit::parse_curve_csv(text, name)));
      },
      py::arg("text"), py::arg("name") = "curve",
      "read_curve_csv of CSV text in memory; `name` starts every error.");
}

// ---- strokes --------------------------------------------------------------------------------

void bind_stroke_tools(py::module_& m) {
  const ResampleOptions defaults;
  m.def(
      "resample",
      [](const py::object& strokes, double spacing, double corner_angle) {
        const ResampleOptions options{spacing, corner_angle};
        check(options.validate());
        const bool one = is_one_stroke(strokes);
        const Strokes input =
            one ? Strokes{to_stroke(strokes, "stroke")} : to_strokes(strokes, "stroke");
        // Refuse before allocating: a tiny spacing on a long drawing would ask for billions.
        double length = 0.0;
        for (const Stroke& s : input) length += stroke_length(s);
        if (length / spacing > kMaxDrawingTargets) {
          raise("spacing " + format_number(spacing) + " would make about " +
                format_number(length / spacing) + " points, more than the limit of " +
                format_number(kMaxDrawingTargets));
        }
        Strokes out;
        {
          py::gil_scoped_release release;
          out = resample(input, options);
        }
        return one ? py::object(points2_to_array(out.front())) : py::object(strokes_to_list(out));
      },
      py::arg("strokes"), py::arg("spacing") = defaults.spacing,
      py::arg("corner_angle") = defaults.corner_angle,
      "Resamples by arc length: corners (turns sharper than corner_angle radians, in (0, pi])\n"
      "and ends are kept, the pieces between cut into equal parts no longer than `spacing`\n"
      "(> 0). strokes: one (k, 2) array (returns one array) or a list of them (returns a\n"
      "list). Raises animkit.Error for bad options, non-finite points, over 1e6 points.");
  m.def(
      "spacing_stats",
      [](const py::object& strokes) {
        const Strokes input = is_one_stroke(strokes) ? Strokes{to_stroke(strokes, "stroke")}
                                                     : to_strokes(strokes, "stroke");
        return spacing_stats(input);
      },
      py::arg("strokes"),
      "SpacingStats of a (k, 2) stroke or a list of them: the distances between consecutive\n"
      "points of each stroke.");
  m.def(
      "stroke_length",
      [](const py::object& stroke) { return stroke_length(to_stroke(stroke, "stroke")); },
      py::arg("stroke"), "Total length of a (k, 2) stroke.");

  m.def(
      "fit_to_box",
      [](const py::object& strokes, const std::optional<DrawingBox>& box, const py::object& frame) {
        const Strokes input = is_one_stroke(strokes) ? Strokes{to_stroke(strokes, "stroke")}
                                                     : to_strokes(strokes, "stroke");
        return strokes_to_list(
            unwrap(fit_to_box(input, box.value_or(DrawingBox{}), to_frame(frame))));
      },
      py::arg("strokes"), py::arg("box") = py::none(), py::arg("frame") = py::none(),
      "Scales strokes uniformly and centres them in `box` (a DrawingBox; None: the default,\n"
      "centred at the origin, half extent 0.6); u runs along +x, v along -z. frame: the\n"
      "extent to fit, (2, 2) [[u_min, v_min], [u_max, v_max]] (None: the strokes' bounds).\n"
      "Returns plane (x, z) strokes. Raises animkit.Error for no points or a bad box.");
  m.def(
      "reachable_box",
      [](const py::object& root, double reach, double plane_y, double fill) {
        const Vec3 r = to_vec3(root, "root");
        if (!is_finite(r) || !std::isfinite(reach) || reach <= 0.0 || !std::isfinite(plane_y) ||
            !std::isfinite(fill) || fill <= 0.0 || fill > 1.0) {
          raise(
              "reachable_box needs a finite root, reach > 0, a finite plane_y and fill in "
              "(0, 1]");
        }
        return reachable_box(r, reach, plane_y, fill);
      },
      py::arg("root"), py::arg("reach"), py::arg("plane_y") = 0.0, py::arg("fill") = 0.7,
      "The largest DrawingBox an arm with this root and reach draws in comfortably: centred\n"
      "under the root, its corners at `fill` of the radius where the plane leaves the reach.");

  const TravelOptions travel;
  m.def(
      "to_trajectory",
      [](const py::object& plane_strokes, double pen_lift, double spacing) {
        return unwrap(
            to_trajectory(to_strokes(plane_strokes, "stroke"), TravelOptions{pen_lift, spacing}));
      },
      py::arg("plane_strokes"), py::arg("pen_lift") = travel.pen_lift,
      py::arg("spacing") = travel.spacing,
      "The Trajectory of plane (x, z) strokes on y = 0: each stroke's points with the pen\n"
      "down, and between strokes a lift by pen_lift (>= 0), a straight move and a drop with\n"
      "the pen up, cut at `spacing` (> 0). Raises animkit.Error for bad options, no points.");
}

// ---- prepare_drawing ---------------------------------------------------------------------

PreparedDrawing prepare(const std::optional<Chain>& chain, const std::optional<std::string>& shape,
                        const std::optional<std::string>& text,
                        const std::optional<std::filesystem::path>& image,
                        const std::optional<std::filesystem::path>& mnist, int index,
                        const std::optional<std::filesystem::path>& curve,
                        const std::optional<std::filesystem::path>& font, bool centerline,
                        std::optional<int> threshold, const std::optional<std::string>& thinning,
                        std::optional<double> spacing, const std::optional<DrawingBox>& box,
                        double pen_lift, double travel_spacing) {
  std::vector<std::string> given;
  if (shape) given.emplace_back("shape");
  if (text) given.emplace_back("text");
  if (image) given.emplace_back("image");
  if (mnist) given.emplace_back("mnist");
  if (curve) given.emplace_back("curve");
  if (given.size() > 1) {
    raise("give one drawing source (shape, text, image, mnist or curve), got " +
          joined(given, " and "));
  }
  DrawingSource source;
  if (shape) source.shape = *shape;
  if (text) {
    source.kind = DrawingSourceKind::text;
    source.text = *text;
  } else if (image) {
    source.kind = DrawingSourceKind::image;
    source.file = *image;
  } else if (mnist) {
    source.kind = DrawingSourceKind::mnist;
    source.file = *mnist;
    source.index = index;
  } else if (curve) {
    source.kind = DrawingSourceKind::curve;
    source.file = *curve;
  }
  const bool picture = image || mnist;
  if ((threshold || thinning) && !picture) {
    raise(std::string(threshold ? "threshold" : "thinning") + " applies to image and mnist only");
  }
  if ((font || centerline) && !text) {
    raise(std::string(font ? "font" : "centerline") + " applies to text only");
  }
  if (index != 0 && !mnist) raise("index applies to mnist only");
  if (box && source.kind == DrawingSourceKind::shape) {
    raise(
        "box applies to text, image, mnist and curve; the built-in shapes keep the lab's "
        "placement");
  }
  if (font) source.text_options.font = *font;
  source.text_options.centerline = centerline;
  if (thinning) source.image.thinning = thinning_kind(*thinning);
  source.image.threshold = threshold;
  check(source.image.validate());
  DrawingLayout layout;
  layout.spacing = spacing;
  layout.box = box;
  layout.travel = TravelOptions{pen_lift, travel_spacing};
  const Chain arm = chain ? *chain : unwrap(build_chain(lab_arm()));
  Result<PreparedDrawing> prepared = fail("not prepared");
  {
    py::gil_scoped_release release;
    prepared = prepare_drawing(source, layout, arm);
  }
  return unwrap(std::move(prepared));
}

void bind_prepare(py::module_& m) {
  const TravelOptions travel;
  const char* doc =
      "Turns one drawing source into the arm's targets exactly as `animkit ik` does (the same\n"
      "options as its --shape, --text, --font, --centerline, --image, --mnist, --index,\n"
      "--curve, --threshold, --thinning, --spacing, --box). Give at most one source: shape\n"
      "(a built-in shape name; the default is 'circle'), text, image (a file path), mnist (an\n"
      "IDX file path, with index) or curve (a CSV path). chain: whose reach places text,\n"
      "images and curves (None: the lab's arm); box: a DrawingBox instead. spacing: resample\n"
      "to this (scene units; default 0.01 for text, images and curves, the lab's own sampling\n"
      "for shapes). pen_lift and travel_spacing shape the pen-up travel between strokes.\n"
      "Raises animkit.Error for two sources, an unknown shape, unreadable files, options that\n"
      "do not apply to the source, bad values.";
  // pybind11 keeps the pointers: the texts must outlive the module.
  static const std::string prepare_doc =
      std::string("A PreparedDrawing (name, trajectory, stroke count, spacing statistics).\n\n") +
      doc;
  static const std::string targets_doc =
      std::string("The Trajectory of prepare_drawing(...): the arm's targets and pen flags.\n\n") +
      doc;
  m.def("prepare_drawing", &prepare, py::kw_only(), py::arg("chain") = py::none(),
        py::arg("shape") = py::none(), py::arg("text") = py::none(), py::arg("image") = py::none(),
        py::arg("mnist") = py::none(), py::arg("index") = 0, py::arg("curve") = py::none(),
        py::arg("font") = py::none(), py::arg("centerline") = false,
        py::arg("threshold") = py::none(), py::arg("thinning") = py::none(),
        py::arg("spacing") = py::none(), py::arg("box") = py::none(),
        py::arg("pen_lift") = travel.pen_lift, py::arg("travel_spacing") = travel.spacing,
        prepare_doc.c_str());
  m.def(
      "drawing_targets",
      [](const std::optional<Chain>& chain, const std::optional<std::string>& shape,
         const std::optional<std::string>& text, const std::optional<std::filesystem::path>& image,
         const std::optional<std::filesystem::path>& mnist, int index,
         const std::optional<std::filesystem::path>& curve,
         const std::optional<std::filesystem::path>& font, bool centerline,
         std::optional<int> threshold, const std::optional<std::string>& thinning,
         std::optional<double> spacing, const std::optional<DrawingBox>& box, double pen_lift,
         double travel_spacing) {
        return prepare(chain, shape, text, image, mnist, index, curve, font, centerline, threshold,
                       thinning, spacing, box, pen_lift, travel_spacing)
            .trajectory;
      },
      py::kw_only(), py::arg("chain") = py::none(), py::arg("shape") = py::none(),
      py::arg("text") = py::none(), py::arg("image") = py::none(), py::arg("mnist") = py::none(),
      py::arg("index") = 0, py::arg("curve") = py::none(), py::arg("font") = py::none(),
      py::arg("centerline") = false, py::arg("threshold") = py::none(),
      py::arg("thinning") = py::none(), py::arg("spacing") = py::none(),
      py::arg("box") = py::none(), py::arg("pen_lift") = travel.pen_lift,
      py::arg("travel_spacing") = travel.spacing, targets_doc.c_str());
}

}  // namespace

void bind_drawings(py::module_& m) {
  bind_classes(m);
  bind_sources(m);
  bind_stroke_tools(m);
  bind_prepare(m);
  bind_kin_render(m);
}

}  // namespace animkit::python
