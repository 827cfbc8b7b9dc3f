// Bindings of the cloth sheets: physical materials and their presets, the grid and the mesh
// sheets.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <variant>

#include "animkit/cloth/material.h"
#include "animkit/cloth/mesh_cloth.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

constexpr Named<GridPins> kPins[] = {
    {"corners", GridPins::corners}, {"edge", GridPins::edge}, {"none", GridPins::none}};

std::string material_names() {
  std::string names;
  for (const MaterialPreset& preset : material_presets())
    names += (names.empty() ? "" : ", ") + std::string(preset.name);
  return names;
}

std::string repr_material(const ClothMaterial& m) {
  return "Material(density=" + repr_number(m.density) + ", stretch=" + repr_number(m.stretch) +
         ", shear=" + repr_number(m.shear) + ", bending=" + repr_number(m.bending) +
         ", damping=" + repr_number(m.damping) + ")";
}

// Gravity when the caller gives none: SI with a physical material, the lab's without (as the
// scene files have it, io/cloth_scene_file.h).
double default_gravity(const std::optional<ClothMaterial>& material) {
  return material ? 9.81 : GridClothOptions{}.gravity;
}

std::vector<Eigen::AlignedBox3d> to_boxes(const py::handle& value) {
  DoubleArray array = as_double_array(value, "pin_boxes");
  if (array.ndim() == 1 && array.shape(0) == 0) return {};
  if (array.ndim() != 2 || array.shape(1) != 6)
    raise("pin_boxes must be an array of shape (k, 6): x0, y0, z0, x1, y1, z1 per box");
  std::vector<Eigen::AlignedBox3d> boxes;
  const auto v = array.unchecked<2>();
  for (py::ssize_t k = 0; k < array.shape(0); ++k) {
    boxes.emplace_back(Vec3(v(k, 0), v(k, 1), v(k, 2)), Vec3(v(k, 3), v(k, 4), v(k, 5)));
  }
  return boxes;
}

}  // namespace

std::string repr_grid(const GridClothOptions& g) {
  return "GridCloth(cells=" + std::to_string(g.cells) + ", size=" + repr_number(g.size) +
         ", height=" + repr_number(g.height) + ", mass=" + repr_number(g.mass) +
         ", stiffness=" + repr_number(g.stiffness) + ", damping=" + repr_number(g.damping) +
         ", gravity=" + repr_number(g.gravity) +
         ", material=" + (g.material ? repr_material(*g.material) : "None") + ", pins='" +
         enum_name(g.pins, kPins) + "', rotation=" + repr_quat(g.rotation) +
         ", offset=" + repr_vec3(g.offset) + ")";
}

std::string repr_mesh(const MeshClothOptions& o) {
  return "MeshCloth(vertices=<" + std::to_string(o.mesh.vertices.size()) + ">, triangles=<" +
         std::to_string(o.mesh.triangles.size()) + ">, mass=" + repr_number(o.mass) +
         ", stiffness=" + repr_number(o.stiffness) + ", damping=" + repr_number(o.damping) +
         ", gravity=" + repr_number(o.gravity) +
         ", material=" + (o.material ? repr_material(*o.material) : "None") +
         ", warp=" + repr_vec3(o.warp) + ", pins=<" + std::to_string(o.pins.size()) +
         ">, pin_boxes=<" + std::to_string(o.pin_boxes.size()) + ">)";
}

