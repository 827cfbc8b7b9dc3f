#include "contact_candidates.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "../stacked_vectors.h"
#include "animkit/cloth/contact.h"
#include "animkit/collision/ccd.h"

namespace animkit {

namespace {

// IPC's mollifier threshold eps_x = 1e-3 |a|^2 |b|^2 from the edges' rest lengths (Li et al.
// 2020, section 4.3; edge_edge_mollifier.h).
double mollifier_threshold(double rest_a2, double rest_b2) {
  return 1e-3 * rest_a2 * rest_b2;
}

}  // namespace

Result<ContactGeometry> build_contact_geometry(const ClothModel& model,
                                               const std::vector<TriangleMesh>& obstacles,
                                               bool self_contact,
                                               const std::vector<double>& sphere_radius) {
  ContactGeometry g;
  g.self_contact = self_contact;
  auto cloth = build_collision_mesh(model.particle_count(), model.triangles);
  if (!cloth) return fail("the cloth's triangles: " + cloth.error().message);
  g.cloth = std::move(*cloth);
  std::vector<std::array<int, 3>> triangles;
  std::vector<Vec3> vertices;
  for (std::size_t m = 0; m < obstacles.size(); ++m) {
    const TriangleMesh& mesh = obstacles[m];
    const int first = static_cast<int>(vertices.size());
    g.obstacle_mesh_start.push_back(first);
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    g.obstacle_radius.insert(g.obstacle_radius.end(), mesh.vertices.size(),
                             m < sphere_radius.size() ? sphere_radius[m] : 0.0);
    g.obstacle_spin.push_back(Eigen::Matrix3d::Zero());
    for (const auto& t : mesh.triangles)
      triangles.push_back({first + t[0], first + t[1], first + t[2]});
  }
  auto obstacle_mesh = build_collision_mesh(static_cast<int>(vertices.size()), triangles);
  if (!obstacle_mesh) return fail("the obstacles' triangles: " + obstacle_mesh.error().message);
  g.obstacles = std::move(*obstacle_mesh);
  g.obstacle_positions.resize(3 * static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    g.obstacle_positions.segment<3>(3 * static_cast<Eigen::Index>(i)) = vertices[i];
  g.obstacle_start_positions = g.obstacle_positions;
  g.obstacle_motion.setZero(g.obstacle_positions.size());
  for (const auto& [a, b] : g.obstacles.edges) {
    g.obstacle_rest_length2.push_back(
        (at(g.obstacle_positions, a) - at(g.obstacle_positions, b)).squaredNorm());
  }
  g.cloth_rest_length2.assign(g.cloth.edges.size(), 0.0);
  return g;
}

int ContactGeometry::obstacle_mesh_of(int v) const {
  const auto after = std::upper_bound(obstacle_mesh_start.begin(), obstacle_mesh_start.end(), v);
  return static_cast<int>(after - obstacle_mesh_start.begin()) - 1;
}

void set_cloth_rest_lengths(ContactGeometry& geometry, const Eigen::VectorXd& cloth_positions) {
  for (std::size_t e = 0; e < geometry.cloth.edges.size(); ++e) {
    const auto [a, b] = geometry.cloth.edges[e];
    geometry.cloth_rest_length2[e] =
        (at(cloth_positions, a) - at(cloth_positions, b)).squaredNorm();
  }
}

Result<void> ContactPairFinder::gather(const ContactGeometry& g, const Eigen::VectorXd& x,
                                       const Eigen::VectorXd* step, double radius,
                                       std::optional<double> ground,
                                       std::vector<ContactPair>& pairs,
                                       const Eigen::VectorXd* obstacle_end) {
  pairs.clear();
  if (step) {
    end_ = x + *step;  // sized once, reused
  } else {
    end_ = x;
  }
  const MeshMotion cloth{g.cloth, x, end_};
  const MeshMotion obstacles{g.obstacles, g.obstacle_positions,
                             obstacle_end ? *obstacle_end : g.obstacle_positions,
                             &g.obstacle_radius};
  const bool any_obstacle = g.obstacles.vertex_count > 0;
  if (auto ok = broad_phase_.find(cloth, radius, candidates_, any_obstacle ? &obstacles : nullptr,
                                  g.self_contact);
      !ok) {
    return ok;
  }
  const int n = g.cloth_vertices();
  const auto point_triangle = [&](int p, const std::array<int, 3>& t, int offset) {
    pairs.push_back(
        {ContactKind::point_triangle, {p, offset + t[0], offset + t[1], offset + t[2]}});
  };
  if (g.self_contact) {
    for (const auto& c : candidates_.vertex_triangle)
      point_triangle(c.vertex, g.cloth.triangles[c.triangle], 0);
    for (const auto& c : candidates_.edge_edge) {
      const auto& a = g.cloth.edges[c.edge_a];
      const auto& b = g.cloth.edges[c.edge_b];
      pairs.push_back(
          {ContactKind::edge_edge,
           {a[0], a[1], b[0], b[1]},
           mollifier_threshold(g.cloth_rest_length2[c.edge_a], g.cloth_rest_length2[c.edge_b])});
    }
  }
  for (const auto& c : candidates_.vertex_collider_triangle)
    point_triangle(c.vertex, g.obstacles.triangles[c.triangle], n);
  for (const auto& c : candidates_.collider_vertex_triangle) {
    const auto& t = g.cloth.triangles[c.triangle];
    pairs.push_back({ContactKind::point_triangle,
                     {n + c.vertex, t[0], t[1], t[2]},
                     0.0,
                     g.obstacle_radius[static_cast<std::size_t>(c.vertex)]});
  }
  for (const auto& c : candidates_.edge_collider_edge) {
    const auto& a = g.cloth.edges[c.edge_a];
    const auto& b = g.obstacles.edges[c.edge_b];
    pairs.push_back(
        {ContactKind::edge_edge,
         {a[0], a[1], n + b[0], n + b[1]},
         mollifier_threshold(g.cloth_rest_length2[c.edge_a], g.obstacle_rest_length2[c.edge_b])});
  }
  if (ground) {
    for (int i = 0; i < n; ++i) {
      if (std::min(x[3 * i + 1], end_[3 * i + 1]) - *ground < radius)
        pairs.push_back({ContactKind::ground, {i, -1, -1, -1}});
    }
  }
  return {};
}

double earliest_contact(const ContactGeometry& g, const std::vector<ContactPair>& pairs,
                        const Eigen::VectorXd& x, const Eigen::VectorXd& step, double ground,
                        double reach, double min_separation, const Eigen::VectorXd* obstacle_step,
                        AdditiveCcdSettings settings, const std::vector<double>* distance_floor2) {
  const int n = g.cloth_vertices();
  const auto start_of = [&](int v) { return v < n ? at(x, v) : at(g.obstacle_positions, v - n); };
  const auto move_of = [&](int v) {
    if (v < n) return at(step, v);
    return obstacle_step ? at(*obstacle_step, v - n) : Vec3(Vec3::Zero());
  };
  settings.separation_fraction = min_separation;
  double bound = 1.0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ContactPair& pair = pairs[k];
    if (pair.kind == ContactKind::ground) {
      // Exact for a plane: the height is linear in t; keep (1 - s) of the gap's closing.
      const int v = pair.vertices[0];
      const double gap = x[3 * v + 1] - ground, dy = step[3 * v + 1];
      if (dy < 0.0) bound = std::min(bound, (1.0 - min_separation) * gap / -dy);
      continue;
    }
    std::array<Vec3, 4> start, end;
    bool moves = false;
    for (int i = 0; i < 4; ++i) {
      start[i] = start_of(pair.vertices[i]);
      const Vec3 d = move_of(pair.vertices[i]);
      moves = moves || !d.isZero(0.0);
      end[i] = start[i] + d;
    }
    // Swept boxes more than `reach` apart: the pair stays farther apart than that. Gathered
    // sets hold many such pairs (gather_region.h: complete for a region larger than one
    // step), and Additive CCD would spend two distance evaluations on each to find it.
    if (!moves || contact_box_gap(pair, start, end) > reach) continue;
    // No gap closes below the smallest gap a start may have: computed gaps are rounding there
    // (a sphere's is its centre's distance less the radius, which loses the digits the two
    // share; a cloth edge stretched to 3 m ending nanometres from a box's corner measured 0
    // against that corner's edges). An obstacle closing in on pinned cloth, a tenth of the gap
    // left each time, or the sheet hit by a box jumping through it in a quarter of a frame,
    // otherwise took a pair to a gap of zero, where the barrier is infinite.
    const double floor = kMinStartGapFraction * reach;
    if (distance_floor2 != nullptr) {
      // A point of a primitive moves no farther than the farthest of its vertices, so the
      // distance falls by at most the two primitives' largest moves together: if that keeps
      // (1 - s) of the gap at x, the pair keeps s of it over the whole step, which Additive
      // CCD would find only after measuring the distances at both ends.
      const int second = pair.kind == ContactKind::point_triangle ? 1 : 2;
      double move[2] = {0.0, 0.0};
      for (int i = 0; i < 4; ++i) {
        double& primitive = move[i < second ? 0 : 1];
        primitive = std::max(primitive, (end[i] - start[i]).norm());
      }
      const double gap = std::sqrt((*distance_floor2)[k]) - settings.thickness - floor;
      if (move[0] + move[1] <= (1.0 - min_separation) * gap) continue;
    }
    settings.max_time = bound;  // nothing past the bound found so far matters
    AdditiveCcdSettings pair_settings = settings;
    pair_settings.thickness += pair.thickness + floor;  // a sphere's radius: to its surface
    const auto hit = pair.kind == ContactKind::point_triangle
                         ? point_triangle_ccd(start, end, pair_settings)
                         : edge_edge_ccd(start, end, pair_settings);
    if (!hit) return 0.0;  // a non-finite coordinate: take no step
    bound = std::min(bound, hit->time_of_impact);
  }
  return bound;
}

}  // namespace animkit
