#!/usr/bin/python3
"""Plots of a run folder analysed by `softgrain analyze`, drawn into RUN_DIR/analysis/.

    /usr/bin/python3 scripts/plot_run.py RUN_DIR      (softgrain analyze --plots runs it)
    /usr/bin/python3 scripts/plot_run.py RUN_DIR --snapshot velocity_x=PNG ...

Reads what `softgrain run` and `softgrain analyze` wrote and draws, each when its inputs
are there (otherwise it says why and goes on):

  mu.png               mu(t) = Ft(t)/Fn(t) of the first bodies `top` and `bottom` (series.csv,
                       sign convention of docs/analysis.md), the steady window shaded and
                       the window means (summary.json) as lines; the window's failed
                       steadiness checks (summary.json "warnings") in red under it
  profiles.png         vx and vy across the gap: mean +- one standard deviation per bin
                       (profiles.csv)
  energy.png           shares of the dissipation p_wb (bulk damping) and p_ws (contacts), and
                       the mean powers over the window: damping, contacts, external work
                       (summary.json); the failed steadiness checks in red, as for mu.png
  agglomerate_pdfs.png grain-weighted PDFs of omega~, diameter and lifetime of the
                       agglomerates (agglomerate_pdfs.csv)
  compaction.png       compaction-box runs only: solid fraction against lid stress, and both
                       against time (compaction.csv); nothing said for other runs
  space_time.png       the filtered coherence |C| > threshold stacked over time, projected on
                       x-t and y-t, red where C > 0 (counter-clockwise), blue where C < 0
                       (clockwise, with the shear) (paper 002 Fig. 8C; agglomerate_space_time.csv)
  cylinders.png        each detected structure as a cylinder in (x, y, t): axis at its centre,
                       height = lifetime, diameter = mean-area diameter, red when it turns
                       counter-clockwise, blue clockwise, the deeper the larger |omega~|;
                       x and y on one scale, so that a cylinder's section is a circle
                       (paper 002 Figs 9, 10, 14; agglomerate_cylinders.csv)
  att.png              activated third-body thickness against time, from the velocity map and
                       from the profile, the window means as lines (paper 003 Fig. 13; att.csv)
  composite.png        shear cells: the run on one page, in the manner of paper 001 Figs 6-12:
                       on the left the layer at the last field snapshot coloured by the
                       horizontal velocity, the strain rate and the von Mises stress; on the
                       right the run's place in (E~, c~, alpha~) (realized, and requested when
                       the run belongs to a campaign: summary.json "campaign"), mu(t) with its
                       window, and the velocity profiles. The snapshots are the PNGs given
                       with --snapshot FIELD=PNG (softgrain analyze draws them into
                       RUN_DIR/render/), else the newest RUN_DIR/render/FIELD_NNNNNN.png; a
                       missing one is said in its place (--snapshot-note TEXT: why)

Needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib). Each picture is
written to a temporary file and renamed, so a reader never sees half a PNG, and names in its
PNG "Software" text the softgrain version and commit that wrote summary.json. Exit status 0
if every picture whose inputs exist was drawn, 1 on an error (one line on stderr).
"""

import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SUMMARY_FORMAT = "softgrain-analysis-summary"
SUMMARY_VERSION = 1


class PlotError(Exception):
    pass


