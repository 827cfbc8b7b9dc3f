"""blender.armature_roundtrip: the add-on's armature <-> animkit conversion is exact.

    blender -b --factory-startup --python-exit-code 1 --python armature_roundtrip_test.py -- \
        PYTHON_DIR DATA_DIR

Imports the CMU walk (data/cmu/131_01.bvh) with io_anim_bvh (bones with non-identity rest
matrices), moves, turns and scales the armature object, then:
1. builds the animkit Skeleton and Motion from the armature and its action; animkit's forward
   kinematics must put every joint on its bone's world head, every frame (to 1e-5 m);
2. writes the motion back unchanged as rotation_quaternion keys of every bone; Blender's
   world heads must be where they were (to 1e-5 m).
"""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bpy  # noqa: E402
import mathutils  # noqa: E402
import numpy as np  # noqa: E402

import blender_test_support as support  # noqa: E402
from blender_test_support import check  # noqa: E402

CMU_SCALE = 0.056444  # metres per CMU BVH unit (the CLI's --scale for CMU files)
TOLERANCE = 1e-5
OBJECT_SCALE = 2.0


def main():
    python_dir, data_dir = support.arguments(2, "PYTHON_DIR DATA_DIR")
    animkit, _ = support.load_addon(python_dir)
    from animkit_blender import armature_motion, footlock_operator
    support.empty_scene()
    armature = support.import_bvh(pathlib.Path(data_dir) / "cmu" / "131_01.bvh", CMU_SCALE)
    rests = [np.array(b.matrix_local)[:3, :3] for b in armature.data.bones]
    turned = sum(not np.allclose(r, np.eye(3), atol=1e-6) for r in rests)
    print(f"{len(rests)} bones, {turned} with a non-identity rest rotation")
    check(turned > len(rests) // 2, "the imported bones rest unrotated: the test proves little")

    # Away from the origin, turned about a slanted axis and scaled: the object's transform
    # must be part of the mapping. Metres per unit then 1 / OBJECT_SCALE.
    armature.location = (0.7, -1.3, 0.2)
    armature.rotation_mode = "QUATERNION"
    armature.rotation_quaternion = mathutils.Quaternion((0.3, 0.2, 1.0), math.radians(35))
    armature.scale = (OBJECT_SCALE,) * 3
    bpy.context.view_layer.update()

    frames = footlock_operator.action_frames(armature.animation_data.action)
    mapping = armature_motion.ArmatureMapping(armature, 1.0 / OBJECT_SCALE)
    names, parents, offsets = mapping.skeleton_arrays()
    skeleton = animkit.Skeleton(names, parents, offsets)
    rotations, translations, heads = armature_motion.sample_motion(bpy.context, mapping, frames)
    motion = animkit.Motion(rotations, translations, frame_time=1.0 / 120.0)
    print(f"{motion.frame_count} frames of {motion.joint_count} joints")
    check(motion.frame_count == len(frames) == 994, f"{len(frames)} frames sampled")

    # 1. animkit's FK lands on Blender's heads.
    fk = np.asarray(motion.global_positions(skeleton))
    expected = mapping.world_points_to_animkit(heads)
    fk_error = np.abs(fk - expected).max()
    print(f"animkit FK vs Blender heads: largest difference {fk_error:.3g} m")
    check(fk_error < TOLERANCE, f"animkit FK misses Blender's heads by {fk_error:.3g} m")
    # The rest skeleton too: joint positions at rest are the rest heads.
    rest_heads = mapping.points_to_animkit(mapping.rest_heads)
    rest_fk = np.asarray(skeleton_rest_positions(animkit, skeleton))
    check(np.abs(rest_fk - rest_heads).max() < 1e-9, "the skeleton's rest is not the armature's")

    # 2. Written back unchanged, Blender's heads stay put.
    armature_motion.write_rotation_keys(mapping, frames, rotations, names)
    check(all(armature.pose.bones[n].rotation_mode == "QUATERNION" for n in names),
          "rotation modes not set to QUATERNION")
    euler = [c.data_path for c in armature.animation_data.action.fcurves
             if c.data_path.endswith("rotation_euler")]
    check(not euler, f"Euler curves left behind: {euler[:3]}")
    _, _, heads_after = armature_motion.sample_motion(bpy.context, mapping, frames)
    roundtrip_error = np.linalg.norm(heads_after - heads, axis=2).max() / OBJECT_SCALE
    print(f"round trip: largest head displacement {roundtrip_error:.3g} m")
    check(roundtrip_error < TOLERANCE,
          f"writing the motion back moved a head by {roundtrip_error:.3g} m")
    print("armature_roundtrip_test: OK")


def skeleton_rest_positions(animkit, skeleton):
    """World joint positions of the skeleton at rest (one frame of rest locals)."""
    count = skeleton.joint_count
    rotations = np.zeros((1, count, 4))
    rotations[..., 0] = 1.0
    translations = np.asarray(skeleton.rest_offsets)[None]
    return animkit.Motion(rotations, translations).global_positions(skeleton)[0]


main()
