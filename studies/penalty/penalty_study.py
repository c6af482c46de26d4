#!/usr/bin/python3
"""What the contact penalty does to the quantities users read (issue #30 item 4).

The penalty k_n of a contact law is a numerical parameter, not a property of the grains: the
stiffer it is, the smaller the overlaps (p / k_n under a traction p) and the smaller the step
(a contact adds 2 k_n l_I / m_I to a contour node's omega^2: docs/method.md "Stable step").
This study measures how mu, the bulk dissipation share p_wb, the solid fraction and the
activated thickness move with k_n, on the sheared cohesive layer of
studies/convergence/mu_convergence.py (80 grains, nu = 0.495, E = 10 p, c = p, alpha = 0.09,
pressure p = 1, V = 1, imex) at its two coarsest spacings h = D/6.75 and D/9, with the penalty
of every contact law set to each of PENALTIES. Each point is an ensemble of five packings
(seeds 1-5); every penalty of a seed and spacing starts from the same packing (drawn before the
contacts act), so the effect of k_n is read seed by seed (paired differences against the
stiffest penalty at the same spacing), and compared with the scatter between packings.

The penalty is given two ways in the tables: k_n h / E (the contact spring against the grain's
own stiffness at the scale of its nodes: what the step sees) and k_n D / E (against the grain's
stiffness at its own scale: the overlap over the diameter is about p / E / (k_n D / E)). The
same k_n at two spacings has the same k_n D / E and different k_n h / E, which tells which of
the two the quantities follow.

    /usr/bin/python3 studies/penalty/penalty_study.py run        # every case, then table
    /usr/bin/python3 studies/penalty/penalty_study.py table      # CSV and figure
    /usr/bin/python3 studies/penalty/penalty_study.py markdown   # verification.md's tables

Options: --bin (default build/app/softgrain), --runs (the folder of runs this script owns,
default out/penalty-study/, which git ignores), --only SUBSTRING (cases whose name contains
it), --threads (per run, default 1; results do not depend on it), --jobs (runs at a time,
default 2), --seeds N (default 5). A case whose analysis/summary.json exists is not run again.
Writes studies/penalty/results.csv (one row per run) and studies/penalty/penalty.png. Needs
numpy and matplotlib (Debian: python3-numpy, python3-matplotlib).
"""

import argparse
import concurrent.futures
import math
import os
import sys

STUDY_DIR = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(STUDY_DIR))
sys.path.insert(0, os.path.join(ROOT, "studies", "convergence"))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import mu_convergence as layer  # noqa: E402  (the sheared layer and its runner)

RESULTS = os.path.join(STUDY_DIR, "results.csv")
FIGURE = os.path.join(STUDY_DIR, "penalty.png")
SPACING_RATIOS = (6.75, 9.0)        # D / h: the layer's two coarsest spacings
PENALTIES = (8000.0, 4000.0, 2000.0, 1000.0, 500.0, 250.0)  # k_n of every contact law
YOUNG = 10.0                        # the layer's grains
STIFFEST = max(PENALTIES)
QUANTITIES = layer.QUANTITIES
LABELS = layer.LABELS


def case_name(n, k, seed):
    return f"h{n:g}-k{k:g}-seed{seed}"


def cases(seeds):
    """(D/h, k_n, seed), seed by seed, so that an interrupted study has whole seeds."""
    return [(n, k, seed) for n in SPACING_RATIOS for seed in range(1, seeds + 1)
            for k in PENALTIES]


def scenario_text(n, k, seed):
    text = layer.scenario_text(n, layer.DEFAULT_SAFETY, seed)
    old = "normal_stiffness = 2000.0"
    assert text.count(old) == 3, "the layer's three contact laws"
    return text.replace(old, f"normal_stiffness = {k:g}")


def read_run(runs, n, k, seed):
    h = layer.MEAN_DIAMETER / n
    return layer.read_row(os.path.join(runs, case_name(n, k, seed)),
                          {"spacing_ratio": n, "normal_stiffness": k, "k_h_over_E": k * h / YOUNG,
                           "k_D_over_E": k * layer.MEAN_DIAMETER / YOUNG, "seed": seed},
                          QUANTITIES)


def collect(runs, seeds):
    return [r for r in (read_run(runs, *case) for case in cases(seeds)) if r is not None]


def write_results(rows):
    layer.write_rows(RESULTS, ["spacing_ratio", "normal_stiffness", "k_h_over_E", "k_D_over_E",
                               "seed", *QUANTITIES, "steps", "nodes", "wall_seconds"], rows)


def mean_and_error(values):
    m = sum(values) / len(values)
    se = (math.sqrt(sum((x - m) ** 2 for x in values) / (len(values) - 1) / len(values))
          if len(values) > 1 else float("nan"))
    return m, se, len(values)


def ensembles(rows, quantity):
    """(D/h, k_n) -> (mean, standard error, runs)."""
    out = {}
    for n in SPACING_RATIOS:
        for k in PENALTIES:
            v = [float(r[quantity]) for r in rows
                 if (r["spacing_ratio"], r["normal_stiffness"]) == (n, k) and r[quantity] != ""]
            if v:
                out[(n, k)] = mean_and_error(v)
    return out


