#include "animkit/scene/cloth_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/validation.h"
#include "animkit/scene/cloth_scenes.h"
#include "animkit/scene/collider_drawing.h"

namespace animkit {

namespace {
constexpr double kDragStiffness = 200.0;  // s^-2, per unit mass
}

std::optional<Error> ClothSceneOptions::validate() const {
  if (auto error = grid.validate()) return error;
  if (auto error = simulation.validate()) return error;
  if (!kTimeStepRange.contains(time_step)) {
    return Error{kTimeStepRange.refusal("time step", time_step)};
  }
  return std::nullopt;
}

ClothWorldDesc ClothSceneOptions::world() const {
  ClothWorldDesc world;
  world.cloth = grid;
  world.simulation = simulation;
  world.time_step = time_step;
  return world;
}

namespace {

ClothSceneOptions lab_view(const ClothWorldDesc& world) {
  ClothSceneOptions options;
  if (const auto* grid = std::get_if<GridClothOptions>(&world.cloth)) options.grid = *grid;
  options.simulation = world.simulation;
  options.time_step = world.time_step;
  return options;
}

// The same particles at the same rest positions, joined into the same triangles: a sheet
// whose motion carries over.
bool same_sheet(const ClothDesc& a, const ClothDesc& b) {
  if (a.particles.size() != b.particles.size() || a.triangles != b.triangles) return false;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    if (a.particles[i].position != b.particles[i].position) return false;
  }
  return true;
}

std::string out_of_range(const char* what, int index, int count) {
  return std::string(what) + " " + std::to_string(index) + " is out of range (the cloth has " +
         std::to_string(count) + ")";
}

}  // namespace

ClothScene::ClothScene(ClothWorldDesc world, std::string name, ClothDesc desc, ClothWorld built)
    : world_(std::move(world)),
      name_(std::move(name)),
      options_(lab_view(world_)),
      desc_(std::move(desc)),
      built_(std::move(built)) {
  floor_height_ =
      cloth_picture_frame(world_, desc_, built_.simulator.state(), built_.colliders).floor_height;
}

Result<ClothScene> ClothScene::create(const ClothSceneOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  return create(options.world(), "lab");
}

Result<ClothScene> ClothScene::create(const ClothWorldDesc& world, std::string name) {
  if (auto error = world.validate()) return fail(error->message);
  auto desc = build_world_cloth(world);
  if (!desc) return fail(desc.error().message);
  auto built = build_cloth_world(world, *desc);
  if (!built) return fail(built.error().message);
  return ClothScene(world, std::move(name), std::move(*desc), std::move(*built));
}

Result<void> ClothScene::load(const ClothWorldDesc& world, std::string name) {
  auto fresh = create(world, std::move(name));
  if (!fresh) return fail(fresh.error().message);
  *this = std::move(*fresh);
  return {};
}

Result<void> ClothScene::reset(const ClothSceneOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  return load(options.world(), "lab");
}

Result<void> ClothScene::restart() {
  return load(world_, name_);
}

Result<void> ClothScene::rebuild_keeping_state(const ClothWorldDesc& world, ClothDesc desc) {
  auto built = build_cloth_world(world, desc);
  if (!built) return fail(built.error().message);
  if (auto kept = built->simulator.set_state(simulator().state()); !kept) return kept;
  // Colliders stand where they stood (they may have moved since the world began).
  for (std::size_t i = 0; i < built->colliders.size(); ++i)
    built->colliders[i].set_time(built_.colliders[i].time());
  built_ = std::move(*built);
  desc_ = std::move(desc);
  world_ = world;
  options_ = lab_view(world_);
  return {};
}

Result<void> ClothScene::apply(const ClothSceneOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  ClothWorldDesc world = world_;
  if (std::holds_alternative<GridClothOptions>(world.cloth)) world.cloth = options.grid;
  world.simulation = options.simulation;
  world.time_step = options.time_step;
  return apply_world(world);
}

Result<void> ClothScene::apply_world(const ClothWorldDesc& world) {
  if (auto error = world.validate()) return fail(error->message);
  auto desc = build_world_cloth(world);
  if (!desc) return fail(desc.error().message);
  if (!same_sheet(*desc, desc_) || world.colliders.size() != world_.colliders.size())
    return load(world, name_);
  // The same particles and springs: take the new parameters, keep the pins and the motion.
  for (std::size_t i = 0; i < desc->particles.size(); ++i)
    desc->particles[i].pinned = desc_.particles[i].pinned;
  return rebuild_keeping_state(world, std::move(*desc));
}

Result<void> ClothScene::toggle_pin(int particle) {
  const int count = simulator().model().particle_count();
  if (particle < 0 || particle >= count) return fail(out_of_range("particle", particle, count));
  ClothDesc desc = desc_;
  desc.particles[particle].pinned = !desc.particles[particle].pinned;
  return rebuild_keeping_state(world_, std::move(desc));
}

bool ClothScene::lab_parameters() const {
  const auto* grid = std::get_if<GridClothOptions>(&world_.cloth);
  return grid && !grid->material;
}

std::optional<int> ClothScene::pick(const OrbitCamera& camera, double x, double y, double width,
                                    double height, double radius_px) const {
  std::optional<int> best;
  double best_depth = std::numeric_limits<double>::infinity();
  const ClothState& state = simulator().state();
  for (int i = 0; i < simulator().model().particle_count(); ++i) {
    const auto p = camera.project(state.position(i), width, height);
    if (!p || std::hypot(p->x() - x, p->y() - y) > radius_px) continue;
    if (p->z() < best_depth) {
      best = i;
      best_depth = p->z();
    }
  }
  return best;
}

