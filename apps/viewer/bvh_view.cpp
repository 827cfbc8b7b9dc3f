#include "bvh_view.h"

#include <imgui.h>

#include <cstdio>
#include <filesystem>

#include "animkit/core/quote.h"
#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/io/bvh_units.h"
#include "animkit/io/joint_limits_file.h"

namespace animkit::viewer {

namespace {
constexpr double kBvhGrabRadiusPx = 12.0;

int find_named(const Skeleton& skeleton, const std::string& name, const std::string& what,
               std::string& error) {
  const int joint = skeleton.find_joint(name);
  if (joint < 0) error = what + ": the clip has no joint named " + quote_input(name);
  return joint;
}
}  // namespace

Result<BvhView> BvhView::create(const BvhViewOptions& options) {
  auto metric = read_bvh_in_metres(options.path, options.scale);
  if (!metric) return fail(metric.error().message + (options.scale ? "" : " with --scale"));
  std::printf("%s: %s\n", options.path.c_str(), metric->description.c_str());
  BvhClip* clip = &metric->clip;
  auto skeleton = build_skeleton(clip->skeleton);
  if (!skeleton) return fail(options.path + ": " + skeleton.error().message);
  std::vector<JointLimit> limits;
  if (!options.limits_path.empty()) {
    auto set = read_joint_limits_file(options.limits_path);
    if (!set) return fail(set.error().message);
    auto bound = bind_joint_limits(*set, skeleton->names());
    if (!bound) return fail(options.limits_path + ": " + bound.error().message);
    limits = std::move(*bound);
  }
  auto scene = BvhScene::create(std::move(*skeleton), motion_from_bvh(*clip), std::move(limits),
                                options.scene);
  if (!scene) return fail(options.path + ": " + scene.error().message);
  const int frames = scene->clock().frame_count();
  if (options.start_frame < 0 || options.start_frame >= frames) {
    return fail("--frame must be in [0, " + std::to_string(frames - 1) + "] (" + options.path +
                " has " + std::to_string(frames) + " frames), got " +
                std::to_string(options.start_frame));
  }
  scene->seek(options.start_frame);
  std::string error;
  if (!options.selected.empty()) {
    scene->select(find_named(scene->skeleton(), options.selected, "--select", error));
    if (!error.empty()) return fail(error);
  }
  for (const HeldFromStart& held : options.held) {
    const int joint = find_named(scene->skeleton(), held.joint, "--hold", error);
    if (!error.empty()) return fail(error);
    const Vec3 target = scene->clip_pose().global_positions[joint] + held.offset;
    if (auto ok = scene->hold(joint, target); !ok) return fail("--hold: " + ok.error().message);
  }
  return BvhView(std::move(*scene), std::filesystem::path(options.path).filename().string(),
                 options.close_up);
}

Eigen::AlignedBox3d BvhView::focus_bounds() const {
  if (!close_up_) return scene_.focus_bounds();
  Eigen::AlignedBox3d box;
  for (const Vec3& p : scene_.pose().global_positions) box.extend(p);
  for (const HeldTarget& held : scene_.held()) box.extend(held.position);
  return box;
}

void BvhView::panel() {
  PlaybackClock& clock = scene_.clock();
  const Skeleton& skeleton = scene_.skeleton();
  ImGui::Text("%s: %d joints, %d frames at %.0f fps", title_.c_str(), skeleton.joint_count(),
              clock.frame_count(), 1.0 / clock.frame_time());
  if (ImGui::Button(clock.playing ? "Pause" : "Play")) clock.playing = !clock.playing;
  ImGui::SameLine();
  float speed = static_cast<float>(clock.speed);
  if (ImGui::SliderFloat("Speed", &speed, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    clock.speed = speed;
  }
  int frame = clock.frame();
  if (ImGui::SliderInt("Frame", &frame, 0, clock.frame_count() - 1)) {
    clock.playing = false;
    scene_.seek(frame);
  }

  if (ImGui::Checkbox("Close-up (frame the character)", &close_up_)) new_view_ = true;

  ImGui::Separator();
  int solver = 0;
  const auto solvers = all_tree_ik_solvers();
  for (int i = 0; i < static_cast<int>(solvers.size()); ++i) {
    if (solvers[i] == scene_.options().solver) solver = i;
  }
  if (ImGui::BeginCombo("IK solver", std::string(to_string(solvers[solver])).c_str())) {
    for (int i = 0; i < static_cast<int>(solvers.size()); ++i) {
      if (ImGui::Selectable(std::string(to_string(solvers[i])).c_str(), i == solver)) {
        scene_.set_solver(solvers[i]);
      }
    }
    ImGui::EndCombo();
  }
  bool pin = scene_.options().pin_feet;
  if (ImGui::Checkbox("Pin feet while dragging", &pin)) scene_.set_pin_feet(pin);
  if (!scene_.held().empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Let go")) scene_.let_go_all();
  }
  if (const auto& last = scene_.last_solve()) {
    ImGui::Text("Effectors   %d (%zu held)", last->effectors, scene_.held().size());
    ImGui::Text("Iterations  %d", last->result.iterations);
    ImGui::Text("Error       %.2f mm", 1000.0 * last->result.error);
    ImGui::Text("Solve time  %.1f us", last->solve_time_us);
    if (!last->result.reachable) {
      ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.0f, 1.0f), "Out of reach");
    }
  } else {
    ImGui::TextDisabled("Drag a joint to hold it at a target.");
  }