void bind_sheets(py::module_& m) {
  py::class_<ClothMaterial>(
      m, "Material",
      "A cloth material in physical units: a sheet made of it gets its particle masses and "
      "stiffnesses from these values and its resolution, so it hangs the same at any grid size.")
      .def(py::init(
               [](double density, double stretch, double shear, double bending, double damping) {
                 ClothMaterial mat{density, stretch, shear, bending, damping};
                 check(mat.validate());
                 return mat;
               }),
           "Raises animkit.Error for an out-of-range value.",
           py::arg("density") = ClothMaterial{}.density,
           py::arg("stretch") = ClothMaterial{}.stretch, py::arg("shear") = ClothMaterial{}.shear,
           py::arg("bending") = ClothMaterial{}.bending,
           py::arg("damping") = ClothMaterial{}.damping)
      .def_readwrite("density", &ClothMaterial::density, "Areal density, kg/m^2.")
      .def_readwrite("stretch", &ClothMaterial::stretch, "Membrane stretch stiffness C11, N/m.")
      .def_readwrite("shear", &ClothMaterial::shear, "Membrane shear stiffness C66, N/m.")
      .def_readwrite("bending", &ClothMaterial::bending, "Bending stiffness B, N m.")
      .def_readwrite("damping", &ClothMaterial::damping, "Spring dashpot coefficient, N s/m.")
      .def("__repr__", &repr_material);

  m.def(
      "material",
      [](const std::string& name) {
        const MaterialPreset* preset = find_material(name);
        if (!preset)
          raise("unknown material '" + name + "' (expected one of: " + material_names() + ")");
        return preset->material;
      },
      "The material preset called `name` (cotton, silk, denim, leather, rubber), a copy. Raises "
      "animkit.Error for an unknown name.",
      py::arg("name"));
  m.def(
      "material_names",
      [] {
        std::vector<std::string> names;
        for (const MaterialPreset& p : material_presets()) names.emplace_back(p.name);
        return names;
      },
      "The material presets' names.");

  const GridClothOptions grid;
  py::class_<GridClothOptions>(
      m, "GridCloth",
      "An (n+1) x (n+1) grid cloth in the plane y = height spanning `size` along x and z, "
      "pinned by `pins`; defaults: the lab's cloth (11 x 11 particles, mass 1, stiffness 100, "
      "damping 0.2, gravity 0.3). With a Material the sheet is physical (SI units).")
      .def(py::init([](int cells, double size, double height, double mass, double stiffness,
                       double damping, std::optional<double> gravity,
                       std::optional<ClothMaterial> material, const std::string& pins,
                       py::object rotation, py::object offset) {
             GridClothOptions g;
             g.cells = cells;
             g.size = size;
             g.height = height;
             g.mass = mass;
             g.stiffness = stiffness;
             g.damping = damping;
             g.material = material;
             g.gravity = gravity ? *gravity : default_gravity(material);
             g.pins = parse_enum(pins, kPins, "pins");
             g.rotation = to_quat(rotation, "rotation");
             g.offset = to_vec3(offset, "offset");
             check(g.validate());
             return g;
           }),
           "cells: cells per side; size, height: scene units (m with a material); mass, "
           "stiffness, damping: the lab's per-particle parameters (unused with a material); "
           "gravity along -y (None: 9.81 with a material, else 0.3); pins: 'corners', 'edge' or "
           "'none'; rotation (w, x, y, z) about the sheet's centre, then offset. Raises "
           "animkit.Error for an out-of-range value.",
           py::arg("cells") = grid.cells, py::arg("size") = grid.size,
           py::arg("height") = grid.height, py::arg("mass") = grid.mass,
           py::arg("stiffness") = grid.stiffness, py::arg("damping") = grid.damping,
           py::arg("gravity") = py::none(), py::arg("material") = py::none(),
           py::arg("pins") = enum_name(grid.pins, kPins),
           py::arg("rotation") = py::make_tuple(1.0, 0.0, 0.0, 0.0),
           py::arg("offset") = py::make_tuple(0.0, 0.0, 0.0))
      .def_readwrite("cells", &GridClothOptions::cells, "Cells per side, >= 1.")
      .def_readwrite("size", &GridClothOptions::size, "Side length.")
      .def_readwrite("height", &GridClothOptions::height, "y of the sheet's plane.")
      .def_readwrite("mass", &GridClothOptions::mass, "Mass per particle (lab parameters).")
      .def_readwrite("stiffness", &GridClothOptions::stiffness, "Spring stiffness (lab).")
      .def_readwrite("damping", &GridClothOptions::damping, "Spring damping (lab).")
      .def_readwrite("gravity", &GridClothOptions::gravity, "Acceleration along -y.")
      .def_property(
          "material", [](const GridClothOptions& g) { return g.material; },
          [](GridClothOptions& g, std::optional<ClothMaterial> v) { g.material = std::move(v); },
          "A physical Material, or None for the lab's parameters (a copy; assign it back to "
          "change the sheet).")
      .def_property(
          "pins", [](const GridClothOptions& g) { return enum_name(g.pins, kPins); },
          [](GridClothOptions& g, const std::string& v) { g.pins = parse_enum(v, kPins, "pins"); },
          "'corners', 'edge' or 'none'.")
      .def_property(
          "rotation", [](const GridClothOptions& g) { return quat_to_array(g.rotation); },
          [](GridClothOptions& g, py::object v) { g.rotation = to_quat(v, "rotation"); },
          "Rotation about the sheet's centre, (w, x, y, z).")
      .def_property(
          "offset", [](const GridClothOptions& g) { return vec3_to_array(g.offset); },
          [](GridClothOptions& g, py::object v) { g.offset = to_vec3(v, "offset"); },
          "Translation after the rotation.")
      .def("__repr__", &repr_grid);

  const MeshClothOptions mesh;
  py::class_<MeshClothOptions>(
      m, "MeshCloth",
      "A cloth cut from a triangle mesh: particles at its vertices, springs on its edges, "
      "bending across interior edges, pins by vertex index or by box.")
      .def(py::init([](py::object vertices, py::object triangles, double mass, double stiffness,
                       double damping, std::optional<double> gravity,
                       std::optional<ClothMaterial> material, py::object warp,
                       std::vector<int> pins, py::object pin_boxes) {
             MeshClothOptions o;
             o.mesh.vertices = to_vec3s(vertices, "vertices");
             o.mesh.triangles = to_triangles(triangles, "triangles");
             o.mass = mass;
             o.stiffness = stiffness;
             o.damping = damping;
             o.material = material;
             o.gravity = gravity ? *gravity : default_gravity(material);
             o.warp = to_vec3(warp, "warp");
             o.pins = std::move(pins);
             o.pin_boxes = to_boxes(pin_boxes);
             unwrap(make_mesh_cloth(o));  // every check the sheet needs
             return o;
           }),
           "vertices (n, 3) at rest in world space (m with a material), triangles (m, 3) vertex "
           "indices (manifold); mass, stiffness, damping: the lab's parameters (unused with a "
           "material); gravity along -y (None: 9.81 with a material, else 0.3); warp: the "
           "material's warp direction; pins: vertex indices; pin_boxes (k, 6): x0, y0, z0, x1, "
           "y1, z1 of boxes pinning the vertices inside. Raises animkit.Error for an invalid "
           "mesh, pin or value.",
           py::arg("vertices"), py::arg("triangles"), py::arg("mass") = mesh.mass,
           py::arg("stiffness") = mesh.stiffness, py::arg("damping") = mesh.damping,
           py::arg("gravity") = py::none(), py::arg("material") = py::none(),
           py::arg("warp") = py::make_tuple(1.0, 0.0, 0.0), py::arg("pins") = std::vector<int>{},
           py::arg("pin_boxes") = py::list())
      .def_property_readonly(
          "vertices", [](const MeshClothOptions& o) { return vec3s_to_array(o.mesh.vertices); },
          "The rest shape's vertices (n, 3), a copy.")
      .def_property_readonly(
          "triangles",
          [](const MeshClothOptions& o) { return triangles_to_array(o.mesh.triangles); },
          "The triangles (m, 3), a copy.")
      .def_readwrite("mass", &MeshClothOptions::mass, "Mass per particle (lab parameters).")
      .def_readwrite("stiffness", &MeshClothOptions::stiffness, "Spring stiffness (lab).")
      .def_readwrite("damping", &MeshClothOptions::damping, "Spring damping (lab).")
      .def_readwrite("gravity", &MeshClothOptions::gravity, "Acceleration along -y.")
      .def_property(
          "material", [](const MeshClothOptions& o) { return o.material; },
          [](MeshClothOptions& o, std::optional<ClothMaterial> v) { o.material = std::move(v); },
          "A physical Material, or None for the lab's parameters (a copy; assign it back to "
          "change the sheet).")
      .def_property(
          "warp", [](const MeshClothOptions& o) { return vec3_to_array(o.warp); },
          [](MeshClothOptions& o, py::object v) { o.warp = to_vec3(v, "warp"); },
          "The material's warp direction.")
      .def_readwrite("pins", &MeshClothOptions::pins, "Pinned vertex indices (a copy).")
      .def_property_readonly(
          "pin_boxes",
          [](const MeshClothOptions& o) {
            py::array_t<double> out({static_cast<py::ssize_t>(o.pin_boxes.size()), py::ssize_t{6}});
            auto v = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < o.pin_boxes.size(); ++k) {
              for (int c = 0; c < 3; ++c) {
                v(static_cast<py::ssize_t>(k), c) = o.pin_boxes[k].min()[c];
                v(static_cast<py::ssize_t>(k), c + 3) = o.pin_boxes[k].max()[c];
              }
            }
            return out;
          },
          "The pin boxes (k, 6), a copy.")
      .def("__repr__", &repr_mesh);
}

}  // namespace animkit::python
