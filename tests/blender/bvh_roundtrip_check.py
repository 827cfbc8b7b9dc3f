"""Imports a BVH file animkit wrote into Blender and checks the armature against animkit.

    blender -b --python-exit-code 1 --python tests/blender/bvh_roundtrip_check.py -- \
        IN.bvh [EXPECTED.json]

EXPECTED.json (default: IN with the suffix .json), as animkit_bvh_blender_fixture writes it:
{"bones": [names], "frames": [{"frame": f, "heads": {name: [x, y, z]}}], "tolerance": t}
with f counted from 0 and positions in the BVH's own axes (Y up). The import keeps those axes
(forward Y, up Z is Blender's own frame, so no conversion) and maps BVH frame f to Blender
frame 1 + f. Any difference raises, and --python-exit-code 1 turns that into a failed run.
"""
import builtins
import json
import math
import pathlib
import sys

import bpy

# Blender 3.4's BVH importer opens files with mode 'rU'; Python 3.11 removed 'U' (it was a
# no-op since 3.0) and raises ValueError. Drop it for the duration of the import.
_open = builtins.open


def _open_without_u(file, mode="r", *args, **kwargs):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _open(file, mode, *args, **kwargs)


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not args:
        raise SystemExit("usage: blender -b --python bvh_roundtrip_check.py -- IN.bvh [EXP.json]")
    bvh = pathlib.Path(args[0])
    expected_path = pathlib.Path(args[1]) if len(args) > 1 else bvh.with_suffix(".json")
    expected = json.loads(expected_path.read_text())

    builtins.open = _open_without_u
    try:
        result = bpy.ops.import_anim.bvh(
            filepath=str(bvh), target="ARMATURE", global_scale=1.0, frame_start=1,
            use_fps_scale=False, rotate_mode="NATIVE", axis_forward="Y", axis_up="Z")
    finally:
        builtins.open = _open
    if result != {"FINISHED"}:
        raise RuntimeError(f"import of {bvh} returned {result}")

    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    if len(armatures) != 1:
        raise RuntimeError(f"expected 1 armature after the import, found {len(armatures)}")
    armature = armatures[0]

    names = [bone.name for bone in armature.data.bones]
    if sorted(names) != sorted(expected["bones"]):
        raise RuntimeError(f"bone names differ: Blender {sorted(names)}, "
                           f"animkit {sorted(expected['bones'])}")

    tolerance = expected["tolerance"]
    scene = bpy.context.scene
    worst = 0.0
    for entry in expected["frames"]:
        scene.frame_set(1 + entry["frame"])
        for name, want in entry["heads"].items():
            head = armature.matrix_world @ armature.pose.bones[name].head
            error = math.dist(head, want)
            worst = max(worst, error)
            if error > tolerance:
                raise RuntimeError(
                    f"frame {entry['frame']} bone {name}: Blender head {tuple(head)}, "
                    f"animkit {tuple(want)} ({error:.3g} apart, tolerance {tolerance})")
    print(f"bvh_roundtrip_check: {len(names)} bones, {len(expected['frames'])} frames, "
          f"largest head difference {worst:.3g} (tolerance {tolerance}): OK")


main()
