#include "animkit/cloth/material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/core/validation.h"

namespace animkit {
namespace {

GridClothOptions sheet(int cells, const ClothMaterial& material) {
  GridClothOptions o{.cells = cells, .size = 1.0, .gravity = 9.81};
  o.material = material;
  return o;
}

TEST(Material, PresetsAreValidAndNamed) {
  for (const char* name : {"cotton", "silk", "denim", "leather", "rubber"}) {
    const MaterialPreset* preset = find_material(name);
    ASSERT_NE(preset, nullptr) << name;
    EXPECT_FALSE(preset->material.validate()) << name;
    EXPECT_FALSE(preset->source.empty());
  }
  EXPECT_EQ(find_material("tweed"), nullptr);
  // The physical-cloth benchmark's cotton sheet.
  EXPECT_EQ(find_material("cotton")->material.density, 0.15);
  EXPECT_EQ(find_material("cotton")->material.stretch, 1000.0);
}

TEST(Material, BadValuesGetOneClearError) {
  const auto error = [](ClothMaterial m) {
    const auto e = m.validate();
    return e ? e->message : "(valid)";
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error({.density = -1}),
            "material density must be between 0.0001 and 1000 kg/m^2, got -1");
  EXPECT_EQ(error({.density = nan}),
            "material density must be between 0.0001 and 1000 kg/m^2, got nan");
  EXPECT_EQ(error({.stretch = 0}),
            "material stretch stiffness must be between 0.001 and 1e+09 N/m, got 0");
  EXPECT_EQ(error({.shear = 0}),
            "material shear stiffness must be positive and below the stretch stiffness (1000 "
            "N/m), got 0");
  EXPECT_EQ(error({.shear = 2000}),
            "material shear stiffness must be positive and below the stretch stiffness (1000 "
            "N/m), got 2000");
  EXPECT_EQ(error({.bending = -1e-5}),
            "material bending stiffness must be between 0 and 1000 N m, got -1e-05");
  EXPECT_EQ(error({.damping = std::numeric_limits<double>::infinity()}),
            "material damping must be between 0 and 1e+06 N s/m, got inf");
  // Through the grid too, and values the resolution would push out of range.
  EXPECT_EQ(sheet(10, {.density = -1}).validate()->message,
            "material density must be between 0.0001 and 1000 kg/m^2, got -1");
  EXPECT_EQ(sheet(500, {.density = 0.01}).validate()->message,
            "the material's particle mass at 501 x 501 particles and 1 m must be between 1e-06 "
            "and 1e+06, got 1e-08");
}

TEST(Material, EveryFieldRefusesNanInfinityAndNonPositiveValues) {
  // Each field, each bad value: exactly one error, naming the field and the value, from the
  // material and through the grid's options (what ClothSimulator's callers validate).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Field {
    const char* name;  // as the message names it
    double ClothMaterial::*value;
    std::vector<double> bad;
  };
  const std::vector<Field> fields{
      {"density", &ClothMaterial::density, {nan, inf, -inf, 0.0, -0.15, 1e-5, 2e3}},
      {"stretch stiffness", &ClothMaterial::stretch, {nan, inf, -inf, 0.0, -1000.0, 1e10}},
      {"shear stiffness", &ClothMaterial::shear, {nan, inf, -inf, 0.0, -40.0}},
      {"bending stiffness", &ClothMaterial::bending, {nan, inf, -inf, -1e-5, 2e3}},
      {"damping", &ClothMaterial::damping, {nan, inf, -inf, -0.1}},
  };
  for (const Field& field : fields) {
    for (double value : field.bad) {
      ClothMaterial material = find_material("cotton")->material;
      material.*field.value = value;
      const std::string got = "got " + format_number(value);
      SCOPED_TRACE(std::string(field.name) + " " + got);
      const auto error = material.validate();
      ASSERT_TRUE(error);
      EXPECT_EQ(error->message.rfind("material " + std::string(field.name) + " must be ", 0), 0u)
          << error->message;
      EXPECT_EQ(error->message.substr(error->message.size() - got.size()), got);
      EXPECT_EQ(error->message.find('\n'), std::string::npos);
      const auto through_grid = sheet(20, material).validate();
      ASSERT_TRUE(through_grid);
      EXPECT_EQ(through_grid->message, error->message);
    }
  }
}

TEST(Material, MassAndStiffnessFollowTheArea) {
  for (int cells : {4, 20, 80}) {
    const ClothMaterial cotton = find_material("cotton")->material;
    const auto built = build_cloth(make_grid_cloth(sheet(cells, cotton)));
    ASSERT_TRUE(built) << built.error().message;
    const ClothModel& m = built->model;
    double mass = 0.0;
    for (double v : m.mass) mass += v;
    EXPECT_NEAR(mass, 0.15, 1e-12) << cells;  // density x 1 m^2, whatever the resolution
    // Every axis spring at stretch - shear (half on the border), diagonals at shear.
    const double spacing = 1.0 / cells;
    int axis = 0, diagonal = 0, coupling = 0;
    for (int s = 0; s < m.spring_count(); ++s) {
      const double l = m.rest_length[s] / spacing;
      if (m.stiffness[s] == 0.0) {
        ++coupling;  // a bend's outer pair
      } else if (std::abs(l - 1.0) < 1e-9) {
        ++axis;
        EXPECT_TRUE(m.stiffness[s] == 960.0 || m.stiffness[s] == 480.0) << m.stiffness[s];
      } else {
        ++diagonal;
        EXPECT_NEAR(l, std::sqrt(2.0), 1e-9);
        EXPECT_EQ(m.stiffness[s], 40.0);
      }
    }
    EXPECT_EQ(axis, 2 * cells * (cells + 1));
    EXPECT_EQ(diagonal, 2 * cells * cells);
    EXPECT_EQ(m.bend_count(), 2 * (cells - 1) * (cells + 1));
    EXPECT_EQ(coupling, m.bend_count());
    for (double c : m.bend_stiffness) {
      EXPECT_TRUE(std::abs(c - 1e-5 / (spacing * spacing)) < 1e-12 ||
                  std::abs(c - 0.5e-5 / (spacing * spacing)) < 1e-12);
    }
  }
}

}  // namespace
}  // namespace animkit
