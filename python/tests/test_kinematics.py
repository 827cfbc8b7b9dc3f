"""The lab's chain IK from Python: chains, poses and forward kinematics, one solve with CCD or
FABRIK, drawing sessions and their per-frame arrays, the same bits as `animkit ik`, bad input
as animkit.Error, and the GIL released while a session runs."""
import csv
import json
import math
import re
import subprocess
import threading

import numpy as np
import pytest

import animkit

LAB_REST = np.array([[0, 1.7, 0], [0, 0.9, 0], [0, 0.5, 0], [0, 0.3, 0], [0, -0.9, 0]], float)
SOLVERS = ["ccd", "fabrik"]


@pytest.fixture(scope="module")
def arm():
    return animkit.Chain.lab_arm()


def quat_z(angle):
    """(w, x, y, z) of a rotation by `angle` radians about +z."""
    return np.array([math.cos(angle / 2), 0, 0, math.sin(angle / 2)])


# ---- chains ---------------------------------------------------------------------------------

def test_lab_arm_is_the_labs(arm):
    assert arm.joint_count == 5
    np.testing.assert_allclose(arm.bone_lengths, [0, 0.8, 0.4, 0.2, 1.2], atol=1e-15)
    assert arm.reach == pytest.approx(2.6)
    assert arm.min_reach == 0.0
    np.testing.assert_array_equal(arm.root_position, [0, 1.7, 0])
    np.testing.assert_allclose(np.cumsum(arm.local_offsets, axis=0), LAB_REST, atol=1e-15)
    np.testing.assert_array_equal(arm.rest_rotations, np.tile([1.0, 0, 0, 0], (5, 1)))
    assert repr(arm).startswith("Chain(joint_count=5, reach=2.5999999999999996, ")


def test_chain_from_offsets_and_from_rest_positions_agree(arm):
    from_offsets = animkit.Chain(arm.local_offsets)
    from_points = animkit.Chain.from_rest_positions(LAB_REST)
    for chain in (from_offsets, from_points):
        np.testing.assert_array_equal(chain.local_offsets, arm.local_offsets)
        assert chain.reach == arm.reach


def test_chain_keeps_rest_rotations_and_a_long_bone_makes_a_minimum_reach():
    rotations = np.array([quat_z(0.3), [1, 0, 0, 0], [1, 0, 0, 0]])
    chain = animkit.Chain([[0, 0, 0], [3, 0, 0], [1, 0, 0]], rotations)
    np.testing.assert_allclose(chain.rest_rotations, rotations, atol=1e-15)
    assert chain.reach == 4.0
    assert chain.min_reach == 2.0  # 2 * 3 - 4


def test_returned_arrays_are_copies(arm):
    offsets = arm.local_offsets
    offsets[:] = 0
    assert arm.local_offsets[1, 1] == pytest.approx(-0.8)


