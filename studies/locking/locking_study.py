#!/usr/bin/python3
"""Volumetric locking of the meshfree grains at large strain (issue #31 item 2).

An elastic disc (diameter D = 1, neo-Hookean, E = 1, rho = 1) is squeezed between two rigid,
rough (no-slip) plates in two quasi-static stages, to 20% and then to 35% of its diameter, each
followed by a hold; the force the plates carry at the end of each hold is read from series.csv.
The disc's sides are free and its faces held by the plates, so most of the deformation is
isochoric shear: the problem that shows a displacement discretization that cannot represent
nearly divergence-free fields (locking: too stiff as nu -> 1/2). Grid: nu = 0.3, 0.45, 0.495, 0.499 x node spacings D/8, D/12, D/16 (and
finer ones for the reference) x 3 and 6 Gauss points per triangle.

    /usr/bin/python3 studies/locking/locking_study.py run      # every case, then table + plot
    /usr/bin/python3 studies/locking/locking_study.py table    # CSV and figure from the runs
    /usr/bin/python3 studies/locking/locking_study.py markdown # the table of verification.md
    /usr/bin/python3 studies/locking/locking_study.py scenario # rewrite the test's scenario

The F-bar option (issue #31 item 3, `volumetric = "fbar"`): the cases named *-fbar, at nu = 0.3,
0.495, 0.499, D/8, 12, 16, both rules, and D/48 (3 points, nu = 0.495 and 0.499) as F-bar's own
reference; their errors are against the standard D/48 run of the same nu and rule (and, in
error_*_own_reference_percent, against the F-bar D/48 run). `run --only fbar` runs them alone:
the standard rows of results.csv whose runs are not in --runs are kept as they are.

Options: --bin (default build/app/softgrain), --runs (the folder of runs this script owns,
default out/locking-study/, which git ignores), --only SUBSTRING (cases whose name contains
it), --rate-check (also the case run at half the loading rate). A case whose series.csv exists
is not run again. Every run is single-threaded (--threads 1), one at a time. Writes
studies/locking/results.csv (one row per run, the errors against the reference of its nu and
rule) and studies/locking/locking.png. Needs numpy and matplotlib (Debian: python3-numpy,
python3-matplotlib).

Why the choices (docs/verification.md "Locking at large strain" gives the numbers):
- quasi-static: each stage is a triangular velocity pulse of the plates over LOAD_TIME, then a
  hold of HOLD_TIME; the disc is lightly damped (Kelvin-Voigt, alpha = 0.05, `imex`, so the
  step is the undamped one) and the force is averaged over the last AVERAGE_TIME of the hold.
  Measured at nu = 0.499, D/16: after the 35% stage the force relaxes with a time constant of
  about 2 to 3 whatever alpha (0.05 or 0.2), so a hold of 5 left it 0.25% high and one of 12
  within 1e-4 of a hold of 20; alpha = 0.2 also left the disc (stuck to the plates) in a state
  at least 0.7% softer at 20% than alpha = 0.05, the viscous overstress changing where it sticks, so
  alpha is kept small (at nu = 0.3 the force then rings by +-0.04% in the hold). The kinetic /
  elastic energy ratio at the end of the hold and a run at half the rate (--rate-check) check it;
- rough plates (Coulomb 10: the disc sticks where it touches) with a penalty fixed in absolute
  terms (k_n = 2000 E, not scaled with h): the contact compliance (2 p / k_n ~ 1e-3 of the
  approach) is then the same at every spacing and cancels from the comparison with the
  reference of the same nu. Frictionless plates were tried first: the disc is then free to
  slide and to roll its material round under a fixed shape (a zero-energy mode of a round
  body), which the discrete contour turns into a slow wandering of the force by 0.4% at D/8
  that no hold settles;
- the disc contour is given as a polygon with vertices at equal angles, 4 m of them, so that a
  vertex sits at each pole (the plates first touch one node) and the body is symmetric.
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time

STUDY_DIR = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(STUDY_DIR))
RESULTS = os.path.join(STUDY_DIR, "results.csv")
FIGURE = os.path.join(STUDY_DIR, "locking.png")
TEST_SCENARIO = os.path.join(STUDY_DIR, "disc-between-plates.toml")

DIAMETER = 1.0
YOUNG = 1.0
DAMPING = 0.05                      # Kelvin-Voigt alpha (time)
NORMAL_STIFFNESS = 2000.0          # plate contact penalty (force / length^2), = 2000 E
PLATE_FRICTION = 10.0              # Coulomb coefficient of the plates: no slip in practice
STAGES = (0.20, 0.35)              # compression (plate approach / D) at the end of each stage
LOAD_TIME = 8.0                    # duration of each stage's velocity pulse
HOLD_TIME = 12.0                    # hold after it
AVERAGE_TIME = 2.0                 # the force is averaged over the hold's last AVERAGE_TIME
POISSON = (0.3, 0.45, 0.495, 0.499)
STUDY_SPACINGS = (8, 12, 16)       # D / h
REFERENCE_SPACINGS = (24, 32, 48)  # finer runs; the finest run of a nu and rule is its reference
GAUSS = (3, 6)
RATE_CHECK = (0.495, 8, 3)         # nu, D/h, Gauss points of the run repeated at half the rate
# The F-bar option (issue #31 item 3, material key volumetric = "fbar"): the same problem at
# these nu and spacings (D/48: its own reference); its errors are against the standard D/48.
FBAR_POISSON = (0.3, 0.495, 0.499)
FBAR_SPACINGS = STUDY_SPACINGS + (48,)
FBAR_REFERENCES = ((0.495, 3), (0.499, 3))  # (nu, Gauss points) run at D/48 with F-bar too


def case_name(nu, n, gauss, slow=1, volumetric="standard"):
    return (f"disc-nu{nu}-n{n}-gp{gauss}" + (f"-slow{slow}" if slow != 1 else "") +
            ("" if volumetric == "standard" else f"-{volumetric}"))


def disc_contour(n):
    """Vertices of the disc at equal angles, 4 m of them with chords below h = D / n, so that
    the builder keeps them as they are (it splits edges longer than h), a vertex at each pole."""
    radius, h = 0.5 * DIAMETER, DIAMETER / n
    m = math.ceil(0.5 * math.pi * radius / h)
    count = 4 * m
    assert 2.0 * radius * math.sin(math.pi / count) < h
    return [(radius * math.cos(2.0 * math.pi * k / count),
             radius * math.sin(2.0 * math.pi * k / count)) for k in range(count)]


def plate_velocity_table(sign, slow):
    """The y velocity of a plate: for each stage a triangular pulse whose area is the plate's
    share (half) of the stage's approach, then zero through the hold."""
    rows, t, reached = [[0.0, 0.0]], 0.0, 0.0
    load, hold = LOAD_TIME * slow, HOLD_TIME * slow
    for target in STAGES:
        peak = (target - reached) * DIAMETER / load  # 0.5 * load * peak = half the approach
        rows += [[t + 0.5 * load, sign * peak], [t + load, 0.0], [t + load + hold, 0.0]]
        t += load + hold
        reached = target
    return "[" + ", ".join(f"[{a:.10g}, {b:.10g}]" for a, b in rows) + "]"


