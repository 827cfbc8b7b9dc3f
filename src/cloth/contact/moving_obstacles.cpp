#include "moving_obstacles.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <variant>

#include "contact_points.h"

namespace animkit {

const std::vector<Vec3>& contact_vertices(const Collider& collider) {
  static const std::vector<Vec3> centre{Vec3::Zero()};
  return contact_radius(collider) > 0.0 ? centre : collider.model().surface.vertices;
}

double contact_radius(const Collider& collider) {
  const auto* sphere = std::get_if<SphereShape>(&collider.model().desc.shape);
  return sphere != nullptr ? sphere->radius : 0.0;
}

void MovingObstacles::add(Collider collider, int first_vertex, int mesh) {
  // A sphere turning about its centre covers the same ground: contact has its centre alone,
  // its drawn surface (surface_points) keeps its first orientation, and friction feels the
  // spin at the surface (ContactGeometry::obstacle_spin, set in begin_substep).
  const bool round = contact_radius(collider) > 0.0;
  surface_rotation_.push_back(round ? std::optional<Quat>(collider.pose().rotation) : std::nullopt);
  poses_.push_back(collider.pose());
  aims_.push_back(collider.pose());
  colliders_.push_back(std::move(collider));
  first_vertex_.push_back(first_vertex);
  mesh_.push_back(mesh);
  targets_.emplace_back();
}

Eigen::VectorXd MovingObstacles::surface_points(const ContactGeometry& g) const {
  std::size_t count = 0;
  for (const Collider& c : colliders_) count += c.model().surface.vertices.size();
  Eigen::VectorXd points(3 * static_cast<Eigen::Index>(count));
  Eigen::Index out = 0;
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    const auto& local = colliders_[c].model().surface.vertices;
    const Eigen::Index first = 3 * static_cast<Eigen::Index>(first_vertex_[c]);
    if (surface_rotation_[c]) {
      const RigidPose surface{g.obstacle_positions.segment<3>(first), *surface_rotation_[c]};
      for (const Vec3& v : local) {
        points.segment<3>(out) = surface.to_world(v);
        out += 3;
      }
    } else {
      const auto size = 3 * static_cast<Eigen::Index>(local.size());
      points.segment(out, size) = g.obstacle_positions.segment(first, size);
      out += size;
    }
  }
  return points;
}

void MovingObstacles::begin_substep(ContactGeometry& g, double t_end) {
  g.obstacle_start_positions = g.obstacle_positions;  // same size: no allocation after the first
  end_ = g.obstacle_positions;                        // fixed meshes end where they are
  largest_surface_move_ = 0.0;
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    aims_[c] = targets_[c] ? *targets_[c] : pose_at(colliders_[c].model().desc.motion, t_end);
    RigidPose surface = aims_[c];
    if (surface_rotation_[c]) {
      surface.rotation = *surface_rotation_[c];
      // The sphere's turn over the substep, for friction at its surface's points.
      g.obstacle_spin[static_cast<std::size_t>(mesh_[c])] =
          (aims_[c].rotation * poses_[c].rotation.inverse()).toRotationMatrix() -
          Eigen::Matrix3d::Identity();
    }
    const std::vector<Vec3>& local = contact_vertices(colliders_[c]);
    for (std::size_t i = 0; i < local.size(); ++i) {
      const Eigen::Index at = 3 * (first_vertex_[c] + static_cast<Eigen::Index>(i));
      end_.segment<3>(at) = surface.to_world(local[i]);
      // The material point at the vertex: carried by the whole motion, spin included.
      const Vec3 start = g.obstacle_start_positions.segment<3>(at);
      largest_surface_move_ =
          std::max(largest_surface_move_, (end_.segment<3>(at) - start).norm());
      g.obstacle_motion.segment<3>(at) = aims_[c].to_world(poses_[c].to_local(start)) - start;
    }
  }
  settled_ = end_ == g.obstacle_positions;
  if (settled_) poses_ = aims_;
}

