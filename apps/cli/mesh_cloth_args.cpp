#include "mesh_cloth_args.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "animkit/core/quote.h"
#include "animkit/io/obj_mesh.h"

namespace animkit::cli {

namespace {

// "a,b,c" split at commas (empty fields kept, so "1,,2" is refused).
std::vector<std::string> fields(std::string_view text) {
  std::vector<std::string> out;
  for (;;) {
    const std::size_t comma = text.find(',');
    out.emplace_back(text.substr(0, comma));
    if (comma == std::string_view::npos) return out;
    text.remove_prefix(comma + 1);
  }
}

bool parse_int(const std::string& field, int& value) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(field.c_str(), &end, 10);
  if (field.empty() || end != field.c_str() + field.size() || errno != 0 || v < INT_MIN ||
      v > INT_MAX)
    return false;
  value = static_cast<int>(v);
  return true;
}

bool parse_double(const std::string& field, double& value) {
  char* end = nullptr;
  value = std::strtod(field.c_str(), &end);
  return !field.empty() && end == field.c_str() + field.size() && std::isfinite(value);
}

}  // namespace

Result<MeshClothOptions> mesh_cloth_options(const MeshClothArgs& args,
                                            const std::optional<ClothMaterial>& material,
                                            double mass, double stiffness, double damping,
                                            double gravity) {
  MeshClothOptions o;
  for (const std::string& list : args.pins) {
    for (const std::string& field : fields(list)) {
      int pin = 0;
      if (!parse_int(field, pin)) {
        return fail("--pin expects vertex indices I,J,... (counted from 0), got " +
                    quote_input(list));
      }
      o.pins.push_back(pin);
    }
  }
  for (const std::string& box : args.pin_boxes) {
    const std::vector<std::string> f = fields(box);
    double v[6];
    bool ok = f.size() == 6;
    for (std::size_t k = 0; ok && k < 6; ++k) ok = parse_double(f[k], v[k]);
    if (!ok) {
      return fail("--pin-box expects six finite numbers X0,Y0,Z0,X1,Y1,Z1, got " +
                  quote_input(box));
    }
    o.pin_boxes.emplace_back(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]));
  }
  auto mesh = read_obj_mesh(args.mesh);
  if (!mesh) return fail(mesh.error().message);
  o.mesh = std::move(*mesh);
  o.source = args.mesh;
  o.material = material;
  o.mass = mass;
  o.stiffness = stiffness;
  o.damping = damping;
  o.gravity = gravity;
  return o;
}

}  // namespace animkit::cli
