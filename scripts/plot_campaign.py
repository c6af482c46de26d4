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
next to campaign.csv, each drawn from the runs that have its quantities. Axes carry the
papers' symbols (LABELS: one table from column to label), not the columns' keys:

  campaign_points.png   the runs in (E~, c~, alpha~) as measured (summary.json's
                        stiffness_tilde, cohesion_tilde, viscosity_tilde), coloured by mu
                        (paper 001 Fig. 3)
  mu_vs_stress.png      mu against sigma_n / E = 10^-E~ for every run, coloured by c~, with
                        error bars: mu's error of the mean (mu_error) where the run has it,
                        else the standard deviation of mu(t) (mu_std); the title says which
                        (paper 001 Fig. 4)
  bulk_share_vs_cohesion.png
                        p_wb (%) against c~, coloured by E~, with a straight line fitted to
                        the runs of each E~ (the requested E~ of a campaign in the papers'
                        coordinates, else E~ rounded to --alpha-step) and a plane p_wb = a +
                        b c~ + d E~ fitted to all runs, their parameters in the legend
                        (paper 001 Fig. 13: "linear fittings ... as a guide for the eye")
  maps[_alpha=A].png    mu, p_wb, mu_b, mu_s and the share of grains in structures over
                        (E~, c~), interpolated between the runs (scipy.interpolate.griddata,
                        linear on the Delaunay triangulation of the points; nothing outside
                        their convex hull), the runs as dots; one figure per slice of alpha~:
                        the runs that requested alpha~ = A (a campaign in the papers'
                        coordinates), else those whose realized alpha~ rounds to A at
                        --alpha-step; the title gives the slice's realized range of alpha~.
                        A quantity no run of the slice has, or that is the same for all, gets
                        no panel; a note under the maps names it (paper 001 Figs 5, 13, 14;
                        paper 002 Figs 11, 13)
  correlations.png      scatter plots of pairs of quantities with their Pearson r and
                        Spearman rho (paper 002 Figs 13A/B, 15, 16, 17A/B; paper 003 Fig. 13d:
                        mu vs ATT); a pair without coefficients (fewer than 3 runs with both,
                        or a constant one) gets no panel, a note under the others names it
  correlations.csv      x,y,n,pearson,spearman for every pair (n: runs with both; empty
                        coefficients for the pairs left out of the picture)

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
from matplotlib.ticker import MaxNLocator  # noqa: E402


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


# (x, y) drawn by default in correlations.png, each as its paper draws it: paper 002 Fig. 13A
# (omega~ against E~), 13B (against the solid fraction), 15 (structure diameter against c~),
# 16 (mu against omega~), 17A (mu_b against omega~), 17B (mu_s against the structure
# diameter); paper 003 Fig. 13d (mu against the ATT); mu against the realized E~ and c~, and
# the ATT against alpha~.
DEFAULT_PAIRS = [("stiffness_tilde", "omega_tilde_mode"), ("solid_fraction", "omega_tilde_mode"),
                 ("cohesion_tilde", "structure_diameter_mean"), ("omega_tilde_mode", "mu"),
                 ("omega_tilde_mode", "bulk_friction"),
                 ("structure_diameter_mean", "contact_friction"), ("att_map", "mu"),
                 ("stiffness_tilde", "mu"), ("cohesion_tilde", "mu"),
                 ("viscosity_tilde", "att_map")]
# Paper 002 Figs 13A/B: the size of a dot is the share of the run's grains in structures.
SIZED_BY_GRAIN_SHARE = {("stiffness_tilde", "omega_tilde_mode"),
                        ("solid_fraction", "omega_tilde_mode")}
MAP_QUANTITIES = ["mu", "bulk_share", "bulk_friction", "contact_friction",
                  "grain_share_in_structures"]

