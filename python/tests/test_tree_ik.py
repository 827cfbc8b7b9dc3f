"""Joint limits and IK on skeleton trees from Python: every solver on the CMU skeleton, with and
without limits, and the limits' own math."""
import math
import threading

import numpy as np
import pytest

import animkit

CMU_SCALE = 0.056444
END_JOINTS = ["LeftWrist", "RightWrist", "LeftAnkle", "RightAnkle", "Head"]


@pytest.fixture(scope="module")
def walk(data_dir):
    return animkit.read_bvh(data_dir / "cmu" / "131_01.bvh", scale=CMU_SCALE)


@pytest.fixture(scope="module")
def skeleton(walk):
    return walk.skeleton


@pytest.fixture(scope="module")
def limits(walk):
    return animkit.human_joint_limits(walk.skeleton, walk.motion)


def quat_about(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])


def captured_pose(walk, frame):
    """Frame `frame` of the walk with the root at its rest position: a pose the skeleton can
    take, so its joints' positions are reachable targets from the rest pose."""
    pose = walk.motion.pose(frame)
    translations = pose.local_translations
    translations[0] = walk.skeleton.rest_offsets[0]
    pose.local_translations = translations
    return animkit.forward_kinematics(walk.skeleton, pose)


def effectors_of(skeleton, pose, names=END_JOINTS):
    return [animkit.Effector(name, pose.global_positions[skeleton.find_joint(name)])
            for name in names]


# --- joint limits ---------------------------------------------------------------------------

def test_limit_classes_and_repr():
    assert repr(animkit.FreeJoint()) == "FreeJoint()"
    hinge = animkit.HingeLimit((0, 0, 2), -1.0, 0.5)
    np.testing.assert_array_equal(hinge.axis, [0, 0, 1])  # normalized
    assert repr(hinge) == "HingeLimit(axis=(0.0, 0.0, 1.0), min_angle=-1.0, max_angle=0.5)"
    ball = animkit.BallLimit((0, 1, 0), 0.5, -0.2, 0.3)
    assert (ball.swing_angle, ball.min_twist, ball.max_twist) == (0.5, -0.2, 0.3)
    assert ball.swing_angle_2 is None
    assert repr(ball).startswith("BallLimit(twist_axis=(0.0, 1.0, 0.0), swing_angle=0.5, ")
    oval = animkit.BallLimit(twist_axis=(0, 1, 0), swing_angle=0.5, swing_axis=(0, 0, 1),
                             swing_angle_2=0.2)
    assert oval.swing_angle_2 == 0.2


@pytest.mark.parametrize("make, message", [
    (lambda: animkit.HingeLimit((0, 0, 1), 1.0, -1.0), "above its maximum"),
    (lambda: animkit.HingeLimit((0, 0, 1), -4.0, 0.0), "hinge"),
    (lambda: animkit.HingeLimit((0, 0, 0), 0.0, 1.0), "hinge axis is not unit length"),
    (lambda: animkit.HingeLimit((math.nan, 0, 1), 0.0, 1.0), "non-finite"),
    (lambda: animkit.BallLimit((0, 1, 0), 4.0), "swing"),
    (lambda: animkit.BallLimit((0, 1, 0), 0.5, 0.3, 0.1), "above its maximum"),
    (lambda: animkit.BallLimit((0, 1, 0), 0.5, swing_axis=(0, 1, 0), swing_angle_2=0.2),
     "perpendicular"),
])
def test_invalid_limits_raise(make, message):
    with pytest.raises(animkit.Error) as info:
        make()
    assert message in str(info.value)


def test_constrain_and_violation():
    hinge = animkit.HingeLimit((0, 0, 1), -0.5, 0.5)
    inside = quat_about((0, 0, 1), 0.3)
    np.testing.assert_array_equal(animkit.constrain(hinge, inside), inside)
    assert animkit.violation(hinge, inside) == 0.0
    outside = quat_about((0, 0, 1), 0.8)
    np.testing.assert_allclose(animkit.constrain(hinge, outside), quat_about((0, 0, 1), 0.5),
                               atol=1e-12)
    assert animkit.violation(hinge, outside) == pytest.approx(0.3)
    ball = animkit.BallLimit((0, 1, 0), 0.4, -0.1, 0.1)
    swung = quat_about((1, 0, 0), 0.7)
    assert animkit.violation(ball, swung) == pytest.approx(0.3)
    np.testing.assert_allclose(animkit.constrain(ball, swung), quat_about((1, 0, 0), 0.4),
                               atol=1e-12)
    assert animkit.violation(animkit.FreeJoint(), swung) == 0.0
    assert animkit.violation(None, swung) == 0.0


