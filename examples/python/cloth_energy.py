"""Runs a cloth scene and plots its energies over time: total, kinetic, elastic (springs and
bends) and gravitational, saved as a PNG.

    PYTHONPATH=build/rel/python /usr/bin/python3 examples/python/cloth_energy.py [out.png]
        [--scene lab] [--frames 300]

The lab's cloth (the default) falls from flat and swings on its two pinned corners: gravity's
energy turns into motion and stretch, while damping (the springs' dashpots and implicit
Euler's own) slowly takes the total down.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # a file, no window
import matplotlib.pyplot as plt  # noqa: E402

import animkit  # noqa: E402


def energies(scene_name, frames):
    """Times (s) and the four energies after every step of the scene."""
    scene = animkit.ClothScene.builtin(scene_name)
    sim = animkit.ClothSimulator(scene)
    series = {"time": [], "total": [], "kinetic": [], "elastic": [], "gravitational": []}

    def record():
        e = sim.energy()
        series["time"].append(sim.time)
        for name in ("total", "kinetic", "elastic", "gravitational"):
            series[name].append(getattr(e, name))

    record()
    sim.run(frames=frames or scene.frames, callback=lambda frame, report: record())
    return series, sim


def plot(series, title, path):
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    for name, colour in (("total", "black"), ("kinetic", "tab:orange"),
                         ("elastic", "tab:green"), ("gravitational", "tab:blue")):
        ax.plot(series["time"], series[name], color=colour, label=name,
                linewidth=2.0 if name == "total" else 1.2)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("energy (scene units)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", nargs="?", default="cloth_energy.png",
                        help="the PNG to write (default: cloth_energy.png here)")
    parser.add_argument("--scene", default="lab",
                        help="a built-in scene: " + ", ".join(animkit.builtin_cloth_scene_names()))
    parser.add_argument("--frames", type=int, default=None,
                        help="steps to simulate (default: the scene's own)")
    args = parser.parse_args()
    series, sim = energies(args.scene, args.frames)
    title = (f"{args.scene}: {sim.particle_count} particles, {sim.integrator_name}, "
             f"{sim.steps_taken} steps of {sim.dt:.4g} s")
    plot(series, title, pathlib.Path(args.out))
    print(f"wrote {args.out}: total energy {series['total'][0]:.4g} -> {series['total'][-1]:.4g}")


if __name__ == "__main__":
    main()
