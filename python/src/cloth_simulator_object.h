#pragma once
// What animkit.ClothSimulator holds: the scene it was built from, the built world (simulator,
// contact, colliders) and what pictures of it need. Shared by bind_cloth_simulator.cpp (the
// simulator's bindings) and bind_pictures.cpp (render_png).
//
// The world lives on the heap behind a unique_ptr and is never moved after it is built, and the
// library keeps the state's buffers in place (every integrator and the divergence undo write
// into them), so numpy views of positions and velocities stay valid while the Python object
// lives (the views hold it as their base).
#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "animkit/cloth/cloth_world.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit::python {

struct SimulatorObject {
  ClothWorldDesc desc;  ///< the scene as given
  ClothDesc cloth;      ///< the sheet's description (for the picture's framing)
  ClothState initial;   ///< the state the run started from
  std::unique_ptr<ClothWorld> world;
  /// Held while C++ reads or writes the simulator without the GIL: two Python threads
  /// stepping the same simulator take turns instead of racing.
  mutable std::mutex mutex;
  /// The simulator's steps_taken(), published after every step: readable from another thread
  /// while a step or run holds `mutex` (a progress bar, the tests' proof that run() lets other
  /// Python threads go on).
  std::atomic<int> steps_taken{0};
  /// The state's time, published with steps_taken (ClothSimulator.time, __repr__).
  std::atomic<double> time{0.0};

  /// Publishes steps_taken and time from the simulator: call with `mutex` held (or before any
  /// other thread can see the object) after anything that changes them.
  void publish() {
    steps_taken.store(sim().steps_taken());
    time.store(sim().state().time);
  }

  ClothSimulator& sim() { return world->simulator; }
  const ClothSimulator& sim() const { return world->simulator; }

  /// The colliders where the solver has them now (as the CLI draws them): on their paths, or
  /// short of them after a step continuous collision detection held back. Call with `mutex`.
  std::vector<Collider> posed_colliders() const {
    std::vector<Collider> posed = world->colliders;
    for (std::size_t i = 0; world->contact && i < posed.size(); ++i)
      posed[i].set_pose(sim().state().time, world->contact->collider_pose(i));
    return posed;
  }

  /// Where pictures look: as the CLI frames its final.png, from the run's first state.
  ClothPictureFrame picture_frame() const {
    return cloth_picture_frame(desc, cloth, initial, world->colliders);
  }
};

void bind_cloth_simulator(pybind11::module_& m);  ///< ClothSimulator, StepReport, ...

}  // namespace animkit::python
