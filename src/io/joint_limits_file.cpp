#include "animkit/io/joint_limits_file.h"

#include <algorithm>
#include <numbers>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/file_bytes.h"
#include "held_fp_exceptions.h"
#include "json_fields.h"

namespace animkit {

namespace {

constexpr double kPi = std::numbers::pi;

// Degrees in [-180, 180] to radians in [-pi, pi] (clamped: 180 * pi / 180 may round past pi).
double to_radians(double degrees) {
  return std::clamp(degrees * kPi / 180.0, -kPi, kPi);
}

// Reads one joint's limit; every error is a FieldError naming the key.
class LimitReader {
 public:
  LimitReader(const nlohmann::json& object, const std::string& joint)
      : fields_(object, joint), joint_(joint) {}

  JointLimit read() {
    const auto type = fields_.string("type");
    if (!type) fields_.error("type", "required: \"hinge\", \"ball\" or \"free\"");
    JointLimit limit = FreeJoint{};
    if (*type == "hinge") {
      limit = read_hinge();
    } else if (*type == "ball") {
      limit = read_ball();
    } else if (*type != "free") {
      fields_.error("type", "unknown joint type " + quote_input(*type) +
                                " (expected \"hinge\", \"ball\" or \"free\")");
    }
    fields_.finish();
    return limit;
  }

 private:
  HingeLimit read_hinge() {
    HingeLimit h;
    h.axis = axis("hinge");
    const double min = angle(required_number("min", "hinge"), "min", -180.0);
    const double max = angle(required_number("max", "hinge"), "max", -180.0);
    order(min, max, nullptr);
    h.min_angle = to_radians(min);
    h.max_angle = to_radians(max);
    return h;
  }

  BallLimit read_ball() {
    BallLimit b;
    b.twist_axis = axis("ball");
    read_swing(b);
    double min = -180.0, max = 180.0;
    if (const auto* twist = fields_.array("twist")) {
      if (twist->size() != 2 || !(*twist)[0].is_number() || !(*twist)[1].is_number()) {
        fields_.error("twist", "expected two numbers [min, max] in degrees");
      }
      min = angle((*twist)[0].get<double>(), "twist", -180.0);
      max = angle((*twist)[1].get<double>(), "twist", -180.0);
      order(min, max, "twist");
    }
    b.min_twist = to_radians(min);
    b.max_twist = to_radians(max);
    return b;
  }

  // "swing": 80 (a circular cone), or [60, 30] with "swing_axis" (an elliptical one: 60
  // degrees about swing_axis, 30 about axis x swing_axis).
  void read_swing(BallLimit& b) {
    const nlohmann::json* swing = fields_.object("swing");
    if (!swing) fields_.error("swing", "required for a ball joint");
    if (!swing->is_array()) {
      b.swing_angle = to_radians(angle(*fields_.number("swing"), "swing", 0.0));
      return;
    }
    if (swing->size() != 2 || !(*swing)[0].is_number() || !(*swing)[1].is_number()) {
      fields_.error("swing",
                    "expected a number or two numbers [about swing_axis, about the "
                    "third axis] in degrees");
    }
    b.swing_angle = to_radians(angle((*swing)[0].get<double>(), "swing", 0.0));
    b.swing_angle_2 = to_radians(angle((*swing)[1].get<double>(), "swing", 0.0));
    const auto swing_axis = fields_.vec3("swing_axis");
    if (!swing_axis) fields_.error("swing_axis", "required with two swing angles");
    if (swing_axis->norm() == 0.0) fields_.error("swing_axis", "must not be zero");
    b.swing_axis = swing_axis->normalized();
    const double cosine = b.swing_axis.dot(b.twist_axis);
    if (std::abs(cosine) > 1e-6) {
      fields_.error("swing_axis",
                    "must be perpendicular to axis (cosine " + format_number(cosine) + ")");
    }
  }

  Vec3 axis(const char* type) {
    const auto axis = fields_.vec3("axis");
    if (!axis) fields_.error("axis", std::string("required for a ") + type + " joint");
    if (axis->norm() == 0.0) fields_.error("axis", "must not be zero");
    return axis->normalized();
  }

  double required_number(const char* key, const char* type) {
    const auto value = fields_.number(key);
    if (!value) fields_.error(key, std::string("required for a ") + type + " joint");
    return *value;
  }

  // An angle in degrees within [lowest, 180].
  double angle(double degrees, const char* key, double lowest) {
    if (!std::isfinite(degrees)) fields_.error(key, "expected a finite number");
    if (degrees < lowest || degrees > 180.0) {
      fields_.error(
          key, format_number(degrees) + " degrees is outside [" + format_number(lowest) + ", 180]");
    }
    return degrees;
  }

  // min <= max, or an error on `key` ("twist"), or on the joint when null (hinge min, max).
  void order(double min, double max, const char* key) {
    if (min <= max) return;
    const std::string what =
        "min " + format_number(min) + " degrees is above max " + format_number(max) + " degrees";
    if (key) fields_.error(key, what);
    throw FieldError(joint_ + ": " + what);
  }

  JsonFields fields_;
  std::string joint_;
};

}  // namespace

Result<JointLimitSet> read_joint_limits(std::string_view text, std::string_view source_name) {
  const std::string prefix = std::string(source_name) + ": ";
  const HeldFloatingPointExceptions held;  // huge numbers parse to infinity, refused below
  auto parsed = parse_json_document(text, prefix);
  if (!parsed) return fail(parsed.error().message);
  const nlohmann::json& document = *parsed;
  if (!document.is_object()) {
    return fail(prefix + "expected an object keyed by joint name {\"LeftKnee\": {...}}");
  }
  JointLimitSet limits;
  try {
    for (const auto& [name, value] : document.items()) {
      if (name.empty()) throw FieldError("a joint name is empty");
      JointLimit limit = LimitReader(value, name).read();
      // The reader checked every range; validate() guards what it builds.
      if (auto error = validate(limit)) throw FieldError(name + ": " + error->message);
      limits.emplace(name, limit);
    }
  } catch (const FieldError& e) {
    return fail(prefix + e.what());
  }
  return limits;
}

Result<JointLimitSet> read_joint_limits_file(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxJointLimitsFileBytes);
  if (!bytes) return fail(bytes.error().message);
  return read_joint_limits(*bytes, path.string());
}

Result<std::vector<JointLimit>> bind_joint_limits(const JointLimitSet& limits,
                                                  std::span<const std::string> joint_names) {
  for (const auto& [name, limit] : limits) {
    if (std::find(joint_names.begin(), joint_names.end(), name) == joint_names.end()) {
      return fail("joint limits name the joint " + quote_input(name) +
                  ", which the skeleton does not have");
    }
  }
  std::vector<JointLimit> bound(joint_names.size(), FreeJoint{});
  for (std::size_t i = 0; i < joint_names.size(); ++i) {
    if (const auto it = limits.find(joint_names[i]); it != limits.end()) bound[i] = it->second;
  }
  return bound;
}

}  // namespace animkit
