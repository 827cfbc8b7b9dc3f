"""blender.footlock: the foot-lock operator on the CMU walk pins the feet as the CLI does.

    blender -b --factory-startup --python-exit-code 1 --python footlock_test.py -- \
        PYTHON_DIR DATA_DIR ANIMKIT_CLI OUT_DIR

Imports data/cmu/131_01.bvh with io_anim_bvh in metres (global scale 0.056444, the CLI's
--scale for CMU files; the scene's fps becomes the file's 120), runs `animkit footlock` on the
same file, and runs the operator. Sliding is measured in Blender from the world heads of the
ankle bones, before and after (the baked action), over the contact spans animkit finds: the
mean horizontal motion per frame of a planted ankle (cm), as the library's metrics define it.
Before must equal the CLI's before; after/before must be close to the CLI's ratio and well
below 1.
"""
import json
import pathlib
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import bpy  # noqa: E402
import numpy as np  # noqa: E402

import blender_test_support as support  # noqa: E402
from blender_test_support import check  # noqa: E402

CMU_SCALE = 0.056444
ANKLES = ("LeftAnkle", "RightAnkle")


def sliding_cm(ankle_heads, contacts):
    """Mean and max horizontal (Blender XY) motion per frame of the ankles inside contact
    spans, cm. ankle_heads: (frames, 2, 3) world, metres; contacts: (left, right) spans
    lists of (first, last, lock) with frames counted from 0."""
    steps = []
    for leg, spans in enumerate(contacts):
        for first, last, _ in spans:
            xy = ankle_heads[first:last + 1, leg, :2]
            steps.extend(np.linalg.norm(np.diff(xy, axis=0), axis=1) * 100.0)
    steps = np.array(steps)
    return float(steps.mean()), float(steps.max()), len(steps)


def ankle_heads(armature, frames):
    scene = bpy.context.scene
    out = np.empty((len(frames), 2, 3))
    for k, frame in enumerate(frames):
        scene.frame_set(frame)
        for leg, name in enumerate(ANKLES):
            out[k, leg] = armature.matrix_world @ armature.pose.bones[name].head
    return out