# Every axis, colour bar and title names a column of campaign.csv by its symbol in the papers
# (matplotlib mathtext); a column not listed keeps its key. "<key>_requested" (the coordinate
# a campaign asked for) is labelled as <key> with "(requested)".
LABELS = {
    "mu": r"$\mu$",
    "mu_std": r"std of $\mu(t)$",
    "mu_error": r"error of the mean of $\mu$",
    "top_mu": r"$\mu$ (top)",
    "bottom_mu": r"$\mu$ (bottom)",
    "stiffness_tilde": r"$\tilde{E}$",
    "cohesion_tilde": r"$\tilde{c}$",
    "viscosity_tilde": r"$\tilde{\alpha}$",
    "normal_stress": r"$\bar{\sigma}_n$",
    "shear_stress": r"$\bar{\sigma}_t$",
    "top_normal_stress": r"$\bar{\sigma}_n$ (top)",
    "bottom_normal_stress": r"$\bar{\sigma}_n$ (bottom)",
    "imposed_pressure": r"$p$",
    "bulk_share": r"$p_{wb}$",
    "contact_share": r"$p_{ws}$",
    "bulk_friction": r"$\mu_b$",
    "contact_friction": r"$\mu_s$",
    "mu_from_dissipation": r"$\mu$ from the dissipation",
    "mu_from_work": r"$\mu$ from the external work",
    "solid_fraction": r"$S_F$",
    "att_map": "ATT (velocity map)",
    "att_profile": "ATT (profile)",
    "structure_count": "structures",
    "grain_share_in_structures": "share of grains in structures",
    "omega_tilde_mode": r"$\tilde{\omega}$ (mode)",
    "omega_tilde_mean": r"$\tilde{\omega}$ (mean)",
    "structure_diameter_mode": r"structure diameter $D$ (mode)",
    "structure_diameter_mean": r"structure diameter $D$ (mean)",
    "structure_lifetime_mean": r"structure lifetime $\mathcal{L}$ (mean)",
}
REQUESTED = "_requested"


def label_of(key):
    """The papers' symbol of a campaign.csv column (LABELS), else the key itself."""
    if key in LABELS:
        return LABELS[key]
    if key.endswith(REQUESTED) and key[:-len(REQUESTED)] in LABELS:
        return LABELS[key[:-len(REQUESTED)]] + " (requested)"
    return key


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


def why_no_panel(x, y, names):
    """Why a scatter of y against x would show nothing (no run has both, fewer than 3, one
    of them constant), or None if it has something to show. `names`: their labels."""
    ok = np.isfinite(x) & np.isfinite(y)
    n = int(ok.sum())
    if n == 0:
        return "no run has both"
    if n < 3:
        return f"{n} run{'s' if n > 1 else ''} with both (3 needed)"
    for v, name in zip((x[ok], y[ok]), names):
        if np.ptp(v) == 0:
            return f"{name} is {v[0]:g} for every run"
    return None


def why_no_map(e, c, z):
    """Why a map of z over (E~, c~) would show nothing, or None."""
    ok = np.isfinite(z) & np.isfinite(e) & np.isfinite(c)
    if ok.sum() == 0:
        return "no run of the slice has it"
    if ok.sum() < 3:
        return f"{int(ok.sum())} run{'s' if ok.sum() > 1 else ''} of the slice have it (3 needed)"
    if np.ptp(e[ok]) == 0 or np.ptp(c[ok]) == 0:
        return r"the runs with it do not span $(\tilde{E}, \tilde{c})$"
    if np.ptp(z[ok]) == 0:
        return f"{z[ok][0]:g} for every run"
    return None


