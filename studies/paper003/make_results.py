#!/usr/bin/python3
"""Paper 003's three friction regimes: the campaign's results table and figure.

Zhang, Mollon et al., "Significance of third body rheology in friction" (§3, Fig. 3): mu
against the grain/grain cohesion (tau = sigma) on the reduced paper 003 cell.

    softgrain sweep studies/paper003/campaign.toml          the six runs
    softgrain sweep studies/paper003/campaign-spacing.toml  the variation (uniform nodes, 20 GPa)
    /usr/bin/python3 studies/paper003/make_results.py       results.csv, mu_vs_cohesion.png,
                                                            profiles.png
    /usr/bin/python3 studies/paper003/make_results.py --run --pictures
                      (both sweeps first; then velocity_<c>GPa.png from each run's last snapshot)

Per run it reads the analysis (analysis/summary.json: mu, mu_std over the steady window
MSER-5 picked, the solid fraction, the activated third-body thickness) and, from series.csv,
mu over fixed windows of sliding so that runs of different lengths compare over the same
sliding (mu = Ft_bar / Fn_bar, the two first bodies averaged as the analysis does;
std = the standard deviation of mu(t) = Ft(t) / Fn(t)): `common` = the sliding window every
run has, and the first and second halves of each run's sliding after the compaction (the
sliding-distance check).
"""
import argparse
import csv
import json
import math
import pathlib
import shutil
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
CAMPAIGN = HERE / "campaign.toml"
RUNS = ROOT / "out" / "campaigns" / "paper003" / "runs"
# The controlled variation at 20 GPa: uniform 60 nm nodes instead of graded ones.
VARIATION = HERE / "campaign-spacing.toml"
VARIATION_RUNS = ROOT / "out" / "campaigns" / "paper003-spacing" / "runs"

# Paper 003 Fig. 3 as its text gives it (§3): linear rise from ~0.14 (1e-4 GPa) to ~0.48
# (1 GPa), a peak ~0.69 at 3 GPa, ~0.64 at 5 GPa, then 0.58-0.62 up to 20 GPa (std ~0.2 at
# 20 GPa). (GPa, mu, low, high): low/high the range the text gives, else mu.
PAPER = [(1e-4, 0.14, 0.14, 0.14), (1.0, 0.48, 0.48, 0.48), (3.0, 0.69, 0.69, 0.69),
         (5.0, 0.64, 0.64, 0.64), (10.0, 0.60, 0.58, 0.62), (20.0, 0.60, 0.58, 0.62)]

RAMP_END = 3e-8  # s: the load ramp of examples/shear-cell-si.toml; sliding starts there
SETTLED = 6e-8   # s: the layer has compacted (top_y steady) by then in every run
COMMON_END = 1.2e-7  # s: the shortest runs' end


def read_series(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in r.items()} for r in rows]


def friction(rows, t0, t1):
    """mu = Ft_bar / Fn_bar and std of mu(t) over t0 <= t < t1, the two bodies averaged."""
    sel = [r for r in rows if t0 <= r["time"] < t1]
    if len(sel) < 5:
        return math.nan, math.nan, len(sel)
    ft = [0.5 * (r["bottom_fx"] - r["top_fx"]) for r in sel]
    fn = [0.5 * (r["top_fy"] - r["bottom_fy"]) for r in sel]
    mu = sum(ft) / sum(fn)
    inst = [a / b for a, b in zip(ft, fn)]
    mean = sum(inst) / len(inst)
    std = math.sqrt(sum((x - mean) ** 2 for x in inst) / (len(inst) - 1))
    return mu, std, len(sel)


def quantity(summary, key):
    q = summary["quantities"].get(key)
    return math.nan if q is None or q.get("value") is None else float(q["value"])


def stopped_series(run):
    """The series of a run stopped before its end (kept by sweep as *.damaged), or None."""
    for name in ("series.csv.partial", "series.csv.partial.damaged"):
        if (run / name).exists():
            return run / name
    return None


def analyze_stopped(run, softgrain, runs):
    """A run stopped before its end (the machine's time): `softgrain analyze` refuses a
    partial series, so its rows, snapshots and scenario are copied to
    <campaign>/stopped/<id>/ as a run folder of what it wrote, and analysed there."""
    copy = runs.parent / "stopped" / run.name
    if not (copy / "analysis" / "summary.json").exists():
        if copy.exists():
            shutil.rmtree(copy)
        copy.mkdir(parents=True)
        for name in ("fields", "grains"):
            shutil.copytree(run / name, copy / name)
        for name in ("fields.pvd", "scenario.toml"):
            shutil.copy(run / name, copy / name)
        shutil.copy(stopped_series(run), copy / "series.csv")
        log = (run / "run.log").read_text()
        (copy / "run.log").write_text(log.replace(f"runs/{run.name}/scenario.toml", "scenario.toml"))
        subprocess.run([softgrain, "--threads", "1", "analyze", "."], cwd=copy, check=True,
                       stdout=subprocess.DEVNULL)
    return copy


