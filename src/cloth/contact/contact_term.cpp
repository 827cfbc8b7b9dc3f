#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "../../core/parallel.h"
#include "animkit/cloth/contact.h"
#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "contact_candidates.h"
#include "contact_pair.h"
#include "contact_points.h"
#include "gather_region.h"
#include "moving_obstacles.h"
#include "start_separation.h"

namespace animkit {

namespace {

// The barrier's force on a particle at distance delta = dhat / 2 is kappa |b'(dhat^2 / 4)| 2
// delta = 4.3294 kappa dhat^3 (b' from barrier.h at d = D / 4: 1.5 D ln 4 + 2.25 D). The
// automatic kappa makes that the weight of an average particle, so cloth resting on a surface
// sits at about half its thickness; heavier loads press closer, where the barrier is steeper.
// A collider moving at speed v must bring the cloth it meets to v within the substep h: a
// force of m v / h on a particle of mass m, which outweighs gravity when v / h > g. Pressed by
// that force against a kappa made for its weight, cloth comes within 1e-10 m of the collider,
// where each Newton iteration's CCD walks take a hundred thousand steps (a ball at 100 m/s into
// a 5 x 5 cotton sheet: 4 frames in 4.1 s, one step at the iteration cap). So each substep's
// automatic kappa takes the larger of the two forces (the same run: 0.73 s, every step
// converged). Colliders at rest, or slower than g h, leave kappa as it is.
constexpr double kHalfThicknessForce = 4.3294;

// A pair's barrier derivatives (a 12 x 12 Hessian and its eigendecomposition) cost about as
// much as this many iterations of a light per-particle loop (parallel::for_each_weighted).
constexpr int kPairWeight = 64;
// And whether a pair is within dhat (its primitives' boxes, then its distance).
constexpr int kActiveTestWeight = 8;

// The most a vertex of an active pair may move in Newton's next correction, as a fraction of
// the pair's distance, for a substep to end on the correction's size
// (EnergyTerm::gaps_settled). Resting cloth under several layers sits at a hundredth of the
// thickness and stays there (drape-sphere 41 x 41: 0.02 mm of 2 mm, its corrections a few
// micrometres); a gap the substep's start closed to a tenth is reopened by a correction
// several times its size.
constexpr double kSettledGapFraction = 0.1;

}  // namespace

std::optional<Error> ContactSettings::validate() const {
  if (!std::isfinite(thickness) || thickness <= 0.0 || thickness > kCoordinateRange.max)
    return Error{"contact thickness must be > 0 m and at most " +
                 format_number(kCoordinateRange.max) + " m, got " + format_number(thickness)};
  if (!kContactStiffnessRange.contains(stiffness))
    return Error{
        kContactStiffnessRange.refusal("contact stiffness (J/m^4, 0: automatic)", stiffness)};
  if (!std::isfinite(min_separation) || min_separation <= 0.0 || min_separation >= 1.0)
    return Error{"contact minimum separation must be in (0, 1), got " +
                 format_number(min_separation)};
  return std::nullopt;
}

int ContactObstacles::vertex_count() const {
  int n = 0;
  for (const TriangleMesh& mesh : meshes) n += static_cast<int>(mesh.vertices.size());
  for (const Collider& c : colliders) n += static_cast<int>(contact_vertices(c).size());
  return n;
}

struct ContactTerm::Impl {
  std::shared_ptr<const ClothModel> model;
  ContactSettings settings;
  LogBarrier barrier = *LogBarrier::create(1.0);  // on squared distances: dhat^2 (set below)
  double kappa = 0.0;
  double weight_kappa = 0.0;  // the automatic kappa for the particles' weight; 0 when hand-set
  double gravity = 1.0;       // the acceleration it was made for, m/s^2 (at least 1)
  std::optional<double> ground;
  ContactGeometry geometry;  // the cloth's and the obstacles' primitives, one index space
  ContactPairFinder finder;
  MovingObstacles moving;
  std::vector<ContactPair> pairs;  // what value, gradient and Hessian sum over
  GatherRegion region;             // where `pairs` holds every pair within dhat
  std::int64_t gathers = 0;
  bool exact_hessian = false;     // this substep's pairs take the projected exact Hessian
  mutable Eigen::VectorXd moved;  // difference()'s workspace
  bool rest_lengths_known = false;

