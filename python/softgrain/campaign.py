"""Campaigns from Python: the table ``softgrain sweep`` gathers, and a list of scenarios run
through the campaign's process queue (src/campaign/run_queue.h) or, with ``slurm=``, submitted
as a campaign through ``softgrain sweep --slurm`` (src/campaign/slurm_campaign.h)."""

from __future__ import annotations

import csv
import os
import re
import shutil
import subprocess
import sys
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _softgrain
from .errors import Error
from .run_reader import RunReadError
from .toml_writer import dumps

__all__ = ["read_campaign", "run_scenarios", "submit_scenarios"]


def read_campaign(path: str | os.PathLike) -> Dict[str, np.ndarray]:
    """campaign.csv (a campaign folder or the file) as NumPy arrays by column.

    A column whose every cell is a number (or empty: NaN) is float64; the others (``id``,
    ``status``, string parameters as written in TOML, quotes kept) are arrays of str. The
    table is rewritten atomically after each run, so it can be read while the campaign runs
    (docs/campaigns.md).
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "campaign.csv")
    try:
        with open(path, encoding="utf-8", newline="") as file:
            # RFC 4180, as the sweep writes it: a cell holding a comma or a quote (a reason,
            # a TOML string) is quoted, its quotes doubled.
            lines = list(csv.reader(file))
    except OSError as error:
        raise RunReadError(f"{path}: {error}") from error
    if not lines:
        raise RunReadError(f"{path}: no header line")
    names = lines[0]
    rows = lines[1:]
    for number, row in enumerate(rows, start=2):
        if len(row) != len(names):
            raise RunReadError(f"{path}:{number}: {len(row)} cells for {len(names)} columns")
    table = {}
    for k, name in enumerate(names):
        cells = [row[k] for row in rows]
        try:
            table[name] = np.array([float(c) if c else np.nan for c in cells], dtype=np.float64)
        except ValueError:
            table[name] = np.array(cells, dtype=str)
    return table


def run_scenarios(scenarios: Sequence, output: str | os.PathLike, *, parallel: int = 1,
                  threads: int = 1,
                  on_finished: Optional[Callable[[dict], None]] = None,
                  slurm: Optional[Dict[str, Any]] = None,
                  executable: Optional[str | os.PathLike] = None,
                  dry_run: bool = False) -> Union[List[dict], Dict[str, Any]]:
    """Runs scenarios as child processes, ``parallel`` at a time, through the campaign's
    process queue (the one ``softgrain sweep`` uses); returns one outcome per scenario.

    Each scenario (a ``softgrain.Scenario``; their names must differ) is written to
    ``OUTPUT/<name>/scenario.toml`` and run there by ``python3 -m softgrain run`` with
    ``threads`` OpenMP threads, so its run folder ``OUTPUT/<name>/`` holds what ``softgrain
    run`` writes, and ``sweep.log`` its output. Relative file keys resolve against that
    folder: give file keys as absolute paths. An outcome is a dict: ``name``, ``directory``,
    ``success``, ``exit_code``, ``signal``, ``seconds``; ``on_finished(outcome)`` is called as
    each run ends. A run that fails does not stop the others. Raises softgrain.Error if the
    queue was interrupted (SIGINT, SIGTERM: the children are terminated).

    With ``slurm`` (a dict of the campaign's ``[slurm]`` keys, e.g. ``{"partition":
    "compute", "time": "02:00:00", "max_running": 20}``; ``{}`` for the cluster's defaults):
    the scenarios become one campaign, submitted as a Slurm job array by ``softgrain sweep
    --slurm`` (see ``submit_scenarios``), and the call returns at once with the job id.
    """
    if slurm is not None:
        return submit_scenarios(scenarios, output, slurm, threads=threads,
                                executable=executable, dry_run=dry_run)
    if dry_run:
        raise Error("run_scenarios: dry_run=True is for the cluster path (give slurm=)")
    output = os.path.abspath(os.fspath(output))
    names = [s.name for s in scenarios]
    if len(set(names)) != len(names):
        raise Error(f"run_scenarios: the scenarios' names must differ, got {names}")
    jobs = []
    for scenario in scenarios:
        folder = os.path.join(output, scenario.name)
        os.makedirs(folder, exist_ok=True)
        scenario_file = os.path.join(folder, "scenario.toml")
        with open(scenario_file, "w", encoding="utf-8") as file:
            file.write(scenario.to_toml())
        argv = [sys.executable, "-m", "softgrain", "run", scenario_file, "-o", output,
                "--threads", str(threads)]
        jobs.append(([argv], output, os.path.join(folder, "sweep.log")))

    def outcome_of(raw):
        name = names[raw["job"]]
        return {"name": name, "directory": os.path.join(output, name),
                **{k: raw[k] for k in ("success", "exit_code", "signal", "seconds")}}

    callback = (lambda raw: on_finished(outcome_of(raw))) if on_finished else None
    completed, outcomes = _softgrain._run_process_queue(jobs, parallel, callback)
    if not completed:
        raise Error("run_scenarios: interrupted (SIGINT or SIGTERM); the runs were stopped")
    return sorted((outcome_of(o) for o in outcomes), key=lambda o: names.index(o["name"]))


# The keys `softgrain sweep` sets in every run's scenario itself (campaign_def.cpp): never
# varied by a campaign.
_SET_BY_SWEEP = ("name", "output.directory")


def _leaves(value: Any, prefix: str = "") -> Dict[str, Any]:
    """The scenario dict's values by dotted path, as a campaign names them
    ("materials.0.young"): tables and arrays of tables are walked, other values are leaves."""
    if isinstance(value, dict):
        items = value.items()
    elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        items = ((str(k), v) for k, v in enumerate(value))
    else:
        return {prefix: value}
    leaves: Dict[str, Any] = {}
    for key, child in items:
        leaves.update(_leaves(child, f"{prefix}.{key}" if prefix else key))
    return leaves


def _campaign_list(scenarios: Sequence) -> List[Dict[str, Any]]:
    """The [[list]] of a campaign whose base scenario is the first one: per scenario, every
    key in which any scenario differs from the base. A campaign varies values only, so the
    scenarios must share their structure (the same keys, the same number of each array of
    tables)."""
    leaves = [_leaves(s.to_dict()) for s in scenarios]
    base = leaves[0]
    for scenario, these in zip(scenarios, leaves):
        extra = sorted(set(these) ^ set(base))
        if extra:
            raise Error(f"run_scenarios(slurm=...): scenario '{scenario.name}' and "
                        f"'{scenarios[0].name}' differ in structure (key '{extra[0]}' is in one "
                        "only); a campaign varies values of one scenario's keys: run these "
                        "locally (without slurm=) or submit them as separate calls")
    varied = [k for k in base if k not in _SET_BY_SWEEP
              and any(these[k] != base[k] for these in leaves)]
    if not varied:
        raise Error("run_scenarios(slurm=...): the scenarios differ only in their names: "
                    "nothing for a campaign to vary")
    return [{k: these[k] for k in varied} for these in leaves]


def _find_executable(executable: Optional[str | os.PathLike]) -> str:
    path = os.fspath(executable) if executable else shutil.which("softgrain")
    if not path or not os.access(path, os.X_OK):
        raise Error("run_scenarios(slurm=...): the cluster path submits through the command "
                    "line (softgrain sweep --slurm), which the tasks run: pass executable= or "
                    f"put softgrain on PATH (got {path!r})")
    return os.path.abspath(path)


def submit_scenarios(scenarios: Sequence, output: str | os.PathLike,
                     slurm: Dict[str, Any], *, threads: int = 1,
                     executable: Optional[str | os.PathLike] = None,
                     dry_run: bool = False) -> Dict[str, Any]:
    """Submits scenarios to Slurm as one campaign (``run_scenarios(..., slurm=...)``).

    The scenarios (their names must differ) must share their structure and differ in values:
    the first is the campaign's base scenario and each run sets the keys in which they differ
    (a ``[[list]]`` entry per scenario, docs/campaigns.md). Writes ``OUTPUT/base.toml`` and
    ``OUTPUT/scenarios.campaign.toml`` (``name`` the folder's name, ``threads``, the
    ``[slurm]`` table from ``slurm``), and runs ``softgrain sweep OUTPUT/scenarios.campaign.toml
    --slurm`` (with ``dry_run``: ``--dry-run --slurm --no-plan``, which writes the job script
    and submits nothing). OUTPUT is then the campaign folder: ``runs/<id>/`` per run,
    ``slurm-array.sh``, ``slurm-jobs.txt``; follow it with ``softgrain sweep
    OUTPUT/scenarios.campaign.toml --status``, gather it with ``--gather``, and read a run
    with ``open_run``. Calling again submits what is neither done nor queued nor running.

    ``executable``: the softgrain command line the tasks run (default: ``softgrain`` on
    PATH). Returns a dict: ``job_id`` (str; None for a dry run or when every run was done or
    queued already), ``campaign`` (the campaign file), ``folder`` (OUTPUT), ``runs`` (the run
    folder of each scenario, by scenario name) and ``output`` (what sweep printed). Raises
    softgrain.Error with sweep's message if it fails (a bad ``[slurm]`` key names the file
    and the key; sbatch's refusal is quoted).
    """
    names = [s.name for s in scenarios]
    if not names:
        raise Error("run_scenarios: no scenario given")
    if len(set(names)) != len(names):
        raise Error(f"run_scenarios: the scenarios' names must differ, got {names}")
    command = _find_executable(executable)
    folder = os.path.abspath(os.fspath(output))
    name = os.path.basename(folder)
    if not re.fullmatch(r"[A-Za-z0-9._+,-]+", name):
        raise Error(f"run_scenarios(slurm=...): the output folder's name '{name}' is the "
                    "campaign's name: letters, digits and . _ + - , only")
    entries = _campaign_list(scenarios)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "base.toml"), "w", encoding="utf-8") as file:
        file.write(scenarios[0].to_toml())
    campaign = {"name": name, "scenario": "base.toml", "output": "..", "threads": threads,
                "slurm": dict(slurm), "list": entries}
    campaign_file = os.path.join(folder, "scenarios.campaign.toml")
    with open(campaign_file, "w", encoding="utf-8") as file:
        file.write("# Written by softgrain.run_scenarios(..., slurm=...): one run per scenario "
                   f"({', '.join(names)}).\n" + dumps(campaign))
    argv = [command, "sweep", campaign_file, "--slurm"]
    if dry_run:
        argv += ["--dry-run", "--no-plan"]
    done = subprocess.run(argv, capture_output=True, text=True, cwd=folder)
    if done.returncode != 0:
        raise Error(f"softgrain sweep --slurm failed (exit status {done.returncode}):\n"
                    f"{done.stderr.strip() or done.stdout.strip()}")
    with open(os.path.join(folder, "runs.txt"), encoding="utf-8") as file:
        ids = file.read().split()
    return {"job_id": None if dry_run else _latest_job(folder, done.stdout),
            "campaign": campaign_file, "folder": folder,
            "runs": {n: os.path.join(folder, "runs", i) for n, i in zip(names, ids)},
            "output": done.stdout}


def _latest_job(folder: str, printed: str) -> Optional[str]:
    """The job id this submission printed ("submitted job array 12 (...)"), checked against
    the last line of slurm-jobs.txt; None if nothing was submitted."""
    match = re.search(r"submitted job array (\S+) ", printed)
    if not match:
        return None
    with open(os.path.join(folder, "slurm-jobs.txt"), encoding="utf-8") as file:
        recorded = file.read().split("\n")
    last = [line for line in recorded if line.strip()][-1].split()[0]
    if last != match.group(1):
        raise Error(f"{folder}/slurm-jobs.txt: last job {last}, sweep printed {match.group(1)}")
    return last
