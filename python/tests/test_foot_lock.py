"""Foot locking from Python: settings, lock_feet on the CMU walk, its contacts and metrics, and
the same numbers and file as `animkit footlock`."""
import json
import math
import subprocess

import numpy as np
import pytest

import animkit

CMU_SCALE = 0.056444  # CMU's file unit in metres (the CLI's --scale for this clip)


@pytest.fixture(scope="module")
def walk_path(data_dir):
    return data_dir / "cmu" / "131_01.bvh"


@pytest.fixture(scope="module")
def walk(walk_path):
    return animkit.read_bvh(walk_path, scale=CMU_SCALE)


@pytest.fixture(scope="module")
def locked(walk):
    return animkit.lock_feet(walk.skeleton, walk.motion)


def test_settings_defaults_and_repr():
    s = animkit.FootLockSettings()
    assert s.height_threshold == 0.05 and s.speed_threshold == 0.35
    assert (s.min_contact_frames, s.merge_gap_frames, s.blend_frames) == (6, 3, 10)
    assert s.min_knee_flexion == 0.0
    assert s.max_knee_flexion == pytest.approx(math.radians(150))
    assert s.knee_pole == "pelvis-forward" and s.soft_reach == 0.01
    assert repr(s).startswith("FootLockSettings(height_threshold=0.05, speed_threshold=0.35, "
                              "min_contact_frames=6, merge_gap_frames=3, blend_frames=10, ")
    assert "knee_pole='pelvis-forward'" in repr(s)
    s = animkit.FootLockSettings(height_threshold=0.1, knee_pole="original")
    assert s.height_threshold == 0.1 and s.knee_pole == "original"
    s.blend_frames = 0
    assert s.blend_frames == 0
    with pytest.raises(TypeError):
        animkit.FootLockSettings(0.1)  # keyword only


def test_settings_errors():
    with pytest.raises(animkit.Error, match="expected 'pelvis-forward' or 'original'"):
        animkit.FootLockSettings(knee_pole="backward")
    s = animkit.FootLockSettings()
    with pytest.raises(animkit.Error, match="knee_pole"):
        s.knee_pole = "up"
    s.height_threshold = -1.0
    with pytest.raises(animkit.Error, match="foot lock height threshold must be > 0"):
        s.validate()


def test_lock_reduces_sliding(walk, locked):
    frames = walk.frame_count
    m = locked.metrics
    assert m.contacts[0] >= 3 and m.contacts[1] >= 3
    assert m.planted_frames[0] > 100 and m.planted_frames[1] > 100
    assert m.slide_after_mean_cm < 0.1 * m.slide_before_mean_cm
    assert m.slide_after_max_cm < m.slide_before_max_cm
    assert m.ik_error_max_cm < 5.0
    assert m.ms_per_frame > 0
    assert repr(m).startswith(f"FootLockMetrics(contacts=({m.contacts[0]}, {m.contacts[1]}), ")
    assert "slide_after_mean_cm=" in repr(m)
    motion = locked.motion
    assert (motion.frame_count, motion.joint_count) == (frames, walk.joint_count)
    assert locked.ankles_before.shape == (frames, 2, 3)
    assert locked.ankles_after.shape == (frames, 2, 3)
    # The ankles after are the locked motion's ankles.
    positions = motion.global_positions(walk.skeleton)
    ankles = [walk.skeleton.find_joint("LeftAnkle"), walk.skeleton.find_joint("RightAnkle")]
    np.testing.assert_allclose(locked.ankles_after, positions[:, ankles], atol=1e-12)
    before = walk.motion.global_positions(walk.skeleton)
    np.testing.assert_allclose(locked.ankles_before, before[:, ankles], atol=1e-12)
    assert "FootLockResult(frames=994" in repr(locked)


