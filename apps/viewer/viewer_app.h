#pragma once
// The viewer's frame, shared by the window and the headless capture: the scenes, the orbit
// camera, the side panel and the mouse. Hosts own the OpenGL context and Dear ImGui's
// platform side; they call update() between ImGui::NewFrame() and ImGui::Render(), then
// render() before drawing ImGui's draw data.
#include <memory>
#include <optional>

#include "animkit/render/renderer.h"
#include "animkit/scene/scene_registry.h"
#include "bvh_view.h"
#include "cloth_view.h"
#include "ik_view.h"

namespace animkit::viewer {

struct ViewerOptions {
  SceneKind scene = SceneKind::ik;
  IkViewOptions ik;
  BvhViewOptions bvh;       ///< opened at the start for --scene bvh, else when first chosen
  ClothSceneOptions cloth;  ///< the lab's cloth, unless cloth_world is given
  /// A cloth scene to open instead (--scene NAME|FILE.json) and its name for the menu.
  std::optional<NamedClothWorld> cloth_world;
  ClothStyle cloth_style;
  int width = 1280, height = 800;  ///< window or picture size in pixels
  bool paused = false;             ///< start with the scene paused
};

class ViewerApp {
 public:
  /// Builds the scenes (the BVH one only when it is the first shown) and the renderer (an OpenGL
  /// context must be current). Errors: bad scene options, a renderer that cannot start.
  static Result<ViewerApp> create(const ViewerOptions& options);

  /// Reads the mouse and keys from ImGui's IO, advances the current scene one frame and lays
  /// out the side panel. `width` x `height`: the window in ImGui's (logical) pixels.
  void update(int width, int height);
  /// Draws the 3D view into the bound framebuffer, `framebuffer_width` x `framebuffer_height`
  /// pixels (more than the logical size on high-DPI screens).
  void render(int framebuffer_width, int framebuffer_height);

  /// Frames the current scene from its default direction.
  void reset_camera();

 private:
  ViewerApp(Renderer renderer, IkView ik, ClothView cloth, std::optional<BvhView> bvh,
            BvhViewOptions bvh_options, SceneKind scene);
  SceneView& current();
  // Switches to `scene`; the BVH scene is read the first time (an error keeps the current one).
  void choose(SceneKind scene);
  Cursor cursor_at(double x, double y) const;
  void handle_mouse();
  void side_panel();

  Renderer renderer_;
  IkView ik_;
  ClothView cloth_;
  std::optional<BvhView> bvh_;
  BvhViewOptions bvh_options_;
  std::string bvh_error_;  // why the BVH scene could not be opened
  SceneKind scene_;
  OrbitCamera camera_;
  bool camera_placed_ = false;
  int width_ = 1, height_ = 1;  // window, logical pixels
  // The press in progress in the 3D view.
  bool left_down_ = false, scene_grabbed_ = false, moved_ = false, panning_ = false;
  double press_x_ = 0.0, press_y_ = 0.0;
};

/// Width of the side panel in logical pixels; the 3D view fills the rest of the window.
constexpr int kPanelWidth = 380;

}  // namespace animkit::viewer
