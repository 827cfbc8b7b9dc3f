"""Operator "Simulate cloth with animkit": the active mesh is the cloth, the other selected
meshes are colliders; the simulation over the scene's frame range is baked as shape keys or as
a point cache (.pc2 + Mesh Cache modifier)."""
import math
import os
import tempfile
import threading
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


class ClothBake:
    """One bake in three parts: set up on Blender's main thread (reads the scene), run on any
    thread (the library's loop only: no bpy), finished on the main thread (writes the shape
    keys or the Mesh Cache modifier). cancel() from any thread stops the run after the frame in
    progress; a stopped run writes nothing (the point cache file stays absent)."""

    def __init__(self, context, cloth_obj, collider_objs, options, report=None):
        """options: a dict or the operator (its properties). Raises AnimkitMissing,
        ClothSetupError, animkit.Error. Removes the object's earlier bake: the cloth's rest
        shape is read without it."""
        animkit = load_animkit()
        get = options.get if isinstance(options, dict) else (lambda k: getattr(options, k))
        scene = context.scene
        first, last = scene.frame_start, scene.frame_end
        if last <= first:
            raise ClothSetupError(f"the scene's frame range {first}..{last} has no step")
        self.bake_mode = get("bake_mode")
        self.started = time.perf_counter()
        self.scene, self.cloth_obj, self.first = scene, cloth_obj, first
        self.original_frame = scene.frame_current

        # Start from the first frame, without an earlier bake of this operator.
        bake.remove_baked_keys(cloth_obj)
        bake.remove_cache_modifier(cloth_obj)
        matrices = world_matrices(scene, collider_objs, range(first, last + 1))
        depsgraph = context.evaluated_depsgraph_get()
        world, tris, pins = cloth_arrays(cloth_obj, depsgraph)
        if self.bake_mode == "SHAPE_KEYS" and len(world) != len(cloth_obj.data.vertices):
            raise ClothSetupError(
                f"'{cloth_obj.name}' has modifiers that change its vertex count "
                f"({len(cloth_obj.data.vertices)} -> {len(world)}): apply them, or bake as a "
                "point cache")
        if len(tris) == 0:
            raise ClothSetupError(f"'{cloth_obj.name}' has no faces")
        enabled = [m.name for m in cloth_obj.modifiers if m.show_viewport or m.show_render]
        if self.bake_mode == "SHAPE_KEYS" and enabled and report is not None:
            report({"WARNING"}, f"'{cloth_obj.name}' has modifiers ({', '.join(enabled)}) "
                                "that apply again on top of the baked shape keys: apply or "
                                "disable them, or bake as a point cache")

        friction = get("friction")
        frame_dt = frame_step(scene)
        built = []
        kinds = []
        for obj, obj_matrices in zip(collider_objs, matrices):
            collider, kind = collider_for(animkit, obj, depsgraph, friction, obj_matrices,
                                          frame_dt)
            built.append(collider)
            kinds.append(f"{obj.name}: {kind}{' (moving)' if collider.moving else ''}")
        ground = (animkit.Ground(height=get("ground_height"), friction=friction)
                  if get("use_ground") else None)

        material = animkit.material(get("material"))
        cloth = animkit.MeshCloth(axes.points_to_animkit(world), tris, material=material,
                                  gravity=get("gravity"), pins=list(pins))
        substeps = get("substeps") or max(1, math.ceil(frame_dt / AUTO_MAX_STEP - 1e-9))
        self.frame_count = last - first + 1
        # One simulator step a Blender frame, cut into substeps by the integrator: every step
        # the run hands its sinks is a frame to keep. No integrator given: the sheet has a
        # material, so the library's fast settings.
        scene_desc = animkit.ClothScene(cloth=cloth, colliders=built, ground=ground,
                                        dt=frame_dt, substeps=substeps,
                                        frames=self.frame_count - 1)
        self.simulator = animkit.ClothSimulator(scene_desc)
        self.stats = {"frames": self.frame_count, "substeps": substeps,
                      "dt": frame_dt / substeps, "vertices": len(world),
                      "triangles": len(tris), "pins": len(pins), "colliders": kinds}

        # animkit's world (Y up) into the object's local space with Blender's axes.
        inverse = np.linalg.inv(np.array(cloth_obj.matrix_world, dtype=np.float64))
        to_local = np.eye(4)
        to_local[:3, :3] = inverse[:3, :3] @ axes.ANIMKIT_TO_BLENDER
        to_local[:3, 3] = inverse[:3, 3]
        self.frames_done = 0
        self.cancelled = False
        self.error = None
        self.sinks = [self._count]
        if self.bake_mode == "SHAPE_KEYS":
            self.local = np.empty((self.frame_count, len(world), 3), dtype=np.float64)
            self.local[0] = world @ inverse[:3, :3].T + inverse[:3, 3]
            simulator = self.simulator

            def keep(frame, report):
                self.local[frame] = (np.asarray(simulator.positions) @ to_local[:3, :3].T
                                     + to_local[:3, 3])
            self.sinks.append(keep)
        else:
            self.path = cache_path(cloth_obj, get("cache_dir"))
            os.makedirs(os.path.dirname(self.path), exist_ok=True)
            # The library's point cache, written whole when the run ends (or not at all).
            self.sinks.append(animkit.PointCacheSink(
                os.path.dirname(self.path), file=os.path.basename(self.path),
                colliders=False, transform=to_local, start_frame=first))

    def _count(self, frame, report):
        self.frames_done = frame
        return not self.cancelled  # False stops the run (its sinks write nothing)

    def cancel(self):
        self.cancelled = True

    def run(self, progress=None):
        """The simulation (any thread). `progress(frame)` after each frame, on this thread.
        An animkit.Error is kept in self.error, not raised: run() may be a thread's target."""
        sinks = self.sinks + ([lambda frame, report: progress(frame)] if progress else [])
        try:
            self.simulator.run(sinks=sinks)
        except animkit_error_types() as error:
            self.error = error
        self.stats["simulate_seconds"] = time.perf_counter() - self.started

    def finish(self):
        """Writes the bake (main thread) unless the run was cancelled or failed; returns the
        stats. Raises the run's animkit.Error."""
        try:
            if self.error is not None:
                raise self.error
            if self.cancelled:
                return self.stats
            if self.bake_mode == "SHAPE_KEYS":
                bake.bake_shape_keys(self.cloth_obj, self.first, self.local)
                self.stats["keys"] = self.frame_count
            else:
                path = self.path
                bake.add_cache_modifier(
                    self.cloth_obj, bpy.path.relpath(path) if bpy.data.filepath else path,
                    self.first)
                self.stats["cache"] = path
            self.stats["total_seconds"] = time.perf_counter() - self.started
            return self.stats
        finally:
            self.scene.frame_set(self.original_frame)


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

    def _objects(self, context):
        """The cloth and its colliders from the selection (warns about what is skipped)."""
        cloth_obj = context.active_object
        others = [o for o in context.selected_objects if o is not cloth_obj]
        skipped = [o.name for o in others if o.type != "MESH"]
        if skipped:
            self.report({"WARNING"}, f"not meshes, ignored as colliders: {', '.join(skipped)}")
        return cloth_obj, [o for o in others if o.type == "MESH"]

    def _start(self, context):
        """The bake set up from the selection and the operator's properties, or None after
        reporting why not."""
        cloth_obj, collider_objs = self._objects(context)
        errors = (AnimkitMissing, ClothSetupError) + animkit_error_types()
        try:
            return ClothBake(context, cloth_obj, collider_objs, self, self.report)
        except errors as error:
            self.report({"ERROR"}, str(error))
            return None

    def _finished(self, job):
        """Reports a bake's end: FINISHED with its numbers, or CANCELLED with why."""
        try:
            stats = job.finish()
        except animkit_error_types() as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        except ReferenceError:  # the cloth or the scene was deleted while the run went on
            self.report({"ERROR"}, "animkit cloth: the cloth object was removed during the "
                                   "bake; nothing was baked")
            return {"CANCELLED"}
        if job.cancelled:
            self.report({"WARNING"}, f"animkit cloth: cancelled after {job.frames_done} of "
                                     f"{job.frame_count - 1} frames; nothing was baked")
            return {"CANCELLED"}
        where = (f"{stats['keys']} shape keys" if "keys" in stats
                 else f"point cache {stats['cache']}")
        self.report({"INFO"},
                    f"animkit cloth: {stats['vertices']} vertices, {stats['frames']} frames "
                    f"({stats['substeps']} substeps), colliders "
                    f"[{', '.join(stats['colliders'])}], simulated in "
                    f"{stats['simulate_seconds']:.2f} s, baked as {where}")
        return {"FINISHED"}

    def execute(self, context):
        """Bakes at once, blocking Blender (scripts, background mode), Blender's progress
        indicator following the frames."""
        job = self._start(context)
        if job is None:
            return {"CANCELLED"}
        wm = context.window_manager
        wm.progress_begin(0, job.frame_count)
        try:
            job.run(progress=wm.progress_update)
        finally:
            wm.progress_end()
        return self._finished(job)

    def invoke(self, context, event):
        """From the menu: the run goes on a thread while Blender stays responsive, the status
        bar counts the frames, and Esc cancels (a modal operator on a timer)."""
        if bpy.app.background:
            return self.execute(context)
        self._job = self._start(context)
        if self._job is None:
            return {"CANCELLED"}
        self._thread = threading.Thread(target=self._job.run, daemon=True)
        self._thread.start()
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0, self._job.frame_count)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        job = self._job
        if event.type == "ESC":
            job.cancel()
        elif event.type != "TIMER":
            return {"PASS_THROUGH"}
        wm = context.window_manager
        wm.progress_update(job.frames_done)
        context.workspace.status_text_set(
            f"animkit cloth: frame {job.frames_done} of {job.frame_count - 1} "
            f"({time.perf_counter() - job.started:.0f} s), Esc to cancel")
        if self._thread.is_alive():
            return {"RUNNING_MODAL"}
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)
        return self._finished(job)
