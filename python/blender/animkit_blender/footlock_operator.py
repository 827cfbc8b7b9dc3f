"""Operator "Lock feet with animkit": pins the planted feet of the active armature's action
with animkit.lock_feet and keys the bones it turned (rotation_quaternion)."""
import math
import time

import bpy
import numpy as np

from . import armature_motion
from .module import AnimkitMissing, animkit_error_types, load_animkit

# animkit.FootLockSettings' fields as operator properties. The defaults are read from the
# library (animkit.FootLockSettings()) when the add-on registers; these are only used when
# the module is not installed yet, and match the library's.
_FALLBACK_SETTINGS = {
    "height_threshold": 0.05, "speed_threshold": 0.35, "min_contact_frames": 6,
    "merge_gap_frames": 3, "blend_frames": 10, "min_knee_flexion": 0.0,
    "max_knee_flexion": 2.6179938779914944, "knee_pole": "pelvis-forward", "soft_reach": 0.01,
}


def library_settings():
    """The library's default FootLockSettings as a dict (fallback values without animkit)."""
    try:
        animkit = load_animkit()
        defaults = animkit.FootLockSettings()
        return {name: getattr(defaults, name) for name in _FALLBACK_SETTINGS}
    except (AnimkitMissing, AttributeError):
        return dict(_FALLBACK_SETTINGS)


def _unrounded(value, default):
    """A setting as the library gets it: Blender keeps float properties as float32, so a
    property left at the library's default (0.05) reads back rounded (0.0500000007); that
    value is given as the exact default, so the result matches the CLI's bit for bit."""
    if isinstance(default, float) and abs(value - default) <= 1e-7 * max(1.0, abs(default)):
        return default
    return value


def action_frames(action):
    """The whole frames an action covers: first..last of its frame range."""
    first, last = action.frame_range
    return list(range(int(math.floor(first + 1e-6)), int(math.ceil(last - 1e-6)) + 1))


def build_properties(defaults):
    """The operator's annotations, with the library's defaults."""
    props = bpy.props
    return {
        "detect_scale": props.BoolProperty(
            name="Detect scale", default=True,
            description="Tell metres per Blender unit from the legs' length at rest (metres, "
                        "centimetres, millimetres, inches or CMU's unit: the one that makes them "
                        "nearest an adult's 0.8 m); off: use Metres per unit"),
        "scale": props.FloatProperty(
            name="Metres per unit", default=1.0, min=1e-9, soft_max=100.0, precision=6,
            description="Metres per Blender unit when Detect scale is off (animkit's "
                        "thresholds are in metres)"),
        "height_threshold": props.FloatProperty(
            name="Height threshold", default=defaults["height_threshold"], min=1e-6,
            precision=4, unit="NONE",
            description="A foot can be planted at most this high (m) above the lowest ankle"),
        "speed_threshold": props.FloatProperty(
            name="Speed threshold", default=defaults["speed_threshold"], min=1e-6, precision=3,
            description="... and moving at most this fast (m/s)"),
        "min_contact_frames": props.IntProperty(
            name="Min contact frames", default=defaults["min_contact_frames"], min=1,
            description="Shorter planted runs are ignored"),
        "merge_gap_frames": props.IntProperty(
            name="Merge gap frames", default=defaults["merge_gap_frames"], min=0,
            description="Planted runs this few frames apart are one contact"),
        "blend_frames": props.IntProperty(
            name="Blend frames", default=defaults["blend_frames"], min=0,
            description="Frames to blend into and out of each contact (0 snaps)"),
        "min_knee_flexion": props.FloatProperty(
            name="Min knee flexion", default=defaults["min_knee_flexion"], min=0.0,
            max=math.pi, subtype="ANGLE", description="Least knee flexion on solved frames"),
        "max_knee_flexion": props.FloatProperty(
            name="Max knee flexion", default=defaults["max_knee_flexion"], min=0.0,
            max=math.pi, subtype="ANGLE", description="Most knee flexion on solved frames"),
        "knee_pole": props.EnumProperty(
            name="Knee pole",
            items=[("pelvis-forward", "Pelvis forward", "Knees point forward of the pelvis"),
                   ("original", "Original", "Knees keep the clip's own bend direction")],
            default=defaults["knee_pole"]),
        "soft_reach": props.FloatProperty(
            name="Soft reach", default=defaults["soft_reach"], min=0.0, precision=4,
            description="Approach the straight leg's reach smoothly over this distance (m)"),
        "left_hip": props.StringProperty(name="Left hip", default="LeftHip"),
        "left_knee": props.StringProperty(name="Left knee", default="LeftKnee"),
        "left_ankle": props.StringProperty(name="Left ankle", default="LeftAnkle"),
        "right_hip": props.StringProperty(name="Right hip", default="RightHip"),
        "right_knee": props.StringProperty(name="Right knee", default="RightKnee"),
        "right_ankle": props.StringProperty(name="Right ankle", default="RightAnkle"),
    }


