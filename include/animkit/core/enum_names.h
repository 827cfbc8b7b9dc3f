#pragma once
// Enumerations named by one fixed list of names in the enumeration's order, as scene files
// and Python spell them: the list is the only place the names live.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace animkit {

/// The enumerator called `name` in `names` (listed in the enumeration's order), or none.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> enum_named(const std::array<std::string_view, N>& names,
                                         std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<Enum>(i);
  return std::nullopt;
}

/// The name of `value` in `names` (listed in the enumeration's order).
template <class Enum, std::size_t N>
constexpr std::string_view enum_name(const std::array<std::string_view, N>& names, Enum value) {
  return names[static_cast<std::size_t>(value)];
}

/// The names joined as "a, b, c", for an error that says what was expected.
template <std::size_t N>
std::string joined_names(const std::array<std::string_view, N>& names) {
  std::string joined;
  for (const std::string_view name : names)
    joined += (joined.empty() ? "" : ", ") + std::string(name);
  return joined;
}

}  // namespace animkit