def note_left_out(fig, left_out):
    """Names the panels left out, under the figure; returns the share of the figure's height
    the note takes (for tight_layout's rect), 0 without one."""
    if not left_out:
        return 0.0
    text = "left out: " + "; ".join(left_out)
    width, height = fig.get_size_inches() * fig.dpi
    # About 5.5 pixels a character at 8 points and 100-120 dpi; wrapped to the figure width.
    lines = math.ceil(len(text) * 5.5 / (0.96 * width))
    fig.text(0.01, 0.005, text, fontsize=8, ha="left", va="bottom", color="0.3", wrap=True)
    return min(0.3, (12.0 * lines + 8.0) / height)


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
    # The 3D axes and the colour bar side by side, each label inside the figure.
    ax = fig.add_axes((0.0, 0.02, 0.80, 0.88), projection="3d")
    ok = np.isfinite(e) & np.isfinite(c)
    a_shown = np.where(np.isfinite(a), a, 0.0)
    points = ax.scatter(e[ok], c[ok], a_shown[ok], c=mu[ok], cmap="viridis", s=40,
                        depthshade=False)
    ax.set_xlabel(label_of("stiffness_tilde"))
    ax.set_ylabel(label_of("cohesion_tilde"))
    ax.set_zlabel(label_of("viscosity_tilde")
                  + ("" if np.isfinite(a[ok]).all() else " (unknown: 0)"), labelpad=12)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(4))
    ax.set_box_aspect(None, zoom=0.85)
    fig.colorbar(points, cax=fig.add_axes((0.84, 0.2, 0.03, 0.6)), label=label_of("mu"))
    fig.suptitle(f"{campaign}: the runs in " + r"$(\tilde{E}, \tilde{c}, \tilde{\alpha})$",
                 x=0.45)
    save(fig, os.path.join(folder, "campaign_points.png"))


def mu_error_bars(rows):
    """Each run's error bar on mu and what it is: the error of the mean (mu_error) where the
    run has it, else the standard deviation of mu(t) (mu_std)."""
    error, std = column(rows, "mu_error"), column(rows, "mu_std")
    bars = np.where(np.isfinite(error), error, std)
    from_std = int(np.sum(~np.isfinite(error) & np.isfinite(std)))
    if from_std == 0:
        what = r"error bars: error of the mean of $\mu$"
    elif from_std == np.isfinite(bars).sum():
        what = r"error bars: standard deviation of $\mu(t)$"
    else:
        what = (r"error bars: error of the mean of $\mu$; std of $\mu(t)$ for "
                f"{from_std} runs without it")
    return bars, what


def plot_mu_vs_stress(rows, folder, campaign):
    e, mu, c = column(rows, "stiffness_tilde"), column(rows, "mu"), column(rows, "cohesion_tilde")
    bars, what = mu_error_bars(rows)
    ok = np.isfinite(e) & np.isfinite(mu)
    fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=110)
    stress = 10.0 ** -e
    coloured = ok & np.isfinite(c)
    norm = plt.Normalize(*(np.nanmin(c[coloured]), np.nanmax(c[coloured]))
                         if coloured.any() else (0.0, 1.0))
    cmap = plt.get_cmap("viridis")
    for k in np.nonzero(ok)[0]:
        colour = cmap(norm(c[k])) if np.isfinite(c[k]) else "grey"
        ax.errorbar(stress[k], mu[k], yerr=bars[k] if np.isfinite(bars[k]) else None,
                    fmt="o", color=colour, ecolor=colour, capsize=3, ms=6)
    if coloured.any():
        fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax,
                     label=label_of("cohesion_tilde"))
    ax.set_xscale("log")
    ax.set_xlabel(r"$\bar{\sigma}_n / E = 10^{-\tilde{E}}$")
    ax.set_ylabel(label_of("mu"))
    ax.set_title(f"{campaign}: " + r"$\mu$ against $\bar{\sigma}_n / E$"
                 + f" ({int(ok.sum())} runs)\n{what}", fontsize=10)
    fig.tight_layout()
    save(fig, os.path.join(folder, "mu_vs_stress.png"))


def stiffness_groups(rows, step):
    """Each run's E~ group for the fits of bulk_share_vs_cohesion.png: the E~ the campaign
    requested (stiffness_tilde_requested), else the realized E~ rounded to `step`."""
    requested = column(rows, "stiffness_tilde" + REQUESTED)
    if np.isfinite(requested).any():
        return requested, "requested"
    e = column(rows, "stiffness_tilde")
    return np.round(e / step) * step, "rounded"


