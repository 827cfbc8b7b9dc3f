"""blender.cloth_drape: the cloth operator drapes a subdivided plane over a UV sphere.

    blender -b --factory-startup --python-exit-code 1 --python cloth_drape_test.py -- \
        PYTHON_DIR DATA_DIR OUT_DIR

A 1 m plane cut into a 16 x 16 grid falls from 0.35 m above a UV sphere (radius 0.25 m, on a
ground plane). Baked as shape keys: one key per frame, only the current frame's key on; every
baked vertex outside the sphere (distance from its centre >= radius) and no baked edge or
triangle crossing the sphere's mesh; the cloth moved, rests on the sphere's top and hangs down
its sides. Then its first frames are baked again as a point cache (.pc2 in OUT_DIR, Mesh Cache
modifier), which must play the same positions. Last, a point-cache bake on a thread cancelled
after its second frame writes nothing.
"""
import pathlib
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bmesh  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402

import blender_test_support as support  # noqa: E402
from blender_test_support import check  # noqa: E402
from geometry_checks import meshes_cross  # noqa: E402

RADIUS = 0.25
CENTRE = np.array([0.0, 0.0, RADIUS])
START_HEIGHT = 2 * RADIUS + 0.1
CUTS = 15
FIRST, LAST = 1, 31
CACHE_FRAMES = 11


def make_cloth():
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=(0.0, 0.0, START_HEIGHT))
    cloth = bpy.context.active_object
    cloth.name = "cloth"
    bm = bmesh.new()
    bm.from_mesh(cloth.data)
    bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=CUTS, use_grid_fill=True)
    bm.to_mesh(cloth.data)
    bm.free()
    return cloth


def make_sphere():
    bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=RADIUS,
                                         location=tuple(CENTRE))
    sphere = bpy.context.active_object
    sphere.name = "ball"
    return sphere


def world_vertices(obj):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    co = np.empty(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", co)
    mesh.calc_loop_triangles()
    tris = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", tris)
    matrix = np.array(evaluated.matrix_world)
    evaluated.to_mesh_clear()
    return co.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3], tris.reshape(-1, 3)


def baked_frames(cloth, last=LAST):
    """World positions of the cloth at each frame, as Blender evaluates them."""
    scene = bpy.context.scene
    frames = []
    for frame in range(FIRST, last + 1):
        scene.frame_set(frame)
        frames.append(world_vertices(cloth)[0])
    scene.frame_set(FIRST)
    return np.array(frames)


def run_operator(cloth, sphere, **options):
    support.make_active(cloth, sphere)
    started = time.perf_counter()
    result = bpy.ops.animkit.simulate_cloth(material="cotton", use_ground=True,
                                            ground_height=0.0, **options)
    seconds = time.perf_counter() - started
    check(result == {"FINISHED"}, f"simulate_cloth returned {result}")
    return seconds


