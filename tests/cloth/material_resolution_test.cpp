// A material hangs the same at any resolution. A sheet of a preset, 1 m square,
// pinned at two corners, is brought to static equilibrium at 21 x 21 up to 161 x 161
// particles, and its sag compared: the drop of the centre of mass and of the lowest particle
// below the pins. (Not the pinned edge's midpoint: a point pin is a logarithmic singularity of
// the membrane, so the sheet around it stretches further the finer the grid.)
//
// The same singularity makes the elastic part of the sag (the drop beyond the 0.5 m and 1 m of
// an unstretched sheet hanging straight) grow slowly with the resolution when the sheet hangs
// from two points; a sheet held along two fixed lengths of its top edge instead converges at
// first order. Both are checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/sanitizers.h"
#include "../support/static_equilibrium.h"
#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

GridClothOptions sheet(const char* material, int cells) {
  GridClothOptions options{.cells = cells, .size = 1.0, .gravity = 9.81};
  options.material = find_material(material)->material;
  return options;
}

// The sheet hanging flat in the vertical plane of its pins, particle (i, j) at (0, height -
// i s, z_j). Gravity and every spring and bend force then lie in that plane, so the
// equilibrium stays in it: the sag measured is the membrane's and the bends' (grid lines curve
// in the plane too), without the mesh-scale wrinkles a sheet with little bending stiffness may
// throw out of plane.
Eigen::VectorXd hanging_plane(int cells, double height) {
  Eigen::VectorXd x(3 * (cells + 1) * (cells + 1));
  const double s = 1.0 / cells;
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j)
      x.segment<3>(3 * grid_index(cells, i, j)) = Vec3(0.0, height - i * s, j * s - 0.5);
  }
  return x;
}

// A coarse grid's positions interpolated onto the grid twice as fine (nested iteration: the
// fine Newton solve starts close to its solution and needs few iterations).
Eigen::VectorXd refine(const Eigen::VectorXd& coarse, int cells) {
  const int fine = 2 * cells;
  Eigen::VectorXd x(3 * (fine + 1) * (fine + 1));
  const auto at = [&](int i, int j) -> Vec3 {
    return coarse.segment<3>(3 * grid_index(cells, i, j));
  };
  for (int i = 0; i <= fine; ++i) {
    for (int j = 0; j <= fine; ++j) {
      const int i0 = i / 2, j0 = j / 2, i1 = (i + 1) / 2, j1 = (j + 1) / 2;
      x.segment<3>(3 * grid_index(fine, i, j)) =
          0.25 * (at(i0, j0) + at(i0, j1) + at(i1, j0) + at(i1, j1));
    }
  }
  return x;
}

struct Sag {
  double centre_of_mass = 0.0;  // drop below the pins, m
  double lowest = 0.0;          // drop of the lowest particle below the pins, m
};

Sag sag_of(const ClothModel& model, const Eigen::VectorXd& x, double height) {
  double moment = 0.0, mass = 0.0, lowest = height;
  for (int i = 0; i < model.particle_count(); ++i) {
    moment += model.mass[i] * x[3 * i + 1];
    mass += model.mass[i];
    lowest = std::min(lowest, x[3 * i + 1]);
  }
  return {height - moment / mass, height - lowest};
}

enum class Pins { corners, edge_segments };

// The sags at 21, 41, 81 (and 161) particles a side, each solve started from the previous
// one's solution refined.
std::vector<Sag> sags(const char* material, Pins pins, int finest_cells) {
  std::vector<Sag> result;
  Eigen::VectorXd x;
  for (int cells = 20; cells <= finest_cells; cells *= 2) {
    const GridClothOptions options = sheet(material, cells);
    ClothDesc desc = make_grid_cloth(options);
    for (int j = 0; j <= cells; ++j) {
      // Pinned edge segments: the 10 cm of the top edge at each corner.
      if (pins == Pins::edge_segments && (10 * j <= cells || 10 * j >= 9 * cells))
        desc.particles[grid_index(cells, 0, j)].pinned = true;
    }
    const auto built = build_cloth(desc);
    EXPECT_TRUE(built);
    x = testing_support::static_equilibrium(
        built->model, cells == 20 ? hanging_plane(cells, options.height) : refine(x, cells / 2));
    result.push_back(sag_of(built->model, x, options.height));
  }
  return result;
}

// The finest grid: under the sanitizers the 161 x 161 solve would take most of a minute, so
// sanitized builds stop at 81 x 81.
constexpr int kFinestCells = test_support::kUnderSanitizers ? 80 : 160;

class MaterialResolution : public testing::TestWithParam<const char*> {};

TEST_P(MaterialResolution, ACornerPinnedSheetSagsTheSameWithinTwoPercent) {
  const std::vector<Sag> s = sags(GetParam(), Pins::corners, kFinestCells);
  ASSERT_EQ(s.size(), kFinestCells == 160 ? 4u : 3u);
  for (std::size_t k = 1; k < s.size(); ++k) {
    SCOPED_TRACE(testing::Message() << (20 << k) + 1 << " x " << (20 << k) + 1);
    EXPECT_NEAR(s[k].centre_of_mass, s[0].centre_of_mass, 0.02 * s[0].centre_of_mass);
    EXPECT_NEAR(s[k].lowest, s[0].lowest, 0.02 * s[0].lowest);
    // Hanging straight down, unstretched, the sheet's centre of mass is 0.5 m below the pins
    // and its lowest particle 1 m: the material must stretch it, and only a little.
    EXPECT_GT(s[k].centre_of_mass, 0.5);
    EXPECT_LT(s[k].centre_of_mass, 0.52);
  }
}

TEST_P(MaterialResolution, TheElasticSagConvergesWhenEdgeSegmentsArePinned) {
  // Up to 81 x 81 only (the 161 x 161 solves are the test above's): three resolutions show
  // the order. First order: each halving of the spacing halves the change.
  const std::vector<Sag> s = sags(GetParam(), Pins::edge_segments, 80);
  ASSERT_EQ(s.size(), 3u);
  for (const bool lowest : {false, true}) {
    SCOPED_TRACE(lowest ? "lowest particle" : "centre of mass");
    // The drop beyond the unstretched sheet's.
    const auto sag = [&](std::size_t k) {
      return lowest ? s[k].lowest - 1.0 : s[k].centre_of_mass - 0.5;
    };
    ASSERT_GT(sag(0), 0.0);
    EXPECT_LT(std::abs(sag(2) - sag(1)), 0.65 * std::abs(sag(1) - sag(0)));
    EXPECT_NEAR(sag(2), sag(0), 0.1 * sag(2));  // the first-order error at 21 x 21 is < 10%
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, MaterialResolution, testing::Values("cotton", "leather"),
                         [](const auto& param_info) { return std::string(param_info.param); });

}  // namespace
}  // namespace animkit