def fit_line(x, y):
    """(a, b) of y = a + b x, least squares."""
    b, a = np.polyfit(x, y, 1)
    return a, b


def fit_plane(c, e, y):
    """(a, b, d, R^2) of y = a + b c + d e, least squares."""
    design = np.column_stack([np.ones_like(c), c, e])
    coefficients = np.linalg.lstsq(design, y, rcond=None)[0]
    residual = y - design @ coefficients
    total = np.sum((y - y.mean()) ** 2)
    r2 = 1.0 - np.sum(residual ** 2) / total if total > 0 else math.nan
    return (*coefficients, r2)


def plot_bulk_share(rows, folder, campaign, step):
    """Paper 001 Fig. 13: p_wb (%) against c~, coloured by E~, with linear fits."""
    c, e = column(rows, "cohesion_tilde"), column(rows, "stiffness_tilde")
    p_wb = 100.0 * column(rows, "bulk_share")
    groups, grouping = stiffness_groups(rows, step)
    ok = np.isfinite(c) & np.isfinite(e) & np.isfinite(p_wb)
    fig, ax = plt.subplots(figsize=(7.2, 4.8), dpi=110)
    cmap = plt.get_cmap("viridis")
    norm = plt.Normalize(*(e[ok].min(), e[ok].max()) if ok.any() and np.ptp(e[ok]) > 0
                         else (e[ok].min() - 1, e[ok].max() + 1) if ok.any() else (0, 1))
    points = ax.scatter(c[ok], p_wb[ok], c=e[ok], cmap=cmap, norm=norm, s=40, zorder=3,
                        edgecolors="k", linewidths=0.4)
    fig.colorbar(points, ax=ax, label=label_of("stiffness_tilde"))
    if not ok.any():
        ax.text(0.5, 0.5, "no run has " + label_of("bulk_share") + r", $\tilde{c}$ and "
                r"$\tilde{E}$", ha="center", transform=ax.transAxes)
    fitted = 0
    for g in sorted({v for v in groups[ok] if np.isfinite(v)}):
        pick = ok & (groups == g)
        if len(set(c[pick])) < 2:
            continue  # one c~: no line
        a, b = fit_line(c[pick], p_wb[pick])
        span = np.array([c[pick].min(), c[pick].max()])
        name = r"$\tilde{E}$ " + ("= " if grouping == "requested" else r"$\approx$ ") + f"{g:g}"
        ax.plot(span, a + b * span, "-", color=cmap(norm(np.mean(e[pick]))), lw=1.2,
                label=name + f": $p_{{wb}}$ = {a:.1f} {'+' if b >= 0 else '-'} {abs(b):.1f} "
                r"$\tilde{c}$")
        fitted += 1
    if ok.sum() >= 4 and np.ptp(c[ok]) > 0 and np.ptp(e[ok]) > 0:
        a, b, d, r2 = fit_plane(c[ok], e[ok], p_wb[ok])
        ax.plot([], [], " ", label=f"plane: $p_{{wb}}$ = {a:.1f} {'+' if b >= 0 else '-'} "
                f"{abs(b):.1f} " + r"$\tilde{c}$" + f" {'+' if d >= 0 else '-'} {abs(d):.1f} "
                + r"$\tilde{E}$" + f" ($R^2$ = {r2:.2f})")
        fitted += 1
    if fitted:
        ax.legend(fontsize=8, loc="best", title="linear fits (%)", title_fontsize=8)
    ax.set_xlabel(label_of("cohesion_tilde"))
    ax.set_ylabel(label_of("bulk_share") + " (%)")
    ax.set_title(f"{campaign}: share of the dissipation in the bulk ({int(ok.sum())} runs)",
                 fontsize=10)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(folder, "bulk_share_vs_cohesion.png"))