def collect(softgrain, runs=RUNS, discretization="graded"):
    table = []
    if not (runs.parent / "runs.txt").exists():
        return table
    # The runs of the campaign as it stands (runs.txt), not older folders of another version.
    for run_id in (runs.parent / "runs.txt").read_text().split():
        run = runs / run_id
        folder, stopped = run, False
        if not (run / "analysis" / "summary.json").exists():
            if stopped_series(run) is None or not (run / "sweep.failed").exists():
                print(f"{run.name}: not run or still running, left out", file=sys.stderr)
                continue
            folder, stopped = analyze_stopped(run, softgrain, runs), True
        summary = json.loads((folder / "analysis" / "summary.json").read_text())
        rows = read_series(folder / "series.csv")
        cohesion = None
        for line in (run / "scenario.toml").read_text().splitlines():
            if line.strip().startswith("cohesion"):  # the grain/grain law's (the first law)
                cohesion = float(line.split("=")[1].split("#")[0])
                break
        end = rows[-1]["time"]
        middle = 0.5 * (SETTLED + end)
        mu_c, std_c, _ = friction(rows, SETTLED, COMMON_END)
        mu_1, std_1, _ = friction(rows, SETTLED, middle)
        mu_2, std_2, _ = friction(rows, middle, end + 1.0)
        window = (quantity(summary, "window_begin"), quantity(summary, "window_end"))
        warnings = ";".join(w if isinstance(w, str) else w.get("check", str(w))
                            for w in summary.get("warnings", []))
        if stopped:
            warnings = f"stopped at {end:.3g} s" + (";" + warnings if warnings else "")
        fn = [0.5 * (r["top_fy"] - r["bottom_fy"]) for r in rows if window[0] <= r["time"] <= window[1]]
        table.append({
            "run": run.name,
            "cohesion_GPa": cohesion / 1e9,
            "sliding_um": (end - RAMP_END) * 100.0 * 1e6,  # V = 100 m/s
            "discretization": discretization,
            "folder": str(folder.relative_to(runs.parent)),
            "mu": quantity(summary, "mu"),
            "mu_std": quantity(summary, "mu_std"),
            "mu_error": quantity(summary, "mu_error"),
            "window_begin_s": window[0],
            "window_end_s": window[1],
            "normal_stress_GPa": sum(fn) / len(fn) / 5.5e-6 / 1e9,  # L = 5.5 um
            "solid_fraction": quantity(summary, "solid_fraction"),
            "att_profile_um": quantity(summary, "att_profile") * 1e6,
            "mu_from_dissipation": quantity(summary, "mu_from_dissipation"),
            "min_step_s": min(r["dt"] for r in rows),
            "first_step_s": rows[0]["dt"],
            "mu_common": mu_c, "mu_common_std": std_c,
            "mu_first_half": mu_1, "mu_first_half_std": std_1,
            "mu_second_half": mu_2, "mu_second_half_std": std_2,
            "warnings": warnings,
        })
    table.sort(key=lambda r: r["cohesion_GPa"])
    return table


def write_csv(table, path):
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        for r in table:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    tmp.replace(path)


def plot(table, variation, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=100)
    # A linear cohesion axis, as the paper's regimes are described (1e-4 GPa sits at 0).
    c = [r["cohesion_GPa"] for r in table]
    ax.errorbar(c, [r["mu"] for r in table], yerr=[r["mu_std"] for r in table], fmt="o-",
                color="C0", capsize=3, label="softgrain: steady window, mean ± std of mu(t)")
    ax.errorbar([x + 0.3 for x in c], [r["mu_common"] for r in table],
                yerr=[r["mu_common_std"] for r in table], fmt="s--", color="C2", capsize=3,
                ms=4, label=f"softgrain: t in [{SETTLED * 1e9:.0f}, {COMMON_END * 1e9:.0f}] ns, all runs")
    if variation:
        ax.errorbar([r["cohesion_GPa"] - 0.3 for r in variation], [r["mu"] for r in variation],
                    yerr=[r["mu_std"] for r in variation], fmt="D", color="C3", capsize=3, ms=5,
                    label="softgrain, uniform 60 nm nodes (variation)")
    pc = [p[0] for p in PAPER]
    ax.plot(pc, [p[1] for p in PAPER], "k^-", label="paper 003 Fig. 3 (text values)")
    ax.fill_between(pc, [p[2] for p in PAPER], [p[3] for p in PAPER], color="k", alpha=0.12)
    ax.set_xlabel("grain/grain cohesion tau = sigma (GPa)")
    ax.set_ylabel("friction coefficient mu")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("Paper 003 regimes: 56 grains, L = 5.5 um, 1 GPa, 100 m/s", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)