  Vec3 position(const Eigen::VectorXd& x, int v) const {
    const int n = model->particle_count();
    return v < n ? Vec3(x.segment<3>(3 * v))
                 : Vec3(geometry.obstacle_positions.segment<3>(3 * (v - n)));
  }
  std::array<Vec3, 4> positions(const Eigen::VectorXd& x, const ContactPair& pair) const {
    std::array<Vec3, 4> p;
    for (int i = 0; i < pair.vertex_count(); ++i) p[i] = position(x, pair.vertices[i]);
    return p;
  }
  double ground_height() const { return ground.value_or(0.0); }

  // Gathers the pairs for boxes around x that hold x + step (gather_region.h). A non-finite
  // x or step finds none, and leaves no region.
  bool gather(const Eigen::VectorXd& x, const Eigen::VectorXd* step) {
    ++gathers;
    at.valid = false;
    region.set(x, step, GatherRegion::kFloorFraction * settings.thickness,
               geometry.obstacle_positions);
    if (!finder.gather(geometry, region.lower(), &region.extent(), settings.thickness, ground,
                       pairs)) {
      pairs.clear();
      region.clear();
      return false;
    }
    keep_reachable(x);
    return true;
  }

  // Drops the gathered pairs that stay beyond dhat while every particle stays in its box
  // (GatherRegion::reach). The broad phase sees each primitive's whole box, and a coarse cloth
  // triangle's box holds much of a finely tessellated collider that stays centimetres away:
  // on a ball at 100 m/s meeting a 5 x 5 sheet, most gathered pairs. What is left is what the
  // barrier, CCD and the line search then go over at every iteration.
  // The distances it measures at x are the kept pairs' entry in `at`.
  std::vector<char> pair_kept;
  void keep_reachable(const Eigen::VectorXd& x) {
    const int n = model->particle_count();
    const double within = std::sqrt(barrier.dhat()) * (1.0 + 1e-6);
    pair_kept.resize(pairs.size());
    at.distance2.resize(pairs.size());
    parallel::for_each_weighted(static_cast<int>(pairs.size()), kActiveTestWeight, [&](int k) {
      const ContactPair& pair = pairs[static_cast<std::size_t>(k)];
      char& kept = pair_kept[static_cast<std::size_t>(k)];
      double& distance2 = at.distance2[static_cast<std::size_t>(k)];
      const std::array<Vec3, 4> p = positions(x, pair);
      if (pair.kind == ContactKind::ground) {
        distance2 = contact_distance_squared(pair, p, ground_height());
        kept = 1;
        return;
      }
      const int second = pair.kind == ContactKind::point_triangle ? 1 : 2;
      double reach[2] = {0.0, 0.0};  // each primitive's: the farthest any of its points gets
      for (int i = 0; i < 4; ++i) {
        const int v = pair.vertices[i];
        double& primitive = reach[i < second ? 0 : 1];
        if (v < n) primitive = std::max(primitive, region.reach(v));
      }
      const double limit = within + reach[0] + reach[1];
      kept = contact_box_gap(pair, p, p) <= limit &&
             (distance2 = contact_distance_squared(pair, p, ground_height())) < limit * limit;
    });
    std::size_t count = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      if (!pair_kept[k]) continue;
      pairs[count] = pairs[k];
      at.distance2[count++] = at.distance2[k];
    }
    pairs.resize(count);
    at.distance2.resize(count);
    at.x = x;
    at.obstacles = geometry.obstacle_positions;
    at.barrier.clear();
    at.valid = true;
  }

