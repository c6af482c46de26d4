"""The three worked examples of docs/python.md (examples/python/) run to completion, shortened
by SOFTGRAIN_EXAMPLES_SHORT (a reduced cell for a fraction of a time unit), and draw their
pictures."""

import os
import subprocess
import sys

import pytest

from conftest import EXAMPLES


def run_example(name, folder, *args):
    env = dict(os.environ, SOFTGRAIN_EXAMPLES_SHORT="1", MPLBACKEND="Agg")
    done = subprocess.run([sys.executable, str(EXAMPLES / "python" / name), *args], cwd=folder,
                          env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout


def assert_picture(path):
    assert path.exists() and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_read_run_and_plot(tmp_path):
    out = run_example("read_run_plot.py", tmp_path)
    assert "4 snapshots" in out and "mean mu over the second half" in out
    assert (tmp_path / "out" / "shear-cell-small" / "series.csv").exists()
    assert_picture(tmp_path / "mu_and_strain_rate.png")
    # Given a folder, it reads that one.
    out = run_example("read_run_plot.py", tmp_path, "out/shear-cell-small", "--out", "again.png")
    assert_picture(tmp_path / "again.png")


def test_cohesion_sweep(tmp_path):
    out = run_example("cohesion_sweep.py", tmp_path)
    lines = [line for line in out.splitlines() if line.startswith("c = ")]
    assert len(lines) == 5 and "nan" not in out and "inf" not in out
    assert_picture(tmp_path / "mu_vs_cohesion.png")


def test_stop_when_settled(tmp_path):
    out = run_example("stop_when_settled.py", tmp_path)
    assert "settled at t = " in out and "saved" in out
    assert_picture(tmp_path / "mu_settling.png")


@pytest.mark.parametrize("name", ["read_run_plot.py", "cohesion_sweep.py",
                                  "stop_when_settled.py"])
def test_examples_have_usage(name):
    text = (EXAMPLES / "python" / name).read_text()
    assert text.startswith("#!/usr/bin/env python3\n\"\"\"") and "python3 examples/python/" in text