def pictures(table, softgrain):
    """The last field snapshot of each run coloured by v_x (softgrain render), as a small
    palette PNG here: velocity_<cohesion>GPa.png."""
    from PIL import Image
    campaign = RUNS.parent
    for r in table:
        folder = campaign / r["folder"]
        # From where run.log's scenario path holds: the campaign folder for its runs, the
        # copy itself for a stopped run's copy.
        if r["folder"].startswith("runs"):
            cwd, arg = campaign, r["folder"]
        else:
            cwd, arg = folder, "."
        subprocess.run([softgrain, "--threads", "1", "render", arg, "--field", "velocity_x",
                        "--frames", "last", "--size", "800x340", "--no-movie"], cwd=cwd,
                       check=True, stdout=subprocess.DEVNULL)
        drawn = sorted((folder / "render").glob("velocity_x_*.png"))[-1]
        out = HERE / f"velocity_{r['cohesion_GPa']:g}GPa.png"
        Image.open(drawn).convert("RGB").quantize(colors=64).save(out, optimize=True)


def plot_profiles(table, path):
    """vx across the layer (analysis/profiles.csv, over each run's window), y scaled to the
    span of the grain centres: paper 003 Figs 5, 7d and 11."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.0, 4.0), dpi=100)
    for i, r in enumerate(table):
        with open(RUNS.parent / r["folder"] / "analysis" / "profiles.csv", newline="") as f:
            prof = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
        prof = [p for p in prof if p["count"] > 0]
        y = [p["y_center"] for p in prof]
        lo, hi = min(y), max(y)
        ax.plot([p["vx_mean"] for p in prof], [(v - lo) / (hi - lo) for v in y], "o-", ms=3,
                color=f"C{i}", label=f"{r['cohesion_GPa']:g} GPa (mu {r['mu']:.2f})")
    ax.plot([-50, 50], [0, 1], "k:", lw=1, label="Couette (linear)")
    ax.set_xlabel("v_x (m/s), grain centres, mean over the window")
    ax.set_ylabel("height in the layer (0: bottom, 1: top)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", action="store_true", help="run the campaign first (softgrain sweep)")
    parser.add_argument("--softgrain", default=str(ROOT / "build" / "app" / "softgrain"))
    parser.add_argument("--pictures", action="store_true",
                        help="also draw each run's last snapshot (v_x) into velocity_*.png")
    args = parser.parse_args()
    if args.run:
        subprocess.run([args.softgrain, "sweep", str(CAMPAIGN)], check=True)
        subprocess.run([args.softgrain, "sweep", str(VARIATION)], check=True)
    softgrain = str(pathlib.Path(args.softgrain).resolve())
    table = collect(softgrain)
    if not table:
        sys.exit("no finished run in " + str(RUNS))
    variation = collect(softgrain, VARIATION_RUNS, "uniform 60 nm")
    write_csv(table + variation, HERE / "results.csv")
    plot(table, variation, HERE / "mu_vs_cohesion.png")
    plot_profiles(table, HERE / "profiles.png")
    if args.pictures:
        pictures(table, str(pathlib.Path(args.softgrain).resolve()))
    for r in table + variation:
        print(f"{r['discretization']:14s}{r['cohesion_GPa']:8.4g} GPa  sliding {r['sliding_um']:5.1f} um  mu {r['mu']:.3f} ± "
              f"{r['mu_std']:.3f} (window {r['window_begin_s'] * 1e9:.0f}-{r['window_end_s'] * 1e9:.0f} ns)"
              f"  common {r['mu_common']:.3f} ± {r['mu_common_std']:.3f}  halves {r['mu_first_half']:.3f}"
              f" / {r['mu_second_half']:.3f}  phi {r['solid_fraction']:.3f}  min dt {r['min_step_s']:.3g}  sigma_n "
              f"{r['normal_stress_GPa']:.3f} GPa  {r['warnings']}")


if __name__ == "__main__":
    main()
