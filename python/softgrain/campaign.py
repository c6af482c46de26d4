"""Campaigns from Python: the table ``softgrain sweep`` gathers, and a list of scenarios run
through the campaign's process queue (src/campaign/run_queue.h)."""

from __future__ import annotations

import csv
import os
import sys
from typing import Callable, Dict, List, Optional, Sequence

import numpy as np

from . import _softgrain
from .errors import Error
from .run_reader import RunReadError

__all__ = ["read_campaign", "run_scenarios"]


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
                  on_finished: Optional[Callable[[dict], None]] = None) -> List[dict]:
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
    """
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
