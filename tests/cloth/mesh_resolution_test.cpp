// A material cut from a triangle mesh hangs the same at any resolution and triangulation, as
// the grid does (material_resolution_test.cpp): a 1 m square of cotton pinned at two corners of
// one edge, brought to static equilibrium as meshes of 21 x 21 and 41 x 41 vertices and as an
// irregular (jittered) 41 x 41 mesh; the drops of the centre of mass and of the lowest vertex
// below the pins agree within 2% between the regular meshes and within 4% on the jittered one.
// The jittered mesh stretches more: its edges leave the warp and weft, and a triangle's three
// springs then couple stretch to the soft shear (C16, C26 in membrane_springs.h), which springs
// cannot cancel for a material as anisotropic as cotton (stretch / shear = 25).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "../support/mesh_sheets.h"
#include "../support/static_equilibrium.h"
#include "animkit/cloth/mesh_cloth.h"

namespace animkit {
namespace {

constexpr double kHeight = 1.5;

struct MeshSag {
  double centre_of_mass = 0.0;  // drop below the pins, m
  double lowest = 0.0;          // drop of the lowest vertex below the pins, m
};

// The equilibrium's sag, solved from the sheet hanging flat in the vertical plane of its pins
// (rest (x, y, z) at (0, y - x, z)): every force then lies in that plane, so the sag is the
// membrane's, free of the out-of-plane wrinkles of a sheet with little bending stiffness.
MeshSag hanging_sag(const TriangleMesh& mesh, int cells) {
  MeshClothOptions o{.mesh = mesh, .gravity = 9.81};
  o.material = find_material("cotton")->material;
  o.pins = {grid_index(cells, 0, 0), grid_index(cells, 0, cells)};
  const auto desc = make_mesh_cloth(o);
  EXPECT_TRUE(desc) << desc.error().message;
  const auto built = build_cloth(*desc);
  EXPECT_TRUE(built) << built.error().message;
  const ClothModel& model = built->model;
  Eigen::VectorXd start = built->state.positions;
  for (int i = 0; i < model.particle_count(); ++i) {
    const Vec3 p = start.segment<3>(3 * i);
    start.segment<3>(3 * i) = Vec3(0.0, p.y() - p.x(), p.z());
  }
  const Eigen::VectorXd x = testing_support::static_equilibrium(model, start);
  double moment = 0.0, mass = 0.0, lowest = kHeight;
  for (int i = 0; i < model.particle_count(); ++i) {
    moment += model.mass[i] * x[3 * i + 1];
    mass += model.mass[i];
    lowest = std::min(lowest, x[3 * i + 1]);
  }
  return {kHeight - moment / mass, kHeight - lowest};
}

TEST(MeshResolution, ACornerPinnedCottonSheetSagsTheSameAtAnyResolutionAndTriangulation) {
  const MeshSag coarse = hanging_sag(testing_support::square_sheet(20, 1.0, kHeight, 0.0), 20);
  const MeshSag fine = hanging_sag(testing_support::square_sheet(40, 1.0, kHeight, 0.0), 40);
  const MeshSag jittered = hanging_sag(testing_support::square_sheet(40, 1.0, kHeight, 0.25), 40);
  std::printf("centre-of-mass drop: 21x21 %.5f m, 41x41 %.5f m, 41x41 jittered %.5f m\n",
              coarse.centre_of_mass, fine.centre_of_mass, jittered.centre_of_mass);
  std::printf("lowest vertex drop:  21x21 %.5f m, 41x41 %.5f m, 41x41 jittered %.5f m\n",
              coarse.lowest, fine.lowest, jittered.lowest);
  EXPECT_NEAR(fine.centre_of_mass, coarse.centre_of_mass, 0.02 * coarse.centre_of_mass);
  EXPECT_NEAR(fine.lowest, coarse.lowest, 0.02 * coarse.lowest);
  EXPECT_NEAR(jittered.centre_of_mass, fine.centre_of_mass, 0.04 * fine.centre_of_mass);
  EXPECT_NEAR(jittered.lowest, fine.lowest, 0.04 * fine.lowest);
  for (const MeshSag& s : {coarse, fine, jittered}) {
    // Hanging straight down, unstretched, the centre of mass is 0.5 m below the pins: the
    // material must stretch the sheet, and only a little (as the grid's cotton).
    EXPECT_GT(s.centre_of_mass, 0.5);
    EXPECT_LT(s.centre_of_mass, 0.53);
  }
}

}  // namespace
}  // namespace animkit
