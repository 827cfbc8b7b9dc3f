// The BVH reader: lines (comments and blank lines dropped) -> the HIERARCHY's tokens parsed
// with an explicit stack (no recursion, so deep nesting cannot overflow the call stack) ->
// MOTION's header and one frame per line.
#include <charconv>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/bvh.h"
#include "animkit/io/file_bytes.h"
#include "held_fp_exceptions.h"

namespace animkit {

namespace {

constexpr std::string_view kSpaces = " \t\r\v\f";

struct Line {
  std::string_view text;
  int number;  // 1-based
};

struct Token {
  std::string_view text;
  int line;
};

// The next whitespace-separated token of `line`, removed from it (empty at the end).
std::string_view next_token(std::string_view& line) {
  const auto first = line.find_first_not_of(kSpaces);
  if (first == std::string_view::npos) {
    line = {};
    return {};
  }
  line.remove_prefix(first);
  const auto end = line.find_first_of(kSpaces);
  const std::string_view token = line.substr(0, end);
  line.remove_prefix(end == std::string_view::npos ? line.size() : end);
  return token;
}

enum class Number { ok, malformed, not_finite };

// All of `token` as a decimal number ("1e-3", "+2", ".5", "nan" and "inf" read as not finite).
Number parse_number(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ptr != end || token.empty()) return Number::malformed;
  if (ec == std::errc::result_out_of_range || !std::isfinite(value)) return Number::not_finite;
  return ec == std::errc() ? Number::ok : Number::malformed;
}

bool parse_count(std::string_view token, long max, long& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return !token.empty() && ptr == end && ec == std::errc() && value >= 0 && value <= max;
}

bool parse_channel(std::string_view token, BvhChannel& channel) {
  for (int c = 0; c < 6; ++c) {
    if (token == bvh_channel_name(static_cast<BvhChannel>(c))) {
      channel = static_cast<BvhChannel>(c);
      return true;
    }
  }
  return false;
}

class BvhReader {
 public:
  BvhReader(std::string_view name, double scale) : name_(name), scale_(scale) {}

  Result<BvhClip> read(std::string_view text) {
    if (auto error = split_lines(text)) return std::unexpected(*error);
    if (lines_.empty()) return fail(name_ + ": the file is empty");
    if (auto error = read_hierarchy()) return std::unexpected(*error);
    if (auto error = read_motion()) return std::unexpected(*error);
    name_end_sites();
    return std::move(clip_);
  }

 private:
  Error at(int line, const std::string& message) const {
    return Error{name_ + ": line " + std::to_string(line) + ": " + message};
  }

  std::optional<Error> split_lines(std::string_view text) {
    int number = 0;
    while (!text.empty()) {
      const std::size_t newline = text.find('\n');
      const std::string_view line = text.substr(0, newline);
      text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
      ++number;
      if (line.find('\0') != std::string_view::npos) {
        return at(number, "holds a NUL byte (not a text file?)");
      }
      const auto first = line.find_first_not_of(kSpaces);
      if (first == std::string_view::npos || line[first] == '#') continue;
      lines_.push_back({line, number});
    }
    return std::nullopt;
  }

  // Tokens of the lines before MOTION; motion_line_ is the index of the MOTION line in lines_
  // (lines_.size() if there is none).
  void tokenize_hierarchy() {
    motion_line_ = lines_.size();
    for (std::size_t l = 0; l < lines_.size(); ++l) {
      std::string_view rest = lines_[l].text;
      std::string_view first = next_token(rest);
      if (first == "MOTION") {
        motion_line_ = l;
        return;
      }
      for (std::string_view t = first; !t.empty(); t = next_token(rest)) {
        tokens_.push_back({t, lines_[l].number});
      }
    }
  }

  struct Open {
    int joint;
    int line;
    std::string label;  // "JOINT LeftKnee", "End Site of LeftToe"
  };