@pytest.mark.parametrize("offsets, rotations, message", [
    ([[0, 0, 0], [0, 0, 0]], None, "bone 1 has zero length"),
    ([[0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 0, 0]], None, "bone 3 has zero length"),
    ([[0, 0, 0]], None, "a chain needs at least 2 joints, got 1"),
    ([], None, "a chain needs at least 2 joints, got 0"),
    ([[0, 0, 0], [np.nan, 1, 0]], None, "joint 1 offset has a non-finite coordinate (nan, 1, 0)"),
    ([[0, 0, 0], [np.inf, 1, 0]], None, "joint 1 offset has a non-finite coordinate (inf, 1, 0)"),
    ([[0, 0], [1, 0]], None, "offsets must be an array of shape (n, 3), got shape (2, 2)"),
    ([0, 0, 1], None, "offsets must be an array of shape (n, 3), got shape (3,)"),
    ("abc", None, "offsets must be an array of numbers"),
    (None, None, "offsets must be an array of numbers, got None"),
    ([[0, 0, 0], [1, 0, 0]], [[1, 0, 0, 0]], "local_rotations has 1 entries for 2 joints"),
    ([[0, 0, 0], [1, 0, 0]], [[1, 0, 0, 0], [2, 0, 0, 0]],
     "joint 1 rotation is not a unit quaternion (norm 2)"),
    ([[0, 0, 0], [1, 0, 0]], [[1, 0, 0, 0], [np.nan, 0, 0, 0]],
     "joint 1 rotation has a non-finite component"),
    ([[0, 0, 0], [1, 0, 0]], [[1, 0, 0], [1, 0, 0]],
     "rotations must be an array of shape (n, 4), got shape (2, 3)"),
])
def test_bad_chains_raise_the_librarys_message(offsets, rotations, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.Chain(offsets, rotations)
    assert str(raised.value).startswith(message)


def test_bad_rest_positions_raise():
    with pytest.raises(animkit.Error, match="bone 2 has zero length"):
        animkit.Chain.from_rest_positions([[0, 0, 0], [1, 0, 0], [1, 0, 0]])
    with pytest.raises(animkit.Error, match=r"points must be an array of shape \(n, 3\)"):
        animkit.Chain.from_rest_positions(np.zeros((3, 2)))


# ---- poses ----------------------------------------------------------------------------------

def test_rest_pose_is_the_rest_positions(arm):
    pose = animkit.rest_pose(arm)
    assert pose.joint_count == 5
    np.testing.assert_allclose(pose.global_positions, LAB_REST, atol=1e-15)
    np.testing.assert_array_equal(pose.end_effector, pose.global_positions[-1])
    np.testing.assert_array_equal(pose.local_rotations, np.tile([1.0, 0, 0, 0], (5, 1)))
    assert repr(pose).startswith("Pose(joint_count=5, end_effector=(0.0, -0.89999")
    np.testing.assert_array_equal(animkit.Pose(arm).global_positions, pose.global_positions)


def test_forward_kinematics_by_hand():
    # Two bones along +x; turning the root 90 degrees about z swings both onto +y, and the
    # elbow's own 90 degrees then turns the second bone onto -x.
    chain = animkit.Chain([[1, 2, 3], [1, 0, 0], [2, 0, 0]])
    rotations = np.array([quat_z(math.pi / 2), quat_z(math.pi / 2), [1, 0, 0, 0]])
    pose = animkit.forward_kinematics(chain, rotations)
    np.testing.assert_allclose(pose.global_positions,
                               [[1, 2, 3], [1, 3, 3], [-1, 3, 3]], atol=1e-15)
    np.testing.assert_allclose(pose.global_rotations[1], quat_z(math.pi), atol=1e-15)
    np.testing.assert_allclose(pose.local_rotations, rotations, atol=1e-15)
    same = animkit.Pose(chain, rotations)
    np.testing.assert_array_equal(same.global_positions, pose.global_positions)


@pytest.mark.parametrize("rotations, message", [
    (np.tile([1.0, 0, 0, 0], (4, 1)), "local_rotations has 4 rotations for a chain of 5 joints"),
    (np.tile([1.1, 0, 0, 0], (5, 1)), "local_rotations joint 0 is not a finite unit quaternion"),
    (np.vstack([np.tile([1.0, 0, 0, 0], (4, 1)), [np.nan, 0, 0, 0]]),
     "local_rotations joint 4 is not a finite unit quaternion"),
    (np.zeros((5, 3)), "local_rotations must be an array of shape (n, 4), got shape (5, 3)"),
])
def test_bad_poses_raise(arm, rotations, message):
    with pytest.raises(animkit.Error) as raised:
        animkit.Pose(arm, rotations)
    assert str(raised.value).startswith(message)
    with pytest.raises(animkit.Error):
        animkit.forward_kinematics(arm, rotations)


# ---- one solve ------------------------------------------------------------------------------

def test_solver_names():
    assert animkit.ik_solver_names() == SOLVERS
    assert animkit.fabrik_rotation_names() == ["rest", "previous"]


@pytest.mark.parametrize("solver", SOLVERS)
def test_solve_reaches_a_target_and_keeps_the_bones(arm, solver):
    target = np.array([0.5, 0.0, 0.3])
    result = animkit.solve(arm, target, solver=solver)
    assert result.converged and result.reachable
    assert 1 <= result.iterations <= 100
    end = result.pose.end_effector
    assert result.error == pytest.approx(np.linalg.norm(end - target), rel=1e-12)
    assert result.error <= 1e-4
    bones = np.linalg.norm(np.diff(result.pose.global_positions, axis=0), axis=1)
    np.testing.assert_allclose(bones, arm.bone_lengths[1:], rtol=1e-12)
    text = repr(result)
    assert text.startswith(f"IkResult(iterations={result.iterations}, error=")
    assert text.endswith("converged=True, reachable=True)")


@pytest.mark.parametrize("solver", SOLVERS)
def test_solve_does_not_change_the_start_pose(arm, solver):
    start = animkit.solve(arm, (0.2, 0.0, 0.4), solver=solver).pose
    before = start.global_positions.copy()
    result = animkit.solve(arm, (-0.3, 0.0, 0.1), solver=solver, pose=start)
    np.testing.assert_array_equal(start.global_positions, before)
    assert not np.array_equal(result.pose.global_positions, before)


@pytest.mark.parametrize("solver", SOLVERS)
def test_unreachable_target_points_the_arm_at_it(arm, solver):
    target = np.array([0.0, 1.7, 5.0])  # 5 from the root, reach 2.6
    result = animkit.solve(arm, target, solver=solver)
    assert not result.reachable and not result.converged
    np.testing.assert_allclose(result.pose.end_effector, [0, 1.7, 2.6], atol=1e-9)
    assert result.error == pytest.approx(5.0 - 2.6, rel=1e-9)


def test_tolerance_and_iteration_cap_are_used(arm):
    loose = animkit.solve(arm, (0.5, 0, 0.3), tolerance=0.05)
    tight = animkit.solve(arm, (0.5, 0, 0.3), tolerance=1e-10)
    assert loose.iterations < tight.iterations
    assert loose.error <= 0.05
    capped = animkit.solve(arm, (0.5, 0, 0.3), max_iterations=2)
    assert capped.iterations == 2 and not capped.converged


def test_fabrik_rotation_modes_give_the_same_positions_from_rest(arm):
    rest = animkit.solve(arm, (0.5, 0, 0.3), solver="fabrik", fabrik_rotations="rest")
    previous = animkit.solve(arm, (0.5, 0, 0.3), solver="fabrik", fabrik_rotations="previous")
    np.testing.assert_allclose(rest.pose.global_positions, previous.pose.global_positions,
                               atol=1e-9)


def test_pose_of_another_chain_is_reposed_first(arm):
    other = animkit.Chain([[0, 0, 0], [1, 0, 0], [1, 0, 0], [1, 0, 0], [1, 0, 0]])
    foreign = animkit.rest_pose(other)
    result = animkit.solve(arm, (0.5, 0, 0.3), pose=foreign)
    assert result.converged
    bones = np.linalg.norm(np.diff(result.pose.global_positions, axis=0), axis=1)
    np.testing.assert_allclose(bones, arm.bone_lengths[1:], rtol=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    ({"target": (np.nan, 0, 0)}, "target has a non-finite coordinate (nan, 0, 0)"),
    ({"target": (0, np.inf, 0)}, "target has a non-finite coordinate (0, inf, 0)"),
    ({"target": (2e9, 0, 0)}, "target (2e+09, 0, 0) has a coordinate beyond +-1e+09"),
    ({"target": (1, 2)}, "target must be 3 numbers, got shape (2,)"),
    ({"target": [[1, 2, 3]]}, "target must be 3 numbers, got shape (1, 3)"),
    ({"target": None}, "target must be an array of numbers, got None"),
    ({"solver": "dls"}, "unknown solver 'dls' (expected ccd or fabrik)"),
    ({"fabrik_rotations": "next"}, "unknown fabrik_rotations 'next' (expected rest or previous)"),
    ({"tolerance": 0.0}, "tolerance must be a positive finite number, got 0"),
    ({"tolerance": -1e-3}, "tolerance must be a positive finite number, got -0.001"),
    ({"tolerance": np.nan}, "tolerance must be a positive finite number, got nan"),
    ({"max_iterations": 0}, "max iterations must be at least 1, got 0"),
])
def test_bad_solves_raise(arm, kwargs, message):
    args = {"target": (0.5, 0, 0.3)} | kwargs
    with pytest.raises(animkit.Error) as raised:
        animkit.solve(arm, **args)
    assert str(raised.value).startswith(message)


