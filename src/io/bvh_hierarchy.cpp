// The HIERARCHY part of a BVH file: its tokens parsed with an explicit stack of open joints
// (no recursion, so deep nesting cannot overflow the call stack).
#include <unordered_map>

#include "bvh_text.h"

namespace animkit::bvh_detail {

namespace {

class HierarchyReader {
 public:
  HierarchyReader(std::span<const Line> lines, const std::string& file, double scale, BvhClip& clip)
      : lines_(lines), name_(file), scale_(scale), clip_(clip) {}

  std::optional<Error> read(std::size_t& motion_line) {
    auto error = read_hierarchy();
    motion_line = motion_line_;
    if (!error) name_end_sites();
    return error;
  }

 private:
  Error at(int line, const std::string& message) const { return error_at(name_, line, message); }

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
      if (!open.empty() && clip_.end_sites[open.back().joint] && token.text != "}") {
        return at(token.line, "unexpected " + quote_input(token.text) + " in " + open.back().label +
                                  " (expected '}'; End Sites have no children)");
      }
      if (token.text == "ROOT" || token.text == "JOINT") {
        if (!open.empty() && token.text == "ROOT") {
          return at(token.line, "ROOT inside " + open.back().label + "; children are JOINTs");
        }
        if (pos == tokens_.size() || tokens_[pos].line != token.line) {
          return at(token.line, std::string(token.text) + " without a name");
        }
        const Token& name = tokens_[pos++];
        if (name.text.find_first_of(kNotInNames) != std::string_view::npos) {
          return at(name.line, "joint name " + quote_input(name.text) +
                                   " holds a brace or '#', which a BVH name cannot");
        }
        const auto [it, inserted] = name_lines.emplace(name.text, name.line);
        if (!inserted) {
          return at(name.line, "a second joint is named " + quote_input(name.text) +
                                   " (the first is on line " + std::to_string(it->second) + ")");
        }
        const std::string label = std::string(token.text) + " " + shown_name(name.text);
        if (auto error = open_joint(std::string(name.text), label, open, pos)) return error;
      } else if (token.text == "End") {
        if (pos == tokens_.size() || tokens_[pos].text != "Site") {
          return at(token.line, "expected 'Site' after End");
        }
        ++pos;
        const std::string label =
            "End Site of " + shown_name(clip_.skeleton.names[open.back().joint]);
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
      const bool raw_beyond = !kBvhValueRange.contains(value);  // as frame values are checked
      if (raw_beyond || !kBvhValueRange.contains(value * scale_)) {
        return at(t.line, "OFFSET of " + label + ": " + quote_input(t.text) + " is beyond " +
                              format_number(kBvhValueRange.max) +
                              (raw_beyond ? "" : " (times the scale)"));
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

  std::span<const Line> lines_;
  const std::string& name_;
  double scale_;
  BvhClip& clip_;
  std::vector<Token> tokens_;
  std::size_t motion_line_ = 0;
};

}  // namespace

std::optional<Error> read_bvh_hierarchy(std::span<const Line> lines, const std::string& file,
                                        double scale, BvhClip& clip, std::size_t& motion_line) {
  return HierarchyReader(lines, file, scale, clip).read(motion_line);
}

}  // namespace animkit::bvh_detail
