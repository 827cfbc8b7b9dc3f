#!/usr/bin/env python3
"""The lab's IK experiment from Python: the lab's arm draws its five shapes with both solvers
(CCD and FABRIK), one target per frame, each solve warm-started from the previous frame, as the
lab's app and `animkit ik` do. Prints a table of what the solvers did and plots the iterations
each target took, one panel per shape.

    PYTHONPATH=build/rel/python /usr/bin/python3 examples/python/lab_drawings.py iterations.png

The table's columns: converged % (targets reached within the tolerance), mean and max
iterations per target, jitter (the largest frame-to-frame change of any joint's rotation,
radians: the lab's question 3) and the mean final error.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")  # a file, never a window
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)

import animkit  # noqa: E402

SOLVERS = {"ccd": "CCD", "fabrik": "FABRIK"}
COLOURS = {"ccd": "tab:blue", "fabrik": "tab:orange"}


def run_lab(max_iterations, tolerance):
    """{(shape, solver): DrawingRun} for the five lab shapes and both solvers."""
    arm = animkit.Chain.lab_arm()
    runs = {}
    for shape in animkit.lab_shape_names():
        targets = animkit.lab_shape(shape)
        for solver in SOLVERS:
            runs[shape, solver] = animkit.run_drawing(arm, targets, solver=solver,
                                                      max_iterations=max_iterations,
                                                      tolerance=tolerance)
    return runs


def print_table(runs):
    header = (f"{'shape':<10}{'solver':<8}{'targets':>8}{'converged %':>13}"
              f"{'mean iter':>11}{'max iter':>10}{'jitter rad':>12}{'mean error':>12}")
    print(header)
    print("-" * len(header))
    for (shape, solver), run in runs.items():
        s = run.summary()
        print(f"{shape:<10}{SOLVERS[solver]:<8}{s.targets:>8d}{100 * s.converged_fraction:>13.1f}"
              f"{s.iterations_mean:>11.2f}{s.iterations_max:>10d}{s.max_joint_step_rad:>12.4f}"
              f"{s.error_mean:>12.3e}")


def plot(runs, path):
    shapes = animkit.lab_shape_names()
    fig, axes = plt.subplots(3, 2, figsize=(11, 10), constrained_layout=True)
    for ax, shape in zip(axes.flat, shapes):
        for solver, label in SOLVERS.items():
            run = runs[shape, solver]
            ax.plot(run.iterations, color=COLOURS[solver], linewidth=1.2,
                    label=f"{label} (mean {run.iterations.mean():.2f})")
        ax.set_title(shape)
        ax.set_xlabel("target")
        ax.set_ylabel("iterations")
        ax.set_ylim(bottom=0)
        ax.legend(loc="best", fontsize="small")
    # The last panel: mean iterations side by side.
    summary = axes.flat[len(shapes)]
    width = 0.38
    for k, (solver, label) in enumerate(SOLVERS.items()):
        means = [runs[shape, solver].iterations.mean() for shape in shapes]
        summary.bar([i + (k - 0.5) * width for i in range(len(shapes))], means, width,
                    color=COLOURS[solver], label=label)
    summary.set_xticks(range(len(shapes)), shapes)
    summary.set_ylabel("mean iterations per target")
    summary.set_title("all shapes")
    summary.legend()
    fig.suptitle("The lab's arm: IK iterations per target (warm start, tolerance "
                 f"{runs[shapes[0], 'ccd'].tolerance:g})")
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("png", help="where to write the plot of iterations per target")
    parser.add_argument("--max-iterations", type=int, default=100, help="cap per target")
    parser.add_argument("--tolerance", type=float, default=1e-4, help="convergence distance")
    args = parser.parse_args(argv)
    try:
        runs = run_lab(args.max_iterations, args.tolerance)
    except animkit.Error as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print_table(runs)
    plot(runs, args.png)
    print(f"wrote {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
