"""animkit for Blender: cloth simulation and foot locking from animkit's Python module.

Install both into your own Blender, no root needed: `make blender` (scripts/install-blender.sh
copies the module and this folder into ~/.config/blender/<version>/scripts and enables the
add-on). File > Import gains BVH and glTF entries that work in Debian's Blender 3.4.
"""

bl_info = {
    "name": "animkit",
    "author": "animkit",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Object menu > Simulate cloth with animkit / Lock feet with animkit (F3)",
    "description": "Cloth simulation and foot locking with the animkit library",
    "category": "Animation",
}

import bpy  # noqa: E402  (after bl_info, as Blender add-ons are laid out)

from . import cloth_operator, footlock_operator, imports  # noqa: E402

_classes = []


def _menu(self, context):
    self.layout.separator()
    self.layout.operator(cloth_operator.ANIMKIT_OT_simulate_cloth.bl_idname)
    self.layout.operator(footlock_operator.ANIMKIT_OT_lock_feet.bl_idname)


def register():
    """Registers the operators and adds them to the Object menu."""
    _classes[:] = [cloth_operator.ANIMKIT_OT_simulate_cloth,
                   footlock_operator.make_operator_class(), imports.ANIMKIT_OT_import_bvh,
                   imports.ANIMKIT_OT_import_gltf]
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_object.append(_menu)
    bpy.types.TOPBAR_MT_file_import.append(imports.menu_entries)


def unregister():
    """Removes what register() added."""
    bpy.types.VIEW3D_MT_object.remove(_menu)
    bpy.types.TOPBAR_MT_file_import.remove(imports.menu_entries)
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
    _classes.clear()