def check_shape_keys(cloth):
    keys = cloth.data.shape_keys
    check(keys is not None, "no shape keys after the bake")
    baked = [k for k in keys.key_blocks if k.name.startswith("animkit ")]
    check(len(baked) == LAST - FIRST + 1,
          f"{len(baked)} baked shape keys for {LAST - FIRST + 1} frames")
    scene = bpy.context.scene
    for frame in (FIRST, (FIRST + LAST) // 2, LAST):
        scene.frame_set(frame)
        on = [k.name for k in baked if abs(k.value) > 1e-9]
        check(on == [f"animkit {frame}"], f"frame {frame}: keys on {on}")
    scene.frame_set(FIRST)


def check_drape(frames, sphere_vertices, sphere_tris, cloth_tris):
    distances = np.linalg.norm(frames - CENTRE, axis=2)
    inside = distances.min()
    print(f"closest cloth vertex to the sphere's centre over all frames: {inside:.6f} m "
          f"(radius {RADIUS})")
    check(inside >= RADIUS, f"a baked vertex is inside the sphere: {inside:.6f} < {RADIUS}")
    for k, positions in enumerate(frames):
        crossing = meshes_cross(positions, cloth_tris, sphere_vertices, sphere_tris)
        check(crossing == (0, 0),
              f"frame {FIRST + k}: cloth and sphere cross ({crossing[0]} cloth edges, "
              f"{crossing[1]} sphere edges through the other's triangles)")
    start, end = frames[0], frames[-1]
    check(np.allclose(start[:, 2], START_HEIGHT, atol=1e-6), "the first frame is not the start")
    moved = np.linalg.norm(end - start, axis=1).max()
    top = CENTRE[2] + RADIUS
    horizontal = np.linalg.norm(end[:, :2] - CENTRE[:2], axis=1)
    over_top = end[horizontal < 0.1, 2]
    lowest = end[:, 2].min()
    print(f"last frame: moved up to {moved:.3f} m, lowest point {lowest:.3f} m (start "
          f"{START_HEIGHT}), cloth over the top at {over_top.min():.3f}..{over_top.max():.3f} m "
          f"(sphere top {top})")
    check(lowest < START_HEIGHT - 0.2, f"the cloth did not fall: lowest point {lowest:.3f} m")
    check(len(over_top) > 0 and np.all(np.abs(over_top - top) < 0.03),
          f"the cloth does not rest on the sphere's top: {over_top}")
    check(lowest < top - RADIUS, f"the cloth does not hang down the sphere's sides: lowest "
                                 f"point {lowest:.3f} m, sphere top {top} m")


def check_cancel(cloth, sphere, cache_dir):
    """What Esc does from the menu (the operator's modal run): the bake runs on a thread and is
    cancelled after its second frame; it then writes nothing, neither a point cache file nor a
    modifier."""
    from animkit_blender.cloth_operator import ClothBake
    support.make_active(cloth, sphere)
    options = {"material": "cotton", "gravity": 9.81, "friction": 0.3, "use_ground": True,
               "ground_height": 0.0, "substeps": 0, "bake_mode": "POINT_CACHE",
               "cache_dir": str(cache_dir)}
    job = ClothBake(bpy.context, cloth, [sphere], options)
    thread = threading.Thread(target=job.run)
    thread.start()
    while job.frames_done < 2 and thread.is_alive():
        time.sleep(0.01)
    job.cancel()
    thread.join()
    stats = job.finish()
    check(job.cancelled and job.error is None, "the bake was not cancelled cleanly")
    check(2 <= job.frames_done < job.frame_count - 1,
          f"cancelled after {job.frames_done} of {job.frame_count - 1} frames")
    check("cache" not in stats and "keys" not in stats, f"a cancelled bake reported {stats}")
    left = sorted(p.name for p in cache_dir.iterdir()) if cache_dir.exists() else []
    check(left == [], f"a cancelled bake left files: {left}")
    check(cloth.modifiers.get("animkit cache") is None and cloth.data.shape_keys is None,
          "a cancelled bake left a modifier or shape keys")
    print(f"cancelled after frame {job.frames_done}: nothing written")


def main():
    python_dir, _, out_dir = support.arguments(3, "PYTHON_DIR DATA_DIR OUT_DIR")
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    support.load_addon(python_dir)
    support.empty_scene()
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = 30, 1.0
    scene.frame_start, scene.frame_end = FIRST, LAST
    cloth = make_cloth()
    sphere = make_sphere()
    sphere_vertices, sphere_tris = world_vertices(sphere)
    cloth_tris = world_vertices(cloth)[1]
    print(f"cloth: {len(cloth.data.vertices)} vertices; sphere: {len(sphere_vertices)} "
          f"vertices, {len(sphere_tris)} triangles")

    seconds = run_operator(cloth, sphere)
    print(f"shape-key bake: {LAST - FIRST + 1} frames in {seconds:.2f} s")
    check_shape_keys(cloth)
    frames = baked_frames(cloth)
    check_drape(frames, sphere_vertices, sphere_tris, cloth_tris)

    # The same simulation as a point cache, over the first CACHE_FRAMES frames (the run is
    # deterministic): the shape keys go, a Mesh Cache modifier plays it.
    scene.frame_end = FIRST + CACHE_FRAMES - 1
    seconds = run_operator(cloth, sphere, bake_mode="POINT_CACHE", cache_dir=str(out))
    print(f"point-cache bake: {CACHE_FRAMES} frames in {seconds:.2f} s")
    check(cloth.data.shape_keys is None, "the point-cache bake left shape keys")
    modifier = cloth.modifiers.get("animkit cache")
    check(modifier is not None and modifier.type == "MESH_CACHE", "no Mesh Cache modifier")
    path = pathlib.Path(bpy.path.abspath(modifier.filepath))
    check(path.is_file() and path.parent == out.resolve(), f"no cache file at {path}")
    cached = baked_frames(cloth, scene.frame_end)
    difference = np.abs(cached - frames[:CACHE_FRAMES]).max()
    print(f"point cache {path}: largest difference from the shape keys {difference:.3g} m")
    check(difference < 1e-5, f"the point cache plays other positions ({difference:.3g} m)")
    check_cancel(cloth, sphere, out / "cancelled")
    print("cloth_drape_test: OK")


main()
