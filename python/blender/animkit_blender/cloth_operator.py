"""Operator "Simulate cloth with animkit": the active mesh is the cloth, the other selected
meshes are colliders; the simulation over the scene's frame range is baked as shape keys or as
a point cache (.pc2 + Mesh Cache modifier)."""
import math
import os
import tempfile
import time

import bpy
import numpy as np

from . import axes, bake, colliders, mesh_data
from .module import AnimkitMissing, animkit_error_types, load_animkit

MATERIALS = ("cotton", "silk", "denim", "leather", "rubber")
# animkit's sphere collider is a subdivided icosahedron inscribed in the sphere; this level
# (the library's default) and the inscribed-radius ratio of its faces set how much larger the
# collider is made so the cloth keeps out of the Blender sphere itself.
SPHERE_TESSELLATION = 3
# Longest simulated step when substeps is 0 (automatic): the lab's 1/60 s.
AUTO_MAX_STEP = 1.0 / 60.0


class ClothSetupError(ValueError):
    """Something in the Blender scene the cloth operator cannot use."""


def collider_for(animkit, obj, depsgraph, friction, matrices=None, frame_dt=1.0 / 24.0):
    """An animkit Collider for a Blender mesh object (its evaluated mesh, world space, now):
    a sphere, a box or a triangle mesh, and its kind ("sphere", "box", "mesh"). `matrices`:
    the object's world matrices (4x4) at each frame of the run, the first one now; when they
    change, the collider is keyframed (one key per frame, `frame_dt` s apart) with the object's
    rigid motion. Raises ClothSetupError for a mesh without faces or a motion that scales."""
    evaluated, mesh = mesh_data.evaluated_mesh(obj, depsgraph)
    try:
        world = mesh_data.to_world(evaluated.matrix_world, mesh_data.local_vertices(mesh))
        tris = mesh_data.triangles(mesh)
    finally:
        evaluated.to_mesh_clear()
    motion = rigid_motion(obj.name, matrices)

    def keyframes(centre, frame):
        """Per-frame (time, position, rotation) in animkit's axes of the collider's local
        frame, whose origin is `centre` and whose axes are the columns of `frame` (both in
        Blender's world at the first frame), carried by the object's motion."""
        if motion is None:
            return None
        keys = []
        for k, (r, t) in enumerate(motion):
            position = axes.points_to_animkit(r @ centre + t)
            turned = axes.matrices_to_quaternions(axes.BLENDER_TO_ANIMKIT @ r @ frame)
            keys.append((k * frame_dt, tuple(position), tuple(turned)))
        return keys

    sphere = colliders.detect_sphere(world)
    if sphere is not None:
        centre, radius = sphere
        inflated = radius / colliders.icosphere_inradius_ratio(SPHERE_TESSELLATION)
        return animkit.Collider.sphere(
            obj.name, inflated, position=tuple(axes.points_to_animkit(centre)),
            keyframes=keyframes(centre, axes.ANIMKIT_TO_BLENDER), friction=friction,
            tessellation=SPHERE_TESSELLATION), "sphere"
    box = colliders.detect_box(world)
    if box is not None:
        centre, half, rotation = box
        # The box's local axes (its edges, Blender world) seen in animkit's world axes.
        quaternion = axes.matrices_to_quaternions(axes.BLENDER_TO_ANIMKIT @ rotation)
        return animkit.Collider.box(
            obj.name, tuple(half), position=tuple(axes.points_to_animkit(centre)),
            rotation=tuple(quaternion), keyframes=keyframes(centre, rotation),
            friction=friction), "box"
    if len(tris) == 0:
        raise ClothSetupError(f"collider '{obj.name}' has no faces")
    # The mesh's local frame is the world at the first frame.
    return animkit.Collider.mesh(obj.name, axes.points_to_animkit(world), tris,
                                 keyframes=keyframes(np.zeros(3), axes.ANIMKIT_TO_BLENDER),
                                 friction=friction), "mesh"


def rigid_motion(name, matrices):
    """None if the world matrices (4x4, per frame) never change; else, per frame, (R, t) of
    the rigid transform M_k M_0^-1 carrying the first frame's world onto frame k's. Raises
    ClothSetupError if that transform scales or shears (a collider keeps its shape)."""
    if matrices is None or len(matrices) < 2:
        return None
    m = [np.array(matrix, dtype=np.float64) for matrix in matrices]
    if all(np.allclose(x, m[0], rtol=0.0, atol=1e-9) for x in m[1:]):
        return None
    inverse = np.linalg.inv(m[0])
    motion = []
    for x in m:
        a = x @ inverse
        r = a[:3, :3]
        if np.max(np.abs(r.T @ r - np.eye(3))) > 1e-6:
            raise ClothSetupError(f"collider '{name}' changes its scale or shape while it "
                                  "moves: only rigid motion can be simulated")
        motion.append((axes.orthonormalize(r), a[:3, 3].copy()))
    return motion