def volumetric_line(volumetric):
    return "" if volumetric == "standard" else f'\nvolumetric = "{volumetric}"'


def scenario_text(nu, n, gauss, slow=1, volumetric="standard"):
    radius = 0.5 * DIAMETER
    stage_time = (LOAD_TIME + HOLD_TIME) * slow
    points = ",\n  ".join(f"[{x:.17g}, {y:.17g}]" for x, y in disc_contour(n))
    return f"""\
# Locking study (studies/locking/locking_study.py, docs/verification.md "Locking at large
# strain"): an elastic disc of diameter {DIAMETER:g} squeezed between two rigid rough plates
# to {STAGES[0]:.0%} and then {STAGES[1]:.0%} of its diameter, each stage a velocity pulse of
# {LOAD_TIME * slow:g} time units and a hold of {HOLD_TIME * slow:g}; the plate force is read at the end of each hold
# (series.csv: top_fy, bottom_fy, top_y, bottom_y). Generated by the study script: do not edit.

name = "{case_name(nu, n, gauss, slow, volumetric)}"

[time]
duration = {len(STAGES) * stage_time:g}
integrator = "imex"      # the damping is implicit: the step is the undamped one

[output]
series_period = 0.05
field_period = {stage_time:g}     # a snapshot at the end of each hold
checkpoint_period = 0

[discretization]
node_spacing = {DIAMETER / n:.17g}   # D / {n}
gauss_points = {gauss}

[[materials]]
name = "disc"
law = "neo_hookean"
young = {YOUNG:g}
poisson = {nu}
density = 1.0
damping = {DAMPING:g}           # Kelvin-Voigt alpha: light, the force is read at rest
damping_model = "corotational"{volumetric_line(volumetric)}

[[materials]]
name = "plate"          # the plates are driven: their density enters only the step estimate,
young = {YOUNG:g}              # where light plates (~0.5) on the stiff penalty would set the step
density = 1000.0

# Rough plates: Coulomb friction {PLATE_FRICTION:g}, so the disc sticks where it touches them
# (frictionless plates leave it free to slide and to roll its material round under a fixed
# shape, neutral modes that never settle). The penalty is fixed (not scaled with h), so that
# its compliance is the same at every node spacing.
[[contact_laws]]
materials = ["disc", "plate"]
law = "coulomb"
friction = {PLATE_FRICTION:g}
normal_stiffness = {NORMAL_STIFFNESS:g}

[[contact_laws]]
materials = ["disc", "disc"]
law = "frictionless"
normal_stiffness = {NORMAL_STIFFNESS:g}

[[contact_laws]]
materials = ["plate", "plate"]
law = "frictionless"
normal_stiffness = {NORMAL_STIFFNESS:g}

[[grains]]
name = "disc"
shape = "contour"
material = "disc"
points = [
  {points}]

[[walls]]
name = "top"
lower_left = [-1.0, {radius:g}]
upper_right = [1.0, {radius + 0.25:g}]
material = "plate"

[walls.drive]
y = {{ velocity = {plate_velocity_table(-1.0, slow)} }}

[[walls]]
name = "bottom"
lower_left = [-1.0, {-radius - 0.25:g}]
upper_right = [1.0, {-radius:g}]
material = "plate"

[walls.drive]
y = {{ velocity = {plate_velocity_table(+1.0, slow)} }}
"""


