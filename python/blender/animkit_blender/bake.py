"""Writing a simulated sequence of vertex positions onto a mesh object: as shape keys (one per
frame, keyed so that only the current frame's key is on) or as a point cache (a .pc2 file the
library's PointCacheSink writes, read by a Mesh Cache modifier). Positions here are in the
object's local space, Blender axes."""
import struct

import numpy as np

KEY_PREFIX = "animkit "
MODIFIER_NAME = "animkit cache"


def remove_baked_keys(obj):
    """Removes shape keys an earlier bake added (named 'animkit <frame>') and their curves;
    the Basis and the user's own keys stay. A Basis left alone is removed too."""
    keys = obj.data.shape_keys
    if keys is None:
        return
    if keys.animation_data and keys.animation_data.action:
        action = keys.animation_data.action
        for curve in list(action.fcurves):
            if curve.data_path.startswith(f'key_blocks["{KEY_PREFIX}'):
                action.fcurves.remove(curve)
    for block in list(keys.key_blocks):
        if block.name.startswith(KEY_PREFIX):
            obj.shape_key_remove(block)
    keys = obj.data.shape_keys
    if keys is not None and len(keys.key_blocks) == 1:
        obj.shape_key_remove(keys.key_blocks[0])


def remove_cache_modifier(obj):
    """Removes the Mesh Cache modifier an earlier bake added."""
    modifier = obj.modifiers.get(MODIFIER_NAME)
    if modifier is not None:
        obj.modifiers.remove(modifier)


def bake_shape_keys(obj, first_frame, frames):
    """Adds one shape key per frame ('animkit <frame>', relative to a Basis) holding
    frames[k] (n, 3), keyed 0 on the frames before and after and 1 on its own frame (linear in
    between), so at each whole frame exactly one baked key is on. Returns the keys' names."""
    if obj.data.shape_keys is None:
        obj.shape_key_add(name="Basis", from_mix=False)
    keys = obj.data.shape_keys
    if keys.animation_data is None:
        keys.animation_data_create()
    if keys.animation_data.action is None:
        keys.animation_data.action = _new_action(f"{obj.name} animkit cloth")
    action = keys.animation_data.action
    names = []
    count = len(frames)
    for k, positions in enumerate(frames):
        frame = first_frame + k
        block = obj.shape_key_add(name=f"{KEY_PREFIX}{frame}", from_mix=False)
        block.data.foreach_set("co", np.asarray(positions, dtype=np.float32).ravel())
        block.value = 0.0
        curve = action.fcurves.new(f'key_blocks["{block.name}"].value')
        points = [(frame, 1.0)]
        if k > 0:
            points.insert(0, (frame - 1, 0.0))
        if k + 1 < count:
            points.append((frame + 1, 0.0))
        curve.keyframe_points.add(len(points))
        curve.keyframe_points.foreach_set("co", [c for p in points for c in p])
        for point in curve.keyframe_points:
            point.interpolation = "LINEAR"
        curve.update()
        names.append(block.name)
    return names


def _new_action(name):
    import bpy  # only here, so the rest of the module imports outside Blender
    return bpy.data.actions.new(name)


def read_pc2(path):
    """(first frame, frames (count, n, 3) float32) of a PC2 file (for tests and checks)."""
    with open(path, "rb") as source:
        header = source.read(32)
        magic, version, points, start, _, samples = struct.unpack("<12siiffi", header)
        if magic != b"POINTCACHE2\0" or version != 1:
            raise ValueError(f"{path}: not a PC2 point cache")
        data = np.frombuffer(source.read(), dtype="<f4")
    return start, data.reshape(samples, points, 3)


def add_cache_modifier(obj, path, first_frame):
    """Adds (last in the stack) a Mesh Cache modifier playing the PC2 file at `path` so that
    its first sample shows on `first_frame`."""
    modifier = obj.modifiers.new(MODIFIER_NAME, "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = path
    modifier.time_mode = "FRAME"
    modifier.play_mode = "SCENE"
    modifier.frame_start = float(first_frame)
    modifier.frame_scale = 1.0
    modifier.deform_mode = "OVERWRITE"
    modifier.interpolation = "LINEAR"
    modifier.forward_axis = "POS_Y"
    modifier.up_axis = "POS_Z"
    return modifier