def world_matrices(scene, objects, frames):
    """Each object's world matrix at each frame (lists of 4x4 arrays), by evaluating the scene
    frame by frame (animation, parents, constraints). Leaves the scene on frames[0]."""
    out = [[] for _ in objects]
    if not objects:
        scene.frame_set(frames[0])
        return out
    for frame in frames:
        scene.frame_set(frame)
        for k, obj in enumerate(objects):
            out[k].append(np.array(obj.matrix_world, dtype=np.float64))
    scene.frame_set(frames[0])
    return out


def cloth_arrays(obj, depsgraph, pin_group="pin"):
    """(world vertices (n, 3) Blender axes, triangles (m, 3), pinned vertex indices) of the
    cloth object's evaluated mesh."""
    evaluated, mesh = mesh_data.evaluated_mesh(obj, depsgraph)
    try:
        world = mesh_data.to_world(evaluated.matrix_world, mesh_data.local_vertices(mesh))
        tris = mesh_data.triangles(mesh)
        pins = mesh_data.group_members(obj, mesh, pin_group)
    finally:
        evaluated.to_mesh_clear()
    return world, tris, pins


def frame_step(scene):
    """Seconds per frame of the scene."""
    return scene.render.fps_base / scene.render.fps


def simulate(context, cloth_obj, collider_objs, options, report=None):
    """Simulates and bakes. options: a dict or the operator (its properties). Returns a dict
    of stats. Raises AnimkitMissing, ClothSetupError, animkit.Error."""
    animkit = load_animkit()
    get = options.get if isinstance(options, dict) else (lambda k: getattr(options, k))
    scene = context.scene
    first, last = scene.frame_start, scene.frame_end
    if last <= first:
        raise ClothSetupError(f"the scene's frame range {first}..{last} has no step")
    bake_mode = get("bake_mode")
    started = time.perf_counter()
    original_frame = scene.frame_current

    # Start from the first frame, without an earlier bake of this operator.
    bake.remove_baked_keys(cloth_obj)
    bake.remove_cache_modifier(cloth_obj)
    matrices = world_matrices(scene, collider_objs, range(first, last + 1))
    depsgraph = context.evaluated_depsgraph_get()
    world, tris, pins = cloth_arrays(cloth_obj, depsgraph)
    if bake_mode == "SHAPE_KEYS" and len(world) != len(cloth_obj.data.vertices):
        raise ClothSetupError(
            f"'{cloth_obj.name}' has modifiers that change its vertex count "
            f"({len(cloth_obj.data.vertices)} -> {len(world)}): apply them, or bake as a "
            "point cache")
    if len(tris) == 0:
        raise ClothSetupError(f"'{cloth_obj.name}' has no faces")
    enabled = [m.name for m in cloth_obj.modifiers if m.show_viewport or m.show_render]
    if bake_mode == "SHAPE_KEYS" and enabled and report is not None:
        report({"WARNING"}, f"'{cloth_obj.name}' has modifiers ({', '.join(enabled)}) that "
                            "apply again on top of the baked shape keys: apply or disable them, "
                            "or bake as a point cache")

    friction = get("friction")
    frame_dt = frame_step(scene)
    built = []
    kinds = []
    for obj, obj_matrices in zip(collider_objs, matrices):
        collider, kind = collider_for(animkit, obj, depsgraph, friction, obj_matrices, frame_dt)
        built.append(collider)
        kinds.append(f"{obj.name}: {kind}{' (moving)' if collider.moving else ''}")
    ground = (animkit.Ground(height=get("ground_height"), friction=friction)
              if get("use_ground") else None)

    material = animkit.material(get("material"))
    cloth = animkit.MeshCloth(axes.points_to_animkit(world), tris, material=material,
                              gravity=get("gravity"), pins=list(pins))
    substeps = get("substeps") or max(1, math.ceil(frame_dt / AUTO_MAX_STEP - 1e-9))
    step_dt = frame_dt / substeps
    frame_count = last - first + 1
    # One simulator step a Blender frame, cut into substeps by the integrator: every step the
    # run hands its sinks is a frame to keep.
    scene_desc = animkit.ClothScene(cloth=cloth, colliders=built, ground=ground, dt=frame_dt,
                                    substeps=substeps, frames=frame_count - 1)
    simulator = animkit.ClothSimulator(scene_desc)

    # animkit's world (Y up) into the object's local space with Blender's axes.
    inverse = np.linalg.inv(np.array(cloth_obj.matrix_world, dtype=np.float64))
    to_local = np.eye(4)
    to_local[:3, :3] = inverse[:3, :3] @ axes.ANIMKIT_TO_BLENDER
    to_local[:3, 3] = inverse[:3, 3]
    wm = context.window_manager
    sinks = [lambda frame, report: wm.progress_update(frame)]
    if bake_mode == "SHAPE_KEYS":
        local = np.empty((frame_count, len(world), 3), dtype=np.float64)
        local[0] = world @ inverse[:3, :3].T + inverse[:3, 3]

        def keep(frame, report):
            local[frame] = np.asarray(simulator.positions) @ to_local[:3, :3].T + to_local[:3, 3]
        sinks.append(keep)
    else:
        path = cache_path(cloth_obj, get("cache_dir"))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        # The library's point cache, written whole when the run ends (or not at all).
        sinks.append(animkit.PointCacheSink(os.path.dirname(path), file=os.path.basename(path),
                                            colliders=False, transform=to_local,
                                            start_frame=first))
    wm.progress_begin(0, frame_count)
    try:
        simulator.run(sinks=sinks)
    finally:
        wm.progress_end()
    simulated = time.perf_counter()

    stats = {"frames": frame_count, "substeps": substeps, "dt": step_dt,
             "vertices": len(world), "triangles": len(tris), "pins": len(pins),
             "colliders": kinds, "simulate_seconds": simulated - started}
    if bake_mode == "SHAPE_KEYS":
        bake.bake_shape_keys(cloth_obj, first, local)
        stats["keys"] = frame_count
    else:
        bake.add_cache_modifier(cloth_obj, bpy.path.relpath(path) if bpy.data.filepath else path,
                                first)
        stats["cache"] = path
    scene.frame_set(original_frame)
    stats["total_seconds"] = time.perf_counter() - started
    return stats


