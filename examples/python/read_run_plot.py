#!/usr/bin/env python3
"""Read a run and plot the friction coefficient mu(t) and a strain-rate snapshot.

    python3 examples/python/read_run_plot.py [RUN_FOLDER] [--out mu_and_strain_rate.png]

Without RUN_FOLDER the script first runs examples/shear-cell-small.toml in-process, writing
out/shear-cell-small/ as `softgrain run` would (SOFTGRAIN_EXAMPLES_SHORT=1: a reduced cell and
a fraction of a time unit, for the tests). docs/python.md walks through it.
"""

import argparse
import os
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

import softgrain  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]


def demo_scenario():
    """examples/shear-cell-small.toml, reduced when SOFTGRAIN_EXAMPLES_SHORT is set."""
    d = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").to_dict()
    if os.environ.get("SOFTGRAIN_EXAMPLES_SHORT"):
        d["time"]["duration"] = 0.6
        d["output"] = {"series_period": 0.01, "field_period": 0.2}
        d["shear_cell"].update(length=6.0, grains=18, compaction_time=0.2)
    return softgrain.Scenario.from_dict(d)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", nargs="?", help="run folder (default: run the demo first)")
    parser.add_argument("--out", default="mu_and_strain_rate.png", help="picture to write")
    args = parser.parse_args()

    folder = args.run
    if folder is None:
        sim = softgrain.Simulation(demo_scenario(), output="out")
        sim.run()
        folder = sim.directory
    run = softgrain.open_run(folder)

    # mu(t) = -F_x / F_y on the top first body (the force it receives from the layer).
    series = run.series
    t = series["time"]
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(series["top_fy"] != 0, -series["top_fx"] / series["top_fy"], np.nan)

    # The last snapshot: the triangles of the deformable grains, coloured by the strain rate
    # (|d|E|/dt| over V/D, io/vtk_writer.h).
    fields = run.fields(-1)
    offsets = np.concatenate([[0], fields["offsets"]])
    triangles = np.array([fields["connectivity"][offsets[c]:offsets[c + 1]]
                          for c in np.flatnonzero(fields["types"] == 5)])
    grid = mtri.Triangulation(fields["points"][:, 0], fields["points"][:, 1], triangles)

    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), constrained_layout=True)
    top.plot(t, mu)
    top.set_xlabel("time")
    top.set_ylabel("μ = −F_x / F_y (top body)")
    top.set_title(f"{run.parameters['name']}: friction coefficient")
    picture = bottom.tripcolor(grid, fields["strain_rate"], shading="gouraud", cmap="viridis")
    bottom.set_aspect("equal")
    bottom.set_title(f"strain rate at t = {run.times[-1]:g}")
    figure.colorbar(picture, ax=bottom, label="strain rate / (V/D)")
    figure.savefig(args.out, dpi=100)
    steady = t > 0.5 * t[-1]
    print(f"{folder}: {len(t)} series rows, {len(run.times)} snapshots; "
          f"mean mu over the second half {np.nanmean(mu[steady]):.4g}; wrote {args.out}")


if __name__ == "__main__":
    main()
