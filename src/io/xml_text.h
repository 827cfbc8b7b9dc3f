#pragma once
// Text made safe for SVG (XML) documents, shared by the SVG writers.
#include <string>
#include <string_view>

namespace animkit {

/// `raw` for XML character data and attribute values: the five markup characters as entities,
/// and what XML 1.0 forbids (control characters, bytes that are not UTF-8) as U+FFFD.
std::string xml_text(std::string_view raw);

}  // namespace animkit
