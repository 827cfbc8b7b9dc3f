#include "viewer_app.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace animkit::viewer {

namespace {
constexpr double kOrbitRadiansPerPx = 0.008;
constexpr double kClickSlopPx = 3.0;  // a press that moves less is a click
}  // namespace

ViewerApp::ViewerApp(Renderer renderer, IkView ik, ClothView cloth, std::optional<BvhView> bvh,
                     BvhViewOptions bvh_options, SceneKind scene)
    : renderer_(std::move(renderer)),
      ik_(std::move(ik)),
      cloth_(std::move(cloth)),
      bvh_(std::move(bvh)),
      bvh_options_(std::move(bvh_options)),
      scene_(scene) {}

Result<ViewerApp> ViewerApp::create(const ViewerOptions& options) {
  auto ik = IkView::create(options.ik);
  if (!ik) return fail(ik.error().message);
  auto cloth = options.cloth_world
                   ? ClothView::create(options.cloth_world->world, options.cloth_world->name)
                   : ClothView::create(options.cloth);
  if (!cloth) return fail(cloth.error().message);
  cloth->set_style(options.cloth_style);
  if (options.paused) {
    ik->set_playing(false);
    cloth->set_playing(false);
  }
  std::optional<BvhView> bvh;
  if (options.scene == SceneKind::bvh) {
    auto opened = BvhView::create(options.bvh);
    if (!opened) return fail(opened.error().message);
    if (options.paused) opened->scene().clock().playing = false;
    bvh = std::move(*opened);
  }
  auto renderer = Renderer::create();
  if (!renderer) return fail(renderer.error().message);
  return ViewerApp(std::move(*renderer), std::move(*ik), std::move(*cloth), std::move(bvh),
                   options.bvh, options.scene);
}

SceneView& ViewerApp::current() {
  switch (scene_) {
    case SceneKind::ik:
      return ik_;
    case SceneKind::bvh:
      return *bvh_;  // choose() opens it before switching
    case SceneKind::cloth:
      return cloth_;
  }
  return ik_;
}

void ViewerApp::choose(SceneKind scene) {
  if (scene == scene_) return;
  if (scene == SceneKind::bvh && !bvh_) {
    auto opened = BvhView::create(bvh_options_);
    if (!opened) {
      bvh_error_ = opened.error().message;
      return;
    }
    bvh_ = std::move(*opened);
    bvh_error_.clear();
  }
  scene_ = scene;
  reset_camera();
}

void ViewerApp::reset_camera() {
  const double view_width = std::max(1, width_ - kPanelWidth);
  camera_ = OrbitCamera::framing(current().focus_bounds(), view_width / height_,
                                 current().default_yaw(), current().default_pitch());
  camera_placed_ = true;
}

Cursor ViewerApp::cursor_at(double x, double y) const {
  Cursor cursor;
  cursor.x = x - kPanelWidth;
  cursor.y = y;
  cursor.view_width = std::max(1, width_ - kPanelWidth);
  cursor.view_height = height_;
  cursor.camera = &camera_;
  cursor.ray = camera_.ray_through_pixel(cursor.x, cursor.y, cursor.view_width, cursor.view_height);
  return cursor;
}

void ViewerApp::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool mouse_valid = ImGui::IsMousePosValid(&io.MousePos);
  const bool in_view = mouse_valid && !io.WantCaptureMouse && io.MousePos.x >= kPanelWidth;
  const Cursor cursor = cursor_at(io.MousePos.x, io.MousePos.y);

  if (in_view && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    left_down_ = true;
    moved_ = false;
    press_x_ = io.MousePos.x;
    press_y_ = io.MousePos.y;
    scene_grabbed_ = current().press(cursor);
  }
  if (left_down_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    if (std::hypot(io.MousePos.x - press_x_, io.MousePos.y - press_y_) > kClickSlopPx) {
      moved_ = true;
    }
    if (scene_grabbed_) {
      if (moved_) current().drag(cursor);
    } else {
      camera_.orbit(-kOrbitRadiansPerPx * io.MouseDelta.x, kOrbitRadiansPerPx * io.MouseDelta.y);
    }
  }
  if (left_down_ && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (scene_grabbed_) current().release(cursor, moved_);
    left_down_ = scene_grabbed_ = false;
  }
  // Right or middle drag pans; the wheel zooms.
  const bool pan_button =
      ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle);
  if (in_view && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
                  ImGui::IsMouseClicked(ImGuiMouseButton_Middle))) {
    panning_ = true;
  }
  if (!pan_button) panning_ = false;
  if (panning_) camera_.pan(io.MouseDelta.x, io.MouseDelta.y, height_);
  if (in_view && io.MouseWheel != 0.0f) camera_.zoom(std::pow(0.88, io.MouseWheel));
}

void ViewerApp::side_panel() {
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(kPanelWidth), static_cast<float>(height_)));
  ImGui::Begin("animkit", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  // One button per kind of scene in the registry, in its order (the cloth view has its own
  // menu of cloth scenes).
  std::optional<SceneKind> previous;
  for (const SceneEntry& entry : scene_entries()) {
    if (entry.kind == previous) continue;
    if (previous) ImGui::SameLine();
    previous = entry.kind;
    if (ImGui::RadioButton(std::string(scene_kind_title(entry.kind)).c_str(),
                           scene_ == entry.kind)) {
      choose(entry.kind);
    }
  }
  if (!bvh_error_.empty()) {
    ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1.0f), "%s", bvh_error_.c_str());
  }
  ImGui::Separator();
  ImGui::PushItemWidth(-130.0f);
  current().panel();
  ImGui::PopItemWidth();
  if (current().take_new_view()) reset_camera();
  ImGui::Separator();
  if (ImGui::Button("Reset view")) reset_camera();
  ImGui::SameLine();
  // The window's drawing rate; a simulation step's own time is in the scene's panel.
  ImGui::TextDisabled("drawn at %.0f fps", static_cast<double>(ImGui::GetIO().Framerate));
  ImGui::TextWrapped(
      "Camera: left drag orbits, right or middle drag pans, the wheel zooms, Home or R resets. "
      "Space starts and pauses.");
  ImGui::End();
}

void ViewerApp::update(int width, int height) {
  width_ = std::max(1, width);
  height_ = std::max(1, height);
  if (!camera_placed_) reset_camera();
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    bool reset = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home));
    for (ImWchar c : io.InputQueueCharacters) reset = reset || c == 'r' || c == 'R';
    if (reset) reset_camera();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) current().toggle_playing();
  }
  handle_mouse();
  current().advance(static_cast<double>(io.DeltaTime));
  side_panel();
}

void ViewerApp::render(int framebuffer_width, int framebuffer_height) {
  const double scale = static_cast<double>(framebuffer_width) / width_;
  const int panel = static_cast<int>(std::lround(kPanelWidth * scale));
  renderer_.clear({framebuffer_width, framebuffer_height}, palette::background);
  const Viewport view{std::max(1, framebuffer_width - panel), framebuffer_height, panel, 0};
  DrawList list;
  current().describe(list);
  renderer_.draw(list, camera_.view(),
                 camera_.projection(static_cast<double>(view.width) / view.height), view);
}

}  // namespace animkit::viewer