  // Per gathered pair at one configuration (x, with the obstacles where they are): its squared
  // distance where its primitives' boxes lie within dhat (or wherever it was measured), else
  // their boxes' gap squared (a lower bound, beyond dhat), and its barrier once a line search
  // asks for it. Either way a pair is within dhat exactly when its entry is below dhat:
  // contact_beyond's margin puts the distance of a pair it passes over at dhat or more. A Newton
  // iteration asks at one x for the active pairs twice (gradient, Hessian), then for CCD's
  // starting distances, the line search's barriers at x and the stopping test's gaps.
  struct PairsAt {
    bool valid = false;
    Eigen::VectorXd x, obstacles;
    std::vector<double> distance2;
    std::vector<double> barrier;  // empty until difference() asks at this x
  };
  mutable PairsAt at;

  const std::vector<double>& distances_at(const Eigen::VectorXd& x) const {
    if (at.valid && at.x.size() == x.size() && at.x == x &&
        at.obstacles == geometry.obstacle_positions) {
      return at.distance2;
    }
    at.valid = true;
    at.x = x;
    at.obstacles = geometry.obstacle_positions;
    at.barrier.clear();
    at.distance2.resize(pairs.size());
    parallel::for_each_weighted(static_cast<int>(pairs.size()), kActiveTestWeight, [&](int k) {
      const ContactPair& pair = pairs[static_cast<std::size_t>(k)];
      const std::array<Vec3, 4> p = positions(x, pair);
      double& d2 = at.distance2[static_cast<std::size_t>(k)];
      if (contact_beyond(pair, p, barrier.dhat())) {
        const double gap = contact_box_gap(pair, p, p);
        d2 = gap * gap;
      } else {
        d2 = contact_distance_squared(pair, p, ground_height());
      }
    });
    return at.distance2;
  }

  const std::vector<double>& barriers_at(const Eigen::VectorXd& x) const {
    distances_at(x);
    if (at.barrier.empty() && !pairs.empty()) {
      at.barrier.resize(pairs.size());
      parallel::for_each_weighted(static_cast<int>(pairs.size()), kActiveTestWeight, [&](int k) {
        const auto pair = static_cast<std::size_t>(k);
        at.barrier[pair] = at.distance2[pair] < barrier.dhat()
                               ? contact_barrier(pairs[pair], positions(x, pairs[pair]),
                                                 ground_height(), barrier)
                               : 0.0;
      });
    }
    return at.barrier;
  }

  // The pairs within dhat at x (indices into `pairs`, in their order), then per active pair
  // the barrier's gradient or its PSD Hessian (ContactSettings::hessian), without kappa, each
  // into its own slot, computed over the threads (summed in their order, so the bits do not
  // depend on the thread count). Only the active pairs get slots: along a fast collider's move
  // the gathered set can hold tens of thousands of pairs of which a few dozen are within dhat,
  // and a 12 x 12 slot for each of them cost more in memory traffic than the derivatives.
  mutable std::vector<int> active_pairs;
  mutable std::vector<Eigen::Matrix<double, 12, 1>> pair_gradients;
  mutable std::vector<Eigen::Matrix<double, 12, 12>> pair_hessians;

  // BarrierHessian::adaptive: a pair closer than kCollapsedGapFraction of the thickness takes
  // the projected exact Hessian whatever the substep's mode (contact.h).
  bool collapsed(double distance2) const {
    return settings.hessian == BarrierHessian::adaptive &&
           distance2 < kCollapsedGapFraction * kCollapsedGapFraction * barrier.dhat();
  }