def read_csv(path):
    """Columns of a CSV (header line, '#' comments skipped) as {name: list of str}."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    if not rows:
        raise PlotError(f"{path}: empty file")
    header, body = rows[0], rows[1:]
    for k, r in enumerate(body, start=2):
        if len(r) != len(header):
            raise PlotError(f"{path}:{k}: {len(r)} fields, the header has {len(header)}")
    return {name: [r[i] for r in body] for i, name in enumerate(header)}


def numbers(path, table, name):
    """One column as floats (empty cells -> NaN)."""
    if name not in table:
        raise PlotError(f"{path}: no column '{name}' (present: {', '.join(table)})")
    out = []
    for k, v in enumerate(table[name], start=2):
        try:
            out.append(float(v) if v != "" else math.nan)
        except ValueError:
            raise PlotError(f"{path}:{k}: column '{name}': cannot parse '{v}' as a number")
    return np.array(out)


def read_summary(analysis_dir):
    path = os.path.join(analysis_dir, "summary.json")
    if not os.path.exists(path):
        raise PlotError(f"{path} is missing: run 'softgrain analyze RUN_DIR' first")
    with open(path) as f:
        doc = json.load(f)
    if doc.get("format") != SUMMARY_FORMAT or doc.get("version") != SUMMARY_VERSION:
        raise PlotError(
            f"{path}: format '{doc.get('format')}' version {doc.get('version')}, expected "
            f"'{SUMMARY_FORMAT}' version {SUMMARY_VERSION}")
    return doc


def value(summary, key):
    """A quantity of summary.json; None if absent or null."""
    q = summary.get("quantities", {}).get(key)
    return None if q is None else q.get("value")


def note_warnings(fig, summary):
    """The window's failed steadiness checks (summary.json "warnings"), in red under the
    picture: the averages drawn are suspect. Returns True if there were any."""
    checks = [w.get("check", "?") for w in summary.get("warnings", [])]
    if not checks:
        return False
    fig.text(0.01, 0.01, "window not steady (summary.json warnings): " + ", ".join(checks),
             color="tab:red", fontsize=8, ha="left", va="bottom")
    return True


# The PNG "Software" text of every picture: the softgrain that wrote summary.json (its
# "softgrain" object), as softgrain's own pictures carry it; set by main().
SOFTWARE = None


def software_of(summary):
    s = summary.get("softgrain")
    if not isinstance(s, dict):
        return None  # written before softgrain recorded itself
    return f"softgrain {s.get('version', '?')} (commit {s.get('commit', 'unknown')}), plot_run.py"


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, metadata={"Software": SOFTWARE} if SOFTWARE else None)
    plt.close(fig)
    os.replace(tmp, path)
    return path


def read_mu_series(run_dir):
    """(time, {body: mu(t)}) of the first bodies, or None for a run without them."""
    path = os.path.join(run_dir, "series.csv")
    series = read_csv(path)
    # docs/analysis.md: Fn = n B_fy, Ft = -s B_fx; top s = n = +1, bottom s = n = -1.
    bodies = [("top", 1.0, 1.0), ("bottom", -1.0, -1.0)]
    if not all(f"{b}_fx" in series and f"{b}_fy" in series for b, _, _ in bodies):
        return None
    t = numbers(path, series, "time")
    mu = {}
    for body, s, n in bodies:
        fn = n * numbers(path, series, f"{body}_fy")
        ft = -s * numbers(path, series, f"{body}_fx")
        with np.errstate(divide="ignore", invalid="ignore"):
            mu[body] = np.where(fn > 0.0, ft / fn, np.nan)  # undefined while nothing presses
    return t, mu


NO_MU = "no mu(t): series.csv has no 'top' and 'bottom' columns (not a shear cell)"


def draw_mu(ax, t, mu_of, summary, legend_size=8, columns=1):
    """mu(t) of both first bodies, the steady window shaded, the window means as lines."""
    t0, t1 = value(summary, "window_begin"), value(summary, "window_end")
    if t0 is not None and t1 is not None:
        ax.axvspan(t0, t1, color="0.9", label=f"window [{t0:.3g}, {t1:.3g}]")
    colours = {"top": "tab:red", "bottom": "tab:blue"}
    for body, mu in mu_of.items():
        ax.plot(t, mu, lw=0.8, color=colours[body], label=f"{body}")
        mean = value(summary, f"{body}_mu")
        if mean is not None and t0 is not None:
            ax.hlines(mean, t0, t1, colors=colours[body], linestyles="--", lw=1.2,
                      label=f"{body} mean {mean:.3f}")
    mean = value(summary, "mu")
    if mean is not None and t0 is not None:
        ax.hlines(mean, t0, t1, colors="k", lw=1.5, label=f"mean mu = {mean:.3f}")
    finite = np.concatenate([l.get_ydata() for l in ax.lines])
    finite = finite[np.isfinite(finite)]
    if finite.size:
        # The compaction transient can reach large ratios; show the 1st-99th percentile.
        lo, hi = np.percentile(finite, [1, 99])
        pad = 0.1 * max(hi - lo, 1e-3)
        ax.set_ylim(lo - pad, hi + pad)
    ax.set_xlabel("time")
    ax.set_ylabel(r"$\mu = F_t / F_n$")
    ax.legend(fontsize=legend_size, loc="best", ncol=columns)


def plot_mu(run_dir, analysis_dir, summary):
    read = read_mu_series(run_dir)
    if read is None:
        return None, NO_MU
    fig, ax = plt.subplots(figsize=(8, 4.2))
    draw_mu(ax, *read, summary)
    ax.set_title("friction coefficient of the first bodies")
    fig.tight_layout(rect=(0, 0.05, 1, 1) if note_warnings(fig, summary) else None)
    return save(fig, os.path.join(analysis_dir, "mu.png")), None


def read_profiles(analysis_dir):
    """(y, {component: (mean, std)}) of analysis/profiles.csv, or None if it is missing."""
    path = os.path.join(analysis_dir, "profiles.csv")
    if not os.path.exists(path):
        return None
    p = read_csv(path)
    return numbers(path, p, "y_center"), {
        comp: (numbers(path, p, f"{comp}_mean"), numbers(path, p, f"{comp}_std"))
        for comp in ("vx", "vy")}


NO_PROFILES = "no profiles: analysis/profiles.csv is missing"


def plot_profiles(analysis_dir):
    read = read_profiles(analysis_dir)
    if read is None:
        return None, NO_PROFILES
    y, profiles = read
    fig, axes = plt.subplots(1, 2, figsize=(8, 4.2), sharey=True)
    for ax, (comp, (mean, std)) in zip(axes, profiles.items()):
        ax.fill_betweenx(y, mean - std, mean + std, color="tab:blue", alpha=0.25,
                         label="mean +- std")
        ax.plot(mean, y, "o-", color="tab:blue", ms=3, lw=1.2, label="mean")
        ax.axvline(0.0, color="0.6", lw=0.8)
        ax.set_xlabel(f"{comp} (length/time)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("y (length)")
    axes[0].legend(fontsize=8)
    fig.suptitle("velocity profiles across the gap (grain centres, window)")
    fig.tight_layout()
    return save(fig, os.path.join(analysis_dir, "profiles.png")), None


def plot_energy(analysis_dir, summary):
    shares = [("p_wb (bulk damping)", value(summary, "bulk_share")),
              ("p_ws (contacts)", value(summary, "contact_share"))]
    powers = [("damping P_b", value(summary, "bulk_power")),
              ("contacts P_s", value(summary, "contact_power")),
              ("external work P_ext", value(summary, "external_power"))]
    if any(v is None for _, v in shares):
        return None, "no energy plot: the energy budget is null in summary.json"
    fig, (a, b) = plt.subplots(1, 2, figsize=(8, 4.2))
    names = [n for n, _ in shares]
    vals = [v for _, v in shares]
    a.bar(names, vals, color=["tab:orange", "tab:green"])
    for k, v in enumerate(vals):
        a.text(k, v, f"{v:.3f}", ha="center", va="bottom")
    mu_b, mu_s = value(summary, "bulk_friction"), value(summary, "contact_friction")
    if mu_b is not None and mu_s is not None:
        a.set_title(f"dissipation shares (mu_b = {mu_b:.3f}, mu_s = {mu_s:.3f})", fontsize=9)
    else:
        a.set_title("dissipation shares", fontsize=10)
    a.set_ylim(0, max(1.0, max(vals) * 1.15))
    names = [n for n, v in powers if v is not None]
    vals = [v for _, v in powers if v is not None]
    b.bar(names, vals, color=["tab:orange", "tab:green", "tab:gray"][: len(vals)])
    for k, v in enumerate(vals):
        b.text(k, v, f"{v:.3g}", ha="center", va="bottom" if v >= 0 else "top")
    b.axhline(0.0, color="k", lw=0.6)
    b.set_title("mean powers over the window (energy/time)", fontsize=10)
    for ax in (a, b):
        ax.tick_params(axis="x", labelsize=8)
    fig.tight_layout(rect=(0, 0.05, 1, 1) if note_warnings(fig, summary) else None)
    return save(fig, os.path.join(analysis_dir, "energy.png")), None


def plot_agglomerates(analysis_dir):
    path = os.path.join(analysis_dir, "agglomerate_pdfs.csv")
    if not os.path.exists(path):
        return None, "no agglomerate PDFs: analysis/agglomerate_pdfs.csv is missing"
    p = read_csv(path)
    quantity = np.array(p.get("quantity", []))
    lo = numbers(path, p, "bin_lo")
    hi = numbers(path, p, "bin_hi")
    density = numbers(path, p, "density")
    panels = [("omega_tilde", "omega~ = omega / (-V/D)"), ("diameter", "diameter (length)"),
              ("lifetime", "lifetime (time)")]
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.8))
    for ax, (q, label) in zip(axes, panels):
        sel = quantity == q
        if not sel.any() or not np.any(density[sel] > 0):
            ax.text(0.5, 0.5, "no structure", ha="center", va="center", transform=ax.transAxes)
        else:
            edges = np.append(lo[sel], hi[sel][-1])
            ax.stairs(density[sel], edges, fill=True, alpha=0.6)
            if q == "omega_tilde":
                used = np.nonzero(density[sel] > 0)[0]
                ax.set_xlim(edges[used[0]] - 0.5, edges[used[-1] + 1] + 0.5)
        ax.set_xlabel(label)
        ax.set_ylabel("PDF (equivalent grains)")
        ax.grid(alpha=0.3)
    fig.suptitle("agglomerates (paper 002): PDFs weighted by equivalent grains")
    fig.tight_layout()
    return save(fig, os.path.join(analysis_dir, "agglomerate_pdfs.png")), None


def plot_compaction(analysis_dir):
    path = os.path.join(analysis_dir, "compaction.csv")
    if not os.path.exists(path):
        return None, None  # not a compaction box: nothing to draw, nothing to say
    c = read_csv(path)
    t = numbers(path, c, "time")
    stress = numbers(path, c, "lid_stress")
    phi = numbers(path, c, "solid_fraction")
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4.2))
    a.plot(stress, phi, "-", color="tab:blue", lw=1.2)
    a.plot(stress[:1], phi[:1], "o", color="tab:green", ms=5, label=f"start: {phi[0]:.4f}")
    a.plot(stress[-1:], phi[-1:], "s", color="tab:red", ms=5, label=f"end: {phi[-1]:.4f}")
    a.set_xlabel("lid stress lid_fy / W (force/length)")
    a.set_ylabel("solid fraction A / (W h)")
    a.set_title("compaction curve", fontsize=10)
    a.grid(alpha=0.3)
    a.legend(fontsize=8, loc="lower right")
    b.plot(t, phi, color="tab:blue", lw=1.2)
    b.set_xlabel("time")
    b.set_ylabel("solid fraction", color="tab:blue")
    b2 = b.twinx()
    b2.plot(t, stress, color="tab:orange", lw=1.0)
    b2.set_ylabel("lid stress (force/length)", color="tab:orange")
    b.set_title("solid fraction and lid stress against time", fontsize=10)
    b.grid(alpha=0.3)
    fig.tight_layout()
    return save(fig, os.path.join(analysis_dir, "compaction.png")), None


def plot_space_time(analysis_dir):
    path = os.path.join(analysis_dir, "agglomerate_space_time.csv")
    if not os.path.exists(path):
        return None, "no space-time picture: analysis/agglomerate_space_time.csv is missing"
    c = read_csv(path)
    t, x, y, sign = (numbers(path, c, k) for k in ("time", "x", "y", "sign"))
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    if t.size == 0:
        for ax in (a, b):
            ax.text(0.5, 0.5, "no cell with |C| above the threshold", ha="center",
                    va="center", transform=ax.transAxes)
    for ax, coordinate, name in ((a, x, "x"), (b, y, "y")):
        for s_value, colour, label in ((1, "tab:red", "C > 0 (counter-clockwise)"),
                                       (-1, "tab:blue", "C < 0 (clockwise)")):
            sel = sign == s_value
            if sel.any():
                ax.scatter(coordinate[sel], t[sel], s=6, marker="s", color=colour,
                           alpha=0.35, linewidths=0, label=label)
        ax.set_xlabel(name)
        ax.set_ylabel("time")
        ax.set_title(f"{name}-t projection", fontsize=10)
        ax.grid(alpha=0.3)
    if t.size:
        a.legend(fontsize=8, loc="upper right")
    fig.suptitle("filtered coherence stacked over time (paper 002)")
    fig.tight_layout()
    return save(fig, os.path.join(analysis_dir, "space_time.png")), None


def rotation_colour(sign, omega, omega_max):
    """Red for a structure turning counter-clockwise (C > 0), blue clockwise (C < 0), as
    paper 002 Fig. 14; the deeper, the larger |omega~| (a floor keeps the slowest visible).
    Grey when the sign is unknown."""
    if not np.isfinite(sign) or sign == 0:
        return "grey"
    depth = 0.6 if not np.isfinite(omega) else 0.25 + 0.75 * min(abs(omega) / omega_max, 1.0)
    return plt.get_cmap("Reds" if sign > 0 else "Blues")(depth)


def plot_cylinders(analysis_dir):
    path = os.path.join(analysis_dir, "agglomerate_cylinders.csv")
    if not os.path.exists(path):
        return None, "no cylinders: analysis/agglomerate_cylinders.csv is missing"
    c = read_csv(path)
    fig = cylinders_figure(*(numbers(path, c, k) for k in (
        "x_center", "y_center", "t_bottom", "height", "diameter", "omega_tilde", "sign")))
    return save(fig, os.path.join(analysis_dir, "cylinders.png")), None


def cylinders_figure(x, y, t0, h, d, w, sign):
    """The structures as cylinders in (x, y, t) (paper 002 Fig. 14)."""
    fig = plt.figure(figsize=(8, 6))
    # The 3D axes leave room on the left for the z label and on the right for the two colour
    # bars (inside the figure's own box: the label was clipped to "tim").
    ax = fig.add_axes((0.0, 0.04, 0.80, 0.86), projection="3d")
    finite_w = np.abs(w[np.isfinite(w)])
    omega_max = max(float(finite_w.max()), 1e-12) if finite_w.size else 1.0
    theta = np.linspace(0, 2 * np.pi, 24)
    for k in range(x.size):
        z = np.array([t0[k], t0[k] + h[k]])
        th, zz = np.meshgrid(theta, z)
        ax.plot_surface(x[k] + 0.5 * d[k] * np.cos(th), y[k] + 0.5 * d[k] * np.sin(th), zz,
                        color=rotation_colour(sign[k], w[k], omega_max), alpha=0.85,
                        linewidth=0, shade=False)
    if x.size:
        # x and y on one scale (a section is a circle); time as tall as half the widest side.
        x_lo, x_hi = np.min(x - 0.5 * d), np.max(x + 0.5 * d)
        y_lo, y_hi = np.min(y - 0.5 * d), np.max(y + 0.5 * d)
        z_lo, z_hi = np.min(t0), np.max(t0 + h)
        dx, dy = max(x_hi - x_lo, 1e-9), max(y_hi - y_lo, 1e-9)
        ax.set_xlim(x_lo, x_hi)
        ax.set_ylim(y_lo, y_hi)
        ax.set_zlim(z_lo, z_hi if z_hi > z_lo else z_lo + 1.0)
        ax.set_box_aspect((dx, dy, 0.5 * max(dx, dy)), zoom=0.9)
    else:
        ax.text2D(0.5, 0.5, "no structure", ha="center", transform=ax.transAxes)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("time", labelpad=6)
    # Two colour bars back to back, their labels outside: red on the left, blue on the right.
    for k, (cmap, label, side) in enumerate((("Reds", "counter-clockwise (C > 0)", "left"),
                                             ("Blues", "clockwise (C < 0)", "right"))):
        bar = fig.add_axes((0.855 + 0.035 * k, 0.15, 0.025, 0.65))
        colours = plt.get_cmap(cmap)(np.linspace(0.25, 1.0, 256))
        mappable = plt.cm.ScalarMappable(
            cmap=matplotlib.colors.ListedColormap(colours), norm=plt.Normalize(0.0, omega_max))
        fig.colorbar(mappable, cax=bar)
        bar.yaxis.set_ticks_position(side)
        bar.yaxis.set_label_position(side)
        bar.set_ylabel(r"$|\tilde{\omega}|$, " + label, fontsize=9)
    fig.suptitle(f"{x.size} structures: height = lifetime, diameter = mean-area diameter",
                 fontsize=10, x=0.42, y=0.97)
    return fig


def plot_att(analysis_dir, summary):
    path = os.path.join(analysis_dir, "att.csv")
    if not os.path.exists(path):
        return None, "no activated thickness: analysis/att.csv is missing"
    c = read_csv(path)
    t, grains, profile = (numbers(path, c, k) for k in ("time", "att_map", "att_profile"))
    fig, ax = plt.subplots(figsize=(8, 4.2))
    ax.plot(t, grains, "o-", ms=3, color="tab:blue", label="from the velocity map")
    ax.plot(t, profile, "s-", ms=3, color="tab:orange", label="from the profile")
    for key, colour in (("att_map", "tab:blue"), ("att_profile", "tab:orange")):
        v = value(summary, key)
        if v is not None:
            ax.axhline(v, color=colour, ls="--", lw=1)
    ax.set_xlabel("time")
    ax.set_ylabel("activated thickness (length)")
    ax.set_title("activated third-body thickness (paper 003 §3.4)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return save(fig, os.path.join(analysis_dir, "att.png")), None


# The composite's snapshots, top to bottom (softgrain analyze draws them: render/
# composite_snapshots.h), with their titles.
COMPOSITE_FIELDS = [("velocity_x", r"horizontal velocity $v_x$"),
                    ("strain_rate", "strain rate"),
                    ("von_mises", "von Mises stress")]
COORDINATES = [("stiffness_tilde", r"$\tilde{E}$"), ("cohesion_tilde", r"$\tilde{c}$"),
               ("viscosity_tilde", r"$\tilde{\alpha}$")]


def newest_render(run_dir, field):
    """RUN_DIR/render/<field>_NNNNNN.png of the largest NNNNNN (the last frame), or None."""
    folder = os.path.join(run_dir, "render")
    if not os.path.isdir(folder):
        return None
    numbered = [f for f in os.listdir(folder) if f.startswith(field + "_")
                and f.endswith(".png") and f[len(field) + 1:-4].isdigit()]
    return os.path.join(folder, max(numbered)) if numbered else None


def composite_snapshots(run_dir, given, notes):
    """{field: PNG} and the notes of the missing ones. Given snapshots (--snapshot,
    --snapshot-note) are taken as they are; without any, the newest render/ pictures."""
    if given or notes:
        return dict(given), list(notes)
    found, missing = {}, []
    for field, _ in COMPOSITE_FIELDS:
        png = newest_render(run_dir, field)
        if png:
            found[field] = png
        else:
            missing.append(f"no {field} snapshot in render/ (softgrain render RUN_DIR "
                           f"--field {field} --frames last)")
    return found, missing


def draw_snapshot(ax, field, title, png, notes):
    ax.set_axis_off()
    ax.set_title(f"{title}, last snapshot", fontsize=9, loc="left")
    if png and os.path.exists(png):
        ax.imshow(plt.imread(png), interpolation="antialiased")
        return
    # The notes about this field, else the general ones (no fields.pvd, ...).
    fields = [f for f, _ in COMPOSITE_FIELDS]
    mine = [n for n in notes if field in n]
    general = [n for n in notes if not any(f in n for f in fields)]
    text = "\n".join(mine or general or [f"no {field} snapshot"])
    ax.text(0.5, 0.5, text, ha="center", va="center", fontsize=8, wrap=True,
            transform=ax.transAxes, color="0.3")


def coordinates_of(summary):
    """(realized, requested) dicts of E~, c~, alpha~ (None where unknown; requested empty
    unless the run belongs to a campaign that asked for coordinates)."""
    campaign = summary.get("campaign") or {}
    requested = campaign.get("requested") or {}
    realized = {k: value(summary, k) for k, _ in COORDINATES}
    return realized, {k: requested.get(k) for k, _ in COORDINATES if requested.get(k) is not None}


def draw_place(fig, cell, summary):
    """The run's place in (E~, c~, alpha~) (paper 001 Figs 6-12, top right): realized as a
    dot, requested (a campaign's run) as a ring, joined by a dashed line."""
    realized, requested = coordinates_of(summary)
    words = ", ".join(f"{label} = " + ("-" if realized[k] is None else f"{realized[k]:.2f}")
                      for k, label in COORDINATES)
    if any(v is None for v in realized.values()):
        ax = fig.add_subplot(cell)
        ax.set_axis_off()
        ax.text(0.5, 0.5, "place in the parameter space unknown:\n" + words
                + "\n(needs E, c, alpha and the normal stress)", ha="center", va="center",
                fontsize=9, transform=ax.transAxes)
        return
    ax = fig.add_subplot(cell, projection="3d")
    point = [realized[k] for k, _ in COORDINATES]
    ax.scatter(*[[v] for v in point], color="tab:red", s=50, depthshade=False,
               label="realized: " + ", ".join(f"{v:.2f}" for v in point))
    points = [point]
    if len(requested) == len(COORDINATES):
        asked = [requested[k] for k, _ in COORDINATES]
        points.append(asked)
        ax.scatter(*[[v] for v in asked], facecolors="none", edgecolors="k", s=60,
                   depthshade=False, label="requested: " + ", ".join(f"{v:g}" for v in asked))
        ax.plot(*[[a, b] for a, b in zip(point, asked)], "k--", lw=0.8)
    # A floor line shows the height in alpha~; the box is at least one unit wide each way.
    points = np.array(points)
    lo, hi = points.min(axis=0) - 0.5, points.max(axis=0) + 0.5
    ax.plot([point[0]] * 2, [point[1]] * 2, [lo[2], point[2]], color="tab:red", lw=0.8, ls=":")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    for setter, (_, label) in zip((ax.set_xlabel, ax.set_ylabel, ax.set_zlabel), COORDINATES):
        setter(label)
    ax.tick_params(labelsize=7)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, 1.12))


