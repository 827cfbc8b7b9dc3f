#include "animkit/cloth/material.h"

#include <array>
#include <cmath>
#include <string>

#include "animkit/cloth/parameter_ranges.h"

namespace animkit {

namespace {

// Fabric weights are the usual grams per square metre of each fabric; membrane and bending
// stiffnesses are representative magnitudes of the Kawabata Evaluation System's tensile (EMT,
// LT), shear (G) and bending (B) measurements of such fabrics (Kawabata, "The standardization
// and analysis of hand evaluation", 1980), converted to SI: 1 gf cm^2/cm = 9.81e-5 N m and
// 1 gf/(cm deg) = 56.2 N/m. Rubber from its bulk properties. Representative, not measured here.
const std::array kPresets{
    MaterialPreset{"cotton",
                   {0.15, 1000.0, 40.0, 1e-5, 0.0},
                   "150 g/m^2 woven cotton (a shirting); stretch 1000 N/m, the convergence "
                   "study's cotton sheet; KES shear ~0.7 gf/(cm deg), bending ~0.1 gf cm^2/cm"},
    MaterialPreset{"silk",
                   {0.05, 400.0, 10.0, 1e-6, 0.0},
                   "50 g/m^2 silk charmeuse; soft in shear (KES ~0.2 gf/(cm deg)) and bending "
                   "(~0.01 gf cm^2/cm)"},
    MaterialPreset{"denim",
                   {0.40, 5000.0, 200.0, 1e-4, 0.0},
                   "12 oz/yd^2 (400 g/m^2) denim; KES shear ~3.5 gf/(cm deg), bending ~1 gf "
                   "cm^2/cm"},
    MaterialPreset{"leather",
                   {1.0, 20000.0, 2000.0, 1e-3, 0.0},
                   "1.2 mm garment leather (~0.8 g/cm^3): Young's modulus ~20 MPa, bending "
                   "E t^3 / 12 ~ 1e-3 N m"},
    MaterialPreset{"rubber",
                   {0.93, 2000.0, 500.0, 1.7e-4, 0.0},
                   "1 mm natural rubber sheet: 930 kg/m^3, E = 1.5 MPa, Poisson 0.5: C11 = E t / "
                   "(1 - nu^2), C66 = E t / (2 (1 + nu)), B = E t^3 / (12 (1 - nu^2))"},
};

}  // namespace

std::optional<Error> ClothMaterial::validate() const {
  const auto refuse = [](const std::string& what, double min, double max, double value,
                         const std::string& unit) {
    return Error{"material " + what + " must be between " + format_number(min) + " and " +
                 format_number(max) + " " + unit + ", got " + format_number(value)};
  };
  if (!(std::isfinite(density) && density >= 1e-4 && density <= 1e3))
    return refuse("density", 1e-4, 1e3, density, "kg/m^2");
  if (!(std::isfinite(stretch) && stretch >= 1e-3 && stretch <= kStiffnessRange.max))
    return refuse("stretch stiffness", 1e-3, kStiffnessRange.max, stretch, "N/m");
  if (!(std::isfinite(shear) && shear > 0.0 && shear < stretch)) {
    return Error{"material shear stiffness must be positive and below the stretch stiffness (" +
                 format_number(stretch) + " N/m), got " + format_number(shear)};
  }
  if (!(std::isfinite(bending) && bending >= 0.0 && bending <= 1e3))
    return refuse("bending stiffness", 0.0, 1e3, bending, "N m");
  if (!kDampingRange.contains(damping))
    return refuse("damping", kDampingRange.min, kDampingRange.max, damping, "N s/m");
  return std::nullopt;
}

std::span<const MaterialPreset> material_presets() {
  return kPresets;
}

const MaterialPreset* find_material(std::string_view name) {
  for (const MaterialPreset& preset : kPresets) {
    if (preset.name == name) return &preset;
  }
  return nullptr;
}

}  // namespace animkit