  // Within dhat at x: the pair's barrier and its derivatives are not zero.
  void find_active(const Eigen::VectorXd& x) const {
    const std::vector<double>& distance2 = distances_at(x);
    active_pairs.clear();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      if (distance2[k] < barrier.dhat()) active_pairs.push_back(static_cast<int>(k));
    }
  }

  void evaluate_gradients(const Eigen::VectorXd& x) const {
    find_active(x);
    pair_gradients.resize(active_pairs.size());
    parallel::for_each_weighted(static_cast<int>(active_pairs.size()), kPairWeight, [&](int a) {
      const ContactPair& pair = pairs[static_cast<std::size_t>(active_pairs[a])];
      pair_gradients[static_cast<std::size_t>(a)] =
          contact_barrier_gradient(pair, positions(x, pair), ground_height(), barrier);
    });
  }

  void evaluate_hessians(const Eigen::VectorXd& x) const {
    find_active(x);
    pair_hessians.resize(active_pairs.size());
    parallel::for_each_weighted(static_cast<int>(active_pairs.size()), kPairWeight, [&](int a) {
      const auto k = static_cast<std::size_t>(active_pairs[a]);
      const ContactPair& pair = pairs[k];
      const std::array<Vec3, 4> p = positions(x, pair);
      pair_hessians[static_cast<std::size_t>(a)] =
          !exact_hessian && !collapsed(at.distance2[k]) && gauss_newton_suffices(pair, p)
              ? contact_barrier_gauss_newton_hessian(pair, p, ground_height(), barrier)
              : contact_barrier_derivatives(pair, p, ground_height(), barrier).hessian;
    });
  }
};

