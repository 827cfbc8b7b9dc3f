"""BVH files from Python: reading, the clip's skeleton and motion, writing and round trips."""
import math

import numpy as np
import pytest

import animkit

SMALL = """HIERARCHY
ROOT Hips
{
\tOFFSET 0 0 0
\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
\tJOINT Chest
\t{
\t\tOFFSET 0 2 0
\t\tCHANNELS 3 Zrotation Xrotation Yrotation
\t\tEnd Site
\t\t{
\t\t\tOFFSET 0 1 0
\t\t}
\t}
}
MOTION
Frames: 2
Frame Time: 0.04
0 1 0 0 0 0 0 0 0
1 1 0 90 0 0 0 0 0
"""


@pytest.fixture(scope="module")
def walk_path(data_dir):
    return data_dir / "cmu" / "131_01.bvh"


@pytest.fixture(scope="module")
def walk(walk_path):
    return animkit.read_bvh(walk_path)


def test_parse_small_clip():
    clip = animkit.parse_bvh(SMALL)
    assert clip.joint_count == 3 and clip.frame_count == 2
    assert clip.frame_time == 0.04
    assert clip.names == ["Hips", "Chest", "Chest_End"]
    assert clip.channels == [
        ["Xposition", "Yposition", "Zposition", "Zrotation", "Xrotation", "Yrotation"],
        ["Zrotation", "Xrotation", "Yrotation"], []]
    assert clip.end_sites == [False, False, True]
    assert clip.channel_count == 9
    assert clip.values.shape == (2, 9)
    assert repr(clip) == "BvhClip(joint_count=3, frame_count=2, frame_time=0.04)"
    positions = clip.motion.global_positions(clip.skeleton)
    np.testing.assert_allclose(positions[0], [[0, 1, 0], [0, 3, 0], [0, 4, 0]], atol=1e-12)
    # Frame 1: the root moved to x = 1 and turned 90 degrees about z: +y goes to -x.
    np.testing.assert_allclose(positions[1], [[1, 1, 0], [-1, 1, 0], [-2, 1, 0]], atol=1e-12)


def test_scale_multiplies_offsets_and_positions():
    clip = animkit.parse_bvh(SMALL, scale=0.5)
    np.testing.assert_allclose(clip.skeleton.rest_offsets[1], [0, 1, 0])
    np.testing.assert_allclose(clip.values[1, :3], [0.5, 0.5, 0])
    back = clip.scaled(2.0)
    np.testing.assert_allclose(back.values, animkit.parse_bvh(SMALL).values)
    with pytest.raises(animkit.Error, match="scale factor must be a finite number > 0"):
        clip.scaled(0.0)
    # A factor that would make positions infinite is refused, not returned as inf.
    with pytest.raises(animkit.Error, match="scaling by 1e\\+308 puts a value beyond"):
        clip.scaled(1e308)
    with pytest.raises(animkit.Error, match="scale"):
        animkit.parse_bvh(SMALL, scale=-1.0)


def test_cmu_walk(walk):
    assert walk.frame_count == 994
    assert walk.frame_time == pytest.approx(0.0083333)
    assert walk.names[0] == "Hips"
    for name in ["LeftHip", "LeftKnee", "LeftAnkle", "RightHip", "RightKnee", "RightAnkle"]:
        assert walk.skeleton.find_joint(name) >= 0
    motion = walk.motion
    assert (motion.frame_count, motion.joint_count) == (994, walk.joint_count)
    assert motion.frame_time == walk.frame_time
    positions = motion.global_positions(walk.skeleton)
    assert positions.shape == (994, walk.joint_count, 3)
    assert np.isfinite(positions).all()


def test_round_trip_of_the_walk(walk, tmp_path):
    path = tmp_path / "walk.bvh"
    animkit.write_bvh(path, walk)
    again = animkit.read_bvh(path)
    assert again.names == walk.names and again.channels == walk.channels
    assert again.end_sites == walk.end_sites
    assert again.frame_time == walk.frame_time
    np.testing.assert_allclose(again.values, walk.values, rtol=0, atol=1e-9)
    np.testing.assert_allclose(again.skeleton.rest_offsets, walk.skeleton.rest_offsets,
                               rtol=0, atol=1e-9)
    assert path.read_text() == walk.to_text()
    assert not list(tmp_path.glob("*.tmp"))


def test_with_motion_round_trips_the_poses(walk):
    motion = walk.motion
    rebuilt = walk.with_motion(motion)
    # Euler angles written back from the quaternions give the same values (to rounding).
    np.testing.assert_allclose(rebuilt.values, walk.values, rtol=0, atol=1e-9)
    np.testing.assert_allclose(rebuilt.motion.global_positions(walk.skeleton),
                               motion.global_positions(walk.skeleton), rtol=0, atol=1e-9)
    # A changed motion shows in the clip: turn the root 90 degrees about y in every frame.
    rotations = motion.local_rotations
    turn = np.array([math.cos(math.pi / 4), 0, math.sin(math.pi / 4), 0])
    w1, v1 = turn[0], turn[1:]
    w2, v2 = rotations[:, 0, 0].copy(), rotations[:, 0, 1:].copy()
    rotations[:, 0, 0] = w1 * w2 - v2 @ v1
    rotations[:, 0, 1:] = w1 * v2 + w2[:, None] * v1 + np.cross(v1, v2)
    turned = animkit.Motion(rotations, motion.local_translations, motion.frame_time)
    clip = walk.with_motion(turned)
    np.testing.assert_allclose(clip.motion.local_rotations[:, 0] *
                               np.sign(clip.motion.local_rotations[:, 0, :1]),
                               rotations[:, 0] * np.sign(rotations[:, 0, :1]), atol=1e-9)


def test_with_motion_checks_sizes(walk):
    small = animkit.parse_bvh(SMALL)
    with pytest.raises(animkit.Error, match="the motion has 2 frames of 3 joints but the clip"):
        walk.with_motion(small.motion)


@pytest.mark.parametrize("text, message", [
    ("", "empty"),
    (SMALL.replace("CHANNELS 3 Zrotation", "CHANNELS 3 Wrotation"), "<string>: line 9:"),
    (SMALL.replace("0 1 0 0 0 0 0 0 0", "0 1 0 0 0 0 0 0"), "line 19:"),
    (SMALL.replace("0 1 0 0 0 0 0 0 0", "0 1 0 0 nan 0 0 0 0"), "line 19:"),
    (SMALL.replace("Frames: 2", "Frames: 3"), "<string>"),
    (SMALL.replace("OFFSET 0 2 0", "OFFSET 0 2"), "line 8:"),
])
def test_malformed_text_names_the_line(text, message):
    with pytest.raises(animkit.Error) as info:
        animkit.parse_bvh(text)
    assert message in str(info.value)


def test_errors_name_the_source():
    with pytest.raises(animkit.Error, match=r"^walk\.bvh: line 9: "):
        animkit.parse_bvh(SMALL.replace("Zrotation Xrotation Yrotation\n\t\tEnd",
                                        "Zrotation Zrotation Yrotation\n\t\tEnd"),
                          name="walk.bvh")


def test_missing_file_and_unwritable_path(tmp_path):
    with pytest.raises(animkit.Error, match="nothing.bvh"):
        animkit.read_bvh(tmp_path / "nothing.bvh")
    clip = animkit.parse_bvh(SMALL)
    with pytest.raises(animkit.Error):
        animkit.write_bvh(tmp_path / "no" / "such" / "dir" / "x.bvh", clip)
    with pytest.raises(TypeError):
        animkit.read_bvh(42)
