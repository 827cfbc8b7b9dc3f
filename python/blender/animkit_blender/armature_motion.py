"""An armature and its action as an animkit Skeleton and Motion, and back.

Blender's bone spaces, and the mapping used here (exact, no approximation):

- A bone's rest matrix `bone.matrix_local` (armature space) has its head as translation and a
  rotation that points the bone's Y axis at its tail: not the identity (a BVH imported by
  io_anim_bvh gives every bone such a roll). A pose bone's armature-space matrix is
      pose(b) = pose(p) rest(p)^-1 rest(b) basis(b)
  with basis(b) the keyed loc/rot/scale (`matrix_basis`) and p the parent.
- animkit joints sit at the bones' heads and rest with identity rotations (world-aligned axes
  at rest), so joint b's world rotation is the bone's rotation away from rest,
      G(b) = W C [rot pose(b) rest(b)^-1] C^T W^T,
  W the armature object's world rotation, C Blender -> animkit axes (axes.py). Its local
  rotation is L(b) = G(p)^T G(b) and its local translation the head's offset in the parent's
  frame, T(b) = G(p)^T (head(b) - head(p)) (the world head for a root), heads in world space,
  animkit axes, metres. animkit's FK then puts every joint exactly at its bone's head.
- Back: from the first formula, basis(b)'s rotation = rest(b)^-1 D(p)^-1 D(b) rest(b) with
  D = rot pose rest^-1 = W^T C^T G C W, i.e.
      basis(b) = rest(b)^T (W^T C^T L(b) C W) rest(b),
  which depends on the joint's local rotation only (bones inherit their parent's rotation;
  bones with inherit_rotation off or constraints are not supported).

Units: `scale` metres per Blender unit (animkit's foot-lock thresholds are metres). The
armature object may be moved, rotated and uniformly scaled.
"""
import numpy as np

from . import axes


class ArmatureError(ValueError):
    """An armature the conversion cannot take (non-uniform object scale, no bones...)."""


def bone_order(armature_data):
    """The armature's bone names, every parent before its children (depth first from the
    roots in the armature's own order)."""
    order = []

    def visit(bone):
        order.append(bone.name)
        for child in bone.children:
            visit(child)

    for bone in armature_data.bones:
        if bone.parent is None:
            visit(bone)
    return order


def _object_transform(obj):
    """(rotation W 3x3, uniform scale s, translation t) of the object's world matrix."""
    m = np.array(obj.matrix_world, dtype=np.float64)
    linear = m[:3, :3]
    scales = np.linalg.norm(linear, axis=0)
    if np.any(scales <= 0.0) or np.ptp(scales) > 1e-6 * scales.max():
        raise ArmatureError(f"armature '{obj.name}' has a non-uniform or zero scale "
                            f"{tuple(scales)}: apply its scale first")
    rotation = axes.orthonormalize(linear / scales)
    return rotation, float(scales.mean()), m[:3, 3].copy()


class ArmatureMapping:
    """What maps an armature object's bones to animkit joints: the joint order, parents, rest
    rotations and the object's transform (frozen when made)."""

    def __init__(self, obj, scale=1.0):
        if obj.type != "ARMATURE":
            raise ArmatureError(f"'{obj.name}' is not an armature")
        if not (np.isfinite(scale) and scale > 0.0):
            raise ArmatureError(f"scale must be > 0 (metres per Blender unit), got {scale}")
        data = obj.data
        self.obj = obj
        self.scale = float(scale)
        self.names = bone_order(data)
        if not self.names:
            raise ArmatureError(f"armature '{obj.name}' has no bones")
        index = {name: i for i, name in enumerate(self.names)}
        bones = [data.bones[name] for name in self.names]
        self.parents = [index[b.parent.name] if b.parent else -1 for b in bones]
        self.rest = axes.orthonormalize(
            np.array([np.array(b.matrix_local, dtype=np.float64)[:3, :3] for b in bones]))
        self.rest_heads = np.array([b.head_local for b in bones], dtype=np.float64)
        self.world_rotation, self.object_scale, self.object_translation = _object_transform(obj)
        # Blender world -> animkit, for directions: C W.
        self.to_animkit = axes.BLENDER_TO_ANIMKIT @ self.world_rotation

    def points_to_animkit(self, armature_points):
        """Armature-space points (..., 3) -> world, animkit axes, metres."""
        world = (self.object_scale * np.asarray(armature_points) @ self.world_rotation.T
                 + self.object_translation)
        return self.scale * axes.points_to_animkit(world)

    def world_points_to_animkit(self, world_points):
        """Blender world points (..., 3) -> animkit axes, metres."""
        return self.scale * axes.points_to_animkit(world_points)

    def animkit_points_to_world(self, points):
        """animkit points (metres) -> Blender world points."""
        return axes.points_to_blender(np.asarray(points) / self.scale)

    def skeleton_arrays(self):
        """(names, parents, rest_offsets (J, 3)) of the animkit skeleton at the armature's
        rest: offsets between rest heads, world-aligned, animkit axes, metres."""
        heads = self.points_to_animkit(self.rest_heads)
        offsets = heads.copy()
        for j, p in enumerate(self.parents):
            if p >= 0:
                offsets[j] = heads[j] - heads[p]
        return list(self.names), list(self.parents), offsets

    def pose_arrays(self):
        """(local rotations (J, 3, 3), local translations (J, 3)) of the armature's current
        (evaluated) pose."""
        pose_bones = self.obj.pose.bones
        matrices = np.array([np.array(pose_bones[n].matrix, dtype=np.float64)
                             for n in self.names])
        deltas = axes.orthonormalize(matrices[:, :3, :3]) @ np.transpose(self.rest, (0, 2, 1))
        globals_ = self.to_animkit @ deltas @ self.to_animkit.T
        heads = self.points_to_animkit(matrices[:, :3, 3])
        local_r = globals_.copy()
        local_t = heads.copy()
        for j, p in enumerate(self.parents):
            if p >= 0:
                local_r[j] = globals_[p].T @ globals_[j]
                local_t[j] = globals_[p].T @ (heads[j] - heads[p])
        return local_r, local_t

    def world_heads(self):
        """The pose bones' heads now, Blender world space (J, 3)."""
        matrix = np.array(self.obj.matrix_world, dtype=np.float64)
        heads = np.array([self.obj.pose.bones[n].head for n in self.names], dtype=np.float64)
        return heads @ matrix[:3, :3].T + matrix[:3, 3]

    def basis_rotations(self, local_rotations):
        """Local joint rotations (..., J, 3, 3) (animkit) -> the bones' matrix_basis rotations
        (..., J, 3, 3), the inverse of pose_arrays' rotations."""
        in_armature = self.to_animkit.T @ np.asarray(local_rotations) @ self.to_animkit
        return np.transpose(self.rest, (0, 2, 1)) @ in_armature @ self.rest


