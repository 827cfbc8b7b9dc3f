// The BVH reader: lines (comments and blank lines dropped) -> the HIERARCHY
// (bvh_hierarchy.cpp) -> MOTION's header and one frame per line.
#include <cmath>
#include <string>
#include <vector>

#include "animkit/core/validation.h"
#include "animkit/io/bvh.h"
#include "animkit/io/file_bytes.h"
#include "bvh_text.h"
#include "held_fp_exceptions.h"

namespace animkit {

namespace {

using namespace bvh_detail;

class BvhReader {
 public:
  BvhReader(std::string_view name, double scale) : name_(name), scale_(scale) {}

  Result<BvhClip> read(std::string_view text) {
    if (auto error = split_lines(text)) return std::unexpected(*error);
    if (lines_.empty()) return fail(name_ + ": the file is empty");
    if (auto error = read_bvh_hierarchy(lines_, name_, scale_, clip_, motion_line_)) {
      return std::unexpected(*error);
    }
    if (auto error = read_motion()) return std::unexpected(*error);
    return std::move(clip_);
  }

 private:
  Error at(int line, const std::string& message) const { return error_at(name_, line, message); }

  std::optional<Error> split_lines(std::string_view text) {
    // A UTF-8 byte order mark (some Windows editors write one) is not part of the first line.
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
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
        // In range both in the file's units and scaled, so a clip written back in the file's
        // units (footlock, reach) stays in range too.
        const double scaled = is_position[count] ? value * scale_ : value;
        const bool raw_beyond = !kBvhValueRange.contains(value);
        if (raw_beyond || !kBvhValueRange.contains(scaled)) {
          return at(line.number, "frame " + std::to_string(f) + " value " + std::to_string(count) +
                                     " (" + channel_label(count) + ") " + quote_input(t) +
                                     " is beyond " + format_number(kBvhValueRange.max) +
                                     (raw_beyond ? "" : " (times the scale)"));
        }
        values.push_back(scaled);
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
        return std::string(bvh_channel_name(list[column])) + " of " +
               shown_name(clip_.skeleton.names[j]);
      }
      column -= static_cast<int>(list.size());
    }
    return "?";
  }

  std::string name_;
  double scale_;
  std::vector<Line> lines_;
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