def read_series(path):
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(v) for v in row] for row in reader if row]
    return {name: [row[i] for row in rows] for i, name in enumerate(header)}


def hold_measurements(series, slow):
    """Per stage: compression reached, mean plate force over the end of the hold, its relative
    spread there, and the kinetic / elastic energy ratio at the end of the hold."""
    t = series["time"]
    gap0 = series["top_y"][0] - series["bottom_y"][0]
    out = []
    for k in range(len(STAGES)):
        end = (k + 1) * (LOAD_TIME + HOLD_TIME) * slow
        rows = [i for i in range(len(t)) if end - AVERAGE_TIME * slow <= t[i] < end]
        force = [0.5 * (series["top_fy"][i] - series["bottom_fy"][i]) for i in rows]
        mean = sum(force) / len(force)
        last = rows[-1]
        out.append({
            "compression": (gap0 - (series["top_y"][last] - series["bottom_y"][last])) / DIAMETER,
            "force": mean,
            "spread": (max(force) - min(force)) / mean,
            "kinetic_ratio": series["kinetic_energy"][last] / series["elastic_energy"][last],
        })
    return out


def disc_at_end(run_dir):
    """The disc's (body 0, the only grain) horizontal centre at the last snapshot (it should
    stay on the axis) and its contour area there over the area at t = 0."""
    grains = os.path.join(run_dir, "grains")
    files = sorted(f for f in os.listdir(grains) if f.endswith(".csv"))

    def disc_row(name):
        with open(os.path.join(grains, name), newline="") as f:
            return next(r for r in csv.DictReader(f) if r["body"] == "0")

    first, last = disc_row(files[0]), disc_row(files[-1])
    return float(last["x"]), float(last["area"]) / float(first["area"])