def sample_motion(context, mapping, frames, progress=None):
    """Evaluates the scene at each Blender frame in `frames` (scene.frame_set) and returns
    (local rotations (F, J, 4) as (w, x, y, z), local translations (F, J, 3), world heads
    (F, J, 3) in Blender's world space). The scene is left on its original frame."""
    scene = context.scene
    original = scene.frame_current
    rotations = np.empty((len(frames), len(mapping.names), 3, 3))
    translations = np.empty((len(frames), len(mapping.names), 3))
    heads = np.empty((len(frames), len(mapping.names), 3))
    try:
        for k, frame in enumerate(frames):
            scene.frame_set(frame)
            rotations[k], translations[k] = mapping.pose_arrays()
            heads[k] = mapping.world_heads()
            if progress is not None:
                progress(k)
    finally:
        scene.frame_set(original)
    return axes.matrices_to_quaternions(rotations), translations, heads


def write_rotation_keys(mapping, frames, local_rotations, bone_names):
    """Keys rotation_quaternion of each bone in `bone_names` on every frame in `frames` from
    animkit local rotations (F, J, 4), setting the bones' rotation mode to QUATERNION and
    removing their other rotation curves (Euler, axis-angle) from the armature's action."""
    obj = mapping.obj
    if obj.animation_data is None:
        obj.animation_data_create()
    if obj.animation_data.action is None:
        import bpy
        obj.animation_data.action = bpy.data.actions.new(f"{obj.name} animkit")
    action = obj.animation_data.action
    index = {name: j for j, name in enumerate(mapping.names)}
    chosen = [index[name] for name in bone_names]
    matrices = axes.quaternions_to_matrices(np.asarray(local_rotations)[:, chosen])
    rest = mapping.rest[chosen]
    in_armature = mapping.to_animkit.T @ matrices @ mapping.to_animkit
    basis = np.transpose(rest, (0, 2, 1)) @ in_armature @ rest
    quaternions = axes.continuous_quaternions(axes.matrices_to_quaternions(basis))
    frame_numbers = np.asarray(frames, dtype=np.float64)
    for k, name in enumerate(bone_names):
        prefix = f'pose.bones["{name}"].'
        for curve in list(action.fcurves):
            if curve.data_path in (prefix + "rotation_euler", prefix + "rotation_quaternion",
                                   prefix + "rotation_axis_angle"):
                action.fcurves.remove(curve)
        obj.pose.bones[name].rotation_mode = "QUATERNION"
        for component in range(4):
            curve = action.fcurves.new(prefix + "rotation_quaternion", index=component,
                                       action_group=name)
            curve.keyframe_points.add(len(frame_numbers))
            co = np.empty(2 * len(frame_numbers))
            co[0::2] = frame_numbers
            co[1::2] = quaternions[:, k, component]
            curve.keyframe_points.foreach_set("co", co)
            curve.keyframe_points.foreach_set(
                "interpolation", [_linear_interpolation()] * len(frame_numbers))
            curve.update()


def _linear_interpolation():
    import bpy
    return bpy.types.Keyframe.bl_rna.properties["interpolation"].enum_items["LINEAR"].value