ContactTerm::ContactTerm(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ContactTerm::~ContactTerm() = default;

Result<std::shared_ptr<ContactTerm>> ContactTerm::create(std::shared_ptr<const ClothModel> model,
                                                         const ContactSettings& settings,
                                                         ContactObstacles obstacles) {
  if (auto error = settings.validate()) return fail(error->message);
  if (model->triangles.empty()) return fail("contact needs the cloth's triangles, and it has none");
  for (std::size_t m = 0; m < obstacles.meshes.size(); ++m) {
    if (auto error = obstacles.meshes[m].validate())
      return fail("obstacle " + std::to_string(m) + ": " + error->message);
  }
  if (obstacles.ground_height && !std::isfinite(*obstacles.ground_height))
    return fail("the ground's height must be finite");
  for (const Collider& c : obstacles.colliders) {
    if (c.is_half_space()) {
      return fail("collider " + quote_input(c.name()) +
                  " is a plane: contact takes a horizontal floor as the ground height");
    }
  }
  auto impl = std::make_unique<Impl>();
  impl->settings = settings;
  impl->exact_hessian = settings.hessian == BarrierHessian::projected;
  impl->barrier = *LogBarrier::create(settings.thickness * settings.thickness);
  impl->ground = obstacles.ground_height;
  // One obstacle list: the fixed meshes, then each collider's surface where it is now (a
  // sphere's centre, standing for its exact surface: contact_vertices).
  std::vector<TriangleMesh> surfaces = std::move(obstacles.meshes);
  std::vector<double> sphere_radius(surfaces.size(), 0.0);
  int first = 0;
  for (const TriangleMesh& mesh : surfaces) first += static_cast<int>(mesh.vertices.size());
  for (Collider& c : obstacles.colliders) {
    sphere_radius.push_back(contact_radius(c));
    if (sphere_radius.back() > 0.0) {
      surfaces.push_back({{c.pose().position}, {}});
    } else {
      surfaces.push_back({c.world_vertices(), c.model().surface.triangles});
    }
    const int count = static_cast<int>(surfaces.back().vertices.size());
    impl->moving.add(std::move(c), first, static_cast<int>(surfaces.size()) - 1);
    first += count;
  }
  auto geometry = build_contact_geometry(*model, surfaces, settings.self_contact, sphere_radius);
  if (!geometry) return fail(geometry.error().message);
  impl->geometry = std::move(*geometry);
  double mass = 0.0;
  int free = 0;
  for (int i = 0; i < model->particle_count(); ++i) {
    if (model->pinned[i]) continue;
    mass += model->mass[i];
    ++free;
  }
  const double gravity = std::max(std::abs(model->gravity), 1.0);
  const double dhat = settings.thickness;
  impl->gravity = gravity;
  impl->weight_kappa = settings.stiffness > 0.0 ? 0.0
                                                : (free > 0 ? mass / free : 1.0) * gravity /
                                                      (kHalfThicknessForce * dhat * dhat * dhat);
  impl->kappa = settings.stiffness > 0.0 ? settings.stiffness : impl->weight_kappa;
  impl->model = std::move(model);
  return std::shared_ptr<ContactTerm>(new ContactTerm(std::move(impl)));
}

double ContactTerm::stiffness() const {
  return impl_->kappa;
}

Result<void> ContactTerm::move_collider(std::size_t index, const RigidPose& target) {
  const auto& colliders = impl_->moving.colliders();
  if (index >= colliders.size()) {
    return fail("no collider " + std::to_string(index) + ": the contact term has " +
                std::to_string(colliders.size()) + " collider(s)");
  }
  if (auto error = validate_pose(target)) {
    return fail("collider " + quote_input(colliders[index].name()) +
                ": target pose: " + error->message);
  }
  impl_->moving.set_target(index, target);
  return {};
}

const std::vector<Collider>& ContactTerm::colliders() const {
  return impl_->moving.colliders();
}

const RigidPose& ContactTerm::collider_pose(std::size_t index) const {
  return impl_->moving.pose(index);
}

Eigen::VectorXd ContactTerm::collider_points() const {
  return impl_->moving.surface_points(impl_->geometry);
}

const Eigen::VectorXd& ContactTerm::obstacle_positions() const {
  return impl_->geometry.obstacle_positions;
}

const Eigen::VectorXd& ContactTerm::obstacle_start_positions() const {
  return impl_->geometry.obstacle_start_positions;
}

void ContactTerm::prepare(const ClothState& state, double h) {
  // The edge-edge mollifier's thresholds come from rest lengths: the cloth's as it starts.
  if (!impl_->rest_lengths_known) {
    set_cloth_rest_lengths(impl_->geometry, state.positions);
    impl_->rest_lengths_known = true;
  }
  impl_->moving.begin_substep(impl_->geometry, state.time + h);
  if (impl_->weight_kappa > 0.0 && h > 0.0) {
    // v / h = (the move / h) / h: the acceleration that brings cloth to the collider's speed.
    const double catch_up = impl_->moving.largest_surface_move() / (h * h);
    impl_->kappa = impl_->weight_kappa * std::max(1.0, catch_up / impl_->gravity);
  }
  impl_->exact_hessian = impl_->settings.hessian == BarrierHessian::projected;
}

bool ContactTerm::settled() const {
  return impl_->moving.settled();
}

void ContactTerm::advance(Eigen::VectorXd& x) {
  // Moving colliders advance toward the substep's end, pushing the cloth in their way, as far
  // as CCD allows (moving_obstacles.h), then stay there for this iteration's line search. The
  // move gathers its own pairs into `pairs`: update() gathers again.
  if (!impl_->moving.settled()) impl_->region.clear();
  impl_->at.valid = false;  // and with them their distances
  impl_->moving.advance(impl_->geometry, impl_->finder, impl_->model->pinned, impl_->ground,
                        impl_->settings.thickness, impl_->settings.min_separation, x, impl_->pairs);
}

void ContactTerm::update(const Eigen::VectorXd& x) {
  // Every pair within dhat of x: what g's gradient and Hessian at x need; the pairs of the last
  // gather still hold them while x is inside its region. A non-finite x finds none (g's own
  // gradient there is not finite, and Newton stops).
  if (!impl_->region.covers(x, impl_->geometry.obstacle_positions)) impl_->gather(x, nullptr);
}

double ContactTerm::max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) {
  // Every pair that may come within dhat anywhere on x + t step, t in [0, 1]: the line search
  // evaluates g there, and CCD bounds t by the first time any of them would touch.
  if (!impl_->region.covers(x, impl_->geometry.obstacle_positions) ||
      !impl_->region.covers_step(x, step)) {
    if (!impl_->gather(x, &step)) return 0.0;  // a non-finite step: take none of it
  }
  const double bound = earliest_contact(
      impl_->geometry, impl_->pairs, x, step, impl_->ground_height(), impl_->settings.thickness,
      impl_->settings.min_separation, nullptr, {}, &impl_->distances_at(x));
  if (impl_->settings.hessian == BarrierHessian::adaptive && bound < kFrozenStepFraction)
    impl_->exact_hessian = true;
  return bound;
}

