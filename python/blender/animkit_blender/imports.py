"""File > Import entries that work in Debian's Blender 3.4 as it ships:

- Motion capture (.bvh) for animkit: Blender's own BVH importer (io_anim_bvh) opens files with
  mode 'rU', which Python 3.11 refuses ("invalid mode: 'rU'"); this runs the same importer with
  the 'U' dropped while it reads. The armature keeps the file's units (the foot-lock operator
  tells them from the legs) and one BVH frame per Blender frame, at the file's rate.
- glTF 2.0 (.glb) from animkit: Blender's glTF importer still uses numpy's `np.bool`, which the
  NumPy of Debian 12 (1.24) removed; the alias is put back (it is the builtin bool) first.
"""
import builtins

import bpy
from bpy_extras.io_utils import ImportHelper

_OPEN = builtins.open


def _open_without_u(file, mode="r", *args, **kwargs):
    if isinstance(mode, str):
        mode = mode.replace("U", "")
    return _OPEN(file, mode, *args, **kwargs)


def import_bvh(path, scale=1.0, **options):
    """Imports a BVH file with io_anim_bvh (global_scale=scale, one BVH frame per Blender frame
    from frame 1, the scene's fps set to the file's) and returns the new armature object."""
    before = set(bpy.context.scene.objects)
    builtins.open = _open_without_u
    try:
        result = bpy.ops.import_anim.bvh(
            filepath=str(path), target="ARMATURE", global_scale=scale, frame_start=1,
            use_fps_scale=False, update_scene_fps=True, update_scene_duration=True,
            rotate_mode="NATIVE", **options)
    finally:
        builtins.open = _OPEN
    if result != {"FINISHED"}:
        raise RuntimeError(f"import of {path} returned {result}")
    armatures = [o for o in bpy.context.scene.objects
                 if o not in before and o.type == "ARMATURE"]
    if len(armatures) != 1:
        raise RuntimeError(f"expected 1 new armature after the import, found {len(armatures)}")
    return armatures[0]


def restore_numpy_bool():
    """Puts numpy's removed alias np.bool back (the builtin bool) for Blender 3.4's glTF
    importer (io_scene_gltf2/blender/imp/gltf2_blender_mesh.py)."""
    import numpy
    if "bool" not in numpy.__dict__:
        numpy.bool = bool


def import_gltf(path):
    """Imports a .glb or .gltf file with Blender's importer, numpy's alias restored first."""
    restore_numpy_bool()
    result = bpy.ops.import_scene.gltf(filepath=str(path))
    if result != {"FINISHED"}:
        raise RuntimeError(f"import of {path} returned {result}")


class ANIMKIT_OT_import_bvh(bpy.types.Operator, ImportHelper):
    """Import a BVH motion-capture clip as an armature (Blender's importer, made to work in
    Blender 3.4 on Python 3.11)"""
    bl_idname = "animkit.import_bvh"
    bl_label = "Motion capture (.bvh) for animkit"
    bl_options = {"REGISTER", "UNDO"}
    filename_ext = ".bvh"
    filter_glob: bpy.props.StringProperty(default="*.bvh", options={"HIDDEN"})

    def execute(self, context):
        try:
            armature = import_bvh(self.filepath)
        except (RuntimeError, OSError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        self.report({"INFO"}, f"imported '{armature.name}' in the file's units; Lock feet with "
                              "animkit tells them from the legs")
        return {"FINISHED"}


class ANIMKIT_OT_import_gltf(bpy.types.Operator, ImportHelper):
    """Import a glTF 2.0 file animkit wrote (cloth.glb, fixed.glb, ...) with Blender's importer,
    made to work with Debian's NumPy"""
    bl_idname = "animkit.import_gltf"
    bl_label = "glTF 2.0 (.glb) from animkit"
    bl_options = {"REGISTER", "UNDO"}
    filename_ext = ".glb"
    filter_glob: bpy.props.StringProperty(default="*.glb;*.gltf", options={"HIDDEN"})

    def execute(self, context):
        try:
            import_gltf(self.filepath)
        except (RuntimeError, OSError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        return {"FINISHED"}


def menu_entries(self, context):
    self.layout.operator(ANIMKIT_OT_import_bvh.bl_idname)
    self.layout.operator(ANIMKIT_OT_import_gltf.bl_idname)
