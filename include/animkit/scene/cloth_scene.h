#pragma once
// The interactive "Mass-Spring Cloth" scene: any cloth world (cloth/cloth_world.h): the lab's
// hanging cloth with live parameters (the default), a built-in scene (scene/cloth_scenes.h) or
// a scene file, with its colliders, ground and air. The user drags particles on a mouse spring,
// toggles pins, grabs colliders and sees the contacts. The viewer and the CLI's pictures drive
// this class; it holds the state, they only show it.
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/scene/cloth_drawing.h"
#include "animkit/scene/collider_picking.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit {

/// The lab's cloth as its parameter panel sees it: a grid sheet, the solver settings and the
/// time step.
struct ClothSceneOptions {
  GridClothOptions grid;         ///< the lab's cloth by default
  SimulationOptions simulation;  ///< implicit Euler with PCG by default
  /// Seconds per frame, > 0: the lab's choice, the frame's duration (a 60 Hz screen), as the
  /// CLI's --dt default.
  double time_step = 1.0 / 60.0;

  /// The world these options describe: the lab's (no colliders, no air) with this grid.
  ClothWorldDesc world() const;

  /// An Error naming the first invalid field (grid, simulation, or a time step outside
  /// kTimeStepRange), or none.
  std::optional<Error> validate() const;
};

/// The mouse spring: pulls one particle towards a point with force
/// m (k (target - x) - c v), k = min(200 s^-2, 1 / (4 h^2)) for the time step h (stable at any
/// step), c = 2 sqrt(k) (critically damped on its own).
struct ClothDrag {
  /// Index of the dragged particle, in [0, particle count).
  int particle = 0;
  Vec3 target = Vec3::Zero();  ///< world space
};

/// A handle under the cursor: a particle (as ClothScene::pick) or a collider's surface,
/// whichever is nearer the eye; both empty when there is nothing there.
struct ClothPick {
  std::optional<int> particle;           ///< the particle's index, when it is in front
  std::optional<ColliderGrab> collider;  ///< the collider's surface, when it is in front
};

/// The interactive cloth scene (see the top of this header): one cloth world stepped a frame
/// at a time, with the mouse spring, pin toggling and collider drags. Made by create().
class ClothScene {
 public:
  /// Builds the lab's cloth (or the given one). Errors name the first bad option.
  static Result<ClothScene> create(const ClothSceneOptions& options = {});
  /// Builds any cloth world (build_cloth_world); `name` names it in menus ("drape-sphere", a
  /// file's path). Errors name the first problem.
  static Result<ClothScene> create(const ClothWorldDesc& world, std::string name);

  /// Advances one frame (the world's time step). A diverging step is undone and reported; the
  /// scene stays usable.
  Result<StepReport> step();
  /// Rebuilds the lab's cloth from scratch with `options` (grid size and everything else).
  Result<void> reset(const ClothSceneOptions& options);
  /// Switches to another world, from its start. Errors leave the scene as it was.
  Result<void> load(const ClothWorldDesc& world, std::string name);
  /// Starts the current world (with the settings changed since) over.
  Result<void> restart();
  /// Takes new lab options while the cloth keeps moving (the grid's parameters apply to a grid
  /// sheet; the solver and time step to any): see apply_world. Errors leave the scene as it was.
  Result<void> apply(const ClothSceneOptions& options);
  /// Takes a changed world while the cloth keeps moving: with the same sheet (particles at the
  /// same rest positions, same triangles) the current positions, velocities and pins are kept
  /// and the solver, contact, air and time step are rebuilt; another sheet starts over. Errors
  /// leave the scene as it was.
  Result<void> apply_world(const ClothWorldDesc& world);
  /// Pins a free particle where it is now, or frees a pinned one. Errors: index out of range.
  Result<void> toggle_pin(int particle);

  /// The particle under pixel (x, y) of a width x height view: of those drawn within
  /// `radius_px` pixels of it, the one nearest the eye (the one the user sees).
  std::optional<int> pick(const OrbitCamera& camera, double x, double y, double width,
                          double height, double radius_px) const;
  /// What a press at pixel (x, y) grabs: that particle or the collider surface the pixel's
  /// ray meets first, whichever is nearer the eye.
  ClothPick pick_handle(const OrbitCamera& camera, double x, double y, double width, double height,
                        double radius_px) const;
  /// Starts or moves the mouse spring. Errors: index out of range, non-finite target.
  Result<void> set_drag(const ClothDrag& drag);
  /// Stops the mouse spring and removes its force from the simulator.
  void clear_drag();
  /// The mouse spring, while a particle is dragged.
  const std::optional<ClothDrag>& drag() const { return drag_; }