def test_swing_twist():
    q = quat_about((1, 0, 0), 0.6)
    twist = quat_about((0, 1, 0), 0.4)
    w1, v1, w2, v2 = q[0], q[1:], twist[0], twist[1:]
    product = np.concatenate([[w1 * w2 - v1 @ v2], w1 * v2 + w2 * v1 + np.cross(v1, v2)])
    swing, tw = animkit.swing_twist(product, (0, 1, 0))
    np.testing.assert_allclose(swing, q, atol=1e-12)
    np.testing.assert_allclose(tw, twist, atol=1e-12)
    with pytest.raises(animkit.Error, match="axis must be a finite unit vector"):
        animkit.swing_twist(product, (0, 2, 0))


def test_limit_math_errors():
    hinge = animkit.HingeLimit((0, 0, 1), -0.5, 0.5)
    with pytest.raises(animkit.Error, match="q is not a unit quaternion"):
        animkit.constrain(hinge, (2, 0, 0, 0))
    with pytest.raises(animkit.Error, match="q has a non-finite"):
        animkit.violation(hinge, (math.nan, 0, 0, 0))
    with pytest.raises(animkit.Error, match="q must be 4 numbers"):
        animkit.constrain(hinge, (1, 0, 0))
    with pytest.raises(animkit.Error, match="limit must be a FreeJoint, HingeLimit, BallLimit"):
        animkit.constrain("hinge", (1, 0, 0, 0))
    hinge.min_angle = 2.0  # attributes are validated when used
    with pytest.raises(animkit.Error, match="limit: "):
        animkit.constrain(hinge, (1, 0, 0, 0))


def test_human_limits(skeleton, walk, limits):
    default = animkit.human_joint_limits(skeleton)
    assert len(default) == len(limits) == skeleton.joint_count
    assert isinstance(default[0], animkit.FreeJoint)  # the root
    knee, elbow = skeleton.find_joint("LeftKnee"), skeleton.find_joint("LeftElbow")
    assert isinstance(limits[knee], animkit.HingeLimit)
    assert isinstance(limits[elbow], animkit.HingeLimit)
    assert isinstance(limits[skeleton.find_joint("LeftHip")], animkit.BallLimit)
    # Fitting to the clip turns the elbow's axis (CMU's carrying angle).
    turn = math.degrees(math.acos(abs(np.dot(default[elbow].axis, limits[elbow].axis))))
    assert turn > 10
    # The walk bends its elbows within the fitted hinges (not the default ones: 0.87 rad off).
    rotations = walk.motion.local_rotations
    assert max(animkit.violation(limits[elbow], q) for q in rotations[:, elbow]) < 1e-5
    assert max(animkit.violation(default[elbow], q) for q in rotations[:, elbow]) > 0.5
    other = animkit.Motion(np.tile([1.0, 0, 0, 0], (2, 1, 1)), np.zeros((2, 1, 3)))
    with pytest.raises(animkit.Error, match="fitting hinge axes"):
        animkit.human_joint_limits(skeleton, other)


def test_limits_files(skeleton, tmp_path):
    text = """{"LeftKnee": {"type": "hinge", "axis": [0, 0, 2], "min": 0, "max": 90},
               "LeftHip": {"type": "ball", "axis": [0, -1, 0], "swing": 80,
                           "twist": [-30, 30]},
               "Head": {"type": "free"}}"""
    limits = animkit.parse_joint_limits(text, skeleton)
    assert len(limits) == skeleton.joint_count
    knee = limits[skeleton.find_joint("LeftKnee")]
    np.testing.assert_array_equal(knee.axis, [0, 0, 1])
    assert knee.max_angle == pytest.approx(math.pi / 2)
    hip = limits[skeleton.find_joint("LeftHip")]
    assert hip.swing_angle == pytest.approx(math.radians(80))
    assert isinstance(limits[skeleton.find_joint("RightKnee")], animkit.FreeJoint)
    path = tmp_path / "limits.json"
    path.write_text(text)
    from_file = animkit.read_joint_limits(path, skeleton)
    assert repr(from_file) == repr(limits)
    with pytest.raises(animkit.Error, match="LeftKnee.max"):
        animkit.parse_joint_limits(text.replace('"max": 90', '"max": 900'), skeleton)
    with pytest.raises(animkit.Error, match="Knee2"):
        animkit.parse_joint_limits('{"Knee2": {"type": "free"}}', skeleton)
    with pytest.raises(animkit.Error, match=r"^mine\.json: "):
        animkit.parse_joint_limits("{", skeleton, name="mine.json")
    with pytest.raises(animkit.Error, match="missing.json"):
        animkit.read_joint_limits(tmp_path / "missing.json", skeleton)


