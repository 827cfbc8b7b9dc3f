"""blender.cloth_setup: how the cloth operator reads a Blender scene, on short runs.

    blender -b --factory-startup --python-exit-code 1 --python cloth_setup_test.py -- \
        PYTHON_DIR DATA_DIR

1. Colliders: a turned, stretched cube is a box (half extents, rotation, centre in animkit's
   axes), a scaled ico sphere a sphere (made a little larger, so its inscribed surface holds
   the true sphere), a cone a triangle mesh; an animated sphere is keyframed along its path.
2. Pins: the vertices of the cloth's vertex group "pin" stay put, the others fall (on a
   turned, scaled plane: the bake converts back to the object's own space).
3. Errors: a cloth starting inside a collider, or no animkit module, cancel the operator with
   an error report (no Python exception escapes it).
"""
import math
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bpy  # noqa: E402
import mathutils  # noqa: E402
import numpy as np  # noqa: E402

import blender_test_support as support  # noqa: E402
from blender_test_support import check  # noqa: E402


def to_animkit(v):
    return np.array([v[0], v[2], -v[1]])


def repr_vector(text, field):
    match = re.search(field + r"=\(([^)]*)\)", text)
    return np.array([float(x) for x in match.group(1).split(",")])


def check_colliders(animkit):
    from animkit_blender import cloth_operator, colliders
    depsgraph = bpy.context.evaluated_depsgraph_get()

    bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0.5, -0.4, 1.0))
    cube = bpy.context.active_object
    cube.rotation_euler = (math.radians(20), math.radians(-35), math.radians(50))
    cube.scale = (0.3, 0.6, 0.9)
    bpy.context.view_layer.update()
    box, kind = cloth_operator.collider_for(animkit, cube, depsgraph, 0.3)
    check(kind == "box", f"the cube was taken for a {kind}")
    half = repr_vector(repr(box), "half_extents")
    check(np.allclose(sorted(half), [0.3, 0.6, 0.9], atol=1e-6), f"box half extents {half}")
    check(np.allclose(box.position, to_animkit(cube.location), atol=1e-6),
          f"box centre {box.position}")
    # Every corner of the animkit box is a corner of the Blender cube.
    rotation = mathutils.Quaternion(box.rotation).to_matrix()
    corners = np.array([to_animkit(cube.matrix_world @ mathutils.Vector(c))
                        for c in [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]])
    for signs in [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]:
        corner = box.position + np.array(rotation @ mathutils.Vector(np.array(signs) * half))
        miss = np.linalg.norm(corners - corner, axis=1).min()
        check(miss < 1e-5, f"box corner {corner} is {miss:.3g} from the cube's corners")

    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2, radius=0.5, location=(-1, 2, 0.3))
    ico = bpy.context.active_object
    ico.scale = (1.5, 1.5, 1.5)
    bpy.context.view_layer.update()
    ball, kind = cloth_operator.collider_for(animkit, ico, depsgraph, 0.3)
    check(kind == "sphere", f"the ico sphere was taken for a {kind}")
    radius = float(re.search(r"radius=([0-9.e-]+)", repr(ball)).group(1))
    expected = 0.75 / colliders.icosphere_inradius_ratio(3)
    check(abs(radius - expected) < 1e-6 and radius > 0.75, f"sphere radius {radius}")
    check(np.allclose(ball.position, to_animkit(ico.location), atol=1e-6), "sphere centre")

    bpy.ops.mesh.primitive_cone_add(location=(3, 0, 0))
    cone = bpy.context.active_object
    _, kind = cloth_operator.collider_for(animkit, cone, depsgraph, 0.3)
    check(kind == "mesh", f"the cone was taken for a {kind}")

    # An animated sphere: keyframed one key per frame along its path.
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 5
    ico.location = (-1, 2, 0.3)
    ico.keyframe_insert("location", frame=1)
    ico.location = (-1, 3, 0.3)
    ico.keyframe_insert("location", frame=5)
    matrices = cloth_operator.world_matrices(scene, [ico], range(1, 6))[0]
    moving, _ = cloth_operator.collider_for(animkit, ico, depsgraph, 0.3, matrices, 0.1)
    check(moving.moving and len(moving.keyframes) == 5, f"animated sphere: {moving!r}")
    scene.frame_set(4)
    position, _ = moving.pose_at(0.3)
    check(np.allclose(position, to_animkit(ico.matrix_world.translation), atol=1e-6),
          f"keyframed sphere at {position}, Blender has {tuple(ico.matrix_world.translation)}")
    scene.frame_set(1)
    for obj in (cube, ico, cone):
        bpy.data.objects.remove(obj, do_unlink=True)
    print("colliders: box, sphere, mesh and a moving sphere: OK")


