#pragma once
// Echoing user input in error messages without letting it take over the terminal or the
// message: control characters, terminal escapes and bytes that are not UTF-8 are shown as
// escapes, and long input is cut, so an error stays one readable line.
#include <cstddef>
#include <string>
#include <string_view>

namespace animkit {

/// How many characters of raw input an error message shows by default.
constexpr std::size_t kQuotedInputChars = 80;

/// `raw` between single quotes, safe to print: printable ASCII and well-formed UTF-8 as they
/// are; \n, \r, \t as those two-character escapes; other control bytes, DEL and bytes that are
/// not well-formed UTF-8 as \xNN. Input that would show as more than `max_chars` characters
/// (an escape counts as the characters it shows) is cut there and ends in "...' (N bytes)". E.g.
/// quote_input("a\x1b[2Jb") == "'a\\x1b[2Jb'".
std::string quote_input(std::string_view raw, std::size_t max_chars = kQuotedInputChars);

/// `raw` made safe the same way, without quotes: for whole messages that may carry input
/// (e.g. the CLI's last line of defence before printing any error).
std::string sanitize_message(std::string_view raw, std::size_t max_chars = 1000);

/// How many characters of a path an error message shows at most.
constexpr std::size_t kShownPathChars = 120;

/// A file's path made safe the same way, for an error message: one longer than `max_chars`
/// characters shows its start and its end (the file's name) around "...", e.g.
/// "/home/me/scenes/...long/drape.json".
std::string shown_path(std::string_view raw, std::size_t max_chars = kShownPathChars);

}  // namespace animkit