namespace {

// The joint move of obstacles and pushed cloth stops where Additive CCD's Lipschitz walk stops,
// short of the exact time a pair would close to its minimum separation. Stopped at the exact
// time (the walk along the separating direction), a pair the pushes do not open is left at
// that separation, and each later advance closes it by the same fraction again: a ball dragged
// through a hanging sheet stalled within a frame (fractions 0.28, then 1e-2 down to 1e-9).
constexpr AdditiveCcdSettings kAdvanceCcd{.along_separation = false};

// The barycentric coordinates (b, c) of e's projection onto the plane of (0, u, v), unit
// normal `normal`, twice the area `twice_area`; inside the triangle when b, c >= 0, b + c <= 1.
std::array<double, 2> projected_barycentric(const Vec3& e, const Vec3& u, const Vec3& v,
                                            const Vec3& normal, double twice_area) {
  return {normal.dot(e.cross(v)) / twice_area, normal.dot(u.cross(e)) / twice_area};
}

bool inside(const std::array<double, 2>& w) {
  return w[0] >= 0.0 && w[1] >= 0.0 && w[0] + w[1] <= 1.0;
}

// The parameters (s, t) of the closest points a0 + s (a1 - a0) and b0 + t (b1 - b0) of two
// lines, when both lie strictly inside their segments and the lines are not parallel; else
// none (the closest points are then at an end: a point-triangle pair covers that case).
std::optional<std::array<double, 2>> inner_closest_parameters(const Vec3& a0, const Vec3& a1,
                                                              const Vec3& b0, const Vec3& b1) {
  const Vec3 u = a1 - a0, v = b1 - b0, w = a0 - b0;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), uw = u.dot(w), vw = v.dot(w);
  const double det = uu * vv - uv * uv;
  if (!(det > 1e-12 * uu * vv)) return std::nullopt;  // parallel within rounding
  const double s = (uv * vw - vv * uw) / det, t = (uu * vw - uv * uw) / det;
  if (!(s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0)) return std::nullopt;
  return std::array<double, 2>{s, t};
}

}  // namespace

// Three cases: a particle over an obstacle face, an obstacle vertex near a cloth triangle (a
// coarse cloth meets a finer collider through its triangles' insides; a box's corner meets the
// cloth vertex beyond it; a sphere's centre stands for its surface), and an obstacle edge
// crossing a cloth edge (a box's edge sweeping across the sheet). The normal and the gap are
// taken where everything is now; the obstacle's move along the normal, less the gap beyond half
// the contact distance, is what the cloth lacks. A particle pushed several ways takes the
// largest push.
void MovingObstacles::push_cloth(const ContactGeometry& g, const std::vector<char>& pinned,
                                 const Eigen::VectorXd& x, double radius,
                                 const std::vector<ContactPair>& pairs) {
  const int n = g.cloth_vertices();
  push_.setZero(x.size());
  carry_.setZero(x.size());
  pushed_.assign(static_cast<std::size_t>(n), 0.0);
  const auto position = [&](int v) -> Vec3 {
    return v < n ? Vec3(x.segment<3>(3 * v)) : Vec3(g.obstacle_positions.segment<3>(3 * (v - n)));
  };
  const auto moving = [&](int v) -> Vec3 { return move_.segment<3>(3 * (v - n)); };
  const auto push = [&](int p, double lack, const Vec3& normal, const Vec3& obstacle_move) {
    if (pinned[static_cast<std::size_t>(p)] || !(lack > pushed_[static_cast<std::size_t>(p)]))
      return;
    pushed_[static_cast<std::size_t>(p)] = lack;
    push_.segment<3>(3 * p) = lack * normal;
    carry_.segment<3>(3 * p) = obstacle_move;
  };
  for (const ContactPair& pair : pairs) {
    if (pair.kind == ContactKind::edge_edge) {
      // Edges (a0, a1) and (b0, b1): one of them the cloth's, the other an obstacle's.
      const bool cloth_first = pair.vertices[0] < n;
      if (cloth_first == (pair.vertices[2] < n)) continue;
      const int c = cloth_first ? 0 : 2, o = 2 - c;  // the cloth's edge, the obstacle's
      const Vec3 c0 = position(pair.vertices[c]), c1 = position(pair.vertices[c + 1]);
      const Vec3 o0 = position(pair.vertices[o]), o1 = position(pair.vertices[o + 1]);
      const auto st = inner_closest_parameters(c0, c1, o0, o1);
      if (!st) continue;
      const auto [s, t] = *st;
      Vec3 normal = (c0 + s * (c1 - c0)) - (o0 + t * (o1 - o0));  // from the obstacle's edge
      const double gap = normal.norm();
      if (!(gap > 0.0)) continue;
      normal /= gap;
      const Vec3 edge_move =
          (1.0 - t) * moving(pair.vertices[o]) + t * moving(pair.vertices[o + 1]);
      const double lack = edge_move.dot(normal) - (gap - 0.5 * radius);
      push(pair.vertices[c], lack, normal, edge_move);
      push(pair.vertices[c + 1], lack, normal, edge_move);
      continue;
    }
    if (pair.kind != ContactKind::point_triangle) continue;
    const int p = pair.vertices[0];
    const bool cloth_point = p < n;
    if (cloth_point == (pair.vertices[1] < n)) continue;  // cloth-cloth (obstacle-obstacle: none)
    if (!cloth_point) {
      // An obstacle vertex (a sphere's centre: its surface, `thickness` nearer) comes toward the
      // cloth triangle's nearest point along the direction from it to that point, wherever on
      // the triangle the point is, and pushes the triangle whole. Beyond a box's corner the
      // nearest point is a cloth vertex; pushed only where the corner was over the triangle's
      // inside, a box keyframed through a 5 x 5 sheet in one frame stalled against it (fractions
      // of 1e-6 to 1e-9, the step at the 300-iteration cap).
      const Vec3 from = position(p);
      Vec3 toward = closest_point_on_triangle(from, position(pair.vertices[1]),
                                              position(pair.vertices[2]),
                                              position(pair.vertices[3])) -
                    from;
      const double distance = toward.norm();
      if (!(distance > 0.0)) continue;
      toward /= distance;
      const double gap = distance - pair.thickness;
      const double lack = moving(p).dot(toward) - (gap - 0.5 * radius);
      for (int i = 1; i < 4; ++i) push(pair.vertices[i], lack, toward, moving(p));
      continue;
    }
    const Vec3 a = position(pair.vertices[1]);
    const Vec3 u = position(pair.vertices[2]) - a, v = position(pair.vertices[3]) - a;
    Vec3 normal = u.cross(v);
    const double twice_area = normal.norm();
    if (!(twice_area > 0.0)) continue;
    normal /= twice_area;
    const Vec3 e = position(p) - a;
    double gap = e.dot(normal);
    if (gap < 0.0) {
      normal = -normal;
      gap = -gap;
    }
    const std::array<double, 2> w =
        projected_barycentric(e - gap * normal, u, v, normal, twice_area);
    if (!inside(w)) continue;
    // The obstacle face comes toward p along `normal` (pointing from the face to p).
    const Vec3 face_move = (1.0 - w[0] - w[1]) * moving(pair.vertices[1]) +
                           w[0] * moving(pair.vertices[2]) + w[1] * moving(pair.vertices[3]);
    push(p, face_move.dot(normal) - (gap - 0.5 * radius), normal, face_move);
  }
}