  /// Gives collider `index` a new pose (world space) to reach by the next step. It goes
  /// through the solver, whose continuous collision detection keeps the cloth from being
  /// crossed. Errors: index out of range, a non-finite pose or non-unit rotation, and, until
  /// the solver moves colliders, "moving colliders is not available yet".
  Result<void> move_collider(int index, const RigidPose& pose);
  /// The collider drag gesture: start with a grab (pick_handle), then each cursor point (on
  /// the plane through the grab facing the camera) asks for the pose that keeps the grabbed
  /// point under it (dragged_pose), through move_collider; end releases it.
  void grab_collider(const ColliderGrab& grab);
  /// Asks for the grabbed collider's pose that puts the grabbed point at `cursor` (world space,
  /// m). Errors: no collider grabbed, a non-finite cursor, or move_collider()'s.
  Result<void> drag_collider_to(const Vec3& cursor);
  /// Ends the collider drag; no further poses are asked for.
  void release_collider() { collider_drag_.reset(); }
  /// The grab and the pose last asked for, while a collider is dragged.
  struct ColliderDrag {
    ColliderGrab grab;           ///< what the press grabbed
    Vec3 cursor = Vec3::Zero();  ///< world space, m: where the grabbed point is asked to go
    RigidPose target;            ///< the pose asked for last (dragged_pose(grab, cursor))
  };
  /// The collider drag in progress, or empty.
  const std::optional<ColliderDrag>& collider_drag() const { return collider_drag_; }

  /// The simulator: the cloth's model and current state.
  const ClothSimulator& simulator() const { return built_.simulator; }
  /// The world's colliders as they stand, in the description's order.
  const std::vector<Collider>& colliders() const { return built_.colliders; }
  /// The contact term, or null in a world without colliders and ground.
  const ContactTerm* contact() const { return built_.contact.get(); }
  /// The closest points of every active contact pair at the current state (none without
  /// contact). `out` is resized.
  void contact_points(std::vector<ContactPoint>& out) const;
  /// The world as described (with any live changes), its name, and the lab's view of it
  /// (the grid's options when the sheet is a grid, the solver and time step).
  const ClothWorldDesc& world() const { return world_; }
  /// The world's name as given to create() or load() ("lab" for the lab's cloth).
  const std::string& name() const { return name_; }
  /// The lab's view of the world: its grid options (the defaults when the sheet is not a
  /// grid), the solver settings and the time step.
  const ClothSceneOptions& options() const { return options_; }
  /// Whether the lab's parameter sliders (mass, stiffness, damping, gravity, grid size) apply:
  /// a grid sheet with per-particle parameters (no physical material).
  bool lab_parameters() const;
  /// The report of the last step that succeeded since the world (re)started; empty before.
  const std::optional<StepReport>& last_step() const { return last_; }
  /// Total energy after each of the last (up to) kEnergyHistory steps, oldest first.
  const std::deque<double>& energy_history() const { return energy_; }
  /// How many steps energy_history() keeps.
  static constexpr std::size_t kEnergyHistory = 600;

  /// Describes the cloth (style.floor_height is set: the ground's height, or below where the
  /// sheet can hang), the colliders, the contacts and the mouse spring as `style` asks.
  void describe(DrawList& out, ClothStyle style = {}) const;
  /// A box around the cloth (where it is and may swing to) and the colliders: what a picture
  /// should frame.
  Eigen::AlignedBox3d focus_bounds() const;

 private:
  ClothScene(ClothWorldDesc world, std::string name, ClothDesc desc, ClothWorld built);
  Result<void> rebuild_keeping_state(const ClothWorldDesc& world, ClothDesc desc);

  ClothWorldDesc world_;
  std::string name_;
  ClothSceneOptions options_;  // the lab's view of world_
  ClothDesc desc_;             // the sheet the simulator was built from (pins as toggled)
  ClothWorld built_;
  double floor_height_ = 0.0;  // where the floor is drawn, fixed when the world is built
  std::optional<ClothDrag> drag_;
  std::optional<ColliderDrag> collider_drag_;
  std::optional<StepReport> last_;
  std::deque<double> energy_;
};

}  // namespace animkit
