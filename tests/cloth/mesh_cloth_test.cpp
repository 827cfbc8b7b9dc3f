#include "animkit/cloth/mesh_cloth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "../support/mesh_sheets.h"
#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/mesh_edges.h"

namespace animkit {
namespace {

using testing_support::square_sheet;

MeshClothOptions cotton(TriangleMesh mesh) {
  MeshClothOptions o{.mesh = std::move(mesh), .gravity = 9.81};
  o.material = find_material("cotton")->material;
  return o;
}

std::string error_of(const MeshClothOptions& options) {
  const auto desc = make_mesh_cloth(options);
  EXPECT_FALSE(desc);
  return desc ? std::string("(no error)") : desc.error().message;
}

TEST(MeshEdges, ListsEachEdgeOnceWithItsTriangles) {
  const TriangleMesh quad{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1)},
                          {{0, 1, 2}, {0, 2, 3}}};
  const auto edges = mesh_edges(quad);
  ASSERT_TRUE(edges) << edges.error().message;
  ASSERT_EQ(edges->size(), 5u);
  int interior = 0;
  for (const MeshEdge& e : *edges) {
    EXPECT_LT(e.vertices[0], e.vertices[1]);
    if (!e.interior()) continue;
    ++interior;
    EXPECT_EQ(e.vertices, (std::array<int, 2>{0, 2}));
    EXPECT_EQ(e.triangles, (std::array<int, 2>{0, 1}));
    EXPECT_EQ(opposite_vertex(quad, 0, e), 1);
    EXPECT_EQ(opposite_vertex(quad, 1, e), 3);
  }
  EXPECT_EQ(interior, 1);
}

TEST(MeshEdges, RefusesAnEdgeOfThreeTriangles) {
  const TriangleMesh fin{
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)},
      {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
  const auto edges = mesh_edges(fin);
  ASSERT_FALSE(edges);
  EXPECT_EQ(edges.error().message,
            "mesh edge between vertices 0 and 1 is shared by 3 triangles (0, 1, 2): a cloth "
            "needs a manifold mesh, at most two triangles per edge");
  EXPECT_EQ(error_of({.mesh = fin}), edges.error().message);
  // The mesh's source, when known, starts the message.
  EXPECT_EQ(error_of({.mesh = fin, .source = "fin.obj"}), "fin.obj: " + edges.error().message);
}

TEST(MeshCloth, TotalMassIsDensityTimesArea) {
  for (const double jitter : {0.0, 0.3}) {
    const auto desc = make_mesh_cloth(cotton(square_sheet(10, 1.0, 0.0, jitter)));
    ASSERT_TRUE(desc) << desc.error().message;
    double mass = 0.0;
    for (const ParticleDesc& p : desc->particles) mass += p.mass;
    EXPECT_NEAR(mass, 0.15 * 1.0, 1e-14);
  }
}

TEST(MeshCloth, RightTrianglesGetTheGridsLatticeSprings) {
  // On a grid's triangulation, legs S - G inside (S/2 - G/2 from each triangle), half on the
  // border: the grid's axis springs; hypotenuses 2G (G from each triangle): the shear C66 = G
  // the grid's two diagonals of G per cell give.
  const ClothMaterial m = find_material("cotton")->material;
  const auto desc = make_mesh_cloth(cotton(square_sheet(4, 1.0, 0.0, 0.0)));
  ASSERT_TRUE(desc) << desc.error().message;
  ASSERT_EQ(desc->springs.size(), 2u * 4 * 5 + 4 * 4);
  for (const SpringDesc& s : desc->springs) {
    const Vec3 d = desc->particles[s.b].position - desc->particles[s.a].position;
    const bool diagonal = std::abs(d.x()) > 0.0 && std::abs(d.z()) > 0.0;
    const bool border = (d.x() == 0.0 && (desc->particles[s.a].position.x() == 0.0 ||
                                          desc->particles[s.a].position.x() == 1.0)) ||
                        (d.z() == 0.0 && std::abs(desc->particles[s.a].position.z()) == 0.5);
    const double expected = diagonal ? 2.0 * m.shear : (border ? 0.5 : 1.0) * (m.stretch - m.shear);
    EXPECT_NEAR(s.stiffness, expected, 1e-9 * m.stretch);
  }
  EXPECT_EQ(desc->bends.size(), 4u * 3 * 2 + 4 * 4);  // one per interior edge
}