def main():
    python_dir, data_dir, cli, out_dir = support.arguments(
        4, "PYTHON_DIR DATA_DIR ANIMKIT_CLI OUT_DIR")
    bvh = pathlib.Path(data_dir) / "cmu" / "131_01.bvh"
    out = pathlib.Path(out_dir)
    animkit, _ = support.load_addon(python_dir)
    from animkit_blender import footlock_operator

    run = subprocess.run([cli, "footlock", "--in", str(bvh), "--scale", str(CMU_SCALE),
                          "--out", str(out / "cli")], capture_output=True, text=True)
    print(run.stdout.strip())
    check(run.returncode == 0, f"animkit footlock failed: {run.stderr.strip()}")
    metrics = json.loads((out / "cli" / "metrics.json").read_text())
    cli_before = metrics["sliding_cm_per_frame"]["before"]["mean"]
    cli_after = metrics["sliding_cm_per_frame"]["after"]["mean"]

    # The spans the library finds on the file (the CLI's), to measure Blender's sliding over.
    clip = animkit.read_bvh(str(bvh), scale=CMU_SCALE)
    reference = animkit.lock_feet(clip.skeleton, clip.motion)
    spans = tuple(c.spans for c in reference.contacts)
    check(abs(reference.metrics.slide_before_mean_cm - cli_before) < 1e-6,
          "the module and the CLI disagree on the clip's sliding")

    support.empty_scene()
    armature = support.import_bvh(bvh, CMU_SCALE)
    check(bpy.context.scene.render.fps == 120, f"scene fps {bpy.context.scene.render.fps}")
    frames = footlock_operator.action_frames(armature.animation_data.action)
    check(len(frames) == clip.motion.frame_count, f"{len(frames)} frames in Blender")
    before = sliding_cm(ankle_heads(armature, frames), spans)

    # The operator's settings default to the library's (Blender stores floats as float32).
    defaults = animkit.FootLockSettings()
    properties = bpy.ops.animkit.lock_feet.get_rna_type().properties
    for name in ("height_threshold", "speed_threshold", "min_contact_frames",
                 "merge_gap_frames", "blend_frames", "min_knee_flexion", "max_knee_flexion",
                 "knee_pole", "soft_reach"):
        ours, theirs = properties[name].default, getattr(defaults, name)
        same = ours == theirs if isinstance(theirs, (int, str)) else abs(ours - theirs) < 1e-6
        check(same, f"operator default {name}={ours!r}, the library's {theirs!r}")

    support.make_active(armature)
    started = time.perf_counter()
    result = bpy.ops.animkit.lock_feet()
    seconds = time.perf_counter() - started
    check(result == {"FINISHED"}, f"lock_feet returned {result}")
    keyed = sorted({c.group.name for c in armature.animation_data.action.fcurves
                    if c.data_path.endswith("rotation_quaternion")})
    print(f"operator: {seconds:.2f} s; bones keyed as quaternions: {keyed}")
    for name in ("LeftHip", "LeftKnee", "RightHip", "RightKnee"):
        check(name in keyed, f"{name} was not keyed")
    heads_after = ankle_heads(armature, frames)
    after = sliding_cm(heads_after, spans)
    # Frame by frame, the baked ankles are where the library's lock put them (animkit's
    # (x, y, z) is Blender's (x, z, -y) on this import).
    library = np.asarray(reference.ankles_after)
    in_animkit = np.stack([heads_after[..., 0], heads_after[..., 2], -heads_after[..., 1]], -1)
    ankle_error = np.linalg.norm(in_animkit - library, axis=2).max()
    print(f"baked ankles vs the library's locked ankles: largest distance {ankle_error:.3g} m")
    check(ankle_error < 1e-5, f"the baked ankles are {ankle_error:.3g} m off the library's")

    ratio_blender = after[0] / before[0]
    ratio_cli = cli_after / cli_before
    print(f"Blender: sliding {before[0]:.6f} -> {after[0]:.6f} cm/frame over {before[2]} "
          f"planted steps (max {before[1]:.4f} -> {after[1]:.4f}), ratio {ratio_blender:.5f}")
    print(f"CLI:     sliding {cli_before:.6f} -> {cli_after:.6f} cm/frame, ratio "
          f"{ratio_cli:.5f}")
    check(abs(before[0] - cli_before) < 1e-3 * cli_before,
          f"Blender measures {before[0]:.5f} cm/frame before, the CLI {cli_before:.5f}")
    check(after[0] < 0.3 * before[0],
          f"the lock barely reduced the sliding: {before[0]:.4f} -> {after[0]:.4f} cm/frame")
    check(abs(ratio_blender - ratio_cli) < 1e-3 + 0.05 * ratio_cli,
          f"after/before in Blender {ratio_blender:.4f}, in the CLI {ratio_cli:.4f}")

    # Imported at Blender's default scale (CMU's units as Blender units, 14 m legs): the
    # operator tells the unit from the legs and locks the same contacts; told the units are
    # metres, it fails saying why instead of keying nothing.
    support.empty_scene()
    raw = support.import_bvh(bvh, 1.0)
    support.make_active(raw)
    result, stats = footlock_operator.lock_armature(bpy.context, raw, {
        "detect_scale": True, "scale": 1.0, **operator_defaults(properties)})
    print(f"default import scale: scale {stats['scale']:.6g} ({stats['scale_source']})")
    check(abs(stats["scale"] - CMU_SCALE) < 1e-12, f"detected scale {stats['scale']}")
    check(result.metrics.contacts == reference.metrics.contacts,
          f"contacts {result.metrics.contacts} at the detected scale, "
          f"{reference.metrics.contacts} in metres")
    support.empty_scene()
    raw = support.import_bvh(bvh, 1.0)
    support.make_active(raw)
    # (An operator's error report is a RuntimeError from bpy.ops in background mode.)
    try:
        failed = str(bpy.ops.animkit.lock_feet(detect_scale=False, scale=1.0))
    except RuntimeError as error:
        failed = str(error)
    check("no foot contact in 994 frames" in failed and "is the clip in metres?" in failed,
          f"a 14 m walk locked as metres: {failed}")
    print("footlock_test: OK")


def operator_defaults(properties):
    """The operator's other properties at their defaults, as lock_armature's options."""
    return {p.identifier: p.default for p in properties
            if p.identifier not in ("rna_type", "detect_scale", "scale")}


main()
