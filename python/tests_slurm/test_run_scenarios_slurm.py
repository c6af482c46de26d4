"""run_scenarios(..., slurm=...) against a real one-node Slurm (run inside
tests/slurm/with_slurm.sh by ctest, python/CMakeLists.txt: SLURM_CONF points at its cluster).

Two scenarios built in Python are submitted as one job array through `softgrain sweep
--slurm`; the call returns the job id Slurm gave (squeue/scontrol know it), the tasks run and
analyse each scenario, and each run's series.csv is bitwise that of the same scenario run in
this process. Submitting again while nothing is left to run submits nothing."""

import os
import pathlib
import subprocess
import sys
import time

import softgrain

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
from conftest import small_cell_dict  # noqa: E402

CLI = os.environ["SOFTGRAIN_CLI"]


def scenario(name, young):
    d = small_cell_dict(duration=0.05)
    d["name"] = name
    d["materials"][0]["young"] = young
    return softgrain.Scenario.from_dict(d)


def wait_until_done(runs, seconds):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if all((pathlib.Path(r) / "analysis" / "summary.json").exists() for r in runs):
            return True
        time.sleep(1)
    return False


def test_scenarios_submitted_to_slurm_run_as_in_process(tmp_path):
    assert os.environ.get("SLURM_CONF"), "run inside tests/slurm/with_slurm.sh"
    scenarios = [scenario("stiff", 20.0), scenario("soft", 10.0)]
    result = softgrain.run_scenarios(scenarios, tmp_path / "study", threads=1,
                                     slurm={"time": "00:10:00", "max_running": 2},
                                     executable=CLI)
    job = result["job_id"]
    assert job and job.isdigit(), result["output"]
    shown = subprocess.run(["scontrol", "show", "job", job], capture_output=True, text=True)
    assert f"ArrayJobId={job}" in shown.stdout, shown.stdout + shown.stderr
    assert wait_until_done(result["runs"].values(), 300), \
        subprocess.run(["squeue"], capture_output=True, text=True).stdout
    for s in scenarios:
        here = softgrain.Simulation(s, threads=1, output=tmp_path / "here")
        here.run()
        on_slurm = pathlib.Path(result["runs"][s.name]) / "series.csv"
        assert on_slurm.read_bytes() == (tmp_path / "here" / s.name / "series.csv").read_bytes()
    # Everything is done: a second call submits nothing.
    again = softgrain.run_scenarios(scenarios, tmp_path / "study", threads=1,
                                    slurm={"time": "00:10:00", "max_running": 2},
                                    executable=CLI)
    assert again["job_id"] is None, again["output"]