def test_pose_with_another_joint_count_raises(arm):
    small = animkit.Chain([[0, 0, 0], [1, 0, 0]])
    with pytest.raises(animkit.Error, match="pose has 2 joints but the chain has 5"):
        animkit.solve(arm, (0.5, 0, 0.3), pose=animkit.rest_pose(small))


def test_wrong_types_are_type_errors(arm):
    with pytest.raises(TypeError):
        animkit.solve("arm", (0, 0, 0))
    with pytest.raises(TypeError):
        animkit.solve(arm, (0, 0, 0), max_iterations=1.5)
    with pytest.raises(TypeError):
        animkit.solve(arm, (0, 0, 0), pose="rest")


# ---- drawing sessions -----------------------------------------------------------------------

@pytest.mark.parametrize("solver", SOLVERS)
def test_run_drawing_arrays(arm, solver):
    targets = animkit.lab_shape("heart")
    run = animkit.run_drawing(arm, targets, solver=solver)
    n = len(targets)
    assert len(run) == run.frame_count == n
    assert run.iterations.dtype == np.int64 and run.iterations.shape == (n,)
    assert run.converged.dtype == bool and run.reachable.dtype == bool
    assert run.pen_down.dtype == bool and run.pen_down.all()
    assert run.joint_positions.shape == (n, 5, 3)
    np.testing.assert_array_equal(run.targets, targets)
    np.testing.assert_array_equal(run.end_effectors, run.joint_positions[:, -1])
    np.testing.assert_allclose(run.errors, np.linalg.norm(run.end_effectors - targets, axis=1),
                               rtol=1e-12)
    np.testing.assert_array_equal(run.converged, run.errors <= 1e-4)
    np.testing.assert_array_equal(run.laps, np.zeros(n))
    assert run.joint_steps[0] == 0.0 and (run.joint_steps >= 0).all()
    assert (run.solve_time_us >= 0).all()
    np.testing.assert_array_equal(run.final_pose.global_positions, run.joint_positions[-1])
    assert run.solver == solver and run.lap_count == 1 and run.warm_start
    assert run.tolerance == 1e-4 and run.max_iterations == 100
    assert run.fabrik_rotations == "rest"
    assert repr(run).startswith(f"DrawingRun(solver='{solver}', frames={n}, laps=1, ")


