"""Skeletons, poses, forward kinematics and motion clips from Python."""
import math

import numpy as np
import pytest

import animkit


def arm():
    """Three joints in a line along +x, bones of 1 and 2."""
    return animkit.Skeleton(["root", "elbow", "hand"], [-1, 0, 1],
                            [[0, 0, 0], [1, 0, 0], [2, 0, 0]])


def quat_z(angle):
    return [math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)]


def test_skeleton_properties():
    s = arm()
    assert s.joint_count == 3 and len(s) == 3
    assert s.names == ["root", "elbow", "hand"]
    assert s.parents == [-1, 0, 1]
    np.testing.assert_array_equal(s.rest_offsets, [[0, 0, 0], [1, 0, 0], [2, 0, 0]])
    np.testing.assert_array_equal(s.rest_rotations, [[1, 0, 0, 0]] * 3)
    np.testing.assert_array_equal(s.bone_lengths, [0, 1, 2])
    assert s.leaves == [2] and s.roots == [0]
    assert s.children(0) == [1] and s.children(2) == []
    assert s.find_joint("elbow") == 1
    assert s.find_joint("nope") == -1
    assert repr(s) == "Skeleton(joint_count=3, roots=[0], leaves=[2])"


def test_tree_with_two_branches_and_rest_rotations():
    s = animkit.Skeleton(["hips", "left", "right"], [-1, 0, 0],
                         [[0, 1, 0], [0.2, 0, 0], [-0.2, 0, 0]],
                         rest_rotations=[quat_z(math.pi / 2), [1, 0, 0, 0], [1, 0, 0, 0]])
    assert s.leaves == [1, 2]
    assert s.children(0) == [1, 2]
    pose = s.rest_pose()
    # The root's rest rotation turns its children's offsets by 90 degrees about z.
    np.testing.assert_allclose(pose.global_positions, [[0, 1, 0], [0, 1.2, 0], [0, 0.8, 0]],
                               atol=1e-12)


@pytest.mark.parametrize("args, message", [
    (([], [], np.zeros((0, 3))), "at least 1 joint"),
    ((["a", "b"], [-1], [[0, 0, 0], [1, 0, 0]]), "parents has 1 entries"),
    ((["a", "a"], [-1, 0], [[0, 0, 0], [1, 0, 0]]), "is named 'a' like joint 0"),
    ((["a", "b"], [-1, 1], [[0, 0, 0], [1, 0, 0]]), "parent"),
    ((["a", "b"], [-1, 0], [[0, 0, 0], [math.nan, 0, 0]]), "non-finite"),
    ((["a", "b"], [-1, 0], [[0, 0, 0]]), "rest_offsets"),
    ((["a"], [-1], [[0, 0]]), "rest_offsets must be an array of shape (n, 3)"),
])
def test_bad_skeletons_raise_the_library_message(args, message):
    with pytest.raises(animkit.Error) as info:
        animkit.Skeleton(*args)
    assert message in str(info.value)


def test_bad_rest_rotation():
    with pytest.raises(animkit.Error, match="not a unit quaternion"):
        animkit.Skeleton(["a"], [-1], [[0, 0, 0]], rest_rotations=[[2, 0, 0, 0]])
    with pytest.raises(TypeError):
        animkit.Skeleton("ab", [-1, 0], [[0, 0, 0], [1, 0, 0]])


def test_forward_kinematics_by_hand():
    s = arm()
    pose = animkit.SkeletonPose(s)
    np.testing.assert_allclose(pose.global_positions, [[0, 0, 0], [1, 0, 0], [3, 0, 0]])
    rotations = pose.local_rotations
    rotations[0] = quat_z(math.pi / 2)
    rotations[1] = quat_z(-math.pi / 2)
    pose.local_rotations = rotations
    returned = animkit.forward_kinematics(s, pose)
    assert returned is pose
    np.testing.assert_allclose(pose.global_positions, [[0, 0, 0], [0, 1, 0], [2, 1, 0]],
                               atol=1e-12)
    np.testing.assert_allclose(pose.global_rotations[2], [1, 0, 0, 0], atol=1e-12)
    assert repr(pose) == "SkeletonPose(joint_count=3)"


def test_returned_arrays_are_copies():
    s = arm()
    pose = s.rest_pose()
    pose.global_positions[2] = [9, 9, 9]
    assert pose.global_positions[2][0] == 3
    copy = pose.copy()
    copy.local_translations = np.zeros((3, 3))
    assert pose.local_translations[1][0] == 1


