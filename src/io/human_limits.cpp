#include "animkit/io/human_limits.h"

#include "animkit/io/joint_limits_file.h"

namespace animkit {

std::string_view cmu_human_limits_json() {
  // Kept byte for byte equal to data/limits/cmu_human.json (tests/cli/reach_cli_test.cpp).
  return R"json({
  "lowerback": {"type": "ball", "axis": [0, 1, 0], "swing": 30, "twist": [-30, 30]},
  "Chest": {"type": "ball", "axis": [0, 1, 0], "swing": 25, "twist": [-25, 25]},
  "Chest2": {"type": "ball", "axis": [0, 1, 0], "swing": 20, "twist": [-20, 20]},
  "LeftCollar": {"type": "ball", "axis": [0.901, 0.434, 0], "swing": 30, "twist": [-30, 30]},
  "LeftShoulder": {"type": "ball", "axis": [0, -1, 0], "swing": 160, "twist": [-90, 90]},
  "LeftElbow": {"type": "hinge", "axis": [1, 0, 0], "min": -150, "max": 0},
  "LeftWrist": {"type": "ball", "axis": [0, -1, 0], "swing": 80, "twist": [-90, 90]},
  "RightCollar": {"type": "ball", "axis": [-0.905, 0.42, -0.072], "swing": 30, "twist": [-30, 30]},
  "RightShoulder": {"type": "ball", "axis": [0, -1, 0], "swing": 160, "twist": [-90, 90]},
  "RightElbow": {"type": "hinge", "axis": [1, 0, 0], "min": -150, "max": 0},
  "RightWrist": {"type": "ball", "axis": [0, -1, 0], "swing": 80, "twist": [-90, 90]}
}
)json";
}

Result<std::vector<JointLimit>> cmu_human_limits(std::span<const std::string> joint_names,
                                                 int* limited) {
  auto set = read_joint_limits(cmu_human_limits_json(), "default human limits");
  if (!set) return fail(set.error().message);
  JointLimitSet present;
  for (const std::string& name : joint_names) {
    if (auto it = set->find(name); it != set->end()) present.insert(*it);
  }
  if (limited) *limited = static_cast<int>(present.size());
  return bind_joint_limits(present, joint_names);
}

}  // namespace animkit
