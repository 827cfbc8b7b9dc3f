// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// (a false positive in the compiler's own headers, see psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "animkit/kinematics/dls_tree.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include "animkit/io/bvh.h"
#include "animkit/kinematics/fabrik_tree.h"
#include "limit_samples.h"
#include "shared_constants.h"
#include "tree_ik_checks.h"

namespace animkit {
namespace {

using limit_samples::kPi;
using limit_samples::random_rotation;
using limit_samples::same_bits;
using limit_samples::uniform;

using testing_support::kWalk;

// A small humanoid in metres: pelvis root, spine, chest, two 3-bone arms, two 3-bone legs.
struct Rig {
  Skeleton skeleton;
  std::vector<JointLimit> limits;
  std::vector<int> effectors;  // hands and feet
};

Rig make_rig() {
  SkeletonDesc d;
  const int pelvis = d.add_joint("pelvis", -1, Vec3(0, 1, 0));
  const int spine = d.add_joint("spine", pelvis, Vec3(0, 0.2, 0));
  const int chest = d.add_joint("chest", spine, Vec3(0, 0.3, 0));
  std::vector<int> hands_feet;
  for (double side : {1.0, -1.0}) {
    const int shoulder =
        d.add_joint(side > 0 ? "l_shoulder" : "r_shoulder", chest, Vec3(side * 0.2, 0.1, 0));
    const int elbow =
        d.add_joint(side > 0 ? "l_elbow" : "r_elbow", shoulder, Vec3(side * 0.3, 0, 0));
    hands_feet.push_back(
        d.add_joint(side > 0 ? "l_hand" : "r_hand", elbow, Vec3(side * 0.25, 0, 0)));
    const int hip = d.add_joint(side > 0 ? "l_hip" : "r_hip", pelvis, Vec3(side * 0.1, -0.1, 0));
    const int knee = d.add_joint(side > 0 ? "l_knee" : "r_knee", hip, Vec3(0, -0.45, 0));
    hands_feet.push_back(d.add_joint(side > 0 ? "l_foot" : "r_foot", knee, Vec3(0, -0.4, 0)));
  }
  Rig rig{*build_skeleton(d), {}, hands_feet};
  for (int j = 0; j < rig.skeleton.joint_count(); ++j) {
    const std::string& name = rig.skeleton.names()[static_cast<std::size_t>(j)];
    const Vec3 bone =
        j + 1 < rig.skeleton.joint_count() && rig.skeleton.parents()[j + 1] == j
            ? rig.skeleton.rest_offsets()[static_cast<std::size_t>(j) + 1].normalized()
            : Vec3::UnitY();
    if (name.ends_with("elbow") || name.ends_with("knee")) {
      rig.limits.push_back(HingeLimit{Vec3::UnitZ(), -2.5, 0.0});
    } else if (name.ends_with("shoulder") || name.ends_with("hip") || name == "spine") {
      rig.limits.push_back(BallLimit{bone, name == "spine" ? 0.5 : 1.6, -0.7, 0.7});
    } else if (name == "chest") {
      rig.limits.push_back(HingeLimit{Vec3::UnitY(), -0.6, 0.6});
    } else {
      rig.limits.push_back(FreeJoint{});
    }
  }
  return rig;
}

// A random pose inside every limit (limited joints: a random rotation constrained).
SkeletonPose random_pose(const Rig& rig, std::mt19937_64& rng) {
  SkeletonPose pose = skeleton_rest_pose(rig.skeleton);
  for (int j = 0; j < rig.skeleton.joint_count(); ++j) {
    if (rig.skeleton.parents()[static_cast<std::size_t>(j)] < 0) continue;
    pose.local_rotations[static_cast<std::size_t>(j)] =
        constrain(rig.limits[static_cast<std::size_t>(j)], random_rotation(rng));
  }
  skeleton_forward_kinematics(rig.skeleton, pose);
  return pose;
}

std::vector<Effector> effectors_of(const std::vector<int>& joints, const SkeletonPose& goal,
                                   bool orientations) {
  std::vector<Effector> effectors;
  for (int j : joints) {
    Effector e{j, goal.global_positions[static_cast<std::size_t>(j)]};
    if (orientations) e.orientation = goal.global_rotations[static_cast<std::size_t>(j)];
    effectors.push_back(e);
  }
  return effectors;
}

double worst_violation(const Rig& rig, const SkeletonPose& pose) {
  double worst = 0.0;
  for (int j = 0; j < rig.skeleton.joint_count(); ++j) {
    worst = std::max(worst, violation(rig.limits[static_cast<std::size_t>(j)],
                                      relative_to_rest(rig.skeleton, pose, j)));
  }
  return worst;
}

double worst_bone_change(const Skeleton& skeleton, const SkeletonPose& pose) {
  double worst = 0.0;
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const int p = skeleton.parents()[static_cast<std::size_t>(j)];
    if (p < 0) continue;
    const double length = (pose.global_positions[static_cast<std::size_t>(j)] -
                           pose.global_positions[static_cast<std::size_t>(p)])
                              .norm();
    worst =
        std::max(worst, std::abs(length - skeleton.bone_lengths()[static_cast<std::size_t>(j)]));
  }
  return worst;
}

class DlsTree : public ::testing::TestWithParam<DlsMethod> {
 protected:
  DlsSettings settings() const { return DlsSettings{.method = GetParam()}; }
};

// The next goal of a motion: every limited joint turned by up to `angle` and constrained.
SkeletonPose next_goal(const Rig& rig, const SkeletonPose& goal, double angle,
                       std::mt19937_64& rng) {
  SkeletonPose next = goal;
  for (int j = 0; j < rig.skeleton.joint_count(); ++j) {
    const auto ju = static_cast<std::size_t>(j);
    if (rig.skeleton.parents()[ju] < 0) continue;
    const Quat turn(Eigen::AngleAxisd(uniform(rng, 0, angle), limit_samples::random_axis(rng)));
    next.local_rotations[ju] = constrain(rig.limits[ju], goal.local_rotations[ju] * turn);
  }
  skeleton_forward_kinematics(rig.skeleton, next);
  return next;
}

// Targets that move as a motion does (each set the FK of a pose inside the limits, each solve
// starting from the last solution): every set is reached.
TEST_P(DlsTree, TracksJointlyReachableTargetsWithinLimits) {
  const Rig rig = make_rig();
  std::mt19937_64 rng(12);
  DlsWorkspace ws;
  SkeletonPose goal = random_pose(rig, rng), pose = skeleton_rest_pose(rig.skeleton);
  int converged = 0;
  const int frames = 1000;
  for (int t = 0; t < frames; ++t) {
    goal = next_goal(rig, goal, 0.1, rng);
    const auto effectors = effectors_of(rig.effectors, goal, false);
    auto result = solve_dls_tree(rig.skeleton, {effectors, rig.limits}, settings(), ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    EXPECT_TRUE(result->reachable);
    EXPECT_LE(worst_violation(rig, pose), 1e-9);
    if (result->converged) {
      ++converged;
      EXPECT_LE(result->error, 1e-4);
    }
  }
  std::printf("converged on %d of %d moving reachable target sets\n", converged, frames);
  EXPECT_GE(converged, frames * 99 / 100);
}

// From rest to far goals in corners of the limits, a local method can stop in a local minimum
// of the limited problem; this records how often (the fraction is printed: 75% for DLS, 73% for
// SDLS when written, with the pelvis free to turn) and that a clear majority is still reached.
// Which local minimum a solve falls into depends on the last bits of its sums, so the fraction
// moves with the CPU's vector width (-march=native) and the optimisation level: SDLS reached 68%
// in a sanitizer build on another machine. The bound leaves room for that, not for a regression
// that loses a fifth of the targets.
TEST_P(DlsTree, ReachesMostFarReachableTargetsFromRest) {
  const Rig rig = make_rig();
  std::mt19937_64 rng(12);
  DlsWorkspace ws;
  int converged = 0;
  const int trials = 300;
  for (int t = 0; t < trials; ++t) {
    const SkeletonPose goal = random_pose(rig, rng);
    const auto effectors = effectors_of(rig.effectors, goal, false);
    SkeletonPose pose = skeleton_rest_pose(rig.skeleton);
    auto result = solve_dls_tree(rig.skeleton, {effectors, rig.limits}, settings(), ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    EXPECT_LE(worst_violation(rig, pose), 1e-9);
    converged += result->converged ? 1 : 0;
  }
  std::printf("converged on %d of %d far reachable target sets from rest\n", converged, trials);
  EXPECT_GE(converged, trials * 60 / 100);
}

// The same far targets through FABRIK with its DLS finish (fabrik_tree.h): the passes alone
// reach almost none of them on this rig (hinges about z, a chest hinge about y), but the pose
// they leave is a better start for DLS than the rest pose, so together they reach more than DLS
// from rest (75% there, 92% here when written; 88% in a clang build, whose contracted
// multiply-adds take other local minima, hence the bound).
TEST(FabrikWithDlsFinish, ReachesMoreFarReachableTargetsFromRestThanDls) {
  const Rig rig = make_rig();
  std::mt19937_64 rng(12);
  FabrikTreeWorkspace ws;
  int converged = 0, by_passes = 0;
  const int trials = 300;
  for (int t = 0; t < trials; ++t) {
    const SkeletonPose goal = random_pose(rig, rng);
    const auto effectors = effectors_of(rig.effectors, goal, false);
    SkeletonPose pose = skeleton_rest_pose(rig.skeleton);
    auto result = solve_fabrik_tree(rig.skeleton, {effectors, rig.limits}, {}, ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    EXPECT_LE(worst_violation(rig, pose), 1e-9);
    converged += result->converged ? 1 : 0;
    by_passes += result->converged && result->finish_iterations == 0 ? 1 : 0;
  }
  std::printf("converged on %d of %d far reachable target sets from rest, %d by the passes\n",
              converged, trials, by_passes);
  EXPECT_GE(converged, trials * 85 / 100);
}

// Roots turn like every joint (tree_ik.h); this rig's pelvis gets a limit with no range, which
// must keep it as it is (to rounding: 1e-12 rad).
TEST_P(DlsTree, LimitsHoldOnThousandsOfRandomTargetsAndRootsAndBonesStay) {
  Rig rig = make_rig();
  rig.limits[0] = BallLimit{Vec3::UnitY(), 0.0, 0.0, 0.0};
  std::mt19937_64 rng(7);
  DlsWorkspace ws;
  DlsSettings s = settings();
  s.max_iterations = 20;
  SkeletonPose pose = random_pose(rig, rng);
  const Quat root_rotation = pose.local_rotations[0];
  const Vec3 root_position = pose.global_positions[0];
  double worst = 0.0, bones = 0.0;
  for (int t = 0; t < 3000; ++t) {
    std::vector<Effector> effectors;
    for (int j : rig.effectors) {
      // Half the sets reachable or not, some far out of reach, weights varied.
      const Vec3 target(uniform(rng, -2, 2), uniform(rng, -1, 3), uniform(rng, -2, 2));
      effectors.push_back({j, target, std::nullopt, uniform(rng, 0.2, 3.0)});
    }
    if (t % 3 == 0) effectors[0].orientation = random_rotation(rng);
    auto result = solve_dls_tree(rig.skeleton, {effectors, rig.limits}, s, ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    ASSERT_TRUE(std::isfinite(result->error));
    worst = std::max(worst, worst_violation(rig, pose));
    bones = std::max(bones, worst_bone_change(rig.skeleton, pose));
    ASSERT_LE(pose.local_rotations[0].angularDistance(root_rotation), 1e-12);
    ASSERT_EQ(pose.global_positions[0], root_position);
  }
  EXPECT_LE(worst, 1e-9);
  EXPECT_LE(bones, 1e-12);
}

TEST_P(DlsTree, TracksOrientationTargets) {
  const Rig rig = make_rig();
  std::mt19937_64 rng(3);
  DlsWorkspace ws;
  SkeletonPose goal = random_pose(rig, rng), pose = skeleton_rest_pose(rig.skeleton);
  int converged = 0;
  const int frames = 300;
  for (int t = 0; t < frames; ++t) {
    goal = next_goal(rig, goal, 0.1, rng);
    auto effectors = effectors_of(rig.effectors, goal, false);
    effectors[0].orientation = goal.global_rotations[static_cast<std::size_t>(effectors[0].joint)];
    auto result = solve_dls_tree(rig.skeleton, {effectors, rig.limits}, settings(), ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    EXPECT_LE(worst_violation(rig, pose), 1e-9);
    if (result->converged) {
      ++converged;
      EXPECT_LE(pose.global_rotations[static_cast<std::size_t>(effectors[0].joint)].angularDistance(
                    *effectors[0].orientation),
                1e-4);
    }
  }
  std::printf("converged on %d of %d moving targets with a hand orientation\n", converged, frames);
  EXPECT_GE(converged, frames * 97 / 100);
}

TEST_P(DlsTree, SameBitsTwiceAndReusedWorkspaceEqualsFresh) {
  const Rig rig = make_rig();
  std::mt19937_64 rng(5);
  const SkeletonPose goal = random_pose(rig, rng);
  const auto effectors = effectors_of(rig.effectors, goal, true);
  const SkeletonPose start = random_pose(rig, rng);
  DlsWorkspace used;
  {
    // Leave the workspace sized for another problem, with stale contents.
    SkeletonPose other = start;
    const std::vector<Effector> one{{rig.effectors[1], Vec3(0.5, 1.5, 0.2)}};
    ASSERT_TRUE(solve_dls_tree(rig.skeleton, {one, rig.limits}, settings(), used, other));
  }
  std::array<SkeletonPose, 3> poses{start, start, start};
  DlsWorkspace fresh1, fresh2;
  DlsWorkspace* workspaces[] = {&fresh1, &fresh2, &used};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(solve_dls_tree(rig.skeleton, {effectors, rig.limits}, settings(), *workspaces[i],
                               poses[static_cast<std::size_t>(i)]));
  }
  for (int j = 0; j < rig.skeleton.joint_count(); ++j) {
    const auto ju = static_cast<std::size_t>(j);
    EXPECT_TRUE(same_bits(poses[0].local_rotations[ju], poses[1].local_rotations[ju]));
    EXPECT_TRUE(same_bits(poses[0].local_rotations[ju], poses[2].local_rotations[ju]));
    EXPECT_EQ(poses[0].global_positions[ju], poses[2].global_positions[ju]);
  }
}

TEST_P(DlsTree, InvalidProblemsAndSettingsReturnTheirErrorsAndLeaveThePose) {
  const Rig rig = make_rig();
  DlsWorkspace ws;
  SkeletonPose pose = skeleton_rest_pose(rig.skeleton);
  const SkeletonPose before = pose;
  const std::vector<Effector> on_root{{0, Vec3(0, 1, 0)}};
  auto result = solve_dls_tree(rig.skeleton, {on_root, rig.limits}, settings(), ws, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message,
            validate_tree_ik(rig.skeleton, {on_root, rig.limits}, pose)->message);
  EXPECT_EQ(result.error().message, "effector 0 is on the root pelvis, which IK never moves");
  const std::vector<Effector> ok{{rig.effectors[0], Vec3(0.5, 1.5, 0)}};
  DlsSettings bad = settings();
  bad.max_iterations = 0;
  result = solve_dls_tree(rig.skeleton, {ok, rig.limits}, bad, ws, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, "DLS max_iterations must be >= 1, got 0");
  bad = settings();
  bad.lambda = -1.0;
  EXPECT_EQ(bad.validate()->message, "DLS lambda must be finite and >= 0, got -1");
  for (int j = 0; j < rig.skeleton.joint_count(); ++j)
    EXPECT_TRUE(same_bits(pose.local_rotations[static_cast<std::size_t>(j)],
                          before.local_rotations[static_cast<std::size_t>(j)]));
}

// The CMU walk with four effectors (hands and feet), each frame's targets from its own FK, each
// solve starting from the previous frame's solution: every target set is jointly reachable.
TEST_P(DlsTree, FollowsTheCmuWalkWithHandsAndFeet) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " is absent";
  auto clip = read_bvh_file(kWalk, {.scale = 0.056444});
  ASSERT_TRUE(clip) << clip.error().message;
  auto skeleton = build_skeleton(clip->skeleton);
  ASSERT_TRUE(skeleton);
  std::vector<int> joints;
  for (const char* name : {"lhand", "rhand", "LeftAnkle", "RightAnkle"})
    joints.push_back(skeleton->find_joint(name));
  SkeletonPose goal = skeleton_rest_pose(*skeleton), pose = goal;
  DlsWorkspace ws;
  int converged = 0, frames = 0;
  for (int f = 0; f < clip->frame_count(); f += 4, ++frames) {
    bvh_frame_to_pose(*clip, f, goal);
    skeleton_forward_kinematics(*skeleton, goal);
    for (int r : skeleton->roots()) {  // roots start where the frame puts them (KDL's too)
      pose.local_rotations[static_cast<std::size_t>(r)] =
          goal.local_rotations[static_cast<std::size_t>(r)];
      pose.local_translations[static_cast<std::size_t>(r)] =
          goal.local_translations[static_cast<std::size_t>(r)];
    }
    const auto effectors = effectors_of(joints, goal, false);
    auto result = solve_dls_tree(*skeleton, {effectors}, settings(), ws, pose);
    ASSERT_TRUE(result) << result.error().message;
    converged += result->converged ? 1 : 0;
  }
  std::printf("converged on %d of %d CMU frames\n", converged, frames);
  EXPECT_EQ(converged, frames);
}

// The checks every tree solver passes (tree_ik_checks.h), DLS and SDLS with their default
// settings.
template <DlsMethod method>
struct Dls {
  using Settings = DlsSettings;
  struct Workspace : DlsWorkspace {
    void resize(const Skeleton&) {}  // sized by the first solve
  };
  static Result<TreeIkResult> solve(const Skeleton& s, const TreeIkProblem& problem,
                                    Settings settings, Workspace& workspace, SkeletonPose& pose) {
    settings.method = method;
    return solve_dls_tree(s, problem, settings, workspace, pose);
  }
};

template <class Solver>
void expect_tree_checks() {
  tree_checks::limits_bones_and_roots_hold<Solver>(1000, 12);
  tree_checks::deterministic_and_workspace_reuse_is_invisible<Solver>(7);
}

TEST(DlsTreeChecks, LimitsBonesRootsAndDeterminism) {
  expect_tree_checks<Dls<DlsMethod::damped>>();
  expect_tree_checks<Dls<DlsMethod::selective>>();
}

// The lab's arm turns its root joint to swing the first bone; DLS does too now that roots are
// degrees of freedom, so it reaches every target the chain's FABRIK reaches.
TEST(DlsTreeChecks, LabArmReachesTheChainSolversTargets) {
  tree_checks::lab_arm_reaches_the_chain_solvers_targets<Dls<DlsMethod::damped>>(
      IkSolverKind::fabrik);
  tree_checks::lab_arm_reaches_the_chain_solvers_targets<Dls<DlsMethod::selective>>(
      IkSolverKind::fabrik);
}

// Targets made by FK of random poses inside the limits (tree_ik_checks.h's five set-ups, hands
// and feet), solved from the rest pose: the fractions reached within tolerance.
TEST(DlsTreeChecksSlow, ReachesJointlyReachableTargetsOnAFigure) {
  const Skeleton s = tree_samples::figure();
  const auto joints = tree_samples::joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  const auto d = tree_checks::reach_fractions<Dls<DlsMethod::damped>>(s, joints, 200);
  const auto sd = tree_checks::reach_fractions<Dls<DlsMethod::selective>>(s, joints, 200);
  std::printf("DLS: %s\nSDLS: %s\n", tree_checks::describe(d).c_str(),
              tree_checks::describe(sd).c_str());
  for (const auto& f : {d, sd}) {
    EXPECT_GE(f.free, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.oriented, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.balls, 1.0) << tree_checks::describe(f);
  }
  EXPECT_GE(d.free_default, 1.0) << tree_checks::describe(d);
  EXPECT_GE(sd.free_default, 0.99) << tree_checks::describe(sd);
  // The misses: hinged elbows and knees from a straight rest, in a local minimum of the limited
  // problem (a local method's limit; FABRIK, whose DLS finish starts from its passes' pose,
  // reaches more). Which of them DLS misses moves with the arithmetic: 0.94 of them reached
  // where the thresholds were set, 0.93 (186 of 200) on a CPU whose -march=native code rounds
  // differently.
  EXPECT_GE(d.hinges, 0.92) << tree_checks::describe(d);
  EXPECT_GE(sd.hinges, 0.99) << tree_checks::describe(sd);
}

// Every jointly reachable target set, in all five set-ups (roots turn, tree_ik.h).
TEST(DlsTreeChecksSlow, ReachesJointlyReachableTargetsOnTheCmuSkeleton) {
  const auto s = tree_samples::cmu_skeleton();
  ASSERT_TRUE(s) << "no CMU data in " ANIMKIT_TEST_DATA_DIR;
  const auto joints = tree_samples::joints_named(*s, {"lhand", "rhand", "LeftAnkle", "RightAnkle"});
  const auto d = tree_checks::reach_fractions<Dls<DlsMethod::damped>>(*s, joints, 200);
  const auto sd = tree_checks::reach_fractions<Dls<DlsMethod::selective>>(*s, joints, 200);
  std::printf("DLS: %s\nSDLS: %s\n", tree_checks::describe(d).c_str(),
              tree_checks::describe(sd).c_str());
  for (const auto& f : {d, sd}) {
    EXPECT_GE(f.free_default, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.free, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.oriented, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.balls, 1.0) << tree_checks::describe(f);
    EXPECT_GE(f.hinges, 1.0) << tree_checks::describe(f);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, DlsTree,
                         ::testing::Values(DlsMethod::damped, DlsMethod::selective),
                         [](const auto& param_info) {
                           return std::string(param_info.param == DlsMethod::damped ? "Dls"
                                                                                    : "Sdls");
                         });

}  // namespace
}  // namespace animkit