ClothPick ClothScene::pick_handle(const OrbitCamera& camera, double x, double y, double width,
                                  double height, double radius_px) const {
  const std::optional<int> particle = pick(camera, x, y, width, height, radius_px);
  const Ray ray = camera.ray_through_pixel(x, y, width, height);
  const std::optional<ColliderGrab> collider = pick_collider(colliders(), ray);
  if (!collider) return {particle, std::nullopt};
  if (!particle) return {std::nullopt, collider};
  // Both: the one nearer the eye is the one the user sees (cloth draped over a ball is in
  // front of it; a ball in front of the cloth hides it).
  const double particle_distance = (simulator().state().position(*particle) - ray.origin).norm();
  if (particle_distance <= collider->distance) return {particle, std::nullopt};
  return {std::nullopt, collider};
}

Result<void> ClothScene::set_drag(const ClothDrag& drag) {
  const int count = simulator().model().particle_count();
  if (drag.particle < 0 || drag.particle >= count)
    return fail(out_of_range("particle", drag.particle, count));
  if (!is_finite(drag.target)) {
    return fail("drag target has a non-finite coordinate " + to_string(drag.target));
  }
  drag_ = drag;
  return {};
}

void ClothScene::clear_drag() {
  drag_.reset();
  built_.simulator.clear_external_forces();
}

Result<void> ClothScene::move_collider(int index, const RigidPose& pose) {
  const int count = static_cast<int>(colliders().size());
  if (index < 0 || index >= count) {
    return fail("collider " + std::to_string(index) + " is out of range (the scene has " +
                std::to_string(count) + ")");
  }
  if (!is_finite(pose.position) || !pose.rotation.coeffs().allFinite() ||
      std::abs(pose.rotation.norm() - 1.0) > 1e-6) {
    return fail("collider pose must be finite with a unit rotation, got position " +
                to_string(pose.position));
  }
  // Not placed here directly (it could land across the cloth): the contact term takes the
  // pose as the collider's target and moves it there within the next step, CCD watching.
  return built_.contact->move_collider(static_cast<std::size_t>(index), pose);
}

void ClothScene::grab_collider(const ColliderGrab& grab) {
  collider_drag_ = ColliderDrag{grab, grab.point, grab.pose};
}

Result<void> ClothScene::drag_collider_to(const Vec3& cursor) {
  if (!collider_drag_) return fail("no collider is grabbed");
  if (!is_finite(cursor))
    return fail("drag target has a non-finite coordinate " + to_string(cursor));
  collider_drag_->cursor = cursor;
  collider_drag_->target = dragged_pose(collider_drag_->grab, cursor);
  return move_collider(collider_drag_->grab.collider, collider_drag_->target);
}

void ClothScene::contact_points(std::vector<ContactPoint>& out) const {
  out.clear();
  if (built_.contact) built_.contact->contact_points(simulator().state().positions, out);
}

Result<StepReport> ClothScene::step() {
  if (drag_) {
    // The mouse spring, evaluated at the start of the step like gravity.
    const ClothState& state = simulator().state();
    const int p = drag_->particle;
    const double m = simulator().model().mass[p];
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(state.positions.size());
    // The force is explicit (held over the step), so the spring must stay stable on its own:
    // h sqrt(k) <= 1/2 keeps both the spring and its damping (h c <= 1) well inside the
    // explicit stability limit (2) at any time step.
    const double h = world_.time_step;
    const double k = std::min(kDragStiffness, 0.25 / (h * h));
    forces.segment<3>(3 * p) =
        m * (k * (drag_->target - state.position(p)) - 2.0 * std::sqrt(k) * state.velocity(p));
    if (auto set = built_.simulator.set_external_forces(forces); !set)
      return fail(set.error().message);
  }
  auto report = built_.simulator.step(world_.time_step);
  if (!report) return report;
  // The colliders are drawn where the solver moved them (along their motions, or dragged).
  const double t = built_.simulator.state().time;
  for (std::size_t i = 0; built_.contact && i < built_.colliders.size(); ++i)
    built_.colliders[i].set_pose(t, built_.contact->collider_pose(i));
  last_ = *report;
  energy_.push_back(report->energy);
  if (energy_.size() > kEnergyHistory) energy_.pop_front();
  return report;
}

void ClothScene::describe(DrawList& out, ClothStyle style) const {
  style.floor_height = floor_height_;
  describe_cloth(out, simulator().model(), simulator().state(), style);
  if (style.colliders) describe_colliders(out, colliders());
  if (style.contacts) {
    std::vector<ContactPoint> points;
    contact_points(points);
    describe_contact_points(out, points);
  }
  if (drag_) {
    const Vec3 grabbed = simulator().state().position(drag_->particle);
    out.add_line(grabbed, drag_->target, palette::dragged, 2.0f);
    out.add_point(drag_->target, palette::dragged, 9.0f);
  }
  if (collider_drag_) {
    // Where the grabbed point is asked to go: the cursor.
    out.add_line(collider_drag_->grab.point, collider_drag_->cursor, palette::dragged, 2.0f);
    out.add_point(collider_drag_->cursor, palette::dragged, 9.0f);
  }
}

Eigen::AlignedBox3d ClothScene::focus_bounds() const {
  return cloth_picture_frame(world_, desc_, simulator().state(), colliders()).focus;
}

}  // namespace animkit
