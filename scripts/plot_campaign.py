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

With --all (what `softgrain sweep` runs), also the campaign figures of papers 001 and 002,
next to campaign.csv, each drawn from the runs that have its quantities:

  campaign_points.png   the runs in (E~, c~, alpha~) as measured (summary.json's
                        stiffness_tilde, cohesion_tilde, viscosity_tilde), coloured by mu
                        (paper 001 Fig. 3)
  mu_vs_stress.png      mu against sigma_n / E = 10^-E~ for every run (paper 001 Fig. 4)
  maps[_alpha=A].png    mu, p_wb, mu_b, mu_s and the share of grains in structures over
                        (E~, c~), interpolated between the runs (scipy.interpolate.griddata,
                        linear on the Delaunay triangulation of the points; nothing outside
                        their convex hull), the runs as dots; one figure per slice of alpha~
                        (runs whose alpha~ rounds to A at --alpha-step) (paper 001 Figs 5, 13,
                        14; paper 002 Figs 11, 13)
  correlations.png      scatter plots of pairs of quantities with their Pearson r and
                        Spearman rho (paper 002 Figs 15-17; paper 003 Fig. 13d: mu vs ATT)
  correlations.csv      x,y,n,pearson,spearman for every pair drawn (n: runs with both)

--pairs X:Y,X:Y chooses the pairs (any two columns of campaign.csv).
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


DEFAULT_PAIRS = [("omega_tilde_mode", "mu"), ("structure_diameter_mean", "contact_friction"),
                 ("att_map", "mu"), ("grain_share_in_structures", "mu"),
                 ("stiffness_tilde", "mu"), ("cohesion_tilde", "mu"),
                 ("viscosity_tilde", "att_map")]
MAP_QUANTITIES = [("mu", "mu"), ("bulk_share", "p_wb"), ("bulk_friction", "mu_b"),
                  ("contact_friction", "mu_s"), ("grain_share_in_structures", "grains in structures")]


def column(rows, key):
    return np.array([number(r.get(key, "")) for r in rows if r["status"] == "done"])


# The PNG "Software" text of every figure: the softgrain builds that analysed the runs
# (campaign.csv's column "softgrain"); set by main().
SOFTWARE = None


def software_of(rows):
    builds = sorted({r.get("softgrain", "") for r in rows} - {""})
    if not builds:
        return None  # a table written before softgrain recorded itself
    return "softgrain " + "; ".join(builds) + " (the runs' analyses), plot_campaign.py"


def metadata():
    return {"Software": SOFTWARE} if SOFTWARE else None


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, metadata=metadata())
    plt.close(fig)
    os.replace(tmp, path)
    print(path)


def correlation(x, y):
    """(n, Pearson r, Spearman rho) over the pairs where both are finite; NaN below 3 pairs
    or for a constant column."""
    from scipy import stats
    ok = np.isfinite(x) & np.isfinite(y)
    x, y = x[ok], y[ok]
    n = int(ok.sum())
    if n < 3 or np.ptp(x) == 0 or np.ptp(y) == 0:
        return n, math.nan, math.nan
    return n, float(stats.pearsonr(x, y)[0]), float(stats.spearmanr(x, y)[0])


def plot_points(rows, folder, campaign):
    e, c, a, mu = (column(rows, k) for k in
                   ("stiffness_tilde", "cohesion_tilde", "viscosity_tilde", "mu"))
    fig = plt.figure(figsize=(6.4, 5.2), dpi=110)
    ax = fig.add_subplot(projection="3d")
    ok = np.isfinite(e) & np.isfinite(c)
    a_shown = np.where(np.isfinite(a), a, 0.0)
    points = ax.scatter(e[ok], c[ok], a_shown[ok], c=mu[ok], cmap="viridis", s=40,
                        depthshade=False)
    ax.set_xlabel("E~")
    ax.set_ylabel("c~")
    ax.set_zlabel("alpha~" + ("" if np.isfinite(a[ok]).all() else " (unknown: 0)"))
    fig.colorbar(points, ax=ax, label="mu", shrink=0.7)
    ax.set_title(f"{campaign}: the runs in (E~, c~, alpha~)")
    save(fig, os.path.join(folder, "campaign_points.png"))


def plot_mu_vs_stress(rows, folder, campaign):
    e, mu = column(rows, "stiffness_tilde"), column(rows, "mu")
    ok = np.isfinite(e) & np.isfinite(mu)
    fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=110)
    ax.plot(10.0 ** -e[ok], mu[ok], "o")
    ax.set_xscale("log")
    ax.set_xlabel("sigma_n / E = 10^-E~")
    ax.set_ylabel("mu")
    ax.set_title(f"{campaign}: mu against sigma_n / E ({int(ok.sum())} runs)")
    save(fig, os.path.join(folder, "mu_vs_stress.png"))