  std::optional<Error> read_hierarchy() {
    tokenize_hierarchy();
    std::size_t pos = 0;
    auto ends_early = [&](const std::vector<Open>& open) -> Error {
      const std::string missing = open.empty()
                                      ? "ROOT"
                                      : "'}' to close " + open.back().label + " (opened on line " +
                                            std::to_string(open.back().line) + ")";
      if (motion_line_ < lines_.size()) {
        return at(lines_[motion_line_].number, "MOTION comes before the expected " + missing);
      }
      return at(lines_.back().number, "the file ends before the expected " + missing);
    };
    if (tokens_.empty() || tokens_[0].text != "HIERARCHY") {
      const int line = tokens_.empty() ? lines_[0].number : tokens_[0].line;
      return at(line, "expected HIERARCHY, got " +
                          quote_input(tokens_.empty() ? "MOTION" : tokens_[0].text));
    }
    ++pos;
    std::vector<Open> open;
    std::unordered_map<std::string_view, int> name_lines;
    do {
      if (pos == tokens_.size()) return ends_early(open);
      const Token& token = tokens_[pos++];
      if (open.empty()) {
        if (token.text != "ROOT") {
          return at(token.line, std::string(clip_.joint_count() == 0 ? "expected ROOT"
                                                                     : "expected ROOT or MOTION") +
                                    ", got " + quote_input(token.text));
        }
      }
      if (token.text == "ROOT" || token.text == "JOINT") {
        if (!open.empty() && token.text == "ROOT") {
          return at(token.line, "ROOT inside " + open.back().label + "; children are JOINTs");
        }
        if (pos == tokens_.size() || tokens_[pos].line != token.line) {
          return at(token.line, std::string(token.text) + " without a name");
        }
        const Token& name = tokens_[pos++];
        const auto [it, inserted] = name_lines.emplace(name.text, name.line);
        if (!inserted) {
          return at(name.line, "a second joint is named " + quote_input(name.text) +
                                   " (the first is on line " + std::to_string(it->second) + ")");
        }
        const std::string label = std::string(token.text) + " " + std::string(name.text);
        if (auto error = open_joint(std::string(name.text), label, open, pos)) return error;
      } else if (token.text == "End") {
        if (pos == tokens_.size() || tokens_[pos].text != "Site") {
          return at(token.line, "expected 'Site' after End");
        }
        ++pos;
        const std::string label = "End Site of " + clip_.skeleton.names[open.back().joint];
        if (auto error = open_joint("", label, open, pos)) return error;
        clip_.end_sites.back() = true;
      } else if (token.text == "}") {
        open.pop_back();
      } else {
        return at(token.line, "unexpected " + quote_input(token.text) + " in " + open.back().label +
                                  " (expected JOINT, End Site or '}')");
      }
    } while (!open.empty() || pos < tokens_.size());
    if (motion_line_ == lines_.size()) {
      return at(lines_.back().number, "the file ends before MOTION");
    }
    return std::nullopt;
  }

  // After "JOINT name": '{', OFFSET x y z, then (not for End Sites) CHANNELS n names...
  std::optional<Error> open_joint(std::string name, const std::string& label,
                                  std::vector<Open>& open, std::size_t& pos) {
    const int line = tokens_[pos - 1].line;
    if (pos == tokens_.size() || tokens_[pos].text != "{") {
      return at(
          pos == tokens_.size() ? line : tokens_[pos].line,
          "expected '{' after " + label +
              (pos == tokens_.size() ? std::string() : ", got " + quote_input(tokens_[pos].text)));
    }
    ++pos;
    const int parent = open.empty() ? -1 : open.back().joint;
    const int joint = clip_.skeleton.add_joint(std::move(name), parent, Vec3::Zero());
    clip_.channels.emplace_back();
    clip_.end_sites.push_back(false);
    open.push_back({joint, line, label});
    if (pos == tokens_.size() || tokens_[pos].text != "OFFSET") {
      return at(
          pos == tokens_.size() ? line : tokens_[pos].line,
          "expected OFFSET in " + label +
              (pos == tokens_.size() ? std::string() : ", got " + quote_input(tokens_[pos].text)));
    }
    const int offset_line = tokens_[pos++].line;
    for (int axis = 0; axis < 3; ++axis) {
      double value = 0.0;
      if (pos == tokens_.size() || tokens_[pos].line != offset_line) {
        return at(offset_line,
                  "OFFSET of " + label + " needs 3 numbers, got " + std::to_string(axis));
      }
      const Token& t = tokens_[pos++];
      const Number parsed = parse_number(t.text, value);
      if (parsed != Number::ok) {
        return at(t.line, "OFFSET of " + label + ": " + quote_input(t.text) +
                              (parsed == Number::malformed ? " is not a number"
                                                           : " is not a finite number"));
      }
      clip_.skeleton.rest_offsets[joint][axis] = value * scale_;
    }
    if (pos < tokens_.size() && tokens_[pos].line == offset_line) {
      return at(offset_line, "OFFSET of " + label + " has more than 3 numbers");
    }
    if (label.starts_with("End Site")) return std::nullopt;
    if (pos == tokens_.size() || tokens_[pos].text != "CHANNELS") {
      return at(
          pos == tokens_.size() ? offset_line : tokens_[pos].line,
          "expected CHANNELS in " + label +
              (pos == tokens_.size() ? std::string() : ", got " + quote_input(tokens_[pos].text)));
    }
    return read_channels(joint, label, pos);
  }

