#include "animkit/collision/collider_inside.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace animkit {

double signed_distance(const PlaneShape&, const Vec3& local) {
  return local.y();
}

double signed_distance(const SphereShape& shape, const Vec3& local) {
  return local.norm() - shape.radius;
}

// With q = |p| - h per axis: outside, the distance to the nearest point of the box is the
// length of q's positive part; inside, the nearest face is the one with the largest q.
double signed_distance(const BoxShape& shape, const Vec3& local) {
  const Vec3 q = local.cwiseAbs() - shape.half_extents;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

double signed_distance(const CapsuleShape& shape, const Vec3& local) {
  const double y = std::clamp(local.y(), -shape.half_length, shape.half_length);
  return (local - Vec3(0.0, y, 0.0)).norm() - shape.radius;
}

// The solid angle of triangle (a, b, c) seen from the origin is 2 atan2(N, D) with
// N = a . (b x c) and D = |a||b||c| + (a . b)|c| + (b . c)|a| + (c . a)|b|.
double winding_number(const TriangleMesh& mesh, const Vec3& point) {
  double solid_angle = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - point;
    const Vec3 b = mesh.vertices[t[1]] - point;
    const Vec3 c = mesh.vertices[t[2]] - point;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    // Both zero only for a point on the triangle's plane touching it (e.g. at a vertex): the
    // triangle subtends no solid angle there, and atan2(0, 0) is left undefined by C.
    if (numerator == 0.0 && denominator == 0.0) continue;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

bool inside(const ColliderShape& shape, const Vec3& local) {
  return std::visit(
      [&local](const auto& s) {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, MeshShape>) {
          return winding_number(s.mesh, local) > 0.5;
        } else {
          return signed_distance(s, local) < 0.0;
        }
      },
      shape);
}

}  // namespace animkit
