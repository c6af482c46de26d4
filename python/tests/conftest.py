"""Shared fixtures of the Python tests (run by ctest: python/CMakeLists.txt sets PYTHONPATH to
the build tree's package and SOFTGRAIN_CLI to the command line of the same build).

The scenes are small shear cells (examples/shear-cell-small.toml reduced to L = 6 and 12
grains, a fraction of a time unit), so that the whole suite takes well under a minute on
one thread: what is checked is that files and values agree, not the physics.
"""

import copy
import os
import pathlib
import shutil
import subprocess

import pytest

import softgrain

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = REPOSITORY / "examples"


def small_cell_dict(duration=0.3):
    """examples/shear-cell-small.toml reduced: L = 6, 12 grains, `duration` time units."""
    d = softgrain.Scenario.from_file(EXAMPLES / "shear-cell-small.toml").to_dict()
    d["name"] = "small-cell"
    d["time"] = {"duration": duration}
    d["output"] = {"series_period": 0.01, "field_period": 0.1, "checkpoint_period": 0.1}
    d["shear_cell"]["length"] = 6.0
    d["shear_cell"]["grains"] = 12
    return d


@pytest.fixture(scope="session")
def small_cell():
    """The small cell as a dict (a deep copy per use is the caller's: copy.deepcopy)."""
    return small_cell_dict()


@pytest.fixture(scope="session")
def cli():
    """The softgrain command line of this build (SOFTGRAIN_CLI), else one on PATH."""
    path = os.environ.get("SOFTGRAIN_CLI") or shutil.which("softgrain")
    if not path:
        pytest.skip("no softgrain command line: set SOFTGRAIN_CLI")
    return path


def run_cli(cli, scenario_file, output_root, *extra):
    """`softgrain run` on one thread; returns the run folder."""
    subprocess.run([cli, "run", str(scenario_file), "-o", str(output_root), "--threads", "1",
                    *extra], check=True, capture_output=True, text=True)
    return output_root


@pytest.fixture(scope="session")
def cli_run(tmp_path_factory, cli, small_cell):
    """A complete CLI run of the small cell: (scenario file, run folder)."""
    root = tmp_path_factory.mktemp("cli")
    scenario_file = root / "small-cell.toml"
    scenario_file.write_text(softgrain.Scenario.from_dict(copy.deepcopy(small_cell)).to_toml())
    run_cli(cli, scenario_file, root / "out")
    return scenario_file, root / "out" / "small-cell"