def test_summary_matches_the_arrays(arm):
    run = animkit.run_drawing(arm, animkit.lab_shape("star"), solver="fabrik")
    s = run.summary()
    assert s.targets == 400
    assert s.converged_fraction == pytest.approx(run.converged.mean())
    assert s.unreachable_targets == int((~run.reachable).sum())
    assert s.iterations_mean == pytest.approx(run.iterations.mean())
    assert s.iterations_median == np.median(run.iterations)
    assert s.iterations_max == run.iterations.max()
    assert s.error_mean == pytest.approx(run.errors.mean())
    assert s.error_max == run.errors.max()
    assert s.max_joint_step_rad == run.joint_steps.max()
    assert s.solve_time_us_median == pytest.approx(np.median(run.solve_time_us))
    assert repr(s).startswith("DrawingSummary(targets=400, converged_fraction=1.0, ")


@pytest.mark.parametrize("solver", SOLVERS)
def test_chained_solves_reproduce_a_session_bit_for_bit(arm, solver):
    targets = animkit.lab_shape("square")[:40]
    run = animkit.run_drawing(arm, targets, solver=solver)
    pose = None
    for i, target in enumerate(targets):
        result = animkit.solve(arm, target, solver=solver, pose=pose)
        pose = result.pose
        assert result.iterations == run.iterations[i]
        assert result.error == run.errors[i]
        np.testing.assert_array_equal(pose.global_positions, run.joint_positions[i])
    # And a session's final pose warm-starts a solve like any other.
    again = animkit.solve(arm, targets[0], solver=solver, pose=run.final_pose)
    assert again.converged