def make_plane(height):
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=6, y_subdivisions=6, size=1.0,
                                    location=(0.0, 0.0, height))
    return bpy.context.active_object


def check_pins():
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 6
    cloth = make_plane(1.0)
    # Turned and scaled: the bake goes back from world space to the object's own.
    cloth.rotation_euler = (0.0, 0.0, math.radians(25))
    cloth.scale = (1.3, 0.8, 1.0)
    bpy.context.view_layer.update()
    corners = [v.index for v in cloth.data.vertices
               if abs(v.co.x) > 0.49 and v.co.y > 0.49]
    check(len(corners) == 2, f"{len(corners)} pin corners")
    group = cloth.vertex_groups.new(name="pin")
    group.add(corners, 1.0, "REPLACE")
    support.make_active(cloth)
    check(bpy.ops.animkit.simulate_cloth() == {"FINISHED"}, "simulate_cloth failed")
    keys = cloth.data.shape_keys.key_blocks
    start = np.array([v.co for v in cloth.data.vertices])
    end = np.array([p.co for p in keys["animkit 6"].data])
    still = np.linalg.norm(end[corners] - start[corners], axis=1).max()
    free = [i for i in range(len(start)) if i not in corners]
    fallen = (start[free, 2] - end[free, 2]).min()
    print(f"pins: pinned vertices moved {still:.3g}, the others fell at least {fallen:.4f}")
    check(still < 1e-9, f"a pinned vertex moved by {still}")
    check(fallen > 0.0, "a free vertex did not fall")
    bpy.data.objects.remove(cloth, do_unlink=True)


def error_report(operator):
    """The ERROR report of an operator call that must fail with one. bpy.ops raises a
    RuntimeError carrying an operator's ERROR report; an exception escaping the operator would
    show as 'Error: Python: Traceback'."""
    try:
        result = operator()
    except RuntimeError as error:
        message = str(error)
        check("Traceback" not in message, f"an exception escaped the operator: {message}")
        return message
    raise AssertionError(f"the operator did not report an error (returned {result})")


def check_errors():
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 3
    cloth = make_plane(0.0)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.3, location=(0.0, 0.0, 0.0))
    ball = bpy.context.active_object
    support.make_active(cloth, ball)
    message = error_report(bpy.ops.animkit.simulate_cloth)
    check("starts inside collider 'Sphere'" in message, f"cloth inside a collider: {message}")
    check(cloth.data.shape_keys is None, "a failed run left shape keys")

    # Without the module: the operator says how to install it.
    from animkit_blender import module
    saved = sys.modules.get("animkit")
    sys.modules["animkit"] = None
    try:
        try:
            module.load_animkit()
            raise AssertionError("load_animkit() found a hidden module")
        except module.AnimkitMissing as error:
            check("cmake --install" in str(error), f"no install hint in: {error}")
        support.make_active(cloth)
        message = error_report(bpy.ops.animkit.simulate_cloth)
        check("cmake --install" in message, f"without animkit: {message}")
    finally:
        sys.modules["animkit"] = saved
    for obj in (cloth, ball):
        bpy.data.objects.remove(obj, do_unlink=True)
    print("errors: cancelled with a report: OK")


def main():
    python_dir, _ = support.arguments(2, "PYTHON_DIR DATA_DIR")
    animkit, _ = support.load_addon(python_dir)
    support.empty_scene()
    bpy.context.scene.render.fps = 30
    check_colliders(animkit)
    check_pins()
    check_errors()
    print("cloth_setup_test: OK")


main()
