"""softgrain from Python: read runs into NumPy, build scenarios, step a simulation.

>>> import softgrain
>>> run = softgrain.open_run("out/shear-cell-small")        # a run folder
>>> mu = -run.series["top_fx"] / run.series["top_fy"]
>>> s = softgrain.Scenario.from_file("examples/shear-cell-small.toml")
>>> sim = softgrain.Simulation(s, threads=2, output="out")   # or output=None: in memory
>>> sim.run(until=1.0, every=100, callback=lambda sim: print(sim.time))

docs/python.md is the guide; every public name has a docstring and a type stub.
"""

import os as _os

# OpenMP threads waiting at a barrier sleep instead of spinning, as in the command line
# (app/main.cpp, README "Several runs on one machine"): libgomp reads the variable when it is
# loaded, which is when the compiled module below is imported. A value the user set is kept.
_os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

from . import errors  # noqa: E402  (the compiled module's error translator imports it)
from ._softgrain import ENERGY_FIELDS, Scenario, Simulation, __version__  # noqa: E402
from .campaign import read_campaign, run_scenarios, submit_scenarios  # noqa: E402
from .errors import Error, ScenarioError  # noqa: E402
from .run_reader import Run, RunReadError, open_run  # noqa: E402
from .scenario_dict import from_dict as _from_dict  # noqa: E402
from .scenario_dict import to_dict as _to_dict  # noqa: E402

# The dict side of Scenario is Python's (softgrain/scenario_dict.py).
Scenario.from_dict = staticmethod(_from_dict)
Scenario.to_dict = _to_dict

__all__ = [
    "ENERGY_FIELDS",
    "Error",
    "Run",
    "RunReadError",
    "Scenario",
    "ScenarioError",
    "Simulation",
    "__version__",
    "open_run",
    "read_campaign",
    "resume",
    "run_scenarios",
    "submit_scenarios",
]


def resume(checkpoint, scenario=None, *, threads=0, output=None, progress=False):
    """Continues a run from a checkpoint file; returns a new Simulation.

    ``checkpoint``: a file written by ``Simulation.checkpoint(path)`` or a run folder's
    ``checkpoint.bin``. ``scenario``: the scenario it belongs to; by default the one
    ``checkpoint(path)`` wrote beside it (``path.toml``), else the one the run folder's
    run.log names. A checkpoint of another scenario is refused (``softgrain.Error``).

    ``output=None`` continues in memory. ``output=ROOT`` continues the run folder
    ``ROOT/<name>/`` as ``softgrain run --resume`` does (its series.csv.partial is cut back to
    the checkpoint's rows): the finished folder is that of a run that never stopped.
    """
    checkpoint = _os.fspath(checkpoint)
    if scenario is None:
        scenario = _scenario_of_checkpoint(checkpoint)
    return Simulation._resume(checkpoint, scenario, threads, output, progress)


def _scenario_of_checkpoint(checkpoint):
    side = checkpoint + ".toml"
    if _os.path.exists(side):
        with open(side, encoding="utf-8") as file:
            return Scenario.from_toml(file.read(), _os.path.dirname(_os.path.abspath(side)))
    run_log = _os.path.join(_os.path.dirname(checkpoint), "run.log")
    if _os.path.exists(run_log):
        from .run_reader import parse_run_log
        source = parse_run_log(run_log).get("scenario")
        if source and _os.path.exists(source):
            return Scenario.from_file(source)
    raise Error(f"{checkpoint}: no scenario found for this checkpoint (no {side}, no run.log "
                "naming an existing scenario file): pass scenario=")


# Simulation.resume(path) as the API names it; softgrain.resume is the same function.
Simulation.resume = staticmethod(resume)
