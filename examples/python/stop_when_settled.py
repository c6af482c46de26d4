#!/usr/bin/env python3
"""Stop a run once the friction coefficient has settled, and report the time saved.

    python3 examples/python/stop_when_settled.py [--threshold 1e-3] [--out mu_settling.png]

examples/shear-cell-small.toml runs in memory; after the compaction, a callback every
`--every` steps adds mu = -F_x / F_y of the top first body (a zero-copy view) to a running
mean, and stops the run (returns False) once the mean's relative change over the last
`--window` checks stays below `--threshold`. The script prints the simulated time and the
wall time saved against running to the scenario's duration, and plots mu and its running
mean. SOFTGRAIN_EXAMPLES_SHORT=1 runs a reduced cell with a looser threshold (tests).
"""

import argparse
import os
import pathlib
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import softgrain  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--threshold", type=float, default=1e-3,
                        help="relative change of the running mean that counts as settled")
    parser.add_argument("--window", type=int, default=20, help="checks below the threshold")
    parser.add_argument("--every", type=int, default=20, help="steps between checks")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", default="mu_settling.png")
    args = parser.parse_args()

    d = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").to_dict()
    if os.environ.get("SOFTGRAIN_EXAMPLES_SHORT"):
        d["time"]["duration"] = 0.6
        d["shear_cell"].update(length=6.0, grains=18, compaction_time=0.2)
        args.threshold, args.window, args.every = 2e-2, 3, 10
    compaction_time = d["shear_cell"]["compaction_time"]
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(d), threads=args.threads)
    top = list(sim.rigid["body"]).index(sim.bodies()["name"].index("top"))
    fx, fy = sim.rigid["fx"], sim.rigid["fy"]
    times, mus, means = [], [], []
    quiet = 0  # consecutive checks below the threshold

    def settled(s):
        nonlocal quiet
        if s.time <= compaction_time or fy[top] == 0:
            return True  # go on: still compacting, or no contact yet
        times.append(s.time)
        mus.append(-fx[top] / fy[top])
        means.append(np.mean(mus))
        if len(means) > 1:
            change = abs(means[-1] - means[-2]) / max(abs(means[-1]), 1e-12)
            quiet = quiet + 1 if change < args.threshold else 0
        return quiet < args.window  # False stops the run

    start = time.perf_counter()
    finished = sim.run(every=args.every, callback=settled)
    wall = time.perf_counter() - start
    if finished:
        print(f"mu did not settle before the end (t = {sim.time:.4g}); "
              f"mean mu {means[-1] if means else float('nan'):.4g}")
    else:
        saved = sim.duration - sim.time
        wall_saved = wall / sim.time * saved  # at the run's mean pace
        print(f"settled at t = {sim.time:.4g} of {sim.duration:g} (step {sim.step_count}): "
              f"mean mu {means[-1]:.4g}; saved {saved:.4g} time units, "
              f"about {wall_saved:.1f} s of {wall + wall_saved:.1f} s")
    sim.close()

    figure, axes = plt.subplots(figsize=(7, 4), constrained_layout=True)
    axes.plot(times, mus, lw=0.8, label="μ")
    axes.plot(times, means, lw=2, label="running mean")
    axes.set_xlabel("time")
    axes.set_ylabel("μ (top body)")
    axes.legend()
    figure.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