def alpha_slices(rows, header, alpha_step):
    """[(A, runs of the slice, how they were chosen)]: the runs that requested alpha~ = A
    (viscosity_tilde_requested), else those whose realized alpha~ rounds to A; [(None, all
    runs, "")] when alpha~ is unknown everywhere."""
    if "viscosity_tilde" + REQUESTED in header:
        requested = column(rows, "viscosity_tilde" + REQUESTED)
        values = sorted({v for v in requested if np.isfinite(v)})
        if values:
            return [(v, requested == v, "requested") for v in values]
    a = column(rows, "viscosity_tilde")
    values = sorted({round(v / alpha_step) * alpha_step for v in a if np.isfinite(v)})
    if not values:
        return [(None, np.ones(a.size, dtype=bool), "")]
    return [(v, np.isfinite(a) & (np.abs(a - v) <= alpha_step / 2 + 1e-12), "rounded")
            for v in values]


def minus(text):
    """A number's hyphen as the minus sign (U+2212), as in the papers' titles."""
    return text.replace("-", "\u2212")


def slice_title(alpha, realized, how, alpha_step):
    """The realized range of alpha~ over a slice, and what chose its runs."""
    if alpha is None:
        return ""
    known = realized[np.isfinite(realized)]
    shown = (r"$\tilde{\alpha} \in$" + minus(f" [{known.min():.2f}, {known.max():.2f}]")
             if known.size else r"$\tilde{\alpha}$ not measured")
    if how == "requested":
        return f", {shown} (requested {minus(f'{alpha:g}')})"
    return f", {shown} (realized within {alpha_step / 2:g} of {minus(f'{alpha:g}')})"


def plot_maps(rows, header, folder, campaign, alpha_step):
    from scipy.interpolate import griddata
    e, c, a = (column(rows, k) for k in ("stiffness_tilde", "cohesion_tilde", "viscosity_tilde"))
    written = []
    for alpha, in_slice, how in alpha_slices(rows, header, alpha_step):
        pick = in_slice & np.isfinite(e) & np.isfinite(c)
        name = "maps.png" if alpha is None else f"maps_alpha={alpha:g}.png"
        fig, axes = plt.subplots(2, 3, figsize=(13, 7.6), dpi=100)
        ex, cx = e[pick], c[pick]
        span = lambda v: (v.min(), v.max()) if v.size and np.ptp(v) > 0 else (-1.0, 1.0)
        xi, yi = np.meshgrid(np.linspace(*span(ex), 80), np.linspace(*span(cx), 80))
        left_out = []
        drawn = 0
        for key in MAP_QUANTITIES:
            z = column(rows, key)[pick]
            why = why_no_map(ex, cx, z)
            if why:
                left_out.append(f"{label_of(key)}: {why}")
                continue
            ax = axes.flat[drawn]
            drawn += 1
            ok = np.isfinite(z)
            zi = griddata((ex[ok], cx[ok]), z[ok], (xi, yi), method="linear")
            mesh = ax.pcolormesh(xi, yi, np.ma.masked_invalid(zi), cmap="viridis",
                                 shading="auto")
            fig.colorbar(mesh, ax=ax)
            ax.plot(ex, cx, "k.", ms=6)
            ax.set_title(label_of(key))
            ax.set_xlabel(label_of("stiffness_tilde"))
            ax.set_ylabel(label_of("cohesion_tilde"))
        for ax in axes.flat[drawn:]:
            ax.axis("off")
        if drawn == 0:
            axes.flat[0].text(0.5, 0.5, "no quantity to map", transform=axes.flat[0].transAxes,
                              ha="center")
        fig.suptitle(f"{campaign}: maps over " + r"$(\tilde{E}, \tilde{c})$"
                     + slice_title(alpha, a[in_slice], how, alpha_step))
        fig.tight_layout(rect=(0, note_left_out(fig, left_out), 1, 1))
        save(fig, os.path.join(folder, name))
        written.append(name)
    return written