def test_contacts(walk, locked):
    frames = walk.frame_count
    contacts = locked.contacts
    assert len(contacts) == 2
    for leg, c in enumerate(contacts):
        assert c.planted.dtype == bool and c.planted.shape == (frames,)
        assert c.weight.shape == (frames,)
        assert c.lock.shape == (frames, 3)
        assert ((c.weight >= 0) & (c.weight <= 1)).all()
        spans = c.spans
        assert len(spans) == locked.metrics.contacts[leg]
        assert int(c.planted.sum()) == locked.metrics.planted_frames[leg]
        for first, last, lock in spans:
            assert c.planted[first:last + 1].all()
            assert (c.weight[first:last + 1] == 1).all()
            assert lock.shape == (3,)
            # Planted: the locked ankle stays (nearly) at the lock point.
            after = locked.ankles_after[first:last + 1, leg]
            assert np.abs(after - lock).max() < 0.02
        assert repr(c) == f"FootContacts(frames={frames}, spans={len(spans)})"


def test_frames_without_weight_are_unchanged(walk, locked):
    free = (locked.contacts[0].weight == 0) & (locked.contacts[1].weight == 0)
    assert free.any()
    np.testing.assert_array_equal(locked.motion.local_rotations[free],
                                  walk.motion.local_rotations[free])


def test_legs_by_name_and_index(walk, locked):
    s = walk.skeleton
    names = (("LeftHip", "LeftKnee", "LeftAnkle"), ("RightHip", "RightKnee", "RightAnkle"))
    by_name = animkit.lock_feet(s, walk.motion, legs=names)
    np.testing.assert_array_equal(by_name.motion.local_rotations, locked.motion.local_rotations)
    indices = [[s.find_joint(n) for n in leg] for leg in names]
    by_index = animkit.lock_feet(s, walk.motion, animkit.FootLockSettings(), indices)
    np.testing.assert_array_equal(by_index.ankles_after, locked.ankles_after)


def test_settings_that_leave_nothing_to_lock_say_so(walk):
    # Settings that leave nothing to lock fail with the cause, not a run that did nothing.
    with pytest.raises(animkit.Error, match=r"no foot contact in 994 frames: .* for 1000 frames "
                                            r"or more \(the height, speed and minimum contact"):
        animkit.lock_feet(walk.skeleton, walk.motion,
                          animkit.FootLockSettings(min_contact_frames=1000))


def test_bad_input(walk):
    s, motion = walk.skeleton, walk.motion
    with pytest.raises(animkit.Error, match="foot lock minimum contact length must be >= 1"):
        animkit.lock_feet(s, motion, animkit.FootLockSettings(min_contact_frames=0))
    with pytest.raises(animkit.Error, match="height threshold"):
        animkit.lock_feet(s, motion, animkit.FootLockSettings(height_threshold=math.nan))
    with pytest.raises(animkit.Error, match="a biped's leg needs LeftKnee to be the parent of "
                                            "RightAnkle"):
        animkit.lock_feet(s, motion, legs=(("LeftHip", "LeftKnee", "RightAnkle"),
                                           ("RightHip", "RightKnee", "RightAnkle")))
    with pytest.raises(animkit.Error, match="no joint named 'Foot'"):
        animkit.lock_feet(s, motion, legs=(("LeftHip", "LeftKnee", "Foot"),
                                           ("RightHip", "RightKnee", "RightAnkle")))
    with pytest.raises(animkit.Error, match="out of range"):
        animkit.lock_feet(s, motion, legs=((0, 1, 999), (0, 1, 2)))
    with pytest.raises(animkit.Error, match="legs must be two"):
        animkit.lock_feet(s, motion, legs="LeftHip")
    one_frame = animkit.Motion(motion.local_rotations[:1], motion.local_translations[:1],
                               motion.frame_time)
    with pytest.raises(animkit.Error, match="foot lock needs at least 2 frames, got 1"):
        animkit.lock_feet(s, one_frame)
    # A root far beyond any scene once gave an IK error of inf as a result.
    far = motion.local_translations.copy()
    far[0, 0, 0] = 1e300
    with pytest.raises(animkit.Error, match="foot lock motion frame 0, joint 0: translation"):
        animkit.lock_feet(s, animkit.Motion(motion.local_rotations, far, motion.frame_time))
    arm = animkit.Skeleton(["a", "b"], [-1, 0], [[0, 0, 0], [1, 0, 0]])
    with pytest.raises(animkit.Error, match="no joint named LeftHip: a biped's legs are found by name"):
        animkit.lock_feet(arm, motion)
    tiny = animkit.Motion(np.tile([1.0, 0, 0, 0], (2, 1, 1)), np.zeros((2, 1, 3)))
    with pytest.raises(animkit.Error, match="foot lock motion has 1 joints but the skeleton 38"):
        animkit.lock_feet(s, tiny)
    with pytest.raises(TypeError):
        animkit.lock_feet(s, motion, settings="defaults")