def test_pose_setters_check_shapes_and_values():
    s = arm()
    pose = s.rest_pose()
    with pytest.raises(animkit.Error, match="must have 3 rows"):
        pose.local_rotations = np.tile([1.0, 0, 0, 0], (2, 1))
    with pytest.raises(animkit.Error, match=r"shape \(n, 4\)"):
        pose.local_rotations = np.zeros((3, 3))
    with pytest.raises(animkit.Error, match="row 1 is not a unit quaternion"):
        pose.local_rotations = [[1, 0, 0, 0], [0.5, 0, 0, 0], [1, 0, 0, 0]]
    with pytest.raises(animkit.Error, match="row 2 has a non-finite"):
        pose.local_translations = [[0, 0, 0], [1, 0, 0], [math.inf, 0, 0]]
    other = animkit.Skeleton(["a"], [-1], [[0, 0, 0]])
    with pytest.raises(animkit.Error, match="the pose has 3 joints but the skeleton 1"):
        animkit.forward_kinematics(other, pose)


def two_frame_motion():
    rotations = np.tile([1.0, 0, 0, 0], (2, 3, 1))
    rotations[1, 0] = quat_z(math.pi / 2)
    translations = np.array([[[0, 0, 0], [1, 0, 0], [2, 0, 0]]] * 2, dtype=float)
    translations[1, 0] = [0, 0, 5]
    return animkit.Motion(rotations, translations, frame_time=0.5)


def test_motion_properties_and_global_positions():
    s = arm()
    motion = two_frame_motion()
    assert (motion.frame_count, motion.joint_count, motion.frame_time) == (2, 3, 0.5)
    assert motion.local_rotations.shape == (2, 3, 4)
    assert motion.local_translations.shape == (2, 3, 3)
    positions = motion.global_positions(s)
    assert positions.shape == (2, 3, 3)
    np.testing.assert_allclose(positions[0], [[0, 0, 0], [1, 0, 0], [3, 0, 0]])
    np.testing.assert_allclose(positions[1], [[0, 0, 5], [0, 1, 5], [0, 3, 5]], atol=1e-12)
    pose = motion.pose(1, s)
    np.testing.assert_allclose(pose.global_positions, positions[1])
    np.testing.assert_allclose(motion.pose(-1).local_translations[0], [0, 0, 5])
    assert repr(motion) == "Motion(frame_count=2, joint_count=3, frame_time=0.5)"


def test_motion_default_frame_time_is_the_librarys():
    motion = animkit.Motion(np.tile([1.0, 0, 0, 0], (1, 1, 1)), np.zeros((1, 1, 3)))
    assert motion.frame_time == pytest.approx(1 / 30)


def test_bad_motions():
    r = np.tile([1.0, 0, 0, 0], (2, 3, 1))
    t = np.zeros((2, 3, 3))
    with pytest.raises(animkit.Error, match=r"shape \(frames, joints, 4\), got shape \(2, 3\)"):
        animkit.Motion(r[:, :, 0:3].reshape(2, 9)[:, :3], t)
    with pytest.raises(animkit.Error, match="2 frames of 3 joints but local_translations 1"):
        animkit.Motion(r, t[:1])
    with pytest.raises(animkit.Error, match="frame_time must be a number > 0"):
        animkit.Motion(r, t, frame_time=0)
    with pytest.raises(animkit.Error, match="frame_time"):
        animkit.Motion(r, t, frame_time=math.nan)
    bad = r.copy()
    bad[1, 2] = [0, 0, 0, 0]
    with pytest.raises(animkit.Error, match=r"local_rotations\[1, 2\] is not a unit quat"):
        animkit.Motion(bad, t)
    bad_t = t.copy()
    bad_t[0, 0, 0] = math.nan
    with pytest.raises(animkit.Error, match=r"local_translations\[0, 0\] has a non-finite"):
        animkit.Motion(r, bad_t)
    motion = animkit.Motion(r, t)
    with pytest.raises(animkit.Error, match="out of range"):
        motion.pose(2)
    with pytest.raises(animkit.Error, match="3 joints but the skeleton 1"):
        motion.global_positions(animkit.Skeleton(["a"], [-1], [[0, 0, 0]]))
    with pytest.raises(animkit.Error):
        motion.frame_time = -1.0


def test_global_positions_runs_in_threads(data_dir, run_watched):
    clip = animkit.read_bvh(data_dir / "cmu" / "131_01.bvh", scale=0.056444)
    skeleton, motion = clip.skeleton, clip.motion
    expected = motion.global_positions(skeleton)
    # A worker runs FK over the clip again and again while this thread does too on each of
    # its turns, which it gets only because global_positions lets go of the GIL (see
    # run_watched in conftest.py). Every result has the bits of one call alone.
    turns, in_worker, in_main = run_watched(
        lambda: [motion.global_positions(skeleton) for _ in range(30)],
        each_turn=lambda: motion.global_positions(skeleton))
    assert turns > 0, "this thread never ran while the worker was inside global_positions"
    for r in in_worker + in_main:
        np.testing.assert_array_equal(r, expected)
    # Frame 0 by FK of one pose equals the clip's.
    pose = motion.pose(0, skeleton)
    np.testing.assert_array_equal(pose.global_positions, expected[0])
