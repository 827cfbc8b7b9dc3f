#pragma once
// The interactive "Mass-Spring Cloth" scene: the lab's hanging cloth with live parameters, a
// mouse spring to drag any particle, and pins the user can toggle. The viewer and the CLI's
// pictures drive this class; it holds the state, they only show it.
#include <deque>
#include <optional>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit {

struct ClothSceneOptions {
  GridClothOptions grid;         ///< the lab's cloth by default
  SimulationOptions simulation;  ///< implicit Euler with PCG by default
  /// Seconds per frame, > 0: the lab's choice, the frame's duration (a 60 Hz screen), as the
  /// CLI's --dt default.
  double time_step = 1.0 / 60.0;

  std::optional<Error> validate() const;
};

/// What describe() draws. The lab shows the springs; the surface is what users expect.
struct ClothStyle {
  bool surface = true;        ///< lit, two-sided, smooth-shaded triangles
  bool springs = false;       ///< every spring as a line
  bool particles = false;     ///< every particle as a point (pinned ones are always marked)
  double floor_height = 0.0;  ///< y of the ground grid (below where the cloth can hang)
};

/// The mouse spring: pulls one particle towards a point with force
/// m (k (target - x) - c v), k = min(200 s^-2, 1 / (4 h^2)) for the time step h (stable at any
/// step), c = 2 sqrt(k) (critically damped on its own).
struct ClothDrag {
  int particle = 0;
  Vec3 target = Vec3::Zero();  ///< world space
};

/// Describes a cloth: ground grid, surface, springs and particles as `style` asks, pinned
/// particles marked. Shared by ClothScene and the CLI's pictures.
void describe_cloth(DrawList& out, const ClothModel& model, const ClothState& state,
                    const ClothStyle& style = {});
/// A box around where a grid cloth is and may swing to: its particles, the flat sheet and the
/// sheet hanging (stretched) down from its pinned edge, so a picture does not jump as it moves.
Eigen::AlignedBox3d cloth_focus_bounds(const GridClothOptions& grid, const ClothState& state);

/// Where a grid cloth's floor goes: below the sheet hanging straight down from its pins,
/// stretched by gravity, so the cloth never passes through the grid.
double cloth_floor_height(const GridClothOptions& grid);

/// The same for any cloth (e.g. cut from a mesh), from its description: the rest shape's box,
/// extended down from its lowest pin (or its lowest point, without pins) by 1.3 times the
/// shape's largest side, so a sheet hanging from its pins stays in the picture. For a grid's
/// description these give the grid overloads' box and floor.
Eigen::AlignedBox3d cloth_focus_bounds(const ClothDesc& desc, const ClothState& state);
double cloth_floor_height(const ClothDesc& desc);

/// The direction pictures of the cloth are taken from: facing the hanging sheet's front
/// (orange) side, a little from above.
inline constexpr double kClothPictureYaw = -1.05, kClothPicturePitch = 0.3;

class ClothScene {
 public:
  /// Builds the lab's cloth (or the given one). Errors name the first bad option.
  static Result<ClothScene> create(const ClothSceneOptions& options = {});

  /// Advances one frame (options().time_step). A diverging step is undone and reported; the
  /// scene stays usable.
  Result<StepReport> step();
  /// Rebuilds the cloth from scratch with `options` (grid size and everything else).
  Result<void> reset(const ClothSceneOptions& options);
  /// Takes new options while the cloth keeps moving: with the same grid layout the current
  /// positions, velocities and pins are kept; a new grid size starts over. Errors leave the
  /// scene as it was.
  Result<void> apply(const ClothSceneOptions& options);
  /// Pins a free particle where it is now, or frees a pinned one. Errors: index out of range.
  Result<void> toggle_pin(int particle);

  /// The particle under pixel (x, y) of a width x height view: of those drawn within
  /// `radius_px` pixels of it, the one nearest the eye (the one the user sees).
  std::optional<int> pick(const OrbitCamera& camera, double x, double y, double width,
                          double height, double radius_px) const;
  /// Starts or moves the mouse spring. Errors: index out of range, non-finite target.
  Result<void> set_drag(const ClothDrag& drag);
  void clear_drag();
  const std::optional<ClothDrag>& drag() const { return drag_; }

  const ClothSimulator& simulator() const { return simulator_; }
  const ClothSceneOptions& options() const { return options_; }
  const std::optional<StepReport>& last_step() const { return last_; }
  /// Total energy after each of the last (up to) kEnergyHistory steps, oldest first.
  const std::deque<double>& energy_history() const { return energy_; }
  static constexpr std::size_t kEnergyHistory = 600;

  /// Describes the cloth (style.floor_height is set from the grid) and the mouse spring.
  void describe(DrawList& out, ClothStyle style = {}) const;
  /// A box around where the cloth is and may swing to: what a picture should frame.
  Eigen::AlignedBox3d focus_bounds() const;

 private:
  ClothScene(ClothSceneOptions options, ClothDesc desc, ClothSimulator simulator);
  Result<void> rebuild_keeping_state(ClothDesc desc);

  ClothSceneOptions options_;
  ClothDesc desc_;  // the description the simulator was built from (pins as toggled)
  ClothSimulator simulator_;
  std::optional<ClothDrag> drag_;
  std::optional<StepReport> last_;
  std::deque<double> energy_;
};

}  // namespace animkit
