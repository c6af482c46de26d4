#!/usr/bin/python3
"""Draw a campaign's friction coefficient over two of its parameters (docs/campaigns.md).

    /usr/bin/python3 scripts/plot_campaign.py out/campaigns/mu-map/campaign.csv
    /usr/bin/python3 scripts/plot_campaign.py campaign.csv --x materials.0.young \\
        --y contact_laws.0.cohesion --z mu_std -o mu_std.png

Reads campaign.csv as `softgrain sweep` writes it: columns id, the varied parameters (named
by their dotted keys), status, then the scalars of each run's analysis/summary.json (empty
when unknown). Draws a map with one cell per pair of parameter values, coloured by the
quantity and annotated with its value ("-": not computed, e.g. no steady state or not run).
The cells are evenly spaced whatever the values (they are the campaign's choices, often
logarithmic), labelled with the values. With one varied parameter it draws a curve.
Several runs in one cell (a third parameter varied) are averaged and the count is shown.
Default output: mu_map.png next to campaign.csv.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def number(text):
    """The cell as a float, NaN if empty or not a number."""
    try:
        return float(text)
    except ValueError:
        return math.nan


def sort_values(values):
    """Distinct values, numerically sorted when they all are numbers."""
    distinct = list(dict.fromkeys(values))
    if all(not math.isnan(number(v)) for v in distinct):
        return sorted(distinct, key=number)
    return distinct


def label(value):
    """A parameter value as written in TOML, shortened for a tick label."""
    x = number(value)
    if not math.isnan(x):
        return f"{x:g}"
    return value.strip("'\"")


def annotate(value, count):
    text = "-" if math.isnan(value) else f"{value:.3g}"
    return text if count <= 1 else f"{text}\n(mean of {count})"


def choose_axes(parameters, rows, x, y):
    """The two parameters to draw: the given ones, else the first pair whose values form a
    full product (two [[list]] keys that change together, such as the cohesions of two
    contact laws, would give a diagonal map), else the first two."""
    if x and y:
        return x, y
    candidates = [p for p in parameters if p != x and p != y]
    def distinct(*keys):
        return len({tuple(r[k] for k in keys) for r in rows})
    pairs = [(a, b) for i, a in enumerate(parameters) for b in parameters[i + 1:]]
    if x or y:
        given = x or y
        pairs = [(given, b) for b in candidates]
    for a, b in pairs:
        if distinct(a) > 1 and distinct(b) > 1 and distinct(a, b) == distinct(a) * distinct(b):
            return (a, b) if (x or not y) else (b, a)
    if x or y:
        other = candidates[0] if candidates else None
        return (x, other) if x else (other, y)
    return parameters[0], (parameters[1] if len(parameters) > 1 else None)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="campaign.csv written by softgrain sweep")
    parser.add_argument("--x", help="parameter along x (default: the first varied one)")
    parser.add_argument("--y", help="parameter along y (default: the second varied one)")
    parser.add_argument("--z", default="mu", help="quantity to draw (default: mu)")
    parser.add_argument("-o", "--output", help="PNG file (default: mu_map.png beside the table)")
    args = parser.parse_args()

    with open(args.table, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [dict(zip(header, r)) for r in reader]
    if "id" not in header or "status" not in header:
        sys.exit(f"{args.table}: not a campaign table (no 'id' and 'status' columns)")
    parameters = header[header.index("id") + 1:header.index("status")]
    if not parameters:
        sys.exit(f"{args.table}: no varied parameter")
    for key in (args.x, args.y):
        if key is not None and key not in parameters:
            sys.exit(f"{args.table}: '{key}' is not a varied parameter; they are: "
                     + ", ".join(parameters))
    x_key, y_key = choose_axes(parameters, rows, args.x, args.y)
    z_key = args.z
    if z_key not in header:
        sys.exit(f"{args.table}: no column '{z_key}' (no run finished yet?)")
    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.table)),
                                         "mu_map.png")
    campaign = os.path.basename(os.path.dirname(os.path.abspath(args.table)))
    done = sum(r["status"] == "done" for r in rows)

    xs = sort_values([r[x_key] for r in rows])
    fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=120)
    if y_key is None:
        # One parameter: a curve (mean per value), each run's point behind it.
        means = []
        for v in xs:
            z = [number(r[z_key]) for r in rows if r[x_key] == v]
            z = [q for q in z if not math.isnan(q)]
            means.append(np.mean(z) if z else math.nan)
        positions = np.arange(len(xs))
        ax.plot(positions, means, "o-")
        for p, m in zip(positions, means):
            ax.annotate(annotate(m, 1), (p, m if not math.isnan(m) else 0),
                        textcoords="offset points", xytext=(0, 6), ha="center")
        ax.set_xticks(positions, [label(v) for v in xs])
        ax.set_xlabel(x_key)
        ax.set_ylabel(z_key)
    else:
        ys = sort_values([r[y_key] for r in rows])
        grid = np.full((len(ys), len(xs)), math.nan)
        counts = np.zeros((len(ys), len(xs)), dtype=int)
        for j, yv in enumerate(ys):
            for i, xv in enumerate(xs):
                z = [number(r[z_key]) for r in rows if r[x_key] == xv and r[y_key] == yv]
                counts[j, i] = len(z)
                z = [q for q in z if not math.isnan(q)]
                if z:
                    grid[j, i] = np.mean(z)
        mesh = ax.pcolormesh(np.arange(len(xs) + 1) - 0.5, np.arange(len(ys) + 1) - 0.5,
                             np.ma.masked_invalid(grid), cmap="viridis", shading="flat")
        finite = grid[np.isfinite(grid)]
        middle = (finite.min() + finite.max()) / 2 if finite.size else 0.0
        if not finite.size:
            mesh.set_clim(0.0, 1.0)  # nothing computed yet: an empty map, labelled "-"
        for j in range(len(ys)):
            for i in range(len(xs)):
                value = grid[j, i]
                dark = not math.isnan(value) and value < middle
                ax.text(i, j, annotate(value, counts[j, i]), ha="center", va="center",
                        color="white" if dark else "black", fontsize=9)
        ax.set_xticks(range(len(xs)), [label(v) for v in xs])
        ax.set_yticks(range(len(ys)), [label(v) for v in ys])
        ax.set_xlim(-0.5, len(xs) - 0.5)
        ax.set_ylim(-0.5, len(ys) - 0.5)
        ax.set_xlabel(x_key)
        ax.set_ylabel(y_key)
        fig.colorbar(mesh, ax=ax, label=z_key)
    ax.set_title(f"{campaign}: {z_key} ({done} of {len(rows)} runs done)")
    fig.tight_layout()
    fig.savefig(output)
    print(output)


if __name__ == "__main__":
    main()