  std::optional<Error> read_channels(int joint, const std::string& label, std::size_t& pos) {
    const int line = tokens_[pos++].line;
    long count = 0;
    if (pos == tokens_.size() || tokens_[pos].line != line ||
        !parse_count(tokens_[pos].text, 6, count)) {
      return at(line, "CHANNELS of " + label + " needs a count from 0 to 6" +
                          (pos < tokens_.size() && tokens_[pos].line == line
                               ? ", got " + quote_input(tokens_[pos].text)
                               : std::string()));
    }
    ++pos;
    std::size_t end = pos;
    while (end < tokens_.size() && tokens_[end].line == line) ++end;
    if (static_cast<long>(end - pos) != count) {
      return at(line, "CHANNELS of " + label + " says " + std::to_string(count) + " but lists " +
                          std::to_string(end - pos));
    }
    for (; pos < end; ++pos) {
      BvhChannel channel{};
      if (!parse_channel(tokens_[pos].text, channel)) {
        return at(line, "unknown channel " + quote_input(tokens_[pos].text) + " in " + label +
                            " (expected Xposition, Yposition, Zposition, Xrotation, Yrotation "
                            "or Zrotation)");
      }
      auto& list = clip_.channels[joint];
      for (BvhChannel c : list) {
        if (c == channel) {
          return at(line, label + " lists " + std::string(bvh_channel_name(c)) + " twice");
        }
      }
      list.push_back(channel);
    }
    return std::nullopt;
  }

  // "Frames: N", "Frame Time: t", then one line of channel values per frame.
  std::optional<Error> read_motion() {
    std::size_t l = motion_line_;
    {
      std::string_view rest = lines_[l].text;
      next_token(rest);
      if (!next_token(rest).empty()) return at(lines_[l].number, "MOTION is followed by more text");
    }
    ++l;
    long frames = 0;
    if (l == lines_.size()) {
      return at(lines_[l - 1].number, "the file ends after MOTION; expected 'Frames: <count>'");
    }
    const int frames_line = lines_[l].number;
    {
      std::string_view rest = lines_[l].text;
      const std::string_view key = next_token(rest);
      const std::string_view value = next_token(rest);
      if (key != "Frames:" || !parse_count(value, 1L << 30, frames) || !next_token(rest).empty()) {
        return at(frames_line, "expected 'Frames: <count>', got " + quote_input(lines_[l].text));
      }
    }
    ++l;
    if (l == lines_.size()) {
      return at(frames_line, "the file ends after Frames:; expected 'Frame Time: <seconds>'");
    }
    {
      std::string_view rest = lines_[l].text;
      const std::string_view frame = next_token(rest);
      const std::string_view time = next_token(rest);
      const std::string_view value = next_token(rest);
      double seconds = 0.0;
      if (frame != "Frame" || time != "Time:" || value.empty() || !next_token(rest).empty()) {
        return at(lines_[l].number,
                  "expected 'Frame Time: <seconds>', got " + quote_input(lines_[l].text));
      }
      if (parse_number(value, seconds) != Number::ok || seconds <= 0.0) {
        return at(lines_[l].number,
                  "Frame Time must be a finite number of seconds > 0, got " + quote_input(value));
      }
      clip_.frame_time = seconds;
    }
    ++l;
    const std::size_t found = lines_.size() - l;
    const int channels = clip_.channel_count();
    if (found != static_cast<std::size_t>(frames)) {
      // Each line's own problems first: a short line explains a count better than the count.
      if (auto error = read_frames(l, std::min<std::size_t>(found, frames), channels)) return error;
      return at(frames_line, "Frames: says " + std::to_string(frames) + " but " +
                                 std::to_string(found) + " motion lines follow");
    }
    return read_frames(l, found, channels);
  }