double ContactTerm::value(const Eigen::VectorXd& x) const {
  double sum = 0.0;
  for (const ContactPair& pair : impl_->pairs) {
    sum += contact_barrier(pair, impl_->positions(x, pair), impl_->ground_height(), impl_->barrier);
  }
  return impl_->kappa * sum;
}

double ContactTerm::difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const {
  // Pair by pair, so a large barrier elsewhere does not swamp a small change.
  Eigen::VectorXd& moved = impl_->moved;
  moved = x + step;  // sized once: the line search calls this every trial
  const std::vector<double>& before = impl_->barriers_at(x);
  double sum = 0.0;
  for (std::size_t k = 0; k < impl_->pairs.size(); ++k) {
    const ContactPair& pair = impl_->pairs[k];
    const double after = contact_barrier(pair, impl_->positions(moved, pair),
                                         impl_->ground_height(), impl_->barrier);
    if (!std::isfinite(after)) return std::numeric_limits<double>::infinity();
    sum += after - before[k];
  }
  return impl_->kappa * sum;
}

void ContactTerm::add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  const int n = impl_->model->particle_count();
  impl_->evaluate_gradients(x);
  for (std::size_t a = 0; a < impl_->active_pairs.size(); ++a) {
    const ContactPair& pair = impl_->pairs[static_cast<std::size_t>(impl_->active_pairs[a])];
    for (int i = 0; i < pair.vertex_count(); ++i) {
      const int v = pair.vertices[i];
      if (v < n)
        gradient.segment<3>(3 * v) += impl_->kappa * impl_->pair_gradients[a].segment<3>(3 * i);
    }
  }
}

void ContactTerm::add_hessian(const Eigen::VectorXd& x, bool /*projected: always*/,
                              std::vector<HessianBlock>& blocks) const {
  const int n = impl_->model->particle_count();
  impl_->evaluate_hessians(x);
  for (std::size_t a = 0; a < impl_->active_pairs.size(); ++a) {
    const ContactPair& pair = impl_->pairs[static_cast<std::size_t>(impl_->active_pairs[a])];
    const Eigen::Matrix<double, 12, 12>& hessian = impl_->pair_hessians[a];
    // The cloth's rows and columns of the pair's PSD Hessian (a principal submatrix: PSD too).
    for (int i = 0; i < pair.vertex_count(); ++i) {
      if (pair.vertices[i] >= n) continue;
      for (int j = i; j < pair.vertex_count(); ++j) {
        if (pair.vertices[j] >= n) continue;
        blocks.push_back(
            {pair.vertices[i], pair.vertices[j], impl_->kappa * hessian.block<3, 3>(3 * i, 3 * j)});
      }
    }
  }
}

void ContactTerm::add_to_report(const Eigen::VectorXd& x, StepReport& report) const {
  const ContactStats s = stats(x);
  report.has_contact = true;
  report.contact_pairs = s.active_pairs;
  report.min_contact_distance = s.min_distance;
}