@pytest.mark.parametrize("solver", SOLVERS)
def test_laps_restart_at_rest_and_cold_start_solves_from_rest(arm, solver):
    targets = animkit.lab_shape("triangle")
    run = animkit.run_drawing(arm, targets, solver=solver, laps=2)
    n = len(targets)
    assert len(run) == 2 * n and run.lap_count == 2
    np.testing.assert_array_equal(run.laps, np.repeat([0, 1], n))
    np.testing.assert_array_equal(run.joint_positions[:n], run.joint_positions[n:])
    np.testing.assert_array_equal(run.iterations[:n], run.iterations[n:])
    assert run.joint_steps[n] == 0.0
    assert len(run.drawn_strokes()) == 2  # a new stroke each lap

    cold = animkit.run_drawing(arm, targets[:20], solver=solver, warm_start=False)
    assert not cold.warm_start
    for i in (0, 7, 19):
        fresh = animkit.solve(arm, targets[i], solver=solver)
        assert fresh.iterations == cold.iterations[i]
        np.testing.assert_array_equal(fresh.pose.global_positions, cold.joint_positions[i])
    warm = animkit.run_drawing(arm, targets[:20], solver=solver)
    assert cold.iterations[1:].sum() > warm.iterations[1:].sum()


def test_pen_flags_are_recorded_and_split_the_drawn_strokes(arm):
    targets = animkit.lab_shape("circle")[:30]
    pen = np.ones(30, bool)
    pen[10:15] = False
    run = animkit.run_drawing(arm, targets, pen_down=pen)
    np.testing.assert_array_equal(run.pen_down, pen)
    strokes = run.drawn_strokes()
    assert [len(s) for s in strokes] == [10, 15]
    np.testing.assert_array_equal(strokes[1], run.end_effectors[15:])
    as_ints = animkit.run_drawing(arm, targets, pen_down=pen.astype(int))
    np.testing.assert_array_equal(as_ints.pen_down, pen)


def test_a_trajectory_brings_its_own_pens(arm):
    trajectory = animkit.drawing_targets(text="QD")
    run = animkit.run_drawing(arm, trajectory)
    np.testing.assert_array_equal(run.targets, trajectory.targets)
    np.testing.assert_array_equal(run.pen_down, trajectory.pen_down)
    assert not run.pen_down.all()
    with pytest.raises(animkit.Error, match="pen_down must be None when targets is a Trajectory"):
        animkit.run_drawing(arm, trajectory, pen_down=trajectory.pen_down)


def test_the_lab_arm_draws_every_lab_shape(arm):
    for name in animkit.lab_shape_names():
        for solver in SOLVERS:
            s = animkit.run_drawing(arm, animkit.lab_shape(name), solver=solver).summary()
            assert s.converged_fraction == 1.0, (name, solver)
            assert s.unreachable_targets == 0