def write_atomically(path, text):
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".tmp-")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.chmod(tmp, 0o644)
    os.replace(tmp, path)


def run_case(args, nu, n, gauss, slow=1, volumetric="standard"):
    name = case_name(nu, n, gauss, slow, volumetric)
    run_dir = os.path.join(args.runs, name)
    if os.path.exists(os.path.join(run_dir, "series.csv")):
        return
    os.makedirs(args.runs, exist_ok=True)
    scenario = os.path.join(args.runs, name + ".toml")
    write_atomically(scenario, scenario_text(nu, n, gauss, slow, volumetric))
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
    start = time.monotonic()
    done = subprocess.run([args.bin, "run", scenario, "-o", args.runs, "--threads", "1"],
                          env=env, capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"{name}: softgrain failed ({done.returncode}): {done.stderr.strip()}")
    write_atomically(os.path.join(run_dir, "study-wall-seconds.txt"), f"{wall:.2f}\n")
    print(f"{name}: {wall:.1f} s  {done.stdout.strip()}", flush=True)


def all_cases(args):
    # Coarsest first: an interrupted study has every spacing up to where it stopped.
    cases = [(nu, n, g, 1) for n in STUDY_SPACINGS + REFERENCE_SPACINGS for nu in POISSON
             for g in GAUSS]
    if args.rate_check:
        cases.append(RATE_CHECK + (2,))
    cases += [(nu, n, g, 1, "fbar") for n in STUDY_SPACINGS for nu in FBAR_POISSON for g in GAUSS]
    cases += [(nu, FBAR_SPACINGS[-1], g, 1, "fbar") for nu, g in FBAR_REFERENCES]
    return [c for c in cases if args.only is None or args.only in case_name(*c)]


def run_info(run_dir):
    """Nodes and steps from run.log, the wall time the study measured."""
    text = open(os.path.join(run_dir, "run.log")).read()
    nodes = re.search(r"(\d+) nodes", text)
    steps = re.search(r"(\d+) accepted", text)
    wall_file = os.path.join(run_dir, "study-wall-seconds.txt")
    wall = float(open(wall_file).read()) if os.path.exists(wall_file) else float("nan")
    return (int(nodes.group(1)) if nodes else -1, int(steps.group(1)) if steps else -1, wall)


