#pragma once
// Reading a JSON object field by field with errors that name the field by its path
// ("colliders[1].radius: expected a number, got \"big\"") and refuse keys nobody read (a typo
// must not be silently ignored). Errors are thrown as FieldError inside one parse and turned
// into a Result at its boundary (see cloth_scene_file.cpp), so readers stay linear.
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

struct FieldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class JsonFields {
 public:
  /// `path` names the object in errors ("" for the document, "cloth", "colliders[2]").
  JsonFields(const nlohmann::json& object, std::string path);

  bool has(const char* key) const;
  /// The value at `key`, typed; nothing when the key is absent. Wrong types and non-finite or
  /// out-of-range numbers throw FieldError.
  std::optional<double> number(const char* key);
  std::optional<int> integer(const char* key);
  std::optional<bool> boolean(const char* key);
  std::optional<std::string> string(const char* key);
  std::optional<Vec3> vec3(const char* key);
  /// {"axis": [x, y, z], "degrees": d}: a rotation by d degrees about the axis (non-zero).
  std::optional<Quat> rotation(const char* key);
  /// An object at `key` (to read with its own JsonFields), or an array; marks the key read.
  const nlohmann::json* object(const char* key);
  const nlohmann::json* array(const char* key);

  /// Throws for the first key no reader asked for, naming the keys the readers asked for.
  void finish() const;
  /// "cloth.grid" for key "grid" in "cloth".
  std::string name(const char* key) const;
  [[noreturn]] void error(const char* key, const std::string& what) const;

 private:
  const nlohmann::json* at(const char* key);
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> asked_;  // every key a reader asked for, present or not
};

/// The JSON document in `text`, or an error starting with `prefix` ("scene.json: ") that says
/// it is not valid JSON and why (the parser's message, cut to 300 characters). Callers hold
/// HeldFloatingPointExceptions around the parse and their reading: a number beyond a double
/// parses to infinity, which their readers refuse.
Result<nlohmann::json> parse_json_document(std::string_view text, const std::string& prefix);

/// The element path "colliders[2]".
std::string element_path(const std::string& array_path, std::size_t index);

}  // namespace animkit
