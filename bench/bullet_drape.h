#pragma once
// Bullet's soft body (btSoftRigidDynamicsWorld, Debian's libbullet-dev in double precision) on
// the drape scene (drape_scene.h), for the drape benchmark's comparison only: the library
// never depends on Bullet. Behind a small interface so that only bullet_drape.cpp sees
// Bullet's headers.
//
// How cotton is mapped onto Bullet's position-based links, as well as Bullet allows:
// - mass: the sheet's total, density x area, spread by face area (setTotalMass(m, true)), as
//   animkit spreads it (material.h);
// - stretch: cotton's 1000 N/m is practically inextensible under the sheet's own weight (a
//   strain of rho g L / C11 ~ 0.15 % for 1 m), so the axis links get Bullet's full linear
//   stiffness kLST = 1, solved with `position_iterations` passes;
// - shear: Bullet has no membrane model; its one diagonal link per cell gets kLST = the
//   diagonal-to-axis ratio of animkit's springs, 2 x shear / (stretch - shear) (two diagonals
//   of stiffness `shear` per cell in animkit, one here);
// - bending: none. Cotton's B = 1e-5 N m gives a bending length (B / (rho g))^(1/3) ~ 2 cm,
//   one grid cell at 41 x 41, and Bullet's distance-2 bending links would be far stiffer;
// - damping 0 (cotton has none); Coulomb friction: the scene's coefficients (kDF = 1 times the
//   colliders' friction, which Bullet multiplies);
// - contact: node against the static ball and ground by Bullet's signed-distance field
//   (SDF_RS, voxels of one grid spacing), collision margin = animkit's contact thickness;
//   self-collision by Bullet's clusters (CL_SS | CL_SELF, one cluster per triangle), the only
//   self-collision btSoftRigidDynamicsWorld offers (VF_SS skips a body against itself).
#include <array>
#include <memory>
#include <vector>

#include "animkit/core/types.h"
#include "drape_scene.h"

namespace animkit::bench {

struct BulletDrapeSettings {
  int position_iterations = 10;  ///< Bullet's piterations, link passes per substep, >= 1
  int substeps = 2;              ///< fixed Bullet steps per frame (1/60 s at 1/30 s frames)
  double margin = 2e-3;          ///< collision margin, m (animkit's contact thickness)
  bool self_collision = true;    ///< clusters against each other (CL_SS | CL_SELF)
};

class BulletDrape {
 public:
  /// The sheet laid between the four corner positions (particles (0,0), (n,0), (0,n), (n,n)
  /// of the animkit grid), over the scene's ball and ground.
  BulletDrape(const DrapeParts& parts, const std::array<Vec3, 4>& corners,
              const BulletDrapeSettings& settings);
  ~BulletDrape();
  BulletDrape(const BulletDrape&) = delete;
  BulletDrape& operator=(const BulletDrape&) = delete;

  /// Advances one frame of `dt` seconds in `settings.substeps` fixed steps.
  void step(double dt);

  int node_count() const;
  /// The nodes' positions now, in Bullet's node order.
  void positions(std::vector<Vec3>& out) const;
  /// Bullet's triangles, as indices into positions().
  const std::vector<std::array<int, 3>>& triangles() const;
  /// Mean and largest relative stretch of the axis links (length / rest length - 1).
  std::array<double, 2> axis_strain() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit::bench
