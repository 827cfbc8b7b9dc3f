#include "json_fields.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "animkit/core/quote.h"

namespace animkit {

namespace {

// What a value is, for "expected a number, got a string".
std::string kind_of(const nlohmann::json& value) {
  if (value.is_string()) return "the string " + quote_input(value.get<std::string>());
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_null()) return "null";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  return "a number";
}

}  // namespace

JsonFields::JsonFields(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw FieldError((path_.empty() ? std::string("the scene") : path_) +
                     ": expected an object {...}, got " + kind_of(object_));
  }
}

std::string JsonFields::name(const char* key) const {
  return path_.empty() ? std::string(key) : path_ + "." + key;
}

void JsonFields::error(const char* key, const std::string& what) const {
  throw FieldError(name(key) + ": " + what);
}

bool JsonFields::has(const char* key) const {
  return object_.contains(key);
}

const nlohmann::json* JsonFields::at(const char* key) {
  asked_.insert(key);
  const auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

std::optional<double> JsonFields::number(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  if (!v->is_number()) error(key, "expected a number, got " + kind_of(*v));
  const double value = v->get<double>();
  if (!std::isfinite(value)) error(key, "expected a finite number");
  return value;
}

std::optional<int> JsonFields::integer(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  if (!v->is_number_integer()) error(key, "expected a whole number, got " + kind_of(*v));
  const auto value = v->get<long long>();
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    error(key, "whole number out of range");
  return static_cast<int>(value);
}

std::optional<bool> JsonFields::boolean(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) error(key, "expected true or false, got " + kind_of(*v));
  return v->get<bool>();
}

std::optional<std::string> JsonFields::string(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) error(key, "expected a string, got " + kind_of(*v));
  return v->get<std::string>();
}

std::optional<Vec3> JsonFields::vec3(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  if (!v->is_array() || v->size() != 3 ||
      !std::all_of(v->begin(), v->end(), [](const auto& e) { return e.is_number(); })) {
    error(key, "expected three numbers [x, y, z], got " + kind_of(*v));
  }
  const Vec3 value((*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>());
  if (!value.allFinite()) error(key, "expected finite numbers");
  return value;
}

std::optional<Quat> JsonFields::rotation(const char* key) {
  const nlohmann::json* v = at(key);
  if (!v) return std::nullopt;
  JsonFields fields(*v, name(key));
  const Vec3 axis = fields.vec3("axis").value_or(Vec3::UnitY());
  const double degrees = fields.number("degrees").value_or(0.0);
  fields.finish();
  if (axis.norm() == 0.0) error(key, "the rotation's axis must not be zero");
  return Quat(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()));
}

const nlohmann::json* JsonFields::object(const char* key) {
  return at(key);
}

const nlohmann::json* JsonFields::array(const char* key) {
  const nlohmann::json* v = at(key);
  if (v && !v->is_array()) error(key, "expected an array [...], got " + kind_of(*v));
  return v;
}

void JsonFields::finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (asked_.count(key) > 0) continue;
    std::string known;
    for (const std::string& k : asked_) known += (known.empty() ? "" : ", ") + k;
    throw FieldError((path_.empty() ? std::string("the scene") : path_) + ": unknown key " +
                     quote_input(key) +
                     (known.empty() ? std::string() : " (this object takes: " + known + ")"));
  }
}

std::string element_path(const std::string& array_path, std::size_t index) {
  return array_path + "[" + std::to_string(index) + "]";
}

namespace {

// A key met twice in one object: RFC 8259 leaves the meaning open and nlohmann keeps the last,
// so {"frames": 3, "frames": 1000000} would quietly run a million frames.
struct DuplicateKey {
  std::string key;
};

}  // namespace

Result<nlohmann::json> parse_json_document(std::string_view text, const std::string& prefix) {
  std::vector<std::set<std::string>> open_objects;  // the keys seen in each enclosing object
  const nlohmann::json::parser_callback_t refuse_duplicates =
      [&open_objects](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (event == Event::object_start) {
          open_objects.emplace_back();
        } else if (event == Event::object_end) {
          open_objects.pop_back();
        } else if (event == Event::key && !open_objects.empty()) {
          std::string key = parsed.get<std::string>();
          if (!open_objects.back().insert(key).second) throw DuplicateKey{std::move(key)};
        }
        return true;
      };
  try {
    return nlohmann::json::parse(text, refuse_duplicates);
  } catch (const nlohmann::json::exception& e) {  // syntax, or a number beyond a double
    return fail(prefix + "not valid JSON (" + sanitize_message(e.what(), 300) + ")");
  } catch (const DuplicateKey& duplicate) {
    return fail(prefix + "the key " + quote_input(duplicate.key) +
                " appears twice in one object (which one was meant?)");
  }
}

}  // namespace animkit
