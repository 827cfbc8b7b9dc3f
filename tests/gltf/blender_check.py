"""Blender 3.4 (Debian's) imports animkit's glTF files with its own importer (io_scene_gltf2):

    blender -b --factory-startup --python-exit-code 1 --python blender_check.py -- \
        PYTHON_DIR CLOTH.glb CLOTH.pc2 FPS SKELETON.glb SKELETON.bvh SCALE

- the cloth: one shape key per frame after the first; the vertices at the first, middle and
  last frames (Blender's evaluated mesh) match the point cache within 1e-5 m;
- the skeleton: every joint of the BVH is a bone, and every bone head at the first, middle and
  last frames matches animkit's forward kinematics of the BVH (read at SCALE metres per unit,
  the animkit module from PYTHON_DIR) within 1e-5 m.
Blender is Z up, glTF Y up: the importer maps glTF (x, y, z) to Blender (x, -z, y).
"""
import pathlib
import struct
import sys

import bpy
import numpy as np

# Debian's Blender 3.4 runs on Debian's NumPy 1.24, which removed the alias np.bool that its
# glTF importer still uses (io_scene_gltf2/blender/imp/gltf2_blender_mesh.py); the alias is put
# back for the importer, as docs/gltf-and-batches.md tells users to.
if "bool" not in np.__dict__:
    np.bool = bool

TOLERANCE = 1e-5
args = sys.argv[sys.argv.index("--") + 1:]
python_dir, cloth_glb, cloth_pc2, fps, skeleton_glb, skeleton_bvh, scale = args
sys.path.insert(0, python_dir)
import animkit  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def read_pc2(path):
    data = pathlib.Path(path).read_bytes()
    _, _, points, _, _, samples = struct.unpack("<12siiffi", data[:32])
    return np.frombuffer(data[32:], dtype="<f4").reshape(samples, points, 3)


def to_gltf(blender_xyz):
    """Blender (X, Y, Z) back to glTF's (x, y, z) = (X, Z, -Y)."""
    p = np.asarray(blender_xyz, dtype=float)
    return np.stack([p[..., 0], p[..., 2], -p[..., 1]], axis=-1)


def sampled(count):
    return sorted({0, (count - 1) // 2, count - 1})


def go_to_time(seconds):
    """Sets the scene to a time, between frames if need be: a BVH's frame time is rounded in
    the file (0.0083333 s), so its 496th frame lands at frame 495.998 at 120 fps."""
    frame = seconds * bpy.context.scene.render.fps
    whole = int(np.floor(frame))
    bpy.context.scene.frame_set(whole, subframe=frame - whole)


def import_glb(path, frames_per_second):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Keyframe times become frames at the scene's rate: the file's own rate keeps one frame a
    # keyframe.
    bpy.context.scene.render.fps = frames_per_second
    bpy.ops.import_scene.gltf(filepath=path)


def check_cloth():
    cache = read_pc2(cloth_pc2)
    import_glb(cloth_glb, int(fps))
    cloth = bpy.data.objects["cloth"]
    keys = cloth.data.shape_keys.key_blocks
    check(len(keys) == len(cache), f"cloth: {len(keys)} shape keys (with the basis) for "
                                   f"{len(cache)} cache frames")
    worst = 0.0
    for frame in sampled(len(cache)):
        go_to_time(frame / float(fps))
        evaluated = cloth.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        world = np.array([tuple(cloth.matrix_world @ v.co) for v in mesh.vertices])
        evaluated.to_mesh_clear()
        error = np.abs(to_gltf(world) - cache[frame]).max()
        worst = max(worst, error)
        check(error <= TOLERANCE, f"cloth frame {frame}: {error:.3g} m from the point cache")
    print(f"cloth: {len(cache)} frames, {len(cache[0])} vertices; worst {worst:.3g} m")


def check_skeleton():
    clip = animkit.read_bvh(skeleton_bvh, scale=float(scale))
    expected = clip.motion.global_positions(clip.skeleton)
    names = list(clip.skeleton.names)
    import_glb(skeleton_glb, round(1.0 / clip.frame_time))
    armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    check(len(armatures) == 1, f"{len(armatures)} armatures imported")
    armature = armatures[0]
    bones = armature.pose.bones
    missing = [n for n in names if n not in bones]
    check(not missing, f"joints missing from the armature: {missing}")
    worst = 0.0
    for frame in sampled(clip.frame_count):
        go_to_time(frame * clip.frame_time)
        for j, name in enumerate(names):
            if name not in bones:
                continue
            head = to_gltf(tuple(armature.matrix_world @ bones[name].head))
            error = float(np.linalg.norm(head - expected[frame, j]))
            worst = max(worst, error)
            check(error <= TOLERANCE, f"{name} at frame {frame}: {error:.3g} m from the BVH's")
    print(f"skeleton: {len(names)} joints, {clip.frame_count} frames; worst {worst:.3g} m")


check_cloth()
check_skeleton()
if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("ok")