def plot_composite(run_dir, analysis_dir, summary, given, notes):
    """The run on one page, in the manner of paper 001 Figs 6-12 (shear cells only)."""
    mu_series = read_mu_series(run_dir)
    if mu_series is None:
        return None, None  # not a shear cell: nothing to compose, nothing to say
    snapshots, notes = composite_snapshots(run_dir, given, notes)
    # Left, three rows of about 9 x 2.4 inches: a 1200 x 300 snapshot (render/
    # composite_snapshots.cpp) shown at about 0.8 of its pixels.
    fig = plt.figure(figsize=(16, 10))
    grid = fig.add_gridspec(3, 2, width_ratios=(1.75, 1.0), left=0.01, right=0.98,
                            top=0.92, bottom=0.07, wspace=0.12, hspace=0.3)
    for row, (field, title) in enumerate(COMPOSITE_FIELDS):
        draw_snapshot(fig.add_subplot(grid[row, 0]), field, title, snapshots.get(field), notes)
    draw_place(fig, grid[0, 1], summary)
    ax = fig.add_subplot(grid[1, 1])
    draw_mu(ax, *mu_series, summary, legend_size=7, columns=2)
    ax.set_title("friction coefficient of the first bodies", fontsize=9)
    ax = fig.add_subplot(grid[2, 1])
    profiles = read_profiles(analysis_dir)
    if profiles is None:
        ax.text(0.5, 0.5, NO_PROFILES, ha="center", va="center", transform=ax.transAxes)
    else:
        y, p = profiles
        for comp, colour, label in (("vx", "tab:blue", "$v_x$"), ("vy", "tab:orange", "$v_y$")):
            mean, std = p[comp]
            ax.fill_betweenx(y, mean - std, mean + std, color=colour, alpha=0.2)
            ax.plot(mean, y, "o-", color=colour, ms=2.5, lw=1.1, label=label + " (mean ± std)")
        ax.axvline(0.0, color="0.6", lw=0.8)
        ax.legend(fontsize=7)
    ax.set_xlabel("velocity (length/time)")
    ax.set_ylabel("y (length)")
    ax.set_title("velocity profiles across the gap (window)", fontsize=9)
    ax.grid(alpha=0.3)
    mu, error = value(summary, "mu"), value(summary, "mu_error")
    name = os.path.basename(os.path.normpath(summary.get("run") or run_dir))
    headline = name + ": " + (r"$\mu$ not measured" if mu is None else rf"$\mu$ = {mu:.3f}"
                              + ("" if error is None else f" ± {error:.3f} (error of the mean)"))
    fig.suptitle(headline, fontsize=12)
    note_warnings(fig, summary)
    return (save(fig, os.path.join(analysis_dir, "composite.png")),
            "; ".join(f"composite: {n}" for n in notes) or None)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog=os.path.basename(argv[0]),
                                     description="Plots of an analysed run folder.")
    parser.add_argument("run_dir", help="run folder analysed by softgrain analyze")
    parser.add_argument("--snapshot", action="append", default=[], metavar="FIELD=PNG",
                        help="a snapshot of the composite figure (repeatable)")
    parser.add_argument("--snapshot-note", action="append", default=[], metavar="TEXT",
                        help="why a snapshot of the composite is missing (repeatable)")
    args = parser.parse_args(argv[1:])
    given = {}
    for item in args.snapshot:
        field, sep, png = item.partition("=")
        if not sep or field not in dict(COMPOSITE_FIELDS):
            parser.error(f"--snapshot '{item}': expected FIELD=PNG with FIELD one of "
                         + ", ".join(f for f, _ in COMPOSITE_FIELDS))
        given[field] = png
    return args.run_dir, given, args.snapshot_note


def main(argv):
    run_dir, given, notes = parse_arguments(argv)
    analysis_dir = os.path.join(run_dir, "analysis")
    try:
        summary = read_summary(analysis_dir)
        global SOFTWARE
        SOFTWARE = software_of(summary)
        written, skipped = [], []
        for draw in (lambda: plot_mu(run_dir, analysis_dir, summary),
                     lambda: plot_profiles(analysis_dir),
                     lambda: plot_energy(analysis_dir, summary),
                     lambda: plot_agglomerates(analysis_dir),
                     lambda: plot_compaction(analysis_dir),
                     lambda: plot_space_time(analysis_dir),
                     lambda: plot_cylinders(analysis_dir),
                     lambda: plot_att(analysis_dir, summary),
                     lambda: plot_composite(run_dir, analysis_dir, summary, given, notes)):
            path, why = draw()
            if path:
                written.append(path)
            if why:
                skipped.append(why)
    except (PlotError, OSError, ValueError, KeyError) as e:
        print(f"plot_run.py: {e}", file=sys.stderr)
        return 1
    for p in written:
        print(f"plot: {p}")
    for s in skipped:
        print(f"plot: {s}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