TEST(MeshCloth, BendWeightsAnnihilateTheFlatRestShapeAndAnyAffineMapOfIt) {
  const auto desc = make_mesh_cloth(cotton(square_sheet(6, 1.0, 0.0, 0.35, 3)));
  ASSERT_TRUE(desc) << desc.error().message;
  const auto built = build_cloth(*desc);
  ASSERT_TRUE(built) << built.error().message;
  Eigen::Matrix3d a;
  a << 1.2, 0.3, -0.1, 0.2, 0.9, 0.4, -0.3, 0.1, 1.1;
  Eigen::VectorXd mapped = built->state.positions;
  for (Eigen::Index i = 0; i < mapped.size() / 3; ++i)
    mapped.segment<3>(3 * i) = a * mapped.segment<3>(3 * i) + Vec3(3, -2, 1);
  const ClothModel& model = built->model;
  ASSERT_GT(model.bend_count(), 0);
  for (int k = 0; k < model.bend_count(); ++k) {
    double scale = 0.0;
    for (double w : model.bend_weights[k]) scale += std::abs(w);
    EXPECT_LT(bend_vector(built->state.positions, model.bends[k], model.bend_weights[k]).norm(),
              1e-13 * scale);
    EXPECT_LT(bend_vector(mapped, model.bends[k], model.bend_weights[k]).norm(), 1e-12 * scale);
  }
}

// The bends' energy of the flat sheet rolled (isometrically) into a cylinder of radius R about
// an axis in the sheet's plane at `angle` to z, over 1/2 B / R^2 times the area the bends stand
// for (a third of their two triangles' area each: the border edges have no bend).
double cylinder_energy_ratio(const TriangleMesh& mesh, double angle, double radius) {
  const auto desc = make_mesh_cloth(cotton(mesh));
  EXPECT_TRUE(desc) << desc.error().message;
  const auto built = build_cloth(*desc);
  const ClothModel& model = built->model;
  const Vec3 across(std::cos(angle), 0.0, -std::sin(angle)),
      along(std::sin(angle), 0.0, std::cos(angle));
  Eigen::VectorXd rolled = built->state.positions;
  for (Eigen::Index i = 0; i < rolled.size() / 3; ++i) {
    const Vec3 p = rolled.segment<3>(3 * i);
    const double u = p.dot(across), v = p.dot(along);
    rolled.segment<3>(3 * i) = radius * std::sin(u / radius) * across +
                               radius * (1.0 - std::cos(u / radius)) * Vec3::UnitY() + v * along;
  }
  double energy = 0.0, area = 0.0;
  const auto triangle_area = [&](int t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    return 0.5 * (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                     .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]])
                     .norm();
  };
  for (int k = 0; k < model.bend_count(); ++k)
    energy += bend_energy(rolled, model.bends[k], model.bend_weights[k], model.bend_stiffness[k]);
  const auto edges = mesh_edges(mesh);
  for (const MeshEdge& e : *edges) {
    if (e.interior()) area += (triangle_area(e.triangles[0]) + triangle_area(e.triangles[1])) / 3;
  }
  const double bending = find_material("cotton")->material.bending;
  return energy / (0.5 * bending / (radius * radius) * area);
}

TEST(MeshCloth, ACylinderOfRadiusRStoresHalfBOverRSquaredPerUnitArea) {
  // Along either axis of a grid's triangulation the element is exact to second order in the
  // spacing over the radius (mesh_bending.h); on a mesh of equilateral triangles, about any
  // axis. What is left is the border: on the grid only the edges along the axis bend, each for a
  // whole cell, so the column of cells at the border that has none of them is missing, a
  // first-order error ((1 - s) / (1 - 2 s / 3) with the normalization above), which halves
  // from 20 to 40 cells.
  double previous_error = 1.0;
  for (const int cells : {20, 40}) {
    SCOPED_TRACE(cells);
    const TriangleMesh grid = square_sheet(cells, 1.0, 0.0, 0.0);
    const double along_z = cylinder_energy_ratio(grid, 0.0, 0.5);
    const double along_x = cylinder_energy_ratio(grid, 0.5 * std::numbers::pi, 0.5);
    std::printf(
        "%d cells, grid triangulation: energy / (1/2 B/R^2 area) %.5f (axis z), %.5f "
        "(axis x)\n",
        cells, along_z, along_x);
    EXPECT_NEAR(along_z, 1.0, cells == 20 ? 0.025 : 0.01);
    EXPECT_NEAR(along_x, along_z, 1e-9);
    EXPECT_LT(std::abs(along_z - 1.0), 0.6 * previous_error);
    previous_error = std::abs(along_z - 1.0);
    const TriangleMesh equilateral = testing_support::equilateral_sheet(cells, 1.0);
    for (const double angle : {0.0, 0.3, 0.9, 1.4}) {
      SCOPED_TRACE(angle);
      const double ratio = cylinder_energy_ratio(equilateral, angle, 0.5);
      std::printf("%d cells, equilateral, axis at %.1f rad: %.5f\n", cells, angle, ratio);
      EXPECT_NEAR(ratio, 1.0, cells == 20 ? 0.025 : 0.01);
    }
  }
}

