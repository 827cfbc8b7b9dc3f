"""A parameter sweep over a Dask cluster: a sheet dropped onto a ball, for every stretch
stiffness x friction pair, each run on whichever worker is free; the results gathered into one
table (CSV) and one plot (PNG).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/cloth_sweep_dask.py \\
        [--scheduler tcp://HOST:8786] [--out sweep] [--frames 20]

Without --scheduler it starts a LocalCluster of two worker processes (one thread each) on this
machine; with it, the same code runs on a real cluster (`dask-scheduler` on one machine,
`dask-worker tcp://HOST:8786` on each of the others, every one with animkit importable). Dask
is Debian's python3-distributed.

Nothing of animkit crosses the network: a task is a plain function of plain numbers that builds
its scene on the worker, and returns plain numbers. animkit's long calls (ClothSimulator.run)
release the GIL, so a worker's other threads (its heartbeat, the scheduler's messages) keep
going while it simulates. Results are the same bits on any worker: the library is
deterministic, whatever the machine's thread count.
"""
import argparse
import csv
import pathlib
import time

import animkit

STRETCHES = (250.0, 1000.0, 4000.0)  # N/m: softer than cotton, cotton, denim-like
FRICTIONS = (0.1, 0.3, 0.6)


def drop_on_ball(stretch, friction, frames=20, cells=12):
    """Drops a 1 m sheet of `cells` cells per side onto a ball (radius 0.25 m) on the ground
    and returns what the run did: how low the sheet hangs, the solver's work, its energy."""
    started = time.perf_counter()
    material = animkit.Material(density=0.15, stretch=stretch, shear=stretch / 25.0)
    cloth = animkit.GridCloth(cells=cells, size=1.0, height=0.6, material=material, pins="none",
                              offset=(-0.5, 0.0, 0.0))
    ball = animkit.Collider.sphere("ball", radius=0.25, position=(0.0, 0.25, 0.0),
                                   friction=friction)
    scene = animkit.ClothScene(cloth=cloth, colliders=[ball],
                               ground=animkit.Ground(height=0.0, friction=friction),
                               dt=1.0 / 30.0, frames=frames)
    sim = animkit.ClothSimulator(scene)
    reports = sim.run()
    heights = sim.positions[:, 1]
    return {
        "stretch": stretch,
        "friction": friction,
        "lowest_m": float(heights.min()),
        "mean_height_m": float(heights.mean()),
        "final_energy_j": reports[-1].energy,
        "newton_mean": sum(r.newton_iterations for r in reports) / len(reports),
        "converged_fraction": sum(r.converged for r in reports) / len(reports),
        "seconds": time.perf_counter() - started,  # the one field that differs run to run
    }


def parameters():
    return [(s, f) for s in STRETCHES for f in FRICTIONS]


def sweep(client, frames=20, cells=12):
    """Every pair run as a task on the client's cluster; results in the parameters' order."""
    futures = [client.submit(drop_on_ball, s, f, frames, cells, pure=False)
               for s, f in parameters()]
    return client.gather(futures)


def sweep_serially(frames=20, cells=12):
    """The same runs one after another in this process (what the cluster's results equal)."""
    return [drop_on_ball(s, f, frames, cells) for s, f in parameters()]


def write_table(results, path):
    with open(path, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(results[0]))
        writer.writeheader()
        writer.writerows(results)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")  # a file, no window
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    for friction in FRICTIONS:
        rows = [r for r in results if r["friction"] == friction]
        ax.plot([r["stretch"] for r in rows], [r["mean_height_m"] for r in rows], marker="o",
                label=f"friction {friction}")
    ax.set_xscale("log")
    ax.set_xlabel("stretch stiffness (N/m)")
    ax.set_ylabel("sheet's mean height at the end (m)")
    ax.set_title("A sheet dropped on a ball: stiffness x friction")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="a Dask scheduler's address (default: a "
                                            "LocalCluster of 2 workers here)")
    parser.add_argument("--out", default="sweep", help="folder for sweep.csv and sweep.png")
    parser.add_argument("--frames", type=int, default=20)
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=None))
    with client:
        started = time.perf_counter()
        results = sweep(client, frames=args.frames)
        wall = time.perf_counter() - started
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_table(results, out / "sweep.csv")
    plot(results, out / "sweep.png")
    busy = sum(r["seconds"] for r in results)
    print(f"{len(results)} runs: {busy:.1f} s of simulation in {wall:.1f} s; wrote "
          f"{out / 'sweep.csv'} and {out / 'sweep.png'}")


if __name__ == "__main__":
    main()
