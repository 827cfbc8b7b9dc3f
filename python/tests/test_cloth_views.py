"""ClothSimulator.positions and .velocities: read-only numpy views of the simulator's own
state, which every integrator, set_state and a diverged step's undo update in place."""
import gc
import weakref

import numpy as np
import pytest

import animkit


def data_pointer(array):
    return array.__array_interface__["data"][0]


@pytest.mark.parametrize("integrator", animkit.integrator_names())
def test_views_follow_every_integrator(integrator):
    scene = animkit.ClothScene(integrator=integrator,
                               substeps=20 if integrator == "explicit" else 0)
    sim = animkit.ClothSimulator(scene)
    positions, velocities = sim.positions, sim.velocities
    assert positions.shape == (sim.particle_count, 3) and positions.dtype == np.float64
    start = positions.copy()
    # Checked after every step (an implementation swapping buffers would alternate between
    # two, right again after an even number of steps), then after 10 more in one run().
    for _ in range(11):
        sim.step()
        assert data_pointer(positions) == data_pointer(sim.positions)
        assert data_pointer(velocities) == data_pointer(sim.velocities)
        np.testing.assert_array_equal(positions, np.array(sim.positions, copy=True))
    sim.run(frames=10)
    # The old views are the state: same memory as fresh ones, and the new values.
    assert np.shares_memory(positions, sim.positions)
    assert data_pointer(positions) == data_pointer(sim.positions)
    assert data_pointer(velocities) == data_pointer(sim.velocities)
    fresh = np.array(sim.positions, copy=True)
    np.testing.assert_array_equal(positions, fresh)
    np.testing.assert_array_equal(velocities, np.array(sim.velocities, copy=True))
    assert not np.array_equal(positions, start)
    assert np.abs(velocities).max() > 0


def test_views_follow_a_contact_scene():
    scene = animkit.ClothScene.builtin("drape-sphere")
    sim = animkit.ClothSimulator(scene)
    positions = sim.positions
    start = positions.copy()
    sim.run(frames=3)
    assert data_pointer(positions) == data_pointer(sim.positions)
    np.testing.assert_array_equal(positions, np.array(sim.positions, copy=True))
    assert not np.array_equal(positions, start)


def test_views_follow_set_state_and_a_diverged_step():
    sim = animkit.ClothSimulator(animkit.ClothScene(integrator="explicit", substeps=1))
    positions, velocities = sim.positions, sim.velocities
    n = sim.particle_count
    target = np.array(positions) + [0.0, 0.5, 0.0]
    sim.set_state(target, np.full((n, 3), 5e7))
    assert data_pointer(positions) == data_pointer(sim.positions)
    np.testing.assert_array_equal(positions, target)
    before = np.array(velocities)
    with pytest.raises(animkit.Error, match="diverged"):
        sim.step(dt=10)
    # Undone in place: the views show the state as it was.
    assert data_pointer(velocities) == data_pointer(sim.velocities)
    np.testing.assert_array_equal(positions, target)
    np.testing.assert_array_equal(velocities, before)


def test_views_are_read_only():
    sim = animkit.ClothSimulator(animkit.ClothScene())
    positions = sim.positions
    assert not positions.flags.writeable and not sim.velocities.flags.writeable
    with pytest.raises(ValueError):
        positions[0, 0] = 1.0
    with pytest.raises(ValueError):
        sim.velocities[:] = 0.0
    with pytest.raises(ValueError):
        positions.flags.writeable = True  # the base is not an array that owns its data
    assert sim.time == 0 and np.array_equal(positions[0], [0.0, 1.5, -1.0])


def test_a_view_keeps_the_simulator_alive():
    sim = animkit.ClothSimulator(animkit.ClothScene())
    sim.run(frames=5)
    positions = sim.positions
    expected = positions.copy()
    alive = weakref.ref(sim)
    del sim
    gc.collect()
    assert alive() is not None  # the view holds it as its base
    # Memory churn that would reuse a freed state buffer.
    garbage = [np.random.default_rng(k).random((121, 3)) for k in range(200)]
    np.testing.assert_array_equal(positions, expected)
    del garbage
    del positions
    gc.collect()
    assert alive() is None  # and lets it go with the last view