def test_two_threads_lock_at_once(walk, locked, run_watched):
    # A worker locks the walk's feet again and again while this thread does too, on each of
    # the turns it gets: it gets some only because lock_feet lets go of the GIL (see
    # run_watched in conftest.py). Every result has the bits of one lock alone.
    def lock():
        return animkit.lock_feet(walk.skeleton, walk.motion)

    turns, in_worker, in_main = run_watched(lambda: [lock() for _ in range(10)], each_turn=lock)
    assert turns > 0, "this thread never ran while the worker was inside lock_feet"
    for r in in_worker + in_main:
        np.testing.assert_array_equal(r.motion.local_rotations, locked.motion.local_rotations)


def cli_metrics(metrics_json):
    """The CLI's metrics.json as FootLockMetrics' field names."""
    j = json.loads(metrics_json)
    return {
        "contacts": (j["contacts"]["left"], j["contacts"]["right"]),
        "planted_frames": (j["planted_frames"]["left"], j["planted_frames"]["right"]),
        "slide_before_mean_cm": j["sliding_cm_per_frame"]["before"]["mean"],
        "slide_before_max_cm": j["sliding_cm_per_frame"]["before"]["max"],
        "slide_after_mean_cm": j["sliding_cm_per_frame"]["after"]["mean"],
        "slide_after_max_cm": j["sliding_cm_per_frame"]["after"]["max"],
        "ik_error_mean_cm": j["ik_error_cm"]["mean"],
        "ik_error_max_cm": j["ik_error_cm"]["max"],
        "max_joint_step_before_cm": j["max_joint_step_cm"]["before"],
        "max_joint_step_after_cm": j["max_joint_step_cm"]["after"],
        "max_leg_step_before_cm": j["max_leg_step_cm"]["before"],
        "max_leg_step_after_cm": j["max_leg_step_cm"]["after"],
        "max_correction_step_cm": j["max_correction_step_cm"],
    }


@pytest.mark.parametrize("scale", [None, CMU_SCALE], ids=["cli-default-scale", "cmu-metres"])
def test_same_bits_as_the_cli(cli, walk_path, tmp_path, scale):
    out = tmp_path / "cli"
    command = [str(cli), "footlock", "--in", str(walk_path), "--out", str(out)]
    if scale is not None:
        command += ["--scale", repr(scale)]
    subprocess.run(command, check=True, capture_output=True, text=True)

    read_scale = CMU_SCALE if scale is None else scale  # the CLI tells CMU's unit by itself
    clip = animkit.read_bvh(walk_path, scale=read_scale)
    result = animkit.lock_feet(clip.skeleton, clip.motion)
    fixed = clip.with_motion(result.motion).scaled(1.0 / read_scale)
    animkit.write_bvh(tmp_path / "fixed.bvh", fixed)
    assert (tmp_path / "fixed.bvh").read_bytes() == (out / "fixed.bvh").read_bytes()

    expected = cli_metrics((out / "metrics.json").read_text())
    got = {name: getattr(result.metrics, name) for name in expected}
    assert got == expected  # the JSON's shortest round-trip digits read back to the same doubles
    assert expected["contacts"][0] > 0  # in metres the walk has contacts to lock


def test_body_scale_tells_the_units_from_the_legs(walk_path):
    raw = animkit.read_bvh(walk_path)  # CMU's own numbers
    metres, unit, leg = animkit.body_scale(raw.skeleton)
    assert (metres, unit) == (CMU_SCALE, "CMU's unit (inch / 0.45)")
    assert leg == pytest.approx(14.2126, abs=1e-3)
    centimetres = animkit.read_bvh(walk_path, scale=CMU_SCALE / 0.01)
    assert animkit.body_scale(centimetres.skeleton)[:2] == (0.01, "centimetres")
    giant = animkit.read_bvh(walk_path, scale=10.0)
    with pytest.raises(animkit.Error, match="cannot tell the units of the skeleton: its legs are "
                                            "142 units long"):
        animkit.body_scale(giant.skeleton)