def lock_armature(context, obj, options, report=None):
    """Runs the whole job on armature `obj` with `options` (a dict or the operator: the
    properties above). Returns (result, stats); raises AnimkitMissing, ArmatureError,
    animkit.Error."""
    animkit = load_animkit()
    get = options.get if isinstance(options, dict) else (lambda k, d=None: getattr(options, k))
    action = obj.animation_data.action
    frames = action_frames(action)
    if len(frames) < 2:
        raise armature_motion.ArmatureError(f"action '{action.name}' has fewer than 2 frames")
    render = context.scene.render
    frame_time = render.fps_base / render.fps
    defaults = animkit.FootLockSettings()
    settings = animkit.FootLockSettings(**{
        name: _unrounded(get(name), getattr(defaults, name)) for name in _FALLBACK_SETTINGS})
    legs = ((get("left_hip"), get("left_knee"), get("left_ankle")),
            (get("right_hip"), get("right_knee"), get("right_ankle")))
    for name in (n for leg in legs for n in leg):
        if name not in obj.data.bones:
            raise armature_motion.ArmatureError(
                f"armature '{obj.name}' has no bone '{name}' (set the leg bones' names in the "
                "operator's properties)")

    started = time.perf_counter()
    scale = get("scale")
    scale_source = "given"
    # Told from the legs unless a scale is given: the operator's Detect scale, or, for a dict
    # of options, no "scale" in it.
    detect = (options.get("detect_scale", "scale" not in options) if isinstance(options, dict)
              else options.detect_scale)
    if detect:
        names, parents, offsets = armature_motion.ArmatureMapping(obj, 1.0).skeleton_arrays()
        scale, unit, leg = animkit.body_scale(animkit.Skeleton(names, parents, offsets), legs)
        scale_source = f"detected: {unit}, legs {leg:.3g} units long"
    mapping = armature_motion.ArmatureMapping(obj, scale)
    names, parents, offsets = mapping.skeleton_arrays()
    skeleton = animkit.Skeleton(names, parents, offsets)
    wm = context.window_manager
    wm.progress_begin(0, len(frames))
    try:
        rotations, translations, _ = armature_motion.sample_motion(
            context, mapping, frames, progress=wm.progress_update)
    finally:
        wm.progress_end()
    motion = animkit.Motion(rotations, translations, frame_time=frame_time)
    sampled = time.perf_counter()
    result = animkit.lock_feet(skeleton, motion, settings, legs=legs)
    locked = np.asarray(result.motion.local_rotations)
    # The bones the lock turned: any frame's local rotation changed (the same rotation as
    # q or -q).
    dots = np.abs(np.sum(locked * rotations, axis=-1))
    changed = [names[j] for j in range(len(names)) if np.any(dots[:, j] < 1.0 - 1e-12)]
    moved = np.max(np.abs(np.asarray(result.motion.local_translations) - translations))
    if moved > 1e-9 and report is not None:
        report({"WARNING"}, f"the lock moved joint translations by up to {moved:.3g} m; only "
                            "rotations are written back")
    armature_motion.write_rotation_keys(mapping, frames, locked, changed)
    context.scene.frame_set(context.scene.frame_current)
    stats = {"frames": len(frames), "bones": changed, "scale": scale,
             "scale_source": scale_source,
             "sample_seconds": sampled - started,
             "total_seconds": time.perf_counter() - started}
    return result, stats


class ANIMKIT_OT_lock_feet(bpy.types.Operator):
    """Pin the planted feet of the active armature's action with animkit (leg IK), keying the
    hips, knees and ankles it turns"""
    bl_idname = "animkit.lock_feet"
    bl_label = "Lock feet with animkit"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return (obj is not None and obj.type == "ARMATURE" and obj.animation_data is not None
                and obj.animation_data.action is not None)

    def execute(self, context):
        errors = (AnimkitMissing, armature_motion.ArmatureError) + animkit_error_types()
        try:
            result, stats = lock_armature(context, context.active_object, self, self.report)
        except errors as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        m = result.metrics
        self.report({"INFO"},
                    f"animkit foot lock: {stats['frames']} frames, contacts left "
                    f"{m.contacts[0]} right {m.contacts[1]}, sliding "
                    f"{m.slide_before_mean_cm:.3f} -> {m.slide_after_mean_cm:.3f} cm/frame "
                    f"(max {m.slide_before_max_cm:.3f} -> {m.slide_after_max_cm:.3f}), "
                    f"{len(stats['bones'])} bones keyed in {stats['total_seconds']:.2f} s; scale "
                    f"{stats['scale']:.6g} m per unit ({stats['scale_source']})")
        return {"FINISHED"}


def make_operator_class():
    """The operator with its properties' defaults taken from the library now."""
    ANIMKIT_OT_lock_feet.__annotations__ = build_properties(library_settings())
    return ANIMKIT_OT_lock_feet
