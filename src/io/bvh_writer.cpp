// The BVH writer: the hierarchy depth first (the only order a BVH file can express), then the
// motion with its columns in that same order.
#include <algorithm>
#include <cassert>
#include <charconv>
#include <string>
#include <vector>

#include "animkit/io/atomic_write.h"
#include "animkit/io/bvh.h"

namespace animkit {

namespace {

// The shortest decimal that reads back as the same double (std::to_chars without a format).
void append_number(std::string& out, double value) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
  assert(ec == std::errc());
  out.append(text, end);
}

// Joints depth first, children in index order: the order a file lists them in.
std::vector<int> depth_first_order(const SkeletonDesc& skeleton) {
  const int n = skeleton.joint_count();
  std::vector<std::vector<int>> children(n);
  std::vector<int> stack;
  for (int j = n - 1; j >= 0; --j) {
    if (skeleton.parents[j] >= 0) {
      children[skeleton.parents[j]].push_back(j);  // reversed: popped in index order
    } else {
      stack.push_back(j);
    }
  }
  std::vector<int> order;
  order.reserve(n);
  while (!stack.empty()) {
    const int j = stack.back();
    stack.pop_back();
    order.push_back(j);
    stack.insert(stack.end(), children[j].begin(), children[j].end());
  }
  return order;
}

// One tab per level up to this depth: indentation is for people, and a long chain indented in
// full grows as the square of its depth (a 100,000-deep chain: gigabytes).
constexpr std::size_t kMaxIndent = 32;

}  // namespace

std::string write_bvh(const BvhClip& clip) {
  assert(!clip.validate());
  const SkeletonDesc& skeleton = clip.skeleton;
  const std::vector<int> order = depth_first_order(skeleton);
  std::string out = "HIERARCHY\n";
  std::vector<int> open;  // joints whose '}' is still to come
  const auto indent_of = [&open] { return std::min(open.size(), kMaxIndent); };
  auto close_until = [&](int parent) {
    while (!open.empty() && open.back() != parent) {
      open.pop_back();
      out.append(indent_of(), '\t');
      out += "}\n";
    }
  };
  for (const int j : order) {
    close_until(skeleton.parents[j]);
    const std::string indent(indent_of(), '\t');
    if (clip.end_sites[j]) {
      out += indent + "End Site\n";
    } else {
      out += indent + (skeleton.parents[j] < 0 ? "ROOT " : "JOINT ") + skeleton.names[j] + "\n";
    }
    out += indent + "{\n" + indent + "\tOFFSET";
    for (int axis = 0; axis < 3; ++axis) {
      out += ' ';
      append_number(out, skeleton.rest_offsets[j][axis]);
    }
    out += '\n';
    if (!clip.end_sites[j]) {
      out += indent + "\tCHANNELS " + std::to_string(clip.channels[j].size());
      for (BvhChannel c : clip.channels[j]) {
        out += ' ';
        out += bvh_channel_name(c);
      }
      out += '\n';
    }
    open.push_back(j);
  }
  close_until(-1);

  // Motion columns of each joint, so they can be written in file order.
  std::vector<int> first_column(skeleton.joint_count() + 1, 0);
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    first_column[j + 1] = first_column[j] + static_cast<int>(clip.channels[j].size());
  }
  out += "MOTION\nFrames: " + std::to_string(clip.frame_count()) + "\nFrame Time: ";
  append_number(out, clip.frame_time);
  out += '\n';
  for (int f = 0; f < clip.frame_count(); ++f) {
    bool first = true;
    for (const int j : order) {
      for (int c = first_column[j]; c < first_column[j + 1]; ++c) {
        if (!first) out += ' ';
        first = false;
        append_number(out, clip.motion(f, c));
      }
    }
    out += '\n';
  }
  return out;
}

Result<void> write_bvh_file(const std::filesystem::path& path, const BvhClip& clip) {
  if (auto error = clip.validate()) {
    return fail(path.string() + ": cannot write this clip: " + error->message);
  }
  return write_file_atomic(path, write_bvh(clip));
}

}  // namespace animkit
