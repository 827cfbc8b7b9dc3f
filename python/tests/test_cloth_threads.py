"""step() and run() release the GIL: two threads simulate their own cloths at once, with the
same bits as one after the other."""
import os
import signal
import sys
import threading

import numpy as np
import pytest

import animkit

BIG_STEPS = 12


def big_scene():
    # 61 x 61 particles: each step takes milliseconds, long enough for the other thread.
    return animkit.ClothScene(cloth=animkit.GridCloth(cells=60))


def test_two_threads_step_at_once_with_the_same_bits():
    big = animkit.ClothSimulator(big_scene())
    small = animkit.ClothSimulator(animkit.ClothScene())
    started = threading.Event()
    errors = []

    def run_big():
        try:
            started.set()
            big.run(frames=BIG_STEPS)  # one call: the whole run in C++
        except Exception as error:  # pragma: no cover (reported below)
            errors.append(error)

    worker = threading.Thread(target=run_big)
    worker.start()
    started.wait()
    # The main thread steps the small cloth while the big one runs, noting the big run's
    # progress before and after each small step. steps_taken counts run()'s steps as they
    # finish: seeing it strictly between 0 and BIG_STEPS means this thread ran Python code
    # while the other was inside run(), which a held GIL would not allow.
    overlapped = 0
    small_steps = 0
    while worker.is_alive():
        before = big.steps_taken
        small.step()
        small_steps += 1
        after = big.steps_taken
        if 0 < before and after < BIG_STEPS:
            overlapped += 1
    worker.join()
    assert not errors
    assert big.steps_taken == BIG_STEPS
    assert overlapped > 0, "no small step ran while the big run was in progress"

    # The same simulations one after the other give the same bits.
    big_alone = animkit.ClothSimulator(big_scene())
    big_alone.run(frames=BIG_STEPS)
    small_alone = animkit.ClothSimulator(animkit.ClothScene())
    for _ in range(small_steps):
        small_alone.step()
    np.testing.assert_array_equal(big.positions, big_alone.positions)
    np.testing.assert_array_equal(big.velocities, big_alone.velocities)
    np.testing.assert_array_equal(small.positions, small_alone.positions)
    np.testing.assert_array_equal(small.velocities, small_alone.velocities)


def test_step_releases_the_gil():
    # The worker calls step() BIG_STEPS times in a Python loop. With a switch interval of
    # 100 s the interpreter never takes the GIL from a thread: it changes hands only when a
    # thread lets go of it. If step() held the GIL, the worker's whole loop would run without
    # the main thread getting a single bytecode in, and it could only see 0 or BIG_STEPS
    # steps taken; it sees counts in between only because step() lets go while C++ runs.
    big = animkit.ClothSimulator(big_scene())
    small = animkit.ClothSimulator(animkit.ClothScene())
    started = threading.Event()

    def step_many():
        started.set()
        for _ in range(BIG_STEPS):
            big.step()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    try:
        worker = threading.Thread(target=step_many)
        worker.start()
        started.wait()
        seen = set()
        while worker.is_alive():
            seen.add(big.steps_taken)
            small.step()  # lets the worker take the GIL back between its steps
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert big.steps_taken == BIG_STEPS
    assert seen & set(range(1, BIG_STEPS)), f"saw only {sorted(seen)}"


def test_run_callback_runs_with_the_gil_between_steps():
    # The callback is Python: run() takes the GIL back for it every frame.
    sim = animkit.ClothSimulator(animkit.ClothScene())
    seen = []
    lock = threading.Lock()

    def callback(frame, report):
        with lock:
            seen.append((frame, threading.get_ident(), sim.steps_taken))

    thread = threading.Thread(target=lambda: sim.run(frames=5, callback=callback))
    thread.start()
    thread.join()
    assert [s[0] for s in seen] == [1, 2, 3, 4, 5]
    assert [s[2] for s in seen] == [1, 2, 3, 4, 5]
    assert all(s[1] == thread.ident for s in seen)


def test_ctrl_c_stops_a_long_run():
    # run() checks for signals between steps: SIGINT 50 ms into a run of 100000 steps (about
    # 10 s) raises KeyboardInterrupt long before its end, leaving the steps taken so far.
    sim = animkit.ClothSimulator(animkit.ClothScene())
    timer = threading.Timer(0.05, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sim.run(frames=100_000)
    finally:
        timer.cancel()
    assert 0 < sim.steps_taken < 100_000
    sim.step()  # still usable


def test_building_reads_its_own_copy_of_the_scene(run_watched):
    # ClothSimulator(scene) builds without the GIL from its own copy of the scene: this
    # thread, which gets turns only while a build runs (see run_watched in conftest.py),
    # changes the caller's scene meanwhile; every simulator still matches the scene it was
    # given (particle count, its `scene`), and the caller's scene keeps the last change.
    scene = big_scene()
    sizes = iter([10, 20, 30, 40] * 100)

    def change():
        scene.cloth = animkit.GridCloth(cells=next(sizes))

    def build_many():
        built = []
        for _ in range(6):
            cells = scene.cloth.cells
            built.append((cells, animkit.ClothSimulator(scene)))
        return built

    turns, built, _ = run_watched(build_many, each_turn=change)
    assert turns > 0, "this thread never ran while the worker was building"
    for cells, sim in built:
        assert sim.scene.cloth.cells == cells
        assert sim.particle_count == (cells + 1) ** 2
        assert np.isfinite(sim.positions).all()


def test_time_and_repr_are_readable_while_another_thread_steps(run_watched):
    # time and __repr__ read values published after each step (atomics), not the state a
    # step is writing: from this thread, while the worker is inside its steps, they show
    # whole steps only.
    sim = animkit.ClothSimulator(big_scene())
    dt = sim.dt

    def look():
        return sim.time, sim.steps_taken, repr(sim)

    turns, _, seen = run_watched(lambda: [sim.step() for _ in range(BIG_STEPS)],
                                 each_turn=look)
    assert turns > 0
    for time, steps, text in seen:
        whole = round(time / dt)
        assert time == pytest.approx(whole * dt, rel=0, abs=1e-12)
        assert 0 <= whole <= BIG_STEPS and 0 <= steps <= BIG_STEPS
        assert text.startswith("ClothSimulator(particles=3721, integrator='implicit-pcg', time=")
    assert sim.time == pytest.approx(BIG_STEPS * dt) and sim.steps_taken == BIG_STEPS
    assert repr(sim).endswith(f"steps_taken={BIG_STEPS})")