@pytest.mark.parametrize("call, message", [
    (lambda a: animkit.run_drawing(a, np.zeros((0, 3))), "the trajectory has no targets"),
    (lambda a: animkit.run_drawing(a, [[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, np.nan, 0]]),
     "target 3 has a non-finite coordinate (0, nan, 0)"),
    (lambda a: animkit.run_drawing(a, np.zeros((4, 2))),
     "targets must be an array of shape (n, 3), got shape (4, 2)"),
    (lambda a: animkit.run_drawing(a, np.zeros(3)),
     "targets must be an array of shape (n, 3), got shape (3,)"),
    (lambda a: animkit.run_drawing(a, np.zeros((4, 3)), pen_down=[1, 0]),
     "the pen list has 2 flags for 4 targets"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), pen_down=[1, np.nan]),
     "pen_down 1 is not a finite number"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), pen_down=[[1, 0]]),
     "pen_down must be a 1-D array of flags"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), laps=0), "laps must be at least 1, got 0"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), solver="sdls"),
     "unknown solver 'sdls' (expected ccd or fabrik)"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), tolerance=np.inf),
     "tolerance must be a positive finite number, got inf"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), max_iterations=-3),
     "max iterations must be at least 1, got -3"),
    (lambda a: animkit.run_drawing(a, np.zeros((2, 3)), fabrik_rotations="x"),
     "unknown fabrik_rotations 'x' (expected rest or previous)"),
    (lambda a: animkit.run_drawing(a, np.zeros((1000, 3)), laps=20000),
     "20000 laps of 1000 targets make 20000000 frames, more than the limit of 10000000"),
])
def test_bad_sessions_raise(arm, call, message):
    with pytest.raises(animkit.Error) as raised:
        call(arm)
    assert str(raised.value).startswith(message)


def test_the_gil_is_released_while_a_session_runs(arm, run_watched):
    # A worker runs a long session (one C++ call): this thread gets turns while it runs only
    # because run_drawing lets go of the GIL (see run_watched in conftest.py; no clocks).
    targets = animkit.lab_shape("star")
    turns, run, _ = run_watched(
        lambda: animkit.run_drawing(arm, targets, solver="ccd", laps=100))
    assert turns > 0, "this thread never ran while the worker was inside run_drawing"
    assert len(run) == 100 * 400


def test_sessions_in_two_threads_at_once_give_the_serial_bits(arm):
    targets = animkit.lab_shape("heart")
    serial = {solver: animkit.run_drawing(arm, targets, solver=solver, laps=20)
              for solver in SOLVERS}
    results = {}

    def draw(solver):
        results[solver] = animkit.run_drawing(arm, targets, solver=solver, laps=20)

    threads = [threading.Thread(target=draw, args=(solver,)) for solver in SOLVERS]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for solver in SOLVERS:
        np.testing.assert_array_equal(results[solver].joint_positions,
                                      serial[solver].joint_positions)
        np.testing.assert_array_equal(results[solver].iterations, serial[solver].iterations)


# ---- the same bits as the CLI -----------------------------------------------------------------

def read_path_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    columns = {name: np.array([float(r[name]) for r in rows]) for name in rows[0]}
    return columns


# What `animkit ik` is given, the same drawing for prepare_drawing(), and run_drawing()'s options.
CLI_CASES = [
    (["--shape", "star"], {"shape": "star"}, {}),
    (["--shape", "heart"], {"shape": "heart"}, {}),
    (["--text", "QD"], {"text": "QD"}, {}),
    (["--shape", "spiral", "--spacing", "0.02"], {"shape": "spiral", "spacing": 0.02}, {}),
    (["--shape", "triangle", "--laps", "2", "--cold-start"], {"shape": "triangle"},
     {"laps": 2, "warm_start": False}),
    (["--shape", "circle", "--fabrik-rotations", "previous", "--tolerance", "1e-6",
      "--max-iterations", "7"], {"shape": "circle"},
     {"fabrik_rotations": "previous", "tolerance": 1e-6, "max_iterations": 7}),
]


def run_cli(cli, out, *args):
    subprocess.run([str(cli), "ik", *args, "--out", str(out), "--no-picture"], check=True,
                   capture_output=True)
    with open(out / "metrics.json") as f:
        metrics = json.load(f)
    return read_path_csv(out / "path.csv"), metrics


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("cli_args, drawing, options", CLI_CASES,
                         ids=[" ".join(case[0]) for case in CLI_CASES])
