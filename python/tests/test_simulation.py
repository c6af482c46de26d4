"""softgrain.Simulation: the command line's run loop stepped from Python."""

import copy
import filecmp
import threading
import time

import numpy as np
import pytest

import softgrain
from conftest import run_cli


def same_tree(a, b):
    """True if the folders hold the same files with the same bytes (run.log aside: it holds
    wall times and the scenario's path)."""
    comparison = filecmp.dircmp(a, b, ignore=["run.log"])
    if comparison.left_only or comparison.right_only or comparison.funny_files:
        return False
    _, mismatch, errors = filecmp.cmpfiles(a, b, comparison.common_files, shallow=False)
    return not mismatch and not errors and all(
        same_tree(a / d, b / d) for d in comparison.common_dirs)


def test_a_python_run_writes_the_cli_files_bitwise(cli_run, small_cell, tmp_path):
    _, cli_folder = cli_run
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    sim = softgrain.Simulation(scenario, threads=1, output=tmp_path)
    assert sim.directory == str(tmp_path / "small-cell")
    assert sim.run() is True
    assert sim.reached_end and sim.closed
    folder = tmp_path / "small-cell"
    for name in ("series.csv", "fields.pvd", "contacts.pvd", "checkpoint.bin"):
        assert (folder / name).read_bytes() == (cli_folder / name).read_bytes(), name
    assert same_tree(folder, cli_folder)
    assert (folder / "run.log").exists()


def test_stepping_one_by_one_and_in_memory_give_the_same_state(small_cell, tmp_path):
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    a = softgrain.Simulation(scenario, threads=1)
    assert a.directory is None
    b = softgrain.Simulation(scenario, threads=2, output=tmp_path)
    for _ in range(40):
        a.step()
    b.run(until=a.time)
    assert b.step_count == a.step_count == 40
    for name in ("ux", "uy", "vx", "vy", "fx", "fy"):
        np.testing.assert_array_equal(a.nodes[name], b.nodes[name])
    assert a.energy.tobytes() == b.energy.tobytes()


def test_views_are_zero_copy_and_read_only(small_cell):
    d = copy.deepcopy(small_cell)
    d["physics"] = {"gravity": [0.3, -1.0]}  # the grains move from the first step
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(d), threads=1)
    nodes, rigid, energy = sim.nodes, sim.rigid, sim.energy
    before = {name: view.copy() for name, view in nodes.items()}
    rigid_before = {name: view.copy() for name, view in rigid.items()}
    kinetic = float(energy["kinetic"])
    for _ in range(5):
        sim.step()
    # The same arrays, taken before the steps, now show the new state.
    for name in ("ux", "uy", "vx", "vy", "fx", "fy"):
        assert not np.array_equal(nodes[name], before[name]), name
        np.testing.assert_array_equal(nodes[name], sim.nodes[name])
    assert not np.array_equal(rigid["y"], rigid_before["y"])  # the top closes the gap
    assert float(energy["kinetic"]) != kinetic
    assert float(energy["kinetic"]) == float(sim.energy["kinetic"])
    np.testing.assert_array_equal(nodes["body"], before["body"])  # fixed
    assert nodes["ux"].base is not None and not nodes["ux"].flags.owndata
    assert len(nodes["body"]) == len(nodes["ux"]) == len(sim.node_positions())
    assert set(softgrain.ENERGY_FIELDS) == set(energy.dtype.names)
    for view in (nodes["ux"], nodes["body"], rigid["fx"], energy):
        with pytest.raises(ValueError):
            view[...] = 0
    # Physical positions through the rows: near the reference plus the parameters.
    positions = sim.node_positions()
    assert np.max(np.abs(positions[:, 0] - nodes["ref_x"] - nodes["ux"])) < 0.1
    bodies = sim.bodies()
    assert bodies["name"][:2] == ["bottom", "top"] and list(bodies["rigid"][:3]) == [True,
                                                                                      True, False]
    top = list(rigid["body"]).index(1)
    assert bodies["x"][1] == rigid["x"][top]


def test_a_callback_stops_the_run_where_asked(small_cell):
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(copy.deepcopy(small_cell)), threads=1)
    seen = []

    def stop_at_37(s):
        seen.append(s.step_count)
        return s.step_count < 37

    assert sim.run(callback=stop_at_37) is False
    assert sim.step_count == 37 and seen == list(range(1, 38))
    assert sim.run(until=0.1, every=10, callback=lambda s: s.step_count < 70) is False
    assert sim.step_count == 77  # 37 + 4 batches of 10
    assert sim.run(until=0.1) is True
    assert 0.1 - 1e-12 <= sim.time < 0.1 + sim.last_dt and not sim.closed