void MovingObstacles::advance(ContactGeometry& g, ContactPairFinder& finder,
                              const std::vector<char>& pinned, std::optional<double> ground,
                              double radius, double min_separation, Eigen::VectorXd& x,
                              std::vector<ContactPair>& pairs) {
  if (settled_) return;
  move_ = end_ - g.obstacle_positions;
  // The faces the obstacles' move sweeps close to the cloth, and what they push.
  if (!finder.gather(g, x, nullptr, radius, std::nullopt, pairs, &end_)) return;  // not finite
  push_cloth(g, pinned, x, radius, pairs);
  // Every pair the joint move may bring within `radius`, then its longest safe fraction.
  if (!finder.gather(g, x, &push_, radius, ground, pairs, &end_)) return;
  double fraction = earliest_contact(g, pairs, x, push_, ground.value_or(0.0), radius,
                                     min_separation, &move_, kAdvanceCcd);
  if (fraction < 1.0 && carry_ != push_) {
    // The pushed particles carried along with the obstacles instead: when several obstacle
    // vertices under one coarse cloth triangle push it along different normals, the normal
    // pushes tilt it into the obstacle's other vertices and the joint move stalls (fractions
    // of 1e-5 to 1e-16, hundreds of iterations per step); carried, the pushed cloth keeps its
    // place on the obstacle. Whichever goes further is taken; Newton then lets it slide.
    if (finder.gather(g, x, &carry_, radius, ground, carried_pairs_, &end_)) {
      const double carried = earliest_contact(g, carried_pairs_, x, carry_, ground.value_or(0.0),
                                              radius, min_separation, &move_, kAdvanceCcd);
      if (carried > fraction) {
        fraction = carried;
        push_.swap(carry_);
        pairs.swap(carried_pairs_);
      }
    }
  }
  if (fraction >= 1.0) {
    g.obstacle_positions = end_;  // exactly: the end pose's vertices, no rounding left over
    x += push_;
    poses_ = aims_;
    settled_ = true;
  } else if (fraction > 0.0) {
    g.obstacle_positions += fraction * move_;
    x += fraction * push_;
  }
}

}  // namespace animkit
