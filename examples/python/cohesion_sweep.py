#!/usr/bin/env python3
"""Vary the cohesion over five values and plot mu against the reduced cohesion c~.

    python3 examples/python/cohesion_sweep.py [--out mu_vs_cohesion.png] [--threads N]

Each run is examples/shear-cell-small.toml with the cohesion c of every cohesive contact law
set to one value, run in memory (no files): a callback reads the top first body's force
from the zero-copy views over the second half of the run. c~ = log10(c / sigma_n) with
sigma_n the mean normal stress on the top body (docs/analysis.md, cohesion_tilde).
SOFTGRAIN_EXAMPLES_SHORT=1 runs a reduced cell for a fraction of a time unit (tests).
"""

import argparse
import copy
import os
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import softgrain  # noqa: E402

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
COHESIONS = [0.02, 0.05, 0.1, 0.2, 0.5]


def base_dict():
    d = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").to_dict()
    if os.environ.get("SOFTGRAIN_EXAMPLES_SHORT"):
        d["time"]["duration"] = 0.6
        d["shear_cell"].update(length=6.0, grains=18, compaction_time=0.2)
    return d


def friction_and_stress(scenario, threads):
    """(mu, sigma_n) on the top first body over the second half of the run."""
    sim = softgrain.Simulation(scenario, threads=threads)
    bodies = sim.bodies()
    top = list(sim.rigid["body"]).index(bodies["name"].index("top"))
    fx, fy = sim.rigid["fx"], sim.rigid["fy"]  # views: they follow the run
    samples = []

    def sample(s):
        if s.time > 0.5 * s.duration:
            samples.append((fx[top], fy[top]))

    sim.run(every=5, callback=sample)
    mean_fx, mean_fy = np.mean(samples, axis=0)
    length = scenario.to_dict()["shear_cell"]["length"]
    return -mean_fx / mean_fy, abs(mean_fy) / length


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="mu_vs_cohesion.png")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()

    base = base_dict()
    results = []
    for c in COHESIONS:
        d = copy.deepcopy(base)
        d["name"] = f"cohesion-{c:g}"
        for law in d["contact_laws"]:
            if "cohesion" in law:
                law["cohesion"] = c
        mu, sigma_n = friction_and_stress(softgrain.Scenario.from_dict(d), args.threads)
        results.append((c, np.log10(c / sigma_n), mu))
        print(f"c = {c:<5g} sigma_n = {sigma_n:.4g}  c~ = {results[-1][1]:+.3f}  mu = {mu:.4g}")

    c_tilde = [r[1] for r in results]
    mu = [r[2] for r in results]
    figure, axes = plt.subplots(figsize=(6, 4), constrained_layout=True)
    axes.plot(c_tilde, mu, "o-")
    axes.set_xlabel("c~ = log10(c / σn)")
    axes.set_ylabel("μ (top body, second half)")
    axes.set_title("friction against cohesion")
    figure.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