def test_checkpoint_and_resume_continue_bitwise(small_cell, tmp_path):
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    whole = softgrain.Simulation(scenario, threads=1)
    whole.run(until=0.12)
    path = tmp_path / "state.bin"
    whole.checkpoint(path)
    assert (tmp_path / "state.bin.toml").exists()
    whole.run()
    resumed = softgrain.Simulation.resume(path, threads=2)
    assert resumed.step_count < whole.step_count
    resumed.run()
    assert resumed.step_count == whole.step_count and resumed.time == whole.time
    for name in ("ux", "uy", "vx", "vy", "ref_x"):
        np.testing.assert_array_equal(resumed.nodes[name], whole.nodes[name])
    for name in ("x", "y", "theta", "vx", "vy", "omega", "fx", "fy"):
        np.testing.assert_array_equal(resumed.rigid[name], whole.rigid[name])
    assert resumed.energy.tobytes() == whole.energy.tobytes()


def test_a_stopped_python_run_resumes_into_the_cli_folder(cli_run, small_cell, tmp_path):
    _, cli_folder = cli_run
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    with softgrain.Simulation(scenario, threads=1, output=tmp_path) as sim:
        sim.run(until=0.25)  # past the checkpoints at 0.1 and 0.2
    folder = tmp_path / "small-cell"
    assert (folder / "series.csv.partial").exists() and not (folder / "series.csv").exists()
    resumed = softgrain.resume(folder / "checkpoint.bin", scenario, threads=1, output=tmp_path)
    resumed.run()
    assert same_tree(folder, cli_folder)


def test_a_checkpoint_of_another_scenario_is_refused(small_cell, tmp_path):
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    sim = softgrain.Simulation(scenario, threads=1)
    sim.step()
    sim.checkpoint(tmp_path / "a.bin")
    other = copy.deepcopy(small_cell)
    other["shear_cell"]["grains"] = 11
    with pytest.raises(softgrain.Error, match="checkpoint"):
        softgrain.resume(tmp_path / "a.bin", softgrain.Scenario.from_dict(other))


def test_stepping_releases_the_gil(small_cell):
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(copy.deepcopy(small_cell)), threads=1)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    thread = threading.Thread(target=count)
    thread.start()
    time.sleep(0.05)
    start = len(ticks)
    sim.run()  # one call: about 300 steps, no callback
    during = len(ticks) - start
    stop.set()
    thread.join()
    assert during > 20, during  # a thread blocked on the GIL would not have counted at all


def test_no_step_after_the_end(small_cell):
    d = copy.deepcopy(small_cell)
    d["time"]["duration"] = 0.01
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(d), threads=1)
    sim.run()
    with pytest.raises(softgrain.Error, match="closed|duration"):
        sim.step()


def test_rigid_force_views_are_the_series_first_body_forces(small_cell, tmp_path):
    # After the step from t_n, rigid fx, fy hold the force evaluation of t_n: what series.csv's
    # row at t_n reports for that body (written with 12 significant digits).
    scenario = softgrain.Scenario.from_dict(copy.deepcopy(small_cell))
    sim = softgrain.Simulation(scenario, threads=1, output=tmp_path)
    top = list(sim.rigid["body"]).index(sim.bodies()["name"].index("top"))
    fx, fy = sim.rigid["fx"], sim.rigid["fy"]
    seen = {}
    sim.run(callback=lambda s: seen.update({s.step_count - 1: (fx[top], fy[top])}))
    series = softgrain.open_run(sim.directory).series
    checked = 0
    for row, step in enumerate(series["step"].astype(int)):
        if step in seen:
            np.testing.assert_allclose(seen[step], (series["top_fx"][row], series["top_fy"][row]),
                                       rtol=1e-10, atol=1e-12)
            checked += 1
    assert checked == len(series["step"]) and np.any(series["top_fy"] != 0)


def test_a_negative_thread_count_is_refused(small_cell):
    with pytest.raises(softgrain.Error, match="threads"):
        softgrain.Simulation(softgrain.Scenario.from_dict(copy.deepcopy(small_cell)), threads=-1)


def test_a_stop_on_the_last_step_still_completes_the_run(small_cell, tmp_path):
    d = copy.deepcopy(small_cell)
    d["time"]["duration"] = 0.02
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(d), threads=1, output=tmp_path)
    assert sim.run(every=10**6, callback=lambda s: False) is False  # one batch: to the end
    assert sim.reached_end and sim.closed
    assert (tmp_path / "small-cell" / "series.csv").exists()


def test_repr_names_the_run(small_cell):
    sim = softgrain.Simulation(softgrain.Scenario.from_dict(copy.deepcopy(small_cell)), threads=1)
    sim.step()
    assert repr(sim) == f"softgrain.Simulation('small-cell', time={sim.time:g}, step_count=1, " \
                        "in memory)"
