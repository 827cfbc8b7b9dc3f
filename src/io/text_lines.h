#pragma once
// Line by line through a text file held in memory, for the line-based readers (CSV curves, OBJ
// meshes, BVH): each line with the "FILE line N" its messages start with, and a NUL byte
// refused rather than read as the end of the line (it would hide what follows it); and token
// by token through a line.
#include <optional>
#include <string>
#include <string_view>

#include "animkit/core/quote.h"
#include "animkit/core/result.h"

namespace animkit {

/// What separates tokens on a line (a '\r' of a CRLF line end included).
inline constexpr std::string_view kTokenSpaces = " \t\r\v\f";

/// The next whitespace-separated token of `line`, removed from it (empty at the end).
inline std::string_view next_token(std::string_view& line) {
  const auto first = line.find_first_not_of(kTokenSpaces);
  if (first == std::string_view::npos) {
    line = {};
    return {};
  }
  line.remove_prefix(first);
  const auto end = line.find_first_of(kTokenSpaces);
  const std::string_view token = line.substr(0, end);
  line.remove_prefix(end == std::string_view::npos ? line.size() : end);
  return token;
}

class TextLines {
 public:
  TextLines(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  /// The next line without its '\n', or nothing at the end of the text; an error naming the
  /// line when it holds a NUL byte.
  std::optional<Result<std::string_view>> next() {
    if (text_.empty()) return std::nullopt;
    const std::size_t newline = text_.find('\n');
    const std::string_view line = text_.substr(0, newline);
    text_.remove_prefix(newline == std::string_view::npos ? text_.size() : newline + 1);
    ++number_;
    where_ = file_ + " line " + std::to_string(number_);
    if (line.find('\0') != std::string_view::npos)
      return fail(where_ + ": holds a NUL byte (not a text file?): " + quote_input(line));
    return line;
  }

  /// "FILE line N" of the last line returned.
  const std::string& where() const { return where_; }
  /// N, 1-based, of the last line returned.
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::string file_;
  std::string where_;
  int number_ = 0;
};

}  // namespace animkit