def paired_differences(rows, quantity):
    """(D/h, k_n) -> (mean, standard error, pairs) of quantity(k_n) - quantity(stiffest) at the
    same spacing, seed by seed."""
    by = {(r["spacing_ratio"], r["normal_stiffness"], r["seed"]): r[quantity] for r in rows
          if r[quantity] != ""}
    out = {}
    for n in SPACING_RATIOS:
        for k in PENALTIES:
            d = [float(by[(n, k, s)]) - float(by[(n, STIFFEST, s)])
                 for (m, j, s) in by if (m, j) == (n, k) and (n, STIFFEST, s) in by]
            if len(d) > 1:
                out[(n, k)] = mean_and_error(d)
    return out


def median_steps(rows, n, k):
    steps = sorted(int(r["steps"]) for r in rows
                   if (r["spacing_ratio"], r["normal_stiffness"]) == (n, k) and r["steps"])
    return steps[len(steps) // 2] if steps else None


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    for ax, q in zip(axes.flat, QUANTITIES):
        stats = ensembles(rows, q)
        for n, marker in zip(SPACING_RATIOS, ("o", "s")):
            ks = [k for k in PENALTIES if (n, k) in stats]
            ax.errorbar([k * layer.MEAN_DIAMETER / YOUNG for k in ks],
                        [stats[(n, k)][0] for k in ks],
                        yerr=[0.0 if math.isnan(stats[(n, k)][1]) else stats[(n, k)][1]
                              for k in ks], marker=marker, capsize=3, label=f"h = D/{n:g}")
        for r in rows:
            if r[q] != "":
                ax.plot(r["k_D_over_E"], float(r[q]), ".", color="grey", alpha=0.5)
        ax.set_xscale("log")
        ax.set_xlabel("penalty k_n D / E (D: mean diameter)")
        ax.set_title(LABELS[q], fontsize=10)
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    fig.suptitle("Sheared cohesive layer (ν = 0.495, Ẽ = 1, c̃ = 0, α̃ ≈ −2): the contact penalty; "
                 "ensemble means ± standard errors (grey: each run, seeds 1-5)", fontsize=11)
    layer.save_figure(fig, FIGURE)


def markdown(rows):
    stats = {q: ensembles(rows, q) for q in QUANTITIES}
    print("| D/h | k_n | k_n h / E | k_n D / E | runs | steps (median) | " +
          " | ".join(LABELS[q] for q in QUANTITIES) + " |")
    print("|---|---|---|---|---|---|" + "---|" * len(QUANTITIES))
    for (n, k) in sorted(stats["mu"], key=lambda nk: (nk[0], -nk[1])):
        cells = []
        for q in QUANTITIES:
            m, e, _ = stats[q][(n, k)]
            cells.append(f"{m:.4g}" if math.isnan(e) else f"{m:.4g} ± {e:.2g}")
        print(f"| {n:g} | {k:g} | {k / n / YOUNG:.3g} | {k * layer.MEAN_DIAMETER / YOUNG:g} | "
              f"{stats['mu'][(n, k)][2]} | {median_steps(rows, n, k)} | " + " | ".join(cells) +
              " |")
    print()
    print(f"Paired differences against k_n = {STIFFEST:g} at the same spacing, seed by seed:")
    print()
    print("| D/h | k_n h / E | k_n D / E | " + " | ".join(LABELS[q] for q in QUANTITIES) + " |")
    print("|---|---|---|" + "---|" * len(QUANTITIES))
    diffs = {q: paired_differences(rows, q) for q in QUANTITIES}
    for (n, k) in sorted(diffs["mu"], key=lambda nk: (nk[0], -nk[1])):
        if k == STIFFEST:
            continue
        cells = [f"{d[0]:+.3g} ± {d[1]:.2g} ({d[2]})"
                 for d in (diffs[q][(n, k)] for q in QUANTITIES)]
        print(f"| {n:g} | {k / n / YOUNG:.3g} | {k * layer.MEAN_DIAMETER / YOUNG:g} | " +
              " | ".join(cells) + " |")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("command", choices=["run", "table", "markdown"])
    p.add_argument("--bin", default=os.path.join(ROOT, "build", "app", "softgrain"))
    p.add_argument("--runs", default=os.path.join(ROOT, "out", "penalty-study"))
    p.add_argument("--only", default="")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--seeds", type=int, default=5)
    a = p.parse_args()
    if a.command == "run":
        os.makedirs(a.runs, exist_ok=True)
        todo = [case for case in cases(a.seeds) if a.only in case_name(*case)]
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            for job in [pool.submit(layer.run_and_analyze, os.path.abspath(a.bin), a.runs,
                                    case_name(*case), scenario_text(*case), a.threads,
                                    layer.WINDOW) for case in todo]:
                job.result()
    layer.report(a.command, collect(a.runs, a.seeds), markdown, write_results, plot,
                 (RESULTS, FIGURE))


if __name__ == "__main__":
    sys.exit(main())