  std::optional<Error> read_frames(std::size_t first, std::size_t frames, int channels) {
    std::vector<double> values;
    values.reserve(frames * channels);
    std::vector<bool> is_position;
    for (const auto& list : clip_.channels) {
      for (BvhChannel c : list) is_position.push_back(static_cast<int>(c) < 3);
    }
    for (std::size_t f = 0; f < frames; ++f) {
      const Line& line = lines_[first + f];
      std::string_view rest = line.text;
      int count = 0;
      for (std::string_view t = next_token(rest); !t.empty(); t = next_token(rest), ++count) {
        double value = 0.0;
        if (count >= channels) continue;  // counted for the message below
        const Number parsed = parse_number(t, value);
        if (parsed != Number::ok) {
          return at(line.number, "frame " + std::to_string(f) + " value " + std::to_string(count) +
                                     " (" + channel_label(count) + ") " + quote_input(t) +
                                     (parsed == Number::malformed ? " is not a number"
                                                                  : " is not a finite number"));
        }
        values.push_back(is_position[count] ? value * scale_ : value);
      }
      if (count != channels) {
        return at(line.number, "frame " + std::to_string(f) + " has " + std::to_string(count) +
                                   " values, the hierarchy declares " + std::to_string(channels) +
                                   " channels");
      }
    }
    clip_.motion =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            values.data(), static_cast<Eigen::Index>(frames), channels);
    return std::nullopt;
  }

  // "Zrotation of Hips" for motion column `column`.
  std::string channel_label(int column) const {
    for (int j = 0; j < clip_.joint_count(); ++j) {
      const auto& list = clip_.channels[j];
      if (column < static_cast<int>(list.size())) {
        return std::string(bvh_channel_name(list[column])) + " of " + clip_.skeleton.names[j];
      }
      column -= static_cast<int>(list.size());
    }
    return "?";
  }

  // End Sites have no name in a file: "<parent>_End", numbered if a joint already has it.
  void name_end_sites() {
    std::unordered_map<std::string, int> taken;
    for (const std::string& n : clip_.skeleton.names) {
      if (!n.empty()) taken.emplace(n, 0);
    }
    for (int j = 0; j < clip_.joint_count(); ++j) {
      if (!clip_.end_sites[j]) continue;
      const std::string base = clip_.skeleton.names[clip_.skeleton.parents[j]] + "_End";
      std::string name = base;
      for (int k = 2; taken.contains(name); ++k) name = base + std::to_string(k);
      taken.emplace(name, 0);
      clip_.skeleton.names[j] = name;
    }
  }

  std::string name_;
  double scale_;
  std::vector<Line> lines_;
  std::vector<Token> tokens_;
  std::size_t motion_line_ = 0;
  BvhClip clip_;
};

}  // namespace

Result<BvhClip> read_bvh(std::string_view text, std::string_view name,
                         const BvhReadOptions& options) {
  const std::string file(name);
  if (!(std::isfinite(options.scale) && options.scale > 0.0)) {
    return fail(file + ": the scale must be a finite number > 0, got " +
                format_number(options.scale));
  }
  const HeldFloatingPointExceptions held;
  return BvhReader(file, options.scale).read(text);
}

Result<BvhClip> read_bvh_file(const std::filesystem::path& path, const BvhReadOptions& options) {
  auto bytes = read_file_bytes(path, kMaxBvhFileBytes);
  if (!bytes) return std::unexpected(bytes.error());
  return read_bvh(*bytes, path.string(), options);
}

}  // namespace animkit