def plot_maps(rows, folder, campaign, alpha_step):
    from scipy.interpolate import griddata
    e, c, a = (column(rows, k) for k in ("stiffness_tilde", "cohesion_tilde", "viscosity_tilde"))
    slices = sorted({round(v / alpha_step) * alpha_step for v in a if np.isfinite(v)})
    written = []
    for alpha in slices or [None]:
        pick = np.isfinite(e) & np.isfinite(c)
        if alpha is not None:
            pick &= np.isfinite(a) & (np.abs(a - alpha) <= alpha_step / 2 + 1e-12)
        name = "maps.png" if alpha is None else f"maps_alpha={alpha:g}.png"
        fig, axes = plt.subplots(2, 3, figsize=(13, 7.6), dpi=100)
        ex, cx = e[pick], c[pick]
        span = lambda v: (v.min(), v.max()) if v.size and np.ptp(v) > 0 else (-1.0, 1.0)
        xi, yi = np.meshgrid(np.linspace(*span(ex), 80), np.linspace(*span(cx), 80))
        for ax, (key, title) in zip(axes.flat, MAP_QUANTITIES):
            z = column(rows, key)[pick]
            ok = np.isfinite(z)
            ax.set_title(title)
            ax.set_xlabel("E~")
            ax.set_ylabel("c~")
            if ok.sum() >= 3 and np.ptp(ex[ok]) > 0 and np.ptp(cx[ok]) > 0:
                zi = griddata((ex[ok], cx[ok]), z[ok], (xi, yi), method="linear")
                mesh = ax.pcolormesh(xi, yi, np.ma.masked_invalid(zi), cmap="viridis",
                                     shading="auto")
                fig.colorbar(mesh, ax=ax)
            else:
                ax.text(0.5, 0.5, f"{int(ok.sum())} runs with {key}: no map",
                        transform=ax.transAxes, ha="center")
            ax.plot(ex, cx, "k.", ms=6)
        axes.flat[-1].axis("off")
        fig.suptitle(f"{campaign}: maps over (E~, c~)"
                     + ("" if alpha is None else f", alpha~ = {alpha:g}"))
        fig.tight_layout()
        save(fig, os.path.join(folder, name))
        written.append(name)
    return written


def plot_correlations(rows, header, folder, campaign, pairs):
    pairs = [(x, y) for x, y in pairs if x in header and y in header]
    table = [("x", "y", "n", "pearson", "spearman")]
    cols = max(1, min(3, len(pairs)))
    lines = max(1, math.ceil(len(pairs) / cols))
    fig, axes = plt.subplots(lines, cols, figsize=(4.4 * cols, 3.8 * lines), dpi=100,
                             squeeze=False)
    for ax, (xk, yk) in zip(axes.flat, pairs):
        x, y = column(rows, xk), column(rows, yk)
        n, r, rho = correlation(x, y)
        table.append((xk, yk, str(n), "" if math.isnan(r) else repr(r),
                      "" if math.isnan(rho) else repr(rho)))
        ax.plot(x, y, "o")
        ax.set_xlabel(xk)
        ax.set_ylabel(yk)
        ax.set_title(f"r = {r:.2f}, rho = {rho:.2f} (n = {n})", fontsize=10)
    for ax in list(axes.flat)[len(pairs):]:
        ax.axis("off")
    fig.suptitle(f"{campaign}: correlations between the runs' quantities")
    fig.tight_layout()
    save(fig, os.path.join(folder, "correlations.png"))
    path = os.path.join(folder, "correlations.csv")
    with open(path + ".tmp", "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(table)
    os.replace(path + ".tmp", path)
    print(path)


def campaign_figures(rows, header, table_path, pairs, alpha_step):
    folder = os.path.dirname(os.path.abspath(table_path))
    campaign = os.path.basename(folder)
    plot_points(rows, folder, campaign)
    plot_mu_vs_stress(rows, folder, campaign)
    plot_maps(rows, folder, campaign, alpha_step)
    plot_correlations(rows, header, folder, campaign, pairs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="campaign.csv written by softgrain sweep")
    parser.add_argument("--x", help="parameter along x (default: the first varied one)")
    parser.add_argument("--y", help="parameter along y (default: the second varied one)")
    parser.add_argument("--z", default="mu", help="quantity to draw (default: mu)")
    parser.add_argument("-o", "--output", help="PNG file (default: mu_map.png beside the table)")
    parser.add_argument("--all", action="store_true",
                        help="also the campaign figures (points, mu vs sigma_n/E, maps, "
                             "correlations) beside the table")
    parser.add_argument("--pairs", help="correlation pairs X:Y,X:Y (default: " +
                        ",".join(f"{x}:{y}" for x, y in DEFAULT_PAIRS) + ")")
    parser.add_argument("--alpha-step", type=float, default=0.5,
                        help="width of the alpha~ slices of the maps (default 0.5)")
    args = parser.parse_args()

    with open(args.table, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [dict(zip(header, r)) for r in reader]
    if "id" not in header or "status" not in header:
        sys.exit(f"{args.table}: not a campaign table (no 'id' and 'status' columns)")
    global SOFTWARE
    SOFTWARE = software_of(rows)
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
    fig.savefig(output, metadata=metadata())
    plt.close(fig)
    print(output)
    if args.all:
        pairs = DEFAULT_PAIRS
        if args.pairs:
            pairs = [tuple(p.split(":", 1)) for p in args.pairs.split(",")]
            bad = [p for p in pairs if len(p) != 2 or p[0] not in header or p[1] not in header]
            if bad:
                sys.exit(f"{args.table}: --pairs: no such columns: {bad}")
        campaign_figures(rows, header, args.table, pairs, args.alpha_step)


if __name__ == "__main__":
    main()
