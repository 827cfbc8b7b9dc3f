"""blender.user_install, run by user_install_test.sh in a Blender whose user folder the install
script filled (no --factory-startup, so the user's add-ons load):

    blender -b --python-exit-code 1 --python user_install_check.py -- DATA_DIR OUT_DIR

The add-on is enabled and animkit imports from the user's modules folder; File > Import's BVH
entry imports the CMU walk at its own units, the foot-lock operator tells them and locks it;
the glTF entry imports a cloth.glb the module writes here.
"""
import pathlib
import sys

import bpy

data_dir, out_dir = (pathlib.Path(a) for a in sys.argv[sys.argv.index("--") + 1:])
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


check("animkit_blender" in bpy.context.preferences.addons, "the add-on is not enabled")
import animkit  # noqa: E402

check("/scripts/modules/animkit/" in animkit.__file__, f"animkit from {animkit.__file__}")

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
result = bpy.ops.animkit.import_bvh(filepath=str(data_dir / "cmu" / "131_01.bvh"))
check(result == {"FINISHED"}, f"import_bvh returned {result}")
armature = next(o for o in bpy.context.scene.objects if o.type == "ARMATURE")
bpy.context.view_layer.objects.active = armature
armature.select_set(True)
result = bpy.ops.animkit.lock_feet()
check(result == {"FINISHED"}, f"lock_feet on the walk in CMU's units returned {result}")

out_dir.mkdir(parents=True, exist_ok=True)
scene = animkit.ClothScene.builtin("drape-sphere")
scene.frames = 3
animkit.ClothSimulator(scene).run(sinks=[animkit.GltfSink(out_dir / "cloth.glb")])
result = bpy.ops.animkit.import_gltf(filepath=str(out_dir / "cloth.glb"))
check(result == {"FINISHED"}, f"import_gltf returned {result}")
cloth = bpy.data.objects.get("cloth")
check(cloth is not None and len(cloth.data.shape_keys.key_blocks) == 4,
      "cloth.glb did not come in with its 3 frames as shape keys")

if failures:
    sys.exit(1)
print("user_install_check: OK")