def correlation_table(rows, pairs):
    """[(x, y, n, r, rho, why no panel or None)] for every pair."""
    table = []
    for xk, yk in pairs:
        x, y = column(rows, xk), column(rows, yk)
        n, r, rho = correlation(x, y)
        why = why_no_panel(x, y, (label_of(xk), label_of(yk)))
        table.append((xk, yk, n, r, rho, why))
    return table


def correlation_grid(panels):
    """(columns, lines) of correlations.png for `panels` panels (one panel at least)."""
    cols = max(1, min(3, panels))
    return cols, max(1, math.ceil(panels / cols))


def plot_correlations(rows, header, folder, campaign, pairs):
    pairs = [(x, y) for x, y in pairs if x in header and y in header]
    table = correlation_table(rows, pairs)
    shown = [t for t in table if t[5] is None]
    cols, lines = correlation_grid(len(shown))
    fig, axes = plt.subplots(lines, cols, figsize=(4.4 * cols, 3.8 * lines), dpi=100,
                             squeeze=False)
    share = column(rows, "grain_share_in_structures")
    for ax, (xk, yk, n, r, rho, _) in zip(axes.flat, shown):
        x, y = column(rows, xk), column(rows, yk)
        if (xk, yk) in SIZED_BY_GRAIN_SHARE and np.isfinite(share).any():
            sizes = 10.0 + 400.0 * np.nan_to_num(share)
            ax.scatter(x, y, s=sizes, alpha=0.7, edgecolors="k", linewidths=0.4)
            ax.text(0.02, 0.02, "dot size: share of grains in structures",
                    transform=ax.transAxes, fontsize=7, color="0.3")
        else:
            ax.plot(x, y, "o")
        ax.xaxis.set_major_locator(MaxNLocator(5))  # a narrow range has long tick labels
        ax.set_xlabel(label_of(xk))
        ax.set_ylabel(label_of(yk))
        ax.set_title(f"r = {r:.2f}, " + r"$\rho$" + f" = {rho:.2f} (n = {n})", fontsize=10)
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[len(shown):]:
        ax.axis("off")
    if not shown:
        axes.flat[0].text(0.5, 0.5, "no pair with coefficients", ha="center",
                          transform=axes.flat[0].transAxes)
    fig.suptitle(f"{campaign}: correlations between the runs' quantities")
    left_out = [f"{label_of(t[1])} against {label_of(t[0])}: {t[5]}" for t in table if t[5]]
    fig.tight_layout(rect=(0, note_left_out(fig, left_out), 1, 1))
    save(fig, os.path.join(folder, "correlations.png"))
    path = os.path.join(folder, "correlations.csv")
    lines_out = [("x", "y", "n", "pearson", "spearman")]
    for xk, yk, n, r, rho, _ in table:
        lines_out.append((xk, yk, str(n), "" if math.isnan(r) else repr(r),
                          "" if math.isnan(rho) else repr(rho)))
    with open(path + ".tmp", "w", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(lines_out)
    os.replace(path + ".tmp", path)
    print(path)


def campaign_figures(rows, header, table_path, pairs, alpha_step):
    folder = os.path.dirname(os.path.abspath(table_path))
    campaign = os.path.basename(folder)
    plot_points(rows, folder, campaign)
    plot_mu_vs_stress(rows, folder, campaign)
    plot_bulk_share(rows, folder, campaign, alpha_step)
    plot_maps(rows, header, folder, campaign, alpha_step)
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
        ax.set_xlabel(label_of(x_key))
        ax.set_ylabel(label_of(z_key))
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
        ax.set_xlabel(label_of(x_key))
        ax.set_ylabel(label_of(y_key))
        fig.colorbar(mesh, ax=ax, label=label_of(z_key))
    ax.set_title(f"{campaign}: {label_of(z_key)} ({done} of {len(rows)} runs done)")
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
