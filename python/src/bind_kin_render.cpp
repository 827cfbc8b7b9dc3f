// render_png(path, run): a picture of a drawing run, the scene `animkit ik --out` renders into
// drawing.png (the library's describe_arm_drawing, camera and offscreen renderer), for one
// frame of the run: the arm's pose, every target, the strokes drawn so far in that lap.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animkit/io/png.h"
#include "animkit/render/picture_renderer.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/ik_scene.h"
#include "animkit/scene/orbit_camera.h"
#include "bind_kin_common.h"
#include "picture_lock.h"
#include "python_errors.h"

namespace animkit::python {

namespace py = pybind11;

namespace {

void render_run(const std::filesystem::path& path, const PyDrawingRun& drawing, int width,
                int height, std::optional<long long> frame) {
  check(check_picture_size(width, height));
  const std::vector<DrawingFrame>& frames = drawing.run.frames;
  if (frames.empty()) raise("the run has no frames");
  const long long count = static_cast<long long>(frames.size());
  const long long shown = frame.value_or(count - 1);
  if (shown < 0 || shown >= count) {
    raise("frame " + std::to_string(shown) + " is not a frame of the run (0 to " +
          std::to_string(count - 1) + ")");
  }
  // The drawing's targets and pens: the first lap's frames.
  std::vector<Vec3> targets;
  std::vector<char> pens;
  for (const DrawingFrame& f : frames) {
    if (f.lap != 0) break;
    targets.push_back(f.target);
    pens.push_back(f.pen_down ? 1 : 0);
  }
  // One camera for the whole run, as the CLI's: it frames the targets and every pose.
  Eigen::AlignedBox3d bounds;
  for (const Vec3& t : targets) bounds.extend(t);
  for (const DrawingFrame& f : frames) {
    for (const Vec3& p : f.joint_positions) bounds.extend(p);
  }
  const DrawingFrame& current = frames[static_cast<std::size_t>(shown)];
  std::vector<std::vector<Vec3>> strokes;  // the shown frame's lap, up to it
  for (long long f = 0; f <= shown; ++f) {
    const DrawingFrame& at = frames[static_cast<std::size_t>(f)];
    if (at.lap != current.lap || !at.pen_down) continue;
    const bool continues = f > 0 && frames[static_cast<std::size_t>(f - 1)].pen_down &&
                           frames[static_cast<std::size_t>(f - 1)].lap == at.lap;
    if (!continues || strokes.empty()) strokes.emplace_back();
    strokes.back().push_back(at.end_effector);
  }
  std::optional<Vec3> unreachable;
  if (!current.ik.reachable) unreachable = current.target;

  DrawList list;
  describe_arm_drawing(list, {current.joint_positions, targets, pens, strokes, unreachable});
  Result<void> written;
  {
    py::gil_scoped_release release;  // rendering and writing without the GIL
    Result<Image> image = fail("not rendered");
    {
      // One renderer at a time in the whole module (picture_lock.h), from its creation to
      // its destruction at the end of this scope.
      std::lock_guard renderer_lock(picture_renderer_mutex());
      auto renderer = PictureRenderer::create(width, height);
      if (!renderer) {
        image = fail("cannot render pictures: " + renderer.error().message);
      } else {
        const OrbitCamera camera =
            OrbitCamera::framing(bounds, renderer->aspect(), kIkPictureYaw, kIkPicturePitch);
        image = renderer->render(list, camera);
      }
    }
    written = image ? write_png(path, *image) : Result<void>(std::unexpected(image.error()));
  }
  unwrap(std::move(written));
}

}  // namespace

void bind_kin_render(py::module_& m) {
  m.def("render_png", &render_run, py::arg("path"), py::arg("run"), py::arg("width") = 960,
        py::arg("height") = 720, py::arg("frame") = py::none(),
        "Renders one frame of a DrawingRun to a PNG file, as `animkit ik --out` renders\n"
        "drawing.png: the ground grid, the targets (green; pen-up travel grey), the strokes\n"
        "drawn so far in that frame's lap (red), the arm, an unreachable target (orange).\n"
        "frame: from 0 (None: the last); width, height: pixels, 16..8192. Needs an OpenGL context\n"
        "(EGL or a display); renders without the GIL. Raises animkit.Error for a frame outside\n"
        "the run, a bad size, no OpenGL, an unwritable path.");
}

}  // namespace animkit::python
