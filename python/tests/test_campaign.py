"""Campaigns from Python: scenarios built in Python run through the campaign's process queue,
and the table `softgrain sweep` gathers read as NumPy arrays."""

import csv
import copy
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
