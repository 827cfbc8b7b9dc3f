#!/usr/bin/env python3
"""Foot-locks the CMU walk with animkit and plots the ankles before and after.

    python3 examples/python/foot_lock_walk.py [walk.bvh] [--scale 0.056444] [--out plot.png]
        [--fixed fixed.bvh]

Reads a BVH walk (default: the repository's data/cmu/131_01.bvh), converts it to metres, pins
each planted foot with animkit.lock_feet (the library `animkit footlock` runs), prints the
metrics and draws, against time, each ankle's height and its horizontal motion per frame before
(orange) and after (blue), the planted spans shaded. Needs numpy and matplotlib.
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)
import numpy as np  # noqa: E402

import animkit  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[2]
CMU_SCALE = 0.056444  # metres per unit of CMU's BVH files


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bvh", nargs="?", type=pathlib.Path,
                        default=REPO / "data" / "cmu" / "131_01.bvh",
                        help="the walk (legs named Left/RightHip, Knee, Ankle)")
    parser.add_argument("--scale", type=float, default=CMU_SCALE,
                        help="metres per file unit (default: CMU's, %(default)s)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("foot_lock_walk.png"),
                        help="the plot to write (PNG)")
    parser.add_argument("--fixed", type=pathlib.Path,
                        help="also write the locked clip here, in the file's own units")
    return parser.parse_args(argv)


def horizontal_motion_cm(ankles):
    """(frames, 2) horizontal (XZ) distance each ankle moved since the previous frame, cm."""
    step = np.diff(ankles[:, :, [0, 2]], axis=0)
    return np.concatenate([np.zeros((1, 2)), 100.0 * np.linalg.norm(step, axis=2)])


def plot(result, frame_time, path):
    frames = result.ankles_before.shape[0]
    t = np.arange(frames) * frame_time
    before_cm = horizontal_motion_cm(result.ankles_before)
    after_cm = horizontal_motion_cm(result.ankles_after)
    fig, axes = plt.subplots(2, 2, figsize=(12, 7), sharex=True)
    for leg, side in enumerate(["left", "right"]):
        contacts = result.contacts[leg]
        height, sliding = axes[0, leg], axes[1, leg]
        for ax in (height, sliding):
            for first, last, _ in contacts.spans:
                ax.axvspan(first * frame_time, last * frame_time, color="tab:green", alpha=0.15,
                           lw=0)
        height.plot(t, result.ankles_before[:, leg, 1], color="tab:orange", label="before")
        height.plot(t, result.ankles_after[:, leg, 1], color="tab:blue", label="after", lw=1)
        height.set_title(f"{side} ankle height (planted spans shaded)")
        height.set_ylabel("height (m)")
        sliding.plot(t, before_cm[:, leg], color="tab:orange", label="before")
        sliding.plot(t, after_cm[:, leg], color="tab:blue", label="after", lw=1)
        sliding.set_title(f"{side} ankle: horizontal motion per frame")
        sliding.set_ylabel("cm per frame")
        sliding.set_xlabel("time (s)")
        # Planted feet barely move: show the bottom of the range, where sliding lives.
        planted = contacts.planted
        top = max(before_cm[planted, leg].max(initial=0.0), 0.1)
        sliding.set_ylim(0, 3 * top)
        height.legend(loc="upper right")
    m = result.metrics
    fig.suptitle(f"animkit foot locking: sliding on planted frames {m.slide_before_mean_cm:.3f} "
                 f"-> {m.slide_after_mean_cm:.3f} cm/frame (max {m.slide_before_max_cm:.3f} -> "
                 f"{m.slide_after_max_cm:.3f})")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        clip = animkit.read_bvh(args.bvh, scale=args.scale)
        result = animkit.lock_feet(clip.skeleton, clip.motion)
    except animkit.Error as error:
        print(f"foot_lock_walk: {error}", file=sys.stderr)
        return 2
    m = result.metrics
    print(f"{clip.frame_count} frames, contacts left {m.contacts[0]} right {m.contacts[1]}, "
          f"sliding {m.slide_before_mean_cm:.3f} -> {m.slide_after_mean_cm:.3f} cm/frame "
          f"(max {m.slide_before_max_cm:.3f} -> {m.slide_after_max_cm:.3f}), "
          f"IK error max {m.ik_error_max_cm:.3f} cm")
    plot(result, clip.frame_time, args.out)
    print(f"wrote {args.out}")
    if args.fixed:
        animkit.write_bvh(args.fixed, clip.with_motion(result.motion).scaled(1.0 / args.scale))
        print(f"wrote {args.fixed}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