# --- tree IK --------------------------------------------------------------------------------

def test_solver_names_and_repr(skeleton):
    assert animkit.tree_ik_solver_names() == ["fabrik", "ccd", "dls", "sdls"]
    solver = animkit.TreeIkSolver(skeleton, "ccd", max_iterations=50, tolerance=1e-3)
    assert repr(solver) == ("TreeIkSolver(solver='ccd', joint_count=38, max_iterations=50, "
                            "tolerance=0.001)")
    assert (solver.solver, solver.max_iterations, solver.tolerance) == ("ccd", 50, 1e-3)
    e = animkit.Effector("Head", (0, 1, 0))
    assert repr(e) == ("Effector(joint='Head', position=(0.0, 1.0, 0.0), orientation=None, "
                       "weight=1.0)")
    e = animkit.Effector(3, (0, 1, 0), orientation=(1, 0, 0, 0), weight=2.0)
    assert e.joint == 3 and e.weight == 2.0
    np.testing.assert_array_equal(e.orientation, [1, 0, 0, 0])


@pytest.mark.parametrize("solver", ["fabrik", "ccd", "dls", "sdls"])
@pytest.mark.parametrize("limited", [False, True], ids=["free", "limits"])
@pytest.mark.parametrize("frame", [100, 300, 600])
def test_reaches_captured_poses(walk, skeleton, limits, solver, limited, frame):
    target = captured_pose(walk, frame)
    effectors = effectors_of(skeleton, target)
    rest = skeleton.rest_pose()
    joint_limits = limits if limited else None
    # CCD's sweeps pull five effectors on one spine slowly: up to 1367 on frame 600.
    cap = 2000 if solver == "ccd" else 1000
    result = animkit.TreeIkSolver(skeleton, solver, max_iterations=cap).solve(
        effectors, pose=rest, limits=joint_limits)
    assert result.converged and result.reachable, result
    assert result.error <= 1e-4
    pose = result.pose
    for e in effectors:
        assert np.linalg.norm(pose.global_positions[skeleton.find_joint(e.joint)] -
                              e.position) <= 1e-4
    # Bones keep their lengths.
    parents = np.array(skeleton.parents)
    child = np.flatnonzero(parents >= 0)
    lengths = np.linalg.norm(pose.global_positions[child] -
                             pose.global_positions[parents[child]], axis=1)
    np.testing.assert_allclose(lengths, skeleton.bone_lengths[child], rtol=0, atol=1e-9)
    # Roots keep their translation; the start pose is untouched.
    np.testing.assert_array_equal(pose.local_translations, rest.local_translations)
    np.testing.assert_array_equal(rest.global_positions, skeleton.rest_pose().global_positions)
    if limited:
        worst = max(animkit.violation(limits[j], q) for j, q in enumerate(pose.local_rotations))
        assert worst <= 1e-9


def test_limits_change_the_answer(skeleton):
    """A target behind the thigh: free, the knee bends forward to reach it; with a hinge that
    only flexes backwards, it cannot, and the result stays inside the limit."""
    knee = skeleton.find_joint("LeftKnee")
    rest = skeleton.rest_pose()
    hinge = animkit.HingeLimit(np.cross(skeleton.rest_offsets[knee + 1], (0, 0, 1)), 0.0, 0.0)
    limits = [None] * skeleton.joint_count
    limits[knee] = hinge
    for j in range(skeleton.joint_count):
        if j != knee:
            limits[j] = animkit.BallLimit(swing_angle=0.0)  # nothing else turns
    ankle = rest.global_positions[knee + 1]
    target = ankle + (0, 0.1, 0.1)
    result = animkit.solve_tree(skeleton, animkit.Effector("LeftAnkle", target), solver="dls",
                                limits=limits)
    assert not result.converged
    np.testing.assert_allclose(result.pose.global_positions, rest.global_positions, atol=1e-9)
    free = animkit.solve_tree(skeleton, animkit.Effector("LeftAnkle", target), solver="dls")
    assert free.converged