def test_run_drawing_equals_the_cli_bit_for_bit(arm, cli, tmp_path, solver, cli_args, drawing,
                                                options):
    # path.csv holds every number at round-trip precision (%.17g), and metrics.json too: float()
    # of its text gives the very double the CLI computed, so == compares bits.
    cli_run, metrics = run_cli(cli, tmp_path / "out", *cli_args, "--solver", solver)
    run = animkit.run_drawing(arm, animkit.drawing_targets(**drawing), solver=solver, **options)
    assert len(run) == len(cli_run["frame"])
    for axis, name in enumerate("xyz"):
        np.testing.assert_array_equal(run.targets[:, axis], cli_run[f"target_{name}"])
        np.testing.assert_array_equal(run.end_effectors[:, axis], cli_run[f"end_{name}"])
    np.testing.assert_array_equal(run.iterations, cli_run["iterations"])
    np.testing.assert_array_equal(run.errors, cli_run["error"])
    np.testing.assert_array_equal(run.converged, cli_run["converged"] == 1)
    np.testing.assert_array_equal(run.reachable, cli_run["reachable"] == 1)
    np.testing.assert_array_equal(run.pen_down, cli_run["pen_down"] == 1)
    s = run.summary()
    assert s.targets == metrics["targets"]
    assert s.converged_fraction == metrics["converged_fraction"]
    assert s.unreachable_targets == metrics["unreachable_targets"]
    assert s.iterations_mean == metrics["iterations"]["mean"]
    assert s.iterations_median == metrics["iterations"]["median"]
    assert s.iterations_max == metrics["iterations"]["max"]
    assert s.error_mean == metrics["error"]["mean"]
    assert s.error_max == metrics["error"]["max"]
    assert s.max_joint_step_rad == metrics["max_joint_step_rad"]


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("target", [(0.5, 0.0, 0.3), (-0.2, 1.1, 0.7), (0.0, 1.7, 4.0)])
def test_solve_equals_the_clis_single_target_bit_for_bit(arm, cli, tmp_path, solver, target):
    cli_run, metrics = run_cli(cli, tmp_path / "out", "--target", ",".join(map(repr, target)),
                               "--solver", solver)
    result = animkit.solve(arm, target, solver=solver)
    assert result.iterations == cli_run["iterations"][0]
    assert result.error == cli_run["error"][0]
    assert result.converged == (cli_run["converged"][0] == 1)
    assert result.reachable == (cli_run["reachable"][0] == 1)
    end = result.pose.end_effector
    assert [end[0], end[1], end[2]] == [cli_run[f"end_{a}"][0] for a in "xyz"]


KINEMATICS_AND_DRAWINGS = [
    "Chain", "Pose", "IkResult", "DrawingRun", "DrawingSummary", "rest_pose",
    "forward_kinematics", "solve", "ik_solver_names", "fabrik_rotation_names", "run_drawing",
    "SpacingStats", "DrawingBox", "Trajectory", "ImageStrokes", "PreparedDrawing", "lab_shape",
    "lab_shape_names", "builtin_shape", "builtin_shape_names", "text_strokes", "read_gray_image",
    "read_mnist_image", "image_strokes", "read_curve_csv", "parse_curve_csv", "resample",
    "spacing_stats", "stroke_length", "fit_to_box", "reachable_box", "to_trajectory",
    "prepare_drawing", "drawing_targets", "render_png",
]


def described(obj):
    """The docstring without pybind11's signature lines."""
    signature = re.compile(r"^(\d+\.\s*)?\w*\(.*\)\s*->")
    lines = [line for line in (obj.__doc__ or "").splitlines()
             if line.strip() and not signature.match(line.strip())
             and line.strip() != "Overloaded function."]
    return " ".join(lines)


@pytest.mark.parametrize("name", KINEMATICS_AND_DRAWINGS)
def test_every_class_function_and_property_says_what_it_is(name):
    obj = getattr(animkit, name)
    assert obj.__module__ == "animkit"
    assert described(obj), f"{name} has no docstring"
    if isinstance(obj, type):
        assert "__repr__" in vars(obj), f"{name} has no __repr__"
        for attr, value in vars(obj).items():
            if attr.startswith("_"):
                continue
            assert described(value), f"{name}.{attr} has no docstring"