def cache_path(obj, cache_dir=""):
    """Where the point cache of `obj` goes: `cache_dir` if set (// is the .blend's folder),
    else a folder 'animkit_cache' next to the saved .blend, else one in the system's temporary
    folder."""
    if cache_dir:
        folder = bpy.path.abspath(cache_dir)
    elif bpy.data.filepath:
        folder = bpy.path.abspath("//animkit_cache")
    else:
        folder = os.path.join(tempfile.gettempdir(), "animkit_cache")
    name = bpy.path.clean_name(obj.name) or "cloth"
    return os.path.join(folder, f"{name}.pc2")


class ANIMKIT_OT_simulate_cloth(bpy.types.Operator):
    """Simulate the active mesh as cloth with animkit over the scene's frame range (other
    selected meshes are colliders) and bake it as shape keys or a point cache"""
    bl_idname = "animkit.simulate_cloth"
    bl_label = "Simulate cloth with animkit"
    bl_options = {"REGISTER", "UNDO"}

    material: bpy.props.EnumProperty(
        name="Material", default="cotton",
        items=[(m, m.capitalize(), f"animkit's {m} preset") for m in MATERIALS])
    gravity: bpy.props.FloatProperty(
        name="Gravity", default=9.81, min=0.0, unit="ACCELERATION",
        description="Acceleration downwards (-Z), m/s^2")
    friction: bpy.props.FloatProperty(
        name="Friction", default=0.3, min=0.0, description="Coulomb coefficient with colliders "
        "and the ground")
    use_ground: bpy.props.BoolProperty(
        name="Ground", default=False, description="A ground plane the cloth stays above")
    ground_height: bpy.props.FloatProperty(
        name="Ground height", default=0.0, unit="LENGTH", description="Z of the ground plane")
    substeps: bpy.props.IntProperty(
        name="Substeps", default=0, min=0, max=64,
        description="Simulation steps per frame (0: enough for steps of at most 1/60 s)")
    bake_mode: bpy.props.EnumProperty(
        name="Bake as", default="SHAPE_KEYS",
        items=[("SHAPE_KEYS", "Shape keys", "One shape key per frame, keyed on its frame"),
               ("POINT_CACHE", "Point cache", "A .pc2 file read by a Mesh Cache modifier")])
    cache_dir: bpy.props.StringProperty(
        name="Cache folder", default="", subtype="DIR_PATH",
        description="Where the .pc2 file goes (empty: animkit_cache next to the .blend, or in "
        "the temporary folder for an unsaved file)")

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH"

    def execute(self, context):
        cloth_obj = context.active_object
        others = [o for o in context.selected_objects if o is not cloth_obj]
        skipped = [o.name for o in others if o.type != "MESH"]
        if skipped:
            self.report({"WARNING"}, f"not meshes, ignored as colliders: {', '.join(skipped)}")
        collider_objs = [o for o in others if o.type == "MESH"]
        errors = (AnimkitMissing, ClothSetupError) + animkit_error_types()
        try:
            stats = simulate(context, cloth_obj, collider_objs, self, self.report)
        except errors as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        where = (f"{stats['keys']} shape keys" if "keys" in stats
                 else f"point cache {stats['cache']}")
        self.report({"INFO"},
                    f"animkit cloth: {stats['vertices']} vertices, {stats['frames']} frames "
                    f"({stats['substeps']} substeps), colliders "
                    f"[{', '.join(stats['colliders'])}], simulated in "
                    f"{stats['simulate_seconds']:.2f} s, baked as {where}")
        return {"FINISHED"}
