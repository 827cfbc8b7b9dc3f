"""What the add-on's headless tests share: their arguments, finding the animkit module and the
add-on, an empty scene, the BVH import, and geometry checks.

Run by run_blender_test.sh as `blender -b --factory-startup --python-exit-code 1 --python
TEST.py -- PYTHON_DIR DATA_DIR [MORE...]`: PYTHON_DIR is the build's python folder (holding
the animkit package), DATA_DIR the repository's data/. The add-on is loaded from this source
tree (python/blender), so the tests run what the repository holds, not an installed copy.
"""
import pathlib
import sys

ADDON_DIR = pathlib.Path(__file__).resolve().parents[1]


def arguments(count, usage):
    """The script's arguments after '--' (at least `count`), else exits with `usage`."""
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) < count:
        raise SystemExit(f"usage: blender -b --python {pathlib.Path(sys.argv[0]).name} -- "
                         f"{usage}")
    return args


def load_addon(python_dir):
    """Puts the build's animkit first on sys.path, registers the add-on from the source tree
    and returns (animkit, animkit_blender)."""
    sys.path.insert(0, str(pathlib.Path(python_dir).resolve()))
    sys.path.insert(0, str(ADDON_DIR))
    import animkit
    import animkit_blender
    animkit_blender.register()
    print(f"animkit {getattr(animkit, '__version__', '?')} from {animkit.__file__}")
    return animkit, animkit_blender


def empty_scene():
    """Removes every object of the factory scene (cube, camera, light)."""
    import bpy
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)


def import_bvh(path, scale, **options):
    """Imports a BVH file through the add-on's importer (animkit_blender.imports: Blender's
    io_anim_bvh, made to work on Python 3.11) and returns the armature object."""
    from animkit_blender import imports
    return imports.import_bvh(path, scale, **options)


def make_active(*objects):
    """Selects exactly `objects` and makes the first one active."""
    import bpy
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


def check(condition, message):
    """Raises AssertionError(message) unless condition (so the failure says what was wrong)."""
    if not condition:
        raise AssertionError(message)