def test_orientation_target(skeleton, walk):
    target = captured_pose(walk, 300)
    wrist = skeleton.find_joint("LeftWrist")
    e = animkit.Effector("LeftWrist", target.global_positions[wrist],
                         orientation=target.global_rotations[wrist])
    result = animkit.solve_tree(skeleton, [e], solver="dls", max_iterations=500)
    assert result.converged, result
    assert result.orientation_error <= 1e-4


def test_repeated_solves_give_the_same_bits(skeleton, walk):
    solver = animkit.TreeIkSolver(skeleton, "fabrik")
    effectors = effectors_of(skeleton, captured_pose(walk, 300))
    first = solver.solve(effectors)  # from the rest pose
    second = solver.solve(effectors, pose=skeleton.rest_pose())
    np.testing.assert_array_equal(first.pose.local_rotations, second.pose.local_rotations)
    once = animkit.solve_tree(skeleton, effectors)
    np.testing.assert_array_equal(once.pose.local_rotations, first.pose.local_rotations)


def test_unreachable_target(skeleton):
    result = animkit.solve_tree(skeleton, [animkit.Effector("LeftWrist", (10.0, 0, 0))])
    assert not result.reachable and not result.converged


def test_bad_input(skeleton, limits):
    rest = skeleton.rest_pose()
    solver = animkit.TreeIkSolver(skeleton)
    target = (0.0, 1.0, 0.0)
    with pytest.raises(animkit.Error, match="unknown tree IK solver 'jacobian' "
                                            r"\(expected one of fabrik, ccd, dls, sdls\)"):
        animkit.TreeIkSolver(skeleton, "jacobian")
    with pytest.raises(animkit.Error, match="max"):
        animkit.TreeIkSolver(skeleton, max_iterations=0)
    with pytest.raises(animkit.Error, match="tolerance"):
        animkit.TreeIkSolver(skeleton, tolerance=-1.0)
    with pytest.raises(TypeError):  # effectors come first, the pose is optional
        solver.solve(rest, [animkit.Effector("Head", target)])
    with pytest.raises(animkit.Error, match="effectors must be an Effector or a list"):
        solver.solve(rest)
    with pytest.raises(animkit.Error, match="no joint named 'Tail'"):
        solver.solve([animkit.Effector("Tail", target)], pose=rest)
    with pytest.raises(animkit.Error, match="out of range"):
        solver.solve([animkit.Effector(99, target)], pose=rest)
    with pytest.raises(animkit.Error, match="root"):
        solver.solve([animkit.Effector(0, target)], pose=rest)
    with pytest.raises(animkit.Error):
        solver.solve([animkit.Effector("Head", target), animkit.Effector("Head", target)],
                     pose=rest)
    with pytest.raises(animkit.Error):
        solver.solve([animkit.Effector("Head", (math.nan, 0, 0))], pose=rest)
    with pytest.raises(animkit.Error, match="unit quaternion"):
        solver.solve([animkit.Effector("Head", target, orientation=(2, 0, 0, 0))], pose=rest)
    with pytest.raises(animkit.Error, match="weight"):
        solver.solve([animkit.Effector("Head", target, weight=0.0)], pose=rest)
    with pytest.raises(animkit.Error):
        solver.solve([], pose=rest)
    with pytest.raises(animkit.Error, match="effectors\\[0\\] must be an Effector"):
        solver.solve([target], pose=rest)
    with pytest.raises(animkit.Error, match="limits has 2 entries for 38 joints"):
        solver.solve([animkit.Effector("Head", target)], rest, [None, None])
    with pytest.raises(animkit.Error, match=r"limits\[1\] must be a FreeJoint"):
        solver.solve([animkit.Effector("Head", target)], limits=[None, 3] + [None] * 36)
    small = animkit.Skeleton(["a", "b"], [-1, 0], [[0, 0, 0], [1, 0, 0]])
    with pytest.raises(animkit.Error):
        solver.solve([animkit.Effector("Head", target)], pose=small.rest_pose())
    with pytest.raises(TypeError):
        animkit.Effector(1.5, target)
    with pytest.raises(animkit.Error, match="effector position must be 3 numbers"):
        animkit.Effector("Head", (1, 2))


