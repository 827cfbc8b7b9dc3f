"""The bindings' array conversions driven with random inputs: every function that takes an array
gets random shapes, dtypes, memory layouts and values (NaN, infinities, 1e300, empty arrays,
ragged lists, strings, None). Each call either returns or raises animkit.Error (TypeError only
when pybind11 finds no overload for a non-array argument); none may crash the interpreter or
return a non-finite number from finite input."""
import math

import numpy as np
import pytest

import animkit

SEED = 20261127
CALLS_PER_TARGET = 400

SPECIAL = [0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, -1e300, math.nan, math.inf, -math.inf]


def random_shape(rng):
    choice = rng.integers(0, 8)
    if choice == 0:
        return ()
    if choice < 3:
        return (int(rng.choice([0, 1, 2, 3, 4, 5, 7])),)
    if choice < 6:
        return (int(rng.integers(0, 6)), int(rng.choice([0, 1, 2, 3, 4, 5])))
    return tuple(int(rng.integers(0, 4)) for _ in range(int(rng.integers(3, 5))))


def random_values(rng, shape):
    values = rng.normal(scale=rng.choice([1e-3, 1.0, 1e3]), size=shape)
    if values.size and rng.random() < 0.4:
        flat = values.reshape(-1)
        picks = rng.integers(0, flat.size, size=max(1, flat.size // 4))
        flat[picks] = rng.choice(SPECIAL, size=picks.size)
    return values


def random_argument(rng, expected):
    """An array-like of a random kind: half the time of the shape the target expects."""
    kind = rng.integers(0, 12)
    shape = expected if rng.random() < 0.5 else random_shape(rng)
    values = random_values(rng, shape)
    if kind == 0:
        return None
    if kind == 1:
        return "not an array"
    if kind == 2:
        return [[1.0, 2.0, 3.0], [4.0, 5.0]]  # ragged
    if kind == 3:
        return values.tolist() if values.ndim else float(values)
    if kind == 4:
        return values.astype(np.float32)
    if kind == 5:
        with np.errstate(invalid="ignore"):
            return np.nan_to_num(values, posinf=2**62, neginf=-2**62).astype(np.int64)
    if kind == 6:
        return values.astype(complex)
    if kind == 7:
        return values.astype(object)
    if kind == 8:
        if values.ndim > 1:
            return np.asfortranarray(values)
        return values[::-1] if values.ndim else values
    if kind == 9:
        # Non-contiguous: every other row of a larger array.
        return np.repeat(values, 2, axis=0)[::2] if values.ndim else values
    if kind == 10:
        return values > 0  # bool
    return values


CHAIN = animkit.Chain.lab_arm()
SKELETON = animkit.Skeleton(["a", "b"], [-1, 0], [[0, 0, 0], [0, 1, 0]])
SCENE = animkit.ClothScene(cloth=animkit.GridCloth(cells=3, size=1.0, height=1.0))
SIMULATOR = animkit.ClothSimulator(SCENE)
HINGE = animkit.HingeLimit(axis=[1, 0, 0], min_angle=-1.0, max_angle=1.0)


def quaternions(frames, joints):
    q = np.zeros((frames, joints, 4))
    q[..., 0] = 1.0
    return q


PARTICLES = SIMULATOR.particle_count

# Each target: the call with the random argument, and the shape it expects.
TARGETS = {
    "Chain": (lambda a: animkit.Chain(a), (3, 3)),
    "Chain.from_rest_positions": (lambda a: animkit.Chain.from_rest_positions(a), (4, 3)),
    "solve": (lambda a: animkit.solve(CHAIN, a, max_iterations=20), (3,)),
    "forward_kinematics": (lambda a: animkit.forward_kinematics(CHAIN, a),
                           (CHAIN.joint_count, 4)),
    "Skeleton offsets": (lambda a: animkit.Skeleton(["a", "b"], [-1, 0], a), (2, 3)),
    "Motion rotations": (lambda a: animkit.Motion(a, np.zeros((2, 2, 3)), 1 / 30), (2, 2, 4)),
    "Motion translations": (lambda a: animkit.Motion(quaternions(2, 2), a, 1 / 30), (2, 2, 3)),
    "Collider position": (lambda a: animkit.Collider.sphere("b", position=a), (3,)),
    "Collider velocity": (lambda a: animkit.Collider.sphere("b", velocity=a), (3,)),
    "Collider rotation": (lambda a: animkit.Collider.box("b", rotation=a), (4,)),
    "Collider mesh vertices": (lambda a: animkit.Collider.mesh(
        "m", vertices=a, triangles=[[0, 1, 2]]), (3, 3)),
    "Collider mesh triangles": (lambda a: animkit.Collider.mesh(
        "m", vertices=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles=a), (1, 3)),
    "MeshCloth vertices": (lambda a: animkit.MeshCloth(vertices=a, triangles=[[0, 1, 2]]),
                           (3, 3)),
    "set_state": (lambda a: SIMULATOR.set_state(a), (PARTICLES, 3)),
    "set_external_forces": (lambda a: SIMULATOR.set_external_forces(a), (PARTICLES, 3)),
    "stroke_length": (lambda a: animkit.stroke_length(a), (5, 2)),
    "spacing_stats": (lambda a: animkit.spacing_stats([a]), (5, 2)),
    "resample": (lambda a: animkit.resample([a], spacing=0.1), (5, 2)),
    "image_strokes": (lambda a: animkit.image_strokes(a), (5, 4)),
    "swing_twist": (lambda a: animkit.swing_twist(a, [0, 1, 0]), (4,)),
    "constrain": (lambda a: animkit.constrain(HINGE, a), (4,)),
    "violation": (lambda a: animkit.violation(HINGE, a), (4,)),
    "solve_two_bone": (lambda a: animkit.solve_two_bone(a, [0, 1, 0], [0, 2, 0], [1, 1, 0],
                                                        [0, 0, 1]), (3,)),
    "reachable_box": (lambda a: animkit.reachable_box(a, 1.0), (3,)),
    "run_drawing": (lambda a: animkit.run_drawing(CHAIN, a, max_iterations=5), (4, 3)),
}


def finite_input(argument):
    try:
        array = np.asarray(argument, dtype=float)
    except (TypeError, ValueError):
        return False
    return bool(np.all(np.isfinite(array)))


def finite_output(result):
    if isinstance(result, np.ndarray) and result.dtype.kind == "f":
        return bool(np.all(np.isfinite(result)))
    if isinstance(result, float):
        return math.isfinite(result)
    return True


@pytest.mark.parametrize("name", sorted(TARGETS))
def test_random_arrays_raise_clean_errors(name):
    rng = np.random.default_rng([SEED, sorted(TARGETS).index(name)])
    target, expected = TARGETS[name]
    for _ in range(CALLS_PER_TARGET):
        argument = random_argument(rng, expected)
        try:
            result = target(argument)
        except animkit.Error as error:
            assert str(error) and "\n" not in str(error), (name, argument)
            continue
        except TypeError as error:
            # pybind11's overload resolution: only for a value that is no array at all.
            assert "incompatible function arguments" in str(error), (name, argument, error)
            continue
        # Complex numbers are refused, never cast to their real parts.
        assert not np.iscomplexobj(argument) or np.size(argument) == 0, (name, argument)
        if finite_input(argument):
            assert finite_output(result), (name, argument, result)
