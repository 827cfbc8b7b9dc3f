#pragma once
// What a scene wants drawn, as plain data: lit triangles, lines and points with colours. Scenes
// fill a DrawList; the OpenGL renderer (src/render) draws one, and tests inspect one directly.
// Keeping this free of OpenGL lets the library describe pictures that a test can check without
// a GPU, and lets the CLI and the viewer draw exactly the same thing.
#include <Eigen/Geometry>
#include <vector>

#include "animkit/core/types.h"

namespace animkit {

/// A colour, linear RGB in [0, 1] with opacity a in [0, 1].
struct Rgba {
  float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f;
};

/// Colours shared by every picture, so the viewer, the CLI and the tests agree. The lab's
/// convention: targets green, drawn path red.
namespace palette {
inline constexpr Rgba target{0.10f, 0.75f, 0.20f, 1.0f};
inline constexpr Rgba path{0.90f, 0.10f, 0.10f, 1.0f};
inline constexpr Rgba pen_up{0.55f, 0.57f, 0.60f, 1.0f};  ///< travel targets between strokes
inline constexpr Rgba unreachable{1.00f, 0.55f, 0.00f, 1.0f};
inline constexpr Rgba bone{0.35f, 0.50f, 0.85f, 1.0f};
inline constexpr Rgba joint{0.95f, 0.80f, 0.20f, 1.0f};
inline constexpr Rgba end_effector{0.95f, 0.95f, 0.95f, 1.0f};
inline constexpr Rgba cloth_front{0.85f, 0.45f, 0.20f, 1.0f};
inline constexpr Rgba cloth_back{0.30f, 0.55f, 0.75f, 1.0f};
inline constexpr Rgba spring{0.15f, 0.15f, 0.15f, 1.0f};
inline constexpr Rgba particle{0.10f, 0.10f, 0.10f, 1.0f};
inline constexpr Rgba pinned{0.85f, 0.10f, 0.60f, 1.0f};
inline constexpr Rgba dragged{1.00f, 0.90f, 0.10f, 1.0f};
inline constexpr Rgba grid{0.62f, 0.64f, 0.68f, 1.0f};
/// Obstacles the cloth collides with: a muted violet, apart from the cloth's orange and blue.
inline constexpr Rgba collider{0.56f, 0.52f, 0.66f, 1.0f};
/// Contact points: the cloth's side red, the other side white.
inline constexpr Rgba contact{0.90f, 0.05f, 0.05f, 1.0f};
inline constexpr Rgba contact_other{1.00f, 1.00f, 1.00f, 1.0f};
inline constexpr Rgba background{0.88f, 0.90f, 0.93f, 1.0f};
}  // namespace palette

using Vec3f = Eigen::Vector3f;

/// One vertex of a lit triangle. Both sides are lit; `back` is the colour seen from the side
/// the normal points away from (cloth shows two colours, solids use the same one twice).
struct LitVertex {
  Vec3f position;  ///< world space
  Vec3f normal;    ///< world space, unit
  Rgba front, back;
};

struct LineSegment {
  Vec3f a, b;  ///< world space
  Rgba color;
  float width_px = 1.0f;  ///< on-screen width in pixels, > 0
};

struct PointMarker {
  Vec3f position;  ///< world space
  Rgba color;
  float size_px = 6.0f;  ///< on-screen diameter in pixels, > 0
};

class DrawList {
 public:
  /// Three vertices per triangle, counter-clockwise seen from the front.
  std::vector<LitVertex> triangles;
  std::vector<LineSegment> lines;
  std::vector<PointMarker> points;

  void clear();
  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgba front, Rgba back);
  /// A triangle with its own per-vertex normals (smooth shading).
  void add_triangle(const Vec3 (&p)[3], const Vec3 (&n)[3], Rgba front, Rgba back);
  void add_line(const Vec3& a, const Vec3& b, Rgba color, float width_px = 1.0f);
  /// Consecutive points joined by segments (nothing for fewer than 2 points).
  void add_polyline(const std::vector<Vec3>& points, Rgba color, float width_px = 1.0f);
  void add_point(const Vec3& p, Rgba color, float size_px = 6.0f);
  /// A box from `a` to `b` with a square cross-section of side `thickness`: a bone.
  void add_bone_box(const Vec3& a, const Vec3& b, double thickness, Rgba color);
  /// A sphere tessellated into `slices` x `stacks` quads.
  void add_sphere(const Vec3& center, double radius, Rgba color, int slices = 16, int stacks = 10);
  /// A square grid on the plane y = height, `cells` per side of size `spacing`, centred on the
  /// origin, plus the world axes (x red, y green, z blue) from the origin, `axis_length` long.
  void add_ground_grid(double height, int cells, double spacing, double axis_length);

  /// Bounds of everything in the list (empty box when the list is empty).
  Eigen::AlignedBox3d bounds() const;
  bool empty() const { return triangles.empty() && lines.empty() && points.empty(); }
};

}  // namespace animkit
