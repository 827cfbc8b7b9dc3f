#include "animkit/scene/cloth_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/validation.h"

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

ClothScene::ClothScene(ClothSceneOptions options, ClothDesc desc, ClothSimulator simulator)
    : options_(std::move(options)), desc_(std::move(desc)), simulator_(std::move(simulator)) {}

Result<ClothScene> ClothScene::create(const ClothSceneOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  ClothDesc desc = make_grid_cloth(options.grid);
  auto simulator = ClothSimulator::create(desc, options.simulation);
  if (!simulator) return fail(simulator.error().message);
  return ClothScene(options, std::move(desc), std::move(*simulator));
}

Result<void> ClothScene::reset(const ClothSceneOptions& options) {
  auto fresh = create(options);
  if (!fresh) return fail(fresh.error().message);
  *this = std::move(*fresh);
  return {};
}

Result<void> ClothScene::rebuild_keeping_state(ClothDesc desc) {
  auto simulator = ClothSimulator::create(desc, options_.simulation);
  if (!simulator) return fail(simulator.error().message);
  if (auto kept = simulator->set_state(simulator_.state()); !kept) return kept;
  simulator_ = std::move(*simulator);
  desc_ = std::move(desc);
  return {};
}

Result<void> ClothScene::apply(const ClothSceneOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  const bool same_layout = options.grid.cells == options_.grid.cells &&
                           options.grid.size == options_.grid.size &&
                           options.grid.height == options_.grid.height;
  if (!same_layout) return reset(options);
  // Same particles and springs: take the new physical parameters, keep pins and motion.
  ClothDesc desc = make_grid_cloth(options.grid);
  for (std::size_t i = 0; i < desc.particles.size(); ++i) {
    desc.particles[i].pinned = desc_.particles[i].pinned;
    desc.particles[i].position = desc_.particles[i].position;
  }
  const ClothSceneOptions previous = options_;
  options_ = options;
  if (auto rebuilt = rebuild_keeping_state(std::move(desc)); !rebuilt) {
    options_ = previous;
    return rebuilt;
  }
  return {};
}

Result<void> ClothScene::toggle_pin(int particle) {
  const int count = simulator_.model().particle_count();
  if (particle < 0 || particle >= count) {
    return fail("particle " + std::to_string(particle) + " is out of range (the cloth has " +
                std::to_string(count) + ")");
  }
  ClothDesc desc = desc_;
  desc.particles[particle].pinned = !desc.particles[particle].pinned;
  return rebuild_keeping_state(std::move(desc));
}

std::optional<int> ClothScene::pick(const OrbitCamera& camera, double x, double y, double width,
                                    double height, double radius_px) const {
  std::optional<int> best;
  double best_depth = std::numeric_limits<double>::infinity();
  const ClothState& state = simulator_.state();
  for (int i = 0; i < simulator_.model().particle_count(); ++i) {
    const auto p = camera.project(state.position(i), width, height);
    if (!p || std::hypot(p->x() - x, p->y() - y) > radius_px) continue;
    if (p->z() < best_depth) {
      best = i;
      best_depth = p->z();
    }
  }
  return best;
}

Result<void> ClothScene::set_drag(const ClothDrag& drag) {
  const int count = simulator_.model().particle_count();
  if (drag.particle < 0 || drag.particle >= count) {
    return fail("particle " + std::to_string(drag.particle) + " is out of range (the cloth has " +
                std::to_string(count) + ")");
  }
  if (!is_finite(drag.target)) {
    return fail("drag target has a non-finite coordinate " + to_string(drag.target));
  }
  drag_ = drag;
  return {};
}

void ClothScene::clear_drag() {
  drag_.reset();
  simulator_.clear_external_forces();
}

Result<StepReport> ClothScene::step() {
  if (drag_) {
    // The mouse spring, evaluated at the start of the step like gravity.
    const ClothState& state = simulator_.state();
    const int p = drag_->particle;
    const double m = simulator_.model().mass[p];
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(state.positions.size());
    // The force is explicit (held over the step), so the spring must stay stable on its own:
    // h sqrt(k) <= 1/2 keeps both the spring and its damping (h c <= 1) well inside the
    // explicit stability limit (2) at any time step.
    const double h = options_.time_step;
    const double k = std::min(kDragStiffness, 0.25 / (h * h));
    forces.segment<3>(3 * p) =
        m * (k * (drag_->target - state.position(p)) - 2.0 * std::sqrt(k) * state.velocity(p));
    if (auto set = simulator_.set_external_forces(forces); !set) return fail(set.error().message);
  }
  auto report = simulator_.step(options_.time_step);
  if (!report) return report;
  last_ = *report;
  energy_.push_back(report->energy);
  if (energy_.size() > kEnergyHistory) energy_.pop_front();
  return report;
}