def richardson(points):
    """Extrapolation to h -> 0 from the three finest (D/h, force) points, with the order p they
    show: (F1 - F2) / (F2 - F3) = (h1^p - h2^p) / (h2^p - h3^p), solved by bisection on p in
    [0.5, 4]. None when the three are not monotone or p falls outside that range (then no
    asymptotic regime is visible and the finest run is the only reference)."""
    if len(points) < 3:
        return None
    (n1, f1), (n2, f2), (n3, f3) = sorted(points)[-3:]
    h1, h2, h3 = 1.0 / n1, 1.0 / n2, 1.0 / n3
    if (f1 - f2) * (f2 - f3) <= 0.0:
        return None
    ratio = (f1 - f2) / (f2 - f3)

    def gap(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - ratio

    lo, hi = 0.5, 4.0
    if gap(lo) * gap(hi) > 0.0:
        return None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        (lo, hi) = (mid, hi) if gap(lo) * gap(mid) > 0.0 else (lo, mid)
    p = 0.5 * (lo + hi)
    return f3 - (f2 - f3) * h3 ** p / (h2 ** p - h3 ** p), p


def finished_runs(args):
    """Every run of the study found in args.runs, measured."""
    runs = []
    cases = [(nu, n, g, slow, "standard") for nu in POISSON for g in GAUSS
             for n in STUDY_SPACINGS + REFERENCE_SPACINGS for slow in (1, 2)]
    cases += [(nu, n, g, 1, "fbar") for nu in FBAR_POISSON for g in GAUSS for n in FBAR_SPACINGS]
    for nu, n, g, slow, volumetric in cases:
        run_dir = os.path.join(args.runs, case_name(nu, n, g, slow, volumetric))
        if not os.path.exists(os.path.join(run_dir, "series.csv")):
            continue
        stages = hold_measurements(read_series(os.path.join(run_dir, "series.csv")), slow)
        nodes, steps, wall = run_info(run_dir)
        runs.append({"nu": nu, "n": n, "gauss": g, "slow": slow, "volumetric": volumetric,
                     "stages": stages, "nodes": nodes, "steps": steps, "wall": wall,
                     "end": disc_at_end(run_dir)})
    return runs


def previous_rows():
    """The rows of results.csv as they are (a standard run not in args.runs keeps its row: the
    F-bar runs of item 3 were added without running the standard ones again)."""
    if not os.path.exists(RESULTS):
        return []
    with open(RESULTS, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r.setdefault("volumetric", "standard")
        r["volumetric"] = r["volumetric"] or "standard"
        for key in ("poisson", "rate"):
            r[key] = float(r[key])
        for key in ("spacing_D_over_h", "gauss_points", "reference_D_over_h"):
            r[key] = int(r[key])
    return rows


def collect(args):
    """One row per run, with its error against the reference of its nu and rule: the standard
    run at the finest spacing (D/48); an F-bar row also against the finest F-bar run."""
    runs = finished_runs(args)
    kept = [r for r in previous_rows() if r["volumetric"] == "standard" and not any(
        q["volumetric"] == "standard" and q["nu"] == r["poisson"] and q["n"] == r[
            "spacing_D_over_h"] and q["gauss"] == r["gauss_points"] and 1.0 / q["slow"] == r[
            "rate"] for q in runs)]

    def standard_reference(nu, g, k):
        same = [q for q in runs if q["volumetric"] == "standard" and q["nu"] == nu
                and q["gauss"] == g and q["slow"] == 1]
        if same:
            return max(same, key=lambda q: q["n"])["stages"][k]["force"]
        pct = round(100 * STAGES[k])
        row = next(r for r in kept if r["poisson"] == nu and r["gauss_points"] == g
                   and r["rate"] == 1.0 and r["reference_D_over_h"] == r["spacing_D_over_h"])
        return float(row[f"force_{pct}"])

    rows = []
    for r in runs:
        same = [q for q in runs if q["nu"] == r["nu"] and q["gauss"] == r["gauss"]
                and q["slow"] == 1 and q["volumetric"] == r["volumetric"]]
        own_ref = max(same, key=lambda q: q["n"])
        if own_ref["n"] != FBAR_SPACINGS[-1]:
            own_ref = None  # no F-bar reference run for this nu and rule
        row = {"volumetric": r["volumetric"], "poisson": r["nu"], "spacing_D_over_h": r["n"],
               "gauss_points": r["gauss"], "rate": 1.0 / r["slow"], "nodes": r["nodes"],
               "steps": r["steps"], "wall_s": f"{r['wall']:.1f}",
               "reference_D_over_h": REFERENCE_SPACINGS[-1],
               "disc_x_end": f"{r['end'][0]:.2e}",
               "area_ratio_end": f"{r['end'][1]:.6f}"}
        for k, s in enumerate(r["stages"]):
            pct = round(100 * STAGES[k])
            reference = standard_reference(r["nu"], r["gauss"], k)
            extrapolated = richardson([(q["n"], q["stages"][k]["force"]) for q in same])
            row[f"compression_{pct}"] = f"{s['compression']:.6f}"
            row[f"force_{pct}"] = f"{s['force']:.6g}"
            row[f"error_{pct}_percent"] = f"{100.0 * (s['force'] / reference - 1):.3f}"
            row[f"richardson_{pct}"] = f"{extrapolated[0]:.6g}" if extrapolated else ""
            row[f"richardson_order_{pct}"] = f"{extrapolated[1]:.2f}" if extrapolated else ""
            row[f"error_richardson_{pct}_percent"] = (
                f"{100.0 * (s['force'] / extrapolated[0] - 1):.3f}" if extrapolated else "")
            row[f"hold_spread_{pct}"] = f"{s['spread']:.1e}"
            row[f"kinetic_over_elastic_{pct}"] = f"{s['kinetic_ratio']:.1e}"
            row[f"error_{pct}_own_reference_percent"] = (
                "" if r["volumetric"] == "standard" or own_ref is None else
                f"{100.0 * (s['force'] / own_ref['stages'][k]['force'] - 1):.3f}")
        rows.append(row)
    columns = list(rows[0].keys()) if rows else []
    for r in kept:
        rows.append({c: r.get(c, "") for c in columns} if columns else r)
    order = {"standard": 0, "fbar": 1}
    rows.sort(key=lambda r: (order[r["volumetric"]], r["poisson"], r["gauss_points"],
                             -r["rate"], r["spacing_D_over_h"]))
    return rows


def write_table(rows):
    if not rows:
        sys.exit("no finished runs to tabulate")
    columns = list(rows[0].keys())
    lines = [",".join(columns)] + [",".join(str(r[c]) for c in columns) for r in rows]
    write_atomically(RESULTS, "\n".join(lines) + "\n")
    print(f"wrote {RESULTS} ({len(rows)} runs)")


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, len(STAGES), figsize=(11, 12))
    base = [r for r in rows if r["rate"] == 1.0 and r["volumetric"] == "standard"]
    fbar = [r for r in rows if r["volumetric"] == "fbar"]
    spacings = sorted({r["spacing_D_over_h"] for r in base})
    colors = {n: plt.cm.viridis(i / max(1, len(spacings) - 1)) for i, n in enumerate(spacings)}
    for k, stage in enumerate(STAGES):
        pct = round(100 * stage)
        ax = axes[0][k]
        for n in spacings:
            for g, style in zip(GAUSS, ("-o", "--s")):
                pts = sorted((r["poisson"], float(r[f"error_{pct}_percent"])) for r in base
                             if r["spacing_D_over_h"] == n and r["gauss_points"] == g
                             and r["reference_D_over_h"] != n)
                if pts:
                    ax.plot([1.0 / (1.0 - 2.0 * p) for p, _ in pts], [e for _, e in pts], style,
                            color=colors[n], label=f"D/h = {n}, {g} GP")
        ax.set_xscale("log")
        ax.set_xlabel("1 / (1 - 2 nu)   (nu = 0.3, 0.45, 0.495, 0.499)")
        ax.set_ylabel(f"force error at {pct}% compression (%)")
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_title(f"error against the finest run of each nu (D/48), {pct}%")
        ax.legend(fontsize=7)
        ax = axes[1][k]
        for i, nu in enumerate(POISSON):
            for g, style in zip(GAUSS, ("-o", "--s")):
                pts = sorted((r["spacing_D_over_h"], r[f"force_{pct}"]) for r in base
                             if r["poisson"] == nu and r["gauss_points"] == g)
                if pts:
                    ax.plot([n for n, _ in pts], [float(f) for _, f in pts], style,
                            color=plt.cm.plasma(i / len(POISSON)), label=f"nu = {nu}, {g} GP")
        ax.set_xlabel("D / h")
        ax.set_ylabel(f"plate force per unit length at {pct}% (E D)")
        ax.set_title(f"force against the node spacing, {pct}%")
        ax.legend(fontsize=7)
        ax = axes[2][k]
        for n in spacings:
            for g, style in zip(GAUSS, ("-o", "--s")):
                pts = sorted((r["poisson"], float(r[f"error_{pct}_percent"])) for r in fbar
                             if r["spacing_D_over_h"] == n and r["gauss_points"] == g)
                if pts and n != REFERENCE_SPACINGS[-1]:
                    ax.plot([1.0 / (1.0 - 2.0 * p) for p, _ in pts], [e for _, e in pts], style,
                            color=colors[n], label=f"F-bar, D/h = {n}, {g} GP")
        ax.set_xscale("log")
        ax.set_xlabel("1 / (1 - 2 nu)   (nu = 0.3, 0.495, 0.499)")
        ax.set_ylabel(f"force error at {pct}% compression (%)")
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_ylim(axes[0][k].get_ylim())
        ax.set_title(f"volumetric = \"fbar\": error against the standard D/48, {pct}%")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fd, tmp = tempfile.mkstemp(dir=STUDY_DIR, prefix=".tmp-", suffix=".png")
    os.close(fd)
    fig.savefig(tmp, dpi=80)
    os.chmod(tmp, 0o644)
    os.replace(tmp, FIGURE)
    print(f"wrote {FIGURE}")


def print_markdown(rows):
    """The table of docs/verification.md: per nu and spacing, the force at each stage and its
    error against the reference, 3 and 6 Gauss points side by side."""
    base = [r for r in rows if r["rate"] == 1.0 and r["volumetric"] == "standard"]
    head = "| ν | D/h |"
    rule = "|---|---|"
    for stage in STAGES:
        pct = round(100 * stage)
        for g in GAUSS:
            head += f" F {pct}%, {g} GP (error) |"
            rule += "---|"
    print(head)
    print(rule)
    for nu in POISSON:
        for n in STUDY_SPACINGS + REFERENCE_SPACINGS:
            line = f"| {nu} | {n} |"
            found = False
            for stage in STAGES:
                pct = round(100 * stage)
                for g in GAUSS:
                    r = next((q for q in base if q["poisson"] == nu and q["spacing_D_over_h"] == n
                              and q["gauss_points"] == g), None)
                    if r is None:
                        line += " |"
                        continue
                    found = True
                    ref = r["reference_D_over_h"] == n
                    error = float(r[f"error_{pct}_percent"])
                    error = 0.0 if abs(error) < 0.05 else error  # no "-0.0%"
                    line += (f" {float(r[f'force_{pct}']):.4f} (reference) |" if ref else
                             f" {float(r[f'force_{pct}']):.4f} ({error:+.1f}%) |")
            if found:
                print(line)
    print()
    print_fbar_markdown([r for r in rows if r["volumetric"] == "fbar"])


def print_fbar_markdown(rows):
    """The F-bar table: force, error against the standard D/48 and (in brackets) against the
    F-bar D/48, 3 and 6 Gauss points side by side."""
    head, rule = "| ν | D/h |", "|---|---|"
    for stage in STAGES:
        for g in GAUSS:
            head += f" F {round(100 * stage)}%, {g} GP: error (against F-bar D/48) |"
            rule += "---|"
    print(head)
    print(rule)
    for nu in FBAR_POISSON:
        for n in FBAR_SPACINGS:
            line, found = f"| {nu} | {n} |", False
            for stage in STAGES:
                pct = round(100 * stage)
                for g in GAUSS:
                    r = next((q for q in rows if q["poisson"] == nu and q["spacing_D_over_h"] == n
                              and q["gauss_points"] == g), None)
                    if r is None:
                        line += " |"
                        continue
                    found = True
                    e = float(r[f"error_{pct}_percent"])
                    e = 0.0 if abs(e) < 0.05 else e
                    own = r[f"error_{pct}_own_reference_percent"]
                    o = "" if own == "" else f" ({float(own):+.1f}%)"
                    line += (f" {float(r[f'force_{pct}']):.4f}: {e:+.1f}% (F-bar reference) |"
                             if n == FBAR_SPACINGS[-1] else
                             f" {float(r[f'force_{pct}']):.4f}: {e:+.1f}%{o} |")
            if found:
                print(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("action", choices=("run", "table", "markdown", "scenario"))
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "app", "softgrain"))
    parser.add_argument("--runs", default=os.path.join(ROOT, "out", "locking-study"))
    parser.add_argument("--only", default=None)
    parser.add_argument("--rate-check", action="store_true")
    args = parser.parse_args()
    if args.action == "scenario":
        write_atomically(TEST_SCENARIO, scenario_text(*RATE_CHECK))
        print(f"wrote {TEST_SCENARIO}")
        return
    if args.action == "run":
        for case in all_cases(args):
            run_case(args, *case)
    rows = collect(args)
    if args.action == "markdown":
        print_markdown(rows)
        return
    write_table(rows)
    plot(rows)


if __name__ == "__main__":
    main()
