"""Campaigns from Python: scenarios built in Python run through the campaign's process queue,
and the table `softgrain sweep` gathers read as NumPy arrays."""

import csv
import pathlib
import subprocess

import numpy as np
import pytest

import softgrain
from conftest import small_cell_dict


def tiny(name, young):
    d = small_cell_dict(duration=0.05)
    d["name"] = name
    d["materials"][0]["young"] = young
    return softgrain.Scenario.from_dict(d)


def test_scenarios_run_through_the_queue_as_in_process(tmp_path):
    scenarios = [tiny("stiff", 20.0), tiny("soft", 10.0)]
    finished = []
    outcomes = softgrain.run_scenarios(scenarios, tmp_path / "runs", parallel=2, threads=1,
                                       on_finished=finished.append)
    assert [o["name"] for o in outcomes] == ["stiff", "soft"]
    assert all(o["success"] and o["exit_code"] == 0 for o in outcomes)
    assert sorted(o["name"] for o in finished) == ["soft", "stiff"]
    for scenario, outcome in zip(scenarios, outcomes):
        folder = tmp_path / "runs" / scenario.name
        assert (folder / "sweep.log").exists() and (folder / "scenario.toml").exists()
        here = softgrain.Simulation(scenario, threads=1, output=tmp_path / "here")
        here.run()
        assert (folder / "series.csv").read_bytes() == \
            (tmp_path / "here" / scenario.name / "series.csv").read_bytes()
    stiff, soft = (softgrain.open_run(tmp_path / "runs" / n).series for n in ("stiff", "soft"))
    assert stiff["dt"][0] < soft["dt"][0]  # each ran its own scenario: the stiffer, a smaller step


def test_a_failing_run_is_reported_and_the_others_go_on(tmp_path):
    good = tiny("good", 10.0)
    # A run folder that is not a softgrain one is refused when the run starts.
    (tmp_path / "runs" / "bad").mkdir(parents=True)
    (tmp_path / "runs" / "bad" / "precious.txt").write_text("not a run")
    outcomes = softgrain.run_scenarios([tiny("bad", 10.0), good], tmp_path / "runs")
    assert [o["success"] for o in outcomes] == [False, True]
    assert outcomes[0]["exit_code"] == 1
    assert "error" in (tmp_path / "runs" / "bad" / "sweep.log").read_text()


def test_names_must_differ(tmp_path):
    with pytest.raises(softgrain.Error, match="names must differ"):
        softgrain.run_scenarios([tiny("a", 10.0), tiny("a", 20.0)], tmp_path)


def test_the_sweep_table_as_arrays(cli, tmp_path):
    base = tmp_path / "base.toml"
    base.write_text(tiny("base", 10.0).to_toml())
    (tmp_path / "campaign.toml").write_text(
        'name = "tiny"\nscenario = "base.toml"\noutput = "out"\nparallel = 2\nthreads = 1\n'
        'analyze_options = ["--no-agglomerates"]\n[grid]\n"materials.0.young" = [10.0, 20.0]\n')
    subprocess.run([cli, "sweep", str(tmp_path / "campaign.toml")], capture_output=True,
                   text=True, cwd=tmp_path)
    folder = tmp_path / "out" / "tiny"
    table = softgrain.read_campaign(folder)
    with open(folder / "campaign.csv", newline="") as file:
        lines = list(csv.reader(file))  # RFC 4180: a reason with commas is one quoted cell
    header = lines[0]
    assert list(table) == header and len(table["id"]) == len(lines) - 1 == 2
    assert table["id"].dtype.kind == "U" and table["status"].dtype.kind == "U"
    np.testing.assert_array_equal(table["materials.0.young"], [10.0, 20.0])
    for k, name in enumerate(header):
        cell = lines[1][k]
        if table[name].dtype.kind == "f":
            assert (np.isnan(table[name][0]) and cell == "") or table[name][0] == float(cell)
        else:
            assert table[name][0] == cell


def test_the_cluster_path_writes_the_campaign_and_its_job_script(cli, tmp_path):
    """run_scenarios(..., slurm=..., dry_run=True): the campaign sweep --slurm would submit,
    written and checked by the command line, without a scheduler (the submission itself runs
    against a real one-node Slurm: python/tests_slurm)."""
    scenarios = [tiny("stiff", 20.0), tiny("soft", 10.0)]
    soft = scenarios[1].to_dict()
    soft["contact_laws"][0]["cohesion"] = 0.2
    scenarios[1] = softgrain.Scenario.from_dict(soft)
    result = softgrain.run_scenarios(scenarios, tmp_path / "study", threads=2,
                                     slurm={"partition": "compute", "time": "00:30:00"},
                                     executable=cli, dry_run=True)
    assert result["job_id"] is None
    folder = tmp_path / "study"
    assert result["folder"] == str(folder)
    script = (folder / "slurm-array.sh").read_text()
    assert "#SBATCH --partition=compute" in script and "--time=00:30:00" in script
    assert "--array=0-1" in script and "--cpus-per-task=2" in script
    ids = (folder / "runs.txt").read_text().split()
    assert list(result["runs"]) == ["stiff", "soft"]
    assert [pathlib.Path(p).name for p in result["runs"].values()] == ids
    # Each run's scenario is the scenario given, values and all (only name and directory
    # are the campaign's).
    for scenario, run in zip(scenarios, result["runs"].values()):
        written = softgrain.Scenario.from_file(pathlib.Path(run) / "scenario.toml").to_dict()
        given = scenario.to_dict()
        for d in (written, given):
            d.pop("name")
            d.get("output", {}).pop("directory", None)
        assert written == given
    # Submitting again changes nothing that was written.
    again = softgrain.run_scenarios(scenarios, tmp_path / "study", threads=2,
                                    slurm={"partition": "compute", "time": "00:30:00"},
                                    executable=cli, dry_run=True)
    assert again["runs"] == result["runs"]


def test_the_cluster_path_refuses_what_a_campaign_cannot_hold(cli, tmp_path):
    one, other = tiny("one", 10.0), tiny("other", 10.0)
    with pytest.raises(softgrain.Error, match="differ only in their names"):
        softgrain.run_scenarios([one, other], tmp_path / "s", slurm={}, executable=cli,
                                dry_run=True)
    d = other.to_dict()
    d["materials"].append({**d["materials"][0], "name": "extra"})
    with pytest.raises(softgrain.Error, match=r"differ in structure \(key 'materials\.2\."):
        softgrain.run_scenarios([one, softgrain.Scenario.from_dict(d)], tmp_path / "s",
                                slurm={}, executable=cli, dry_run=True)
    with pytest.raises(softgrain.Error, match="slurm.time"):
        softgrain.run_scenarios([one, tiny("two", 20.0)], tmp_path / "s",
                                slurm={"time": "twelve hours"}, executable=cli, dry_run=True)
    with pytest.raises(softgrain.Error, match="executable"):
        softgrain.run_scenarios([one, tiny("two", 20.0)], tmp_path / "s", slurm={},
                                executable=tmp_path / "none", dry_run=True)