void ContactTerm::contact_points(const Eigen::VectorXd& x, std::vector<ContactPoint>& out) const {
  out.clear();
  const int n = impl_->model->particle_count();
  for (const ContactPair& pair : impl_->pairs) {
    const std::array<Vec3, 4> p = impl_->positions(x, pair);
    if (contact_beyond(pair, p, impl_->barrier.dhat())) continue;
    const double d2 = contact_distance_squared(pair, p, impl_->ground_height());
    if (d2 >= impl_->barrier.dhat()) continue;
    const auto [first, second] = contact_closest_points(pair, p, impl_->ground_height());
    ContactPoint point{.cloth = first, .other = second, .distance = std::sqrt(d2)};
    if (pair.kind == ContactKind::ground) {
      point.with = ContactPoint::With::ground;
    } else if (pair.vertices[0] >= n || pair.vertices[2] >= n) {
      // One primitive is an obstacle's: the cloth's is whichever starts below n.
      point.with = ContactPoint::With::collider;
      if (pair.vertices[0] >= n) std::swap(point.cloth, point.other);
    } else {
      point.with = ContactPoint::With::self;
    }
    out.push_back(point);
  }
}

Result<void> ContactTerm::check_start(const Eigen::VectorXd& x) const {
  const Impl& m = *impl_;
  const std::size_t fixed_meshes =
      m.geometry.obstacle_mesh_start.size() - m.moving.colliders().size();
  const ObstacleNamer name = [&m, fixed_meshes](int v) {
    const auto mesh = static_cast<std::size_t>(m.geometry.obstacle_mesh_of(v));
    if (mesh < fixed_meshes) return "obstacle mesh " + std::to_string(mesh);
    return "collider " + quote_input(m.moving.colliders()[mesh - fixed_meshes].name());
  };
  // With self-contact, a thickness beyond the cloth's own edges makes neighbouring primitives
  // of the sheet repel at rest and puts every pair within reach (a 10 m thickness on an 11 x 11
  // sheet took 19 s a frame).
  double length = 0.0;
  for (const auto& [a, b] : m.geometry.cloth.edges)
    length += (x.segment<3>(3 * a) - x.segment<3>(3 * b)).norm();
  length /= static_cast<double>(std::max<std::size_t>(m.geometry.cloth.edges.size(), 1));
  if (m.settings.self_contact && m.settings.thickness > length) {
    return fail("contact thickness " + format_number(m.settings.thickness) +
                " m is more than the cloth's mean edge length, " + format_number(length) +
                " m: the sheet's neighbouring triangles would repel each other");
  }
  if (auto problem =
          find_start_overlap(m.geometry, x, kMinStartGapFraction * m.settings.thickness, name))
    return fail(*problem);
  return {};
}

bool ContactTerm::gaps_settled(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const {
  const Impl& m = *impl_;
  const int n = m.model->particle_count();
  const std::vector<double>& distance2 = m.distances_at(x);
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    if (distance2[k] >= m.barrier.dhat()) continue;
    const ContactPair& pair = m.pairs[k];
    double move = 0.0;  // the obstacles' vertices follow their motions, not dx
    for (int i = 0; i < pair.vertex_count(); ++i) {
      if (pair.vertices[i] < n) move = std::max(move, dx.segment<3>(3 * pair.vertices[i]).norm());
    }
    if (move > kSettledGapFraction * std::sqrt(distance2[k])) return false;
  }
  return true;
}

ContactStats ContactTerm::stats(const Eigen::VectorXd& x) const {
  ContactStats stats;
  stats.candidate_pairs = static_cast<int>(impl_->pairs.size());
  stats.gathers = impl_->gathers;
  double closest = impl_->barrier.dhat();
  for (const ContactPair& pair : impl_->pairs) {
    const std::array<Vec3, 4> p = impl_->positions(x, pair);
    if (contact_beyond(pair, p, impl_->barrier.dhat())) continue;
    const double d = contact_distance_squared(pair, p, impl_->ground_height());
    if (d < impl_->barrier.dhat()) {
      ++stats.active_pairs;
      closest = std::min(closest, d);
    }
  }
  stats.min_distance = std::sqrt(closest);
  return stats;
}

const ContactSettings& ContactTerm::settings() const {
  return impl_->settings;
}

std::optional<double> ContactTerm::ground_height() const {
  return impl_->ground;
}

const ContactGeometry& ContactTerm::geometry() const {
  return impl_->geometry;
}

}  // namespace animkit