def test_own_solvers_in_two_threads_give_the_serial_bits(skeleton, walk, limits):
    """Each thread's own solver gives the same bits as one solve (determinism; that solve
    releases the GIL is test_a_shared_solver_refuses_an_overlapping_solve's business)."""
    effectors = effectors_of(skeleton, captured_pose(walk, 300))
    expected = animkit.solve_tree(skeleton, effectors, solver="fabrik", limits=limits)
    outcomes = []

    def run(solver):
        for _ in range(3):
            outcomes.append(solver.solve(effectors, limits=limits).pose.local_rotations)

    threads = [threading.Thread(target=run, args=(animkit.TreeIkSolver(skeleton, "fabrik"),))
               for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(outcomes) == 6
    for outcome in outcomes:
        np.testing.assert_array_equal(outcome, expected.pose.local_rotations)


def test_a_shared_solver_refuses_an_overlapping_solve(skeleton, walk, limits, run_watched):
    """One solver shared by two threads refuses the second solve while the first runs instead
    of sharing its workspaces. A worker solves again and again (a few ms of FABRIK with
    limits); this thread gets turns only while the worker is inside a solve, which lets go of
    the GIL (see run_watched in conftest.py): so each of its solves on the same solver
    overlaps one of the worker's, and must be refused."""
    effectors = effectors_of(skeleton, captured_pose(walk, 300))
    expected = animkit.solve_tree(skeleton, effectors, solver="fabrik", limits=limits)
    shared = animkit.TreeIkSolver(skeleton, "fabrik")

    def attempt():
        try:
            shared.solve(effectors, limits=limits)
        except animkit.Error as error:
            return str(error)
        return "solved"

    turns, solved, attempts = run_watched(
        lambda: [shared.solve(effectors, limits=limits) for _ in range(20)], each_turn=attempt)
    assert turns > 0, "this thread never ran while the worker was inside solve"
    assert len(attempts) == turns
    for outcome in attempts:
        assert "already solving in another thread" in outcome
    for result in solved:  # the worker's solves were not disturbed
        np.testing.assert_array_equal(result.pose.local_rotations, expected.pose.local_rotations)
    # Free again once the worker is done.
    np.testing.assert_array_equal(shared.solve(effectors, limits=limits).pose.local_rotations,
                                  expected.pose.local_rotations)


def test_two_bone():
    # Upper bone 1 along +x, lower bone 1 further along +x; target at distance sqrt(2) along
    # the diagonal: a right angle at the middle joint, which bends toward the pole (+y).
    r = animkit.solve_two_bone((0, 0, 0), (1, 0, 0), (2, 0, 0), (1, 1, 0), (0.5, 5, 0))
    assert r.reached and r.error < 1e-12
    np.testing.assert_allclose(r.end, [1, 1, 0], atol=1e-12)
    assert np.linalg.norm(r.middle) == pytest.approx(1.0)
    assert r.middle[1] > 0  # on the pole's side
    np.testing.assert_allclose(np.linalg.norm(r.upper_rotation), 1.0)
    assert repr(r).startswith("TwoBoneResult(reached=True, error=")
    far = animkit.solve_two_bone((0, 0, 0), (1, 0, 0), (2, 0, 0), (5, 0, 0), (0, 1, 0))
    assert not far.reached and far.error == pytest.approx(3.0)
    with pytest.raises(animkit.Error, match="zero length"):
        animkit.solve_two_bone((0, 0, 0), (0, 0, 0), (2, 0, 0), (1, 1, 0), (0, 1, 0))
    with pytest.raises(animkit.Error):
        animkit.solve_two_bone((0, 0, 0), (1, 0, 0), (2, 0, 0), (math.nan, 1, 0), (0, 1, 0))
    with pytest.raises(animkit.Error):
        animkit.solve_two_bone((0, 0, 0), (1, 0, 0), (2, 0, 0), (1, 1, 0), (0, 1, 0),
                               degenerate_length=-1.0)
