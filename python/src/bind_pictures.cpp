// Pictures of a cloth simulation: the same picture as `animkit cloth --out`'s final.png (the
// library's cloth and collider drawings, framed by cloth_picture_frame from the run's first
// state, seen from the cloth pictures' yaw and pitch), as a PNG file or a numpy image.
#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <cstring>
#include <filesystem>
#include <mutex>
#include <string>

#include "animkit/io/png.h"
#include "animkit/render/picture_renderer.h"
#include "animkit/scene/cloth_drawing.h"
#include "animkit/scene/collider_drawing.h"
#include "animkit/scene/orbit_camera.h"
#include "bindings.h"
#include "cloth_simulator_object.h"
#include "picture_lock.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

namespace py = pybind11;

// The cloth and its colliders as they are now, drawn as the CLI draws a run's last frame.
// Called without the GIL.
Result<Image> render(const SimulatorObject& s, int width, int height) {
  if (auto problem = check_picture_size(width, height)) return std::unexpected(*problem);
  DrawList picture;
  ClothPictureFrame framing;
  {
    std::lock_guard lock(s.mutex);
    framing = widened_to_hold(s.picture_frame(), s.sim().state());
    describe_cloth(picture, s.sim().model(), s.sim().state(),
                   {.floor_height = framing.floor_height});
    describe_colliders(picture, s.posed_colliders());
  }
  // One renderer at a time in the whole module (picture_lock.h), from its creation to its
  // destruction at the end of this scope (the lock is taken first, so released last).
  std::lock_guard renderer_lock(picture_renderer_mutex());
  auto renderer = PictureRenderer::create(width, height);
  if (!renderer) return fail("cannot render pictures: " + renderer.error().message);
  const OrbitCamera camera =
      OrbitCamera::framing(framing.focus, renderer->aspect(), kClothPictureYaw, kClothPicturePitch);
  return renderer->render(picture, camera);
}

}  // namespace

void bind_pictures(py::module_& m) {
  m.def(
      "render_png",
      [](const std::filesystem::path& path, const SimulatorObject& simulator, int width,
         int height) {
        Result<void> written;
        {
          py::gil_scoped_release release;
          auto image = render(simulator, width, height);
          written = image ? write_png(path, *image) : Result<void>(std::unexpected(image.error()));
        }
        unwrap(std::move(written));
      },
      "Renders the simulator's cloth and colliders as they are now, framed and lit as "
      "`animkit cloth --out`'s final.png, into the PNG file `path` (written atomically: a "
      "complete file or none). width, height: pixels, 16..8192. Raises animkit.Error when no "
      "OpenGL context can be made (the message says what was tried), for a bad size or an "
      "unwritable path.",
      py::arg("path"), py::arg("simulator"), py::arg("width") = 960, py::arg("height") = 720);
  m.def(
      "render_image",
      [](const SimulatorObject& simulator, int width, int height) {
        std::optional<Result<Image>> image;
        {
          py::gil_scoped_release release;
          image.emplace(render(simulator, width, height));
        }
        const Image picture = unwrap(std::move(*image));
        py::array_t<std::uint8_t> out(
            {py::ssize_t{picture.height}, py::ssize_t{picture.width}, py::ssize_t{4}});
        static_assert(sizeof(Pixel) == 4);
        std::memcpy(out.mutable_data(), picture.pixels.data(), picture.pixels.size() * 4);
        return out;
      },
      "The picture render_png writes, as an (height, width, 4) uint8 RGBA array (row 0 at "
      "the top). Raises animkit.Error like render_png.",
      py::arg("simulator"), py::arg("width") = 960, py::arg("height") = 720);
}

}  // namespace animkit::python