void describe_cloth(DrawList& out, const ClothModel& model, const ClothState& state,
                    const ClothStyle& style) {
  out.add_ground_grid(style.floor_height, 16, 0.25, 0.5);
  if (style.surface) {
    // Smooth shading: each vertex normal is the area-weighted sum of its triangles' normals.
    std::vector<Vec3> normals(model.particle_count(), Vec3::Zero());
    for (const auto& t : model.triangles) {
      const Vec3 n = (state.position(t[1]) - state.position(t[0]))
                         .cross(state.position(t[2]) - state.position(t[0]));
      for (int k : t) normals[k] += n;
    }
    for (Vec3& n : normals) n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitY();
    for (const auto& t : model.triangles) {
      const Vec3 p[3] = {state.position(t[0]), state.position(t[1]), state.position(t[2])};
      const Vec3 n[3] = {normals[t[0]], normals[t[1]], normals[t[2]]};
      out.add_triangle(p, n, palette::cloth_front, palette::cloth_back);
    }
  }
  if (style.springs) {
    for (const auto& [a, b] : model.springs) {
      out.add_line(state.position(a), state.position(b), palette::spring, 1.0f);
    }
  }
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned[i]) {
      out.add_point(state.position(i), palette::pinned, 10.0f);
    } else if (style.particles) {
      out.add_point(state.position(i), palette::particle, 4.0f);
    }
  }
}

// How far below its pins a grid cloth is framed, in sides: the sheet hanging straight down
// spans one side, and its springs stretch under its weight. Measured on the lab's cloth
// (k = 100, m = 1, g = 0.3): its lowest point over 20 s is 1.16 sides below the pins. A soft
// cloth hangs lower (k = 10: 1.98 sides) and passes the floor: it is a drawing aid, not a
// collider.
constexpr double kHangingSides = 1.3;

double cloth_floor_height(const GridClothOptions& grid) {
  return grid.height - (kHangingSides + 0.1) * grid.size;
}

Eigen::AlignedBox3d cloth_focus_bounds(const GridClothOptions& grid, const ClothState& state) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < state.positions.size() / 3; ++i) {
    box.extend(Vec3(state.positions.segment<3>(3 * i)));
  }
  box.extend(Vec3(0.0, grid.height - kHangingSides * grid.size, -0.5 * grid.size));
  box.extend(Vec3(grid.size, grid.height, 0.5 * grid.size));
  return box;
}

namespace {

// The rest shape's box and the lowest point a sheet hanging from its pins reaches (by the
// grid's measure: kHangingSides of its largest side below its lowest pin).
struct Hanging {
  Eigen::AlignedBox3d rest;
  double side = 0.0, bottom = 0.0;
};
Hanging hanging(const ClothDesc& desc) {
  Hanging h;
  double top = std::numeric_limits<double>::infinity();
  for (const ParticleDesc& p : desc.particles) {
    h.rest.extend(p.position);
    if (p.pinned) top = std::min(top, p.position.y());
  }
  if (desc.particles.empty()) return h;
  if (!std::isfinite(top)) top = h.rest.min().y();
  h.side = h.rest.sizes().maxCoeff();
  h.bottom = top - kHangingSides * h.side;
  return h;
}

}  // namespace

double cloth_floor_height(const ClothDesc& desc) {
  const Hanging h = hanging(desc);
  return h.bottom - 0.1 * h.side;
}

Eigen::AlignedBox3d cloth_focus_bounds(const ClothDesc& desc, const ClothState& state) {
  const Hanging h = hanging(desc);
  Eigen::AlignedBox3d box = h.rest;
  for (Eigen::Index i = 0; i < state.positions.size() / 3; ++i) {
    box.extend(Vec3(state.positions.segment<3>(3 * i)));
  }
  if (!h.rest.isEmpty()) box.extend(Vec3(h.rest.center().x(), h.bottom, h.rest.center().z()));
  return box;
}

void ClothScene::describe(DrawList& out, ClothStyle style) const {
  style.floor_height = cloth_floor_height(options_.grid);
  describe_cloth(out, simulator_.model(), simulator_.state(), style);
  if (drag_) {
    const Vec3 grabbed = simulator_.state().position(drag_->particle);
    out.add_line(grabbed, drag_->target, palette::dragged, 2.0f);
    out.add_point(drag_->target, palette::dragged, 9.0f);
  }
}

Eigen::AlignedBox3d ClothScene::focus_bounds() const {
  return cloth_focus_bounds(options_.grid, simulator_.state());
}

}  // namespace animkit
