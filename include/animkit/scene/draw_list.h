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
  /// \var Rgba::r
  /// Red, in [0, 1].
  /// \var Rgba::g
  /// Green, in [0, 1].
  /// \var Rgba::b
  /// Blue, in [0, 1].
  /// \var Rgba::a
  /// Opacity, in [0, 1] (1: opaque). The Renderer blends lines and point markers with it;
  /// lit triangles are drawn opaque whatever it is.
  float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f;
};

/// Colours shared by every picture, so the viewer, the CLI and the tests agree. The lab's
/// convention: targets green, drawn path red.
namespace palette {
/// IK targets with the pen down, and targets held in the motion-capture scene.
inline constexpr Rgba target{0.10f, 0.75f, 0.20f, 1.0f};
/// The strokes the IK arm has drawn.
inline constexpr Rgba path{0.90f, 0.10f, 0.10f, 1.0f};
inline constexpr Rgba pen_up{0.55f, 0.57f, 0.60f, 1.0f};  ///< travel targets between strokes
/// An IK target out of the arm's reach, and the line joining it to the pen.
inline constexpr Rgba unreachable{1.00f, 0.55f, 0.00f, 1.0f};
/// Bones, drawn as boxes.
inline constexpr Rgba bone{0.35f, 0.50f, 0.85f, 1.0f};
/// Joints, drawn as spheres.
inline constexpr Rgba joint{0.95f, 0.80f, 0.20f, 1.0f};
/// The IK arm's end effector (its pen): a sphere and a dot.
inline constexpr Rgba end_effector{0.95f, 0.95f, 0.95f, 1.0f};
/// The cloth's front side: the side its normals point to.
inline constexpr Rgba cloth_front{0.85f, 0.45f, 0.20f, 1.0f};
/// The cloth's back side.
inline constexpr Rgba cloth_back{0.30f, 0.55f, 0.75f, 1.0f};
/// Cloth springs, drawn as lines.
inline constexpr Rgba spring{0.15f, 0.15f, 0.15f, 1.0f};
/// Free cloth particles, drawn as points.
inline constexpr Rgba particle{0.10f, 0.10f, 0.10f, 1.0f};
/// Pinned cloth particles, drawn as larger points.
inline constexpr Rgba pinned{0.85f, 0.10f, 0.60f, 1.0f};
/// What the mouse drags: the spring to a dragged particle or collider and its target, and
/// the selected joint in the motion-capture scene.
inline constexpr Rgba dragged{1.00f, 0.90f, 0.10f, 1.0f};
/// The ground grid's lines (DrawList::add_ground_grid).
inline constexpr Rgba grid{0.62f, 0.64f, 0.68f, 1.0f};
/// Obstacles the cloth collides with: a muted violet, apart from the cloth's orange and blue.
inline constexpr Rgba collider{0.56f, 0.52f, 0.66f, 1.0f};
/// Contact points: the cloth's side red, the other side white.
inline constexpr Rgba contact{0.90f, 0.05f, 0.05f, 1.0f};
/// The other side's closest point of a contact (a collider, the ground or the cloth itself)
/// and the line joining it to the cloth's.
inline constexpr Rgba contact_other{1.00f, 1.00f, 1.00f, 1.0f};
/// What pictures are cleared to behind everything drawn.
inline constexpr Rgba background{0.88f, 0.90f, 0.93f, 1.0f};
}  // namespace palette

/// A single-precision 3-vector: positions and normals in a DrawList, as the GPU takes them.
using Vec3f = Eigen::Vector3f;

/// One vertex of a lit triangle. Both sides are lit; `back` is the colour seen from the side
/// the normal points away from (cloth shows two colours, solids use the same one twice).
struct LitVertex {
  Vec3f position;  ///< world space
  Vec3f normal;    ///< world space, unit
  /// Colour seen from the side the normal points to.
  Rgba front, back;  ///< colour seen from the other side
};

/// A straight line from `a` to `b`, drawn a fixed number of pixels wide at any depth, with
/// anti-aliased edges.
struct LineSegment {
  /// One end; `b` is the other.
  Vec3f a, b;  ///< world space
  /// Colour along the whole line; its alpha is blended.
  Rgba color;
  float width_px = 1.0f;  ///< on-screen width in pixels, > 0
};

/// A round marker of fixed on-screen size at any depth: a disc with a darker rim, drawn
/// slightly towards the eye so it shows over the surface it lies on.
struct PointMarker {
  Vec3f position;  ///< world space
  /// Colour of the disc (its rim drawn darker); its alpha is blended.
  Rgba color;
  float size_px = 6.0f;  ///< on-screen diameter in pixels, > 0
};

/// A picture as plain data: lit triangles, lines and point markers in world space. Scenes fill
/// one; a Renderer draws it; tests inspect it directly.
class DrawList {
 public:
  /// Three vertices per triangle, counter-clockwise seen from the front.
  std::vector<LitVertex> triangles;
  /// Lines, drawn after the points and over them.
  std::vector<LineSegment> lines;
  /// Point markers, drawn after the triangles.
  std::vector<PointMarker> points;

  /// Removes every triangle, line and point.
  void clear();
  /// A flat-shaded triangle, counter-clockwise seen from the front: its normal is
  /// (b - a) x (c - a) normalized (+y for a degenerate triangle).
  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgba front, Rgba back);
  /// A triangle with its own per-vertex normals (smooth shading).
  void add_triangle(const Vec3 (&p)[3], const Vec3 (&n)[3], Rgba front, Rgba back);
  /// A line from `a` to `b`, `width_px` pixels wide on screen.
  void add_line(const Vec3& a, const Vec3& b, Rgba color, float width_px = 1.0f);
  /// Consecutive points joined by segments (nothing for fewer than 2 points).
  void add_polyline(const std::vector<Vec3>& points, Rgba color, float width_px = 1.0f);
  /// A round marker at `p`, `size_px` pixels across on screen.
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
  /// True when the list holds no triangle, line or point.
  bool empty() const { return triangles.empty() && lines.empty() && points.empty(); }
};

}  // namespace animkit