TEST(MeshCloth, PinnedVerticesByIndexAndByBoxNeverMove) {
  MeshClothOptions o = cotton(square_sheet(8, 1.0, 0.0, 0.0));
  o.pins = {0, 80};                                                           // two corners
  o.pin_boxes = {Eigen::AlignedBox3d(Vec3(0.49, -1, -1), Vec3(0.51, 1, 1))};  // a middle row
  const auto desc = make_mesh_cloth(o);
  ASSERT_TRUE(desc) << desc.error().message;
  int pinned = 0;
  for (const ParticleDesc& p : desc->particles) pinned += p.pinned ? 1 : 0;
  EXPECT_EQ(pinned, 2 + 9);
  auto sim = ClothSimulator::create(*desc, {});
  ASSERT_TRUE(sim) << sim.error().message;
  const ClothState start = sim->state();
  for (int frame = 0; frame < 20; ++frame) ASSERT_TRUE(sim->step(1.0 / 60.0));
  double moved = 0.0;
  for (int i = 0; i < sim->model().particle_count(); ++i) {
    if (desc->particles[i].pinned) {
      EXPECT_EQ(sim->state().position(i), start.position(i)) << "particle " << i;
    } else {
      moved = std::max(moved, (sim->state().position(i) - start.position(i)).norm());
    }
  }
  EXPECT_GT(moved, 0.01);  // the rest falls
}

TEST(MeshCloth, RefusesBadPinsAndOptions) {
  MeshClothOptions o = cotton(square_sheet(2, 1.0, 0.0, 0.0));
  o.pins = {3, 9};
  EXPECT_EQ(error_of(o), "pin 9 is not a vertex of the mesh (0..8)");
  o.pins = {-1};
  EXPECT_EQ(error_of(o), "pin -1 is not a vertex of the mesh (0..8)");
  o.pins = {};
  o.pin_boxes = {Eigen::AlignedBox3d(Vec3(0, 0, -1), Vec3(1, 0, 1)),
                 Eigen::AlignedBox3d(Vec3(2, 0, 0), Vec3(3, 1, 1))};
  EXPECT_EQ(error_of(o), "pin box 1 from (2, 0, 0) to (3, 1, 1) holds no vertex of the mesh");
  o.pin_boxes = {Eigen::AlignedBox3d(Vec3(1, 0, 0), Vec3(0, 1, 1))};
  EXPECT_EQ(error_of(o),
            "pin box 0 from (1, 0, 0) to (0, 1, 1) has a min corner above its max "
            "corner");
  o.pin_boxes = {};
  o.warp = Vec3::Zero();
  EXPECT_EQ(error_of(o), "the warp direction must be finite and nonzero, got (0, 0, 0)");
  o = cotton(square_sheet(2, 1.0, 0.0, 0.0));
  o.mesh.vertices.push_back(Vec3(5, 5, 5));
  EXPECT_EQ(error_of(o),
            "mesh vertex 9 is in no triangle (a particle with no area and no "
            "springs)");
  o.mesh = {};
  EXPECT_EQ(error_of(o), "the mesh has no triangles");
}

TEST(MeshCloth, TheLabsParametersGiveEdgeAndAcrossEdgeSprings) {
  const auto desc = make_mesh_cloth({.mesh = square_sheet(3, 2.0, 1.5, 0.0), .mass = 2.0});
  ASSERT_TRUE(desc) << desc.error().message;
  EXPECT_TRUE(desc->bends.empty());
  const int edges = 2 * 3 * 4 + 3 * 3, interior = edges - 4 * 3;
  EXPECT_EQ(desc->springs.size(), static_cast<std::size_t>(edges + interior));
  for (const ParticleDesc& p : desc->particles) EXPECT_EQ(p.mass, 2.0);
  for (const SpringDesc& s : desc->springs) EXPECT_EQ(s.stiffness, 100.0);
  EXPECT_EQ(desc->gravity, 0.3);
  EXPECT_EQ(desc->damping, 0.2);
}

}  // namespace
}  // namespace animkit
