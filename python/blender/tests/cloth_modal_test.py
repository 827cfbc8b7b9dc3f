"""blender.cloth_modal: the cloth operator from the menu (its modal run) in a Blender with a
window (run_blender_window_test.sh: Xvfb, simulated events).

    xvfb-run -a blender --factory-startup --enable-event-simulate --python cloth_modal_test.py \
        -- PYTHON_DIR DATA_DIR

A 10 x 10 plane over a sphere, 31 frames (small: the test waits twice the cancelled run's length
after the Esc, and with a 16 x 16 plane, beside the suite's other tests, the whole took over the
minute a test outside the slow tier is given). Invoked as the menu does, the operator returns
RUNNING_MODAL at once (the run goes on a thread, Blender's event loop keeps going) and, when the
run ends, leaves one shape key per frame. Invoked again and sent Esc while it runs, it leaves no
shape key at all. Blender's timers drive the test; it ends Blender with exit status 0 when both
hold, 1 otherwise (os._exit: a failed check inside a timer would only print).
"""
import os
import pathlib
import sys
import time
import traceback

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bmesh  # noqa: E402
import bpy  # noqa: E402

import blender_test_support as support  # noqa: E402

FRAMES = 31
TIMEOUT = 120.0  # s for each bake (2.7 s measured on a 2-core machine with nothing beside it)


def make_scene():
    support.empty_scene()
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=(0.0, 0.0, 0.6))
    cloth = bpy.context.active_object
    bm = bmesh.new()
    bm.from_mesh(cloth.data)
    bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=9, use_grid_fill=True)
    bm.to_mesh(cloth.data)
    bm.free()
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.25, location=(0.0, 0.0, 0.25))
    sphere = bpy.context.active_object
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, FRAMES
    support.make_active(cloth, sphere)
    return cloth


def invoke():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    with bpy.context.temp_override(window=window, area=area):
        return bpy.ops.animkit.simulate_cloth("INVOKE_DEFAULT", use_ground=True)


def shape_keys(cloth):
    keys = cloth.data.shape_keys
    return [k.name for k in keys.key_blocks if k.name.startswith("animkit ")] if keys else []


def finish(ok, message):
    print(f"cloth_modal_test: {message}", flush=True)
    os._exit(0 if ok else 1)


def steps(cloth):
    """The test as a generator: each yield waits that many seconds (a Blender timer)."""
    result = invoke()
    if result != {"RUNNING_MODAL"}:
        finish(False, f"the menu's call returned {result}, not RUNNING_MODAL")
    started = time.perf_counter()
    while len(shape_keys(cloth)) < FRAMES and time.perf_counter() - started < TIMEOUT:
        yield 0.5
    baked = len(shape_keys(cloth))
    seconds = time.perf_counter() - started
    print(f"modal bake: {baked} shape keys after {seconds:.1f} s")
    if baked != FRAMES:
        finish(False, f"the modal bake left {baked} shape keys for {FRAMES} frames")

    # The cancelled run is four times as long, so the Esc reaches it while it runs however fast
    # the bake has become (31 frames took under a second once contact got faster, and an Esc
    # sent half a second in could come after the end).
    bpy.context.scene.frame_end = 4 * FRAMES
    result = invoke()
    if result != {"RUNNING_MODAL"}:
        finish(False, f"the second call returned {result}")
    yield 0.1
    bpy.context.window_manager.windows[0].event_simulate(type="ESC", value="PRESS")
    started = time.perf_counter()
    # The run stops after the frame in progress; wait far longer than the whole run would take,
    # so an Esc that did not stop it would have let it finish and bake.
    while time.perf_counter() - started < 2.0 * 4 * seconds + 5.0:
        yield 0.5
    left = shape_keys(cloth)
    if left:
        finish(False, f"Esc left {len(left)} shape keys")
    finish(True, "OK (a modal bake, then one cancelled with Esc that baked nothing)")


def main():
    python_dir, _ = support.arguments(2, "PYTHON_DIR DATA_DIR")
    support.load_addon(python_dir)
    cloth = make_scene()
    test = steps(cloth)

    def tick():
        try:
            return next(test)
        except StopIteration:
            return None
        except Exception:  # noqa: BLE001 - any failure ends Blender with status 1
            traceback.print_exc()
            finish(False, "raised")

    bpy.app.timers.register(tick, first_interval=1.0)
    bpy.app.timers.register(lambda: finish(False, "timed out"), first_interval=4 * TIMEOUT)


main()