  ImGui::Separator();
  if (const FootLockResult* lock = scene_.foot_lock()) {
    bool locked = scene_.foot_locked();
    if (ImGui::Checkbox("Foot locking", &locked)) (void)scene_.set_foot_locked(locked);
    ImGui::SameLine();
    bool trails = scene_.options().trails;
    if (ImGui::Checkbox("Trails", &trails)) scene_.set_trails(trails);
    const FootLockMetrics& m = lock->metrics;
    ImGui::Text("Contacts    left %d, right %d", m.contacts[0], m.contacts[1]);
    ImGui::Text("Sliding     %.3f -> %.3f cm/frame", m.slide_before_mean_cm, m.slide_after_mean_cm);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped(
        "Trails: ankles as captured orange, foot-locked dark blue; dots where contacts pin them.");
    ImGui::PopStyleColor();
  } else {
    ImGui::TextDisabled("No foot locking: %s", scene_.foot_lock_problem().c_str());
  }

  ImGui::Separator();
  const int selected = scene_.selected();
  if (selected >= 0) {
    const JointLimit& limit = scene_.limits()[selected];
    const char* kind = std::holds_alternative<HingeLimit>(limit)  ? "hinge (arc)"
                       : std::holds_alternative<BallLimit>(limit) ? "ball (cone)"
                                                                  : "free";
    ImGui::Text("Joint %s: %s", skeleton.names()[selected].c_str(), kind);
    ImGui::Text("Beyond its limit by %.3f rad",
                violation(limit, relative_to_rest(skeleton, scene_.pose(), selected)));
  }
  if (!message_.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1.0f), "%s", message_.c_str());
  ImGui::TextWrapped(
      "Click a joint to see its limit (pink), drag it to hold it at a target (green): the solver "
      "keeps it there while the clip plays. White: where the bone points now.");
}

bool BvhView::press(const Cursor& cursor) {
  const int joint = scene_.pick_joint(*cursor.camera, cursor.x, cursor.y, cursor.view_width,
                                      cursor.view_height, kBvhGrabRadiusPx);
  if (joint < 0) return false;
  scene_.select(joint);
  dragged_ = joint;
  drag_anchor_ = scene_.pose().global_positions[joint];
  message_.clear();
  return true;
}

void BvhView::drag(const Cursor& cursor) {
  if (dragged_ < 0) return;
  // The joint moves in the plane through where it was pressed, facing the camera.
  auto held = scene_.drag_joint(dragged_, cursor.ray, cursor.camera->eye(), drag_anchor_);
  if (!held && scene_.skeleton().parents()[dragged_] < 0) {
    message_ = held.error().message;  // a root: stop trying; a missed ray: wait for the next
    dragged_ = -1;
  }
}

void BvhView::release(const Cursor& /*cursor*/, bool /*moved*/) {
  dragged_ = -1;
}

}  // namespace animkit::viewer
