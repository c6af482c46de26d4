"""softgrain.open_run: every output of a short CLI run read back and checked against the
files themselves (values, counts, names and sizes read from the text independently)."""

import re
import shutil
import struct
import zlib

import numpy as np
import pytest

import softgrain
from conftest import run_cli


def data_array_names(vtu_text, section):
    """The Name attributes of the DataArrays of one section (<PointData>, <Cells>)."""
    block = re.search(rf"<{section}[^>]*>(.*?)</{section}>", vtu_text, re.DOTALL).group(1)
    return re.findall(r'<DataArray[^>]*Name="([^"]+)"', block)


def xml_part(vtu_bytes):
    """The XML of a .vtu as text: all of an ASCII file, the part before the binary data of a
    binary one."""
    return vtu_bytes.split(b"<AppendedData")[0].decode("utf-8")


def first_point(vtu_bytes):
    """(x, y) of the first point, decoded here from the file itself: the text of an ASCII
    file, or the first zlib block of the Points array of a binary one (VTK's layout: a UInt64
    header of 3 + blocks words, then the blocks)."""
    text = xml_part(vtu_bytes)
    ascii_ = re.search(r"<Points>\s*<DataArray[^>]*format=\"ascii\"[^>]*>\s*(\S+)\s+(\S+)", text)
    if ascii_:
        return float(ascii_.group(1)), float(ascii_.group(2))
    offset = int(re.search(r'<Points>\s*<DataArray[^>]*offset="(\d+)"', text).group(1))
    at = vtu_bytes.index(b"_", vtu_bytes.index(b"<AppendedData")) + 1 + offset
    blocks = struct.unpack_from("<Q", vtu_bytes, at)[0]
    packed = struct.unpack_from("<Q", vtu_bytes, at + 24)[0]
    start = at + 24 + 8 * blocks
    return struct.unpack_from("<2d", zlib.decompress(vtu_bytes[start:start + packed]))


def test_series_is_the_csv_column_by_column(cli_run):
    _, folder = cli_run
    run = softgrain.open_run(folder)
    lines = (folder / "series.csv").read_text().splitlines()
    header = lines[0].split(",")
    series = run.series
    assert list(series) == header
    assert "top_fx" in series and "bottom_fy" in series
    for name in header:
        assert series[name].dtype == np.float64
        assert len(series[name]) == len(lines) - 1
    for row in (1, len(lines) // 2, len(lines) - 1):
        cells = lines[row].split(",")
        for k, name in enumerate(header):
            assert series[name][row - 1] == float(cells[k])
    assert run.complete


def test_snapshots_fields_contacts_grains(cli_run):
    _, folder = cli_run
    run = softgrain.open_run(folder)
    pvd = (folder / "fields.pvd").read_text()
    times = [float(t) for t in re.findall(r'timestep="([^"]+)"', pvd)]
    np.testing.assert_array_equal(run.times, times)
    assert len(times) == 4  # t = 0, 0.1, 0.2 and the final 0.3
    files = re.findall(r'file="([^"]+)"', pvd)
    for i in (0, len(files) - 1, -1):
        data = (folder / files[i]).read_bytes()
        text = xml_part(data)
        fields = run.fields(i)
        n = int(re.search(r'NumberOfPoints="(\d+)"', text).group(1))
        cells = int(re.search(r'NumberOfCells="(\d+)"', text).group(1))
        assert fields["points"].shape == (n, 2)
        assert len(fields["types"]) == cells and len(fields["offsets"]) == cells
        assert len(fields["connectivity"]) == fields["offsets"][-1]
        names = data_array_names(text, "PointData")
        assert "von_mises" in names and "strain_rate" in names and "velocity" in names
        for name in names:
            assert name in fields
            assert len(fields[name]) == n
        assert fields["velocity"].shape == (n, 3)
        # The first point's coordinates, as written (binary by default).
        first = first_point(data)
        assert fields["points"][0, 0] == first[0]
        assert fields["points"][0, 1] == first[1]

    contacts = run.contacts(-1)
    contacts_file = re.findall(r'file="([^"]+)"', (folder / "contacts.pvd").read_text())[-1]
    text = xml_part((folder / contacts_file).read_bytes())
    n = int(re.search(r'NumberOfPoints="(\d+)"', text).group(1))
    assert n > 0  # the grains touch at the end of the compaction's start
    for name in data_array_names(text, "PointData"):
        assert len(contacts[name]) == n

    grains = run.grains(-1)
    rows = (folder / "grains" / "000003.csv").read_text().splitlines()
    assert list(grains) == rows[0].split(",")
    assert len(grains["x"]) == len(rows) - 1 == 14  # 12 grains and two first bodies
    np.testing.assert_array_equal(grains["body"], np.arange(14))
    assert grains["x"][5] == float(rows[6].split(",")[1])


def test_parameters_come_from_run_log(cli_run):
    scenario_file, folder = cli_run
    parameters = softgrain.open_run(folder).parameters
    assert parameters["name"] == "small-cell"
    assert parameters["scenario"] == str(scenario_file)
    assert parameters["time"]["duration"] == 0.3
    assert parameters["output"]["series_period"] == 0.01
    assert [m["name"] for m in parameters["materials"]] == ["soft", "first_body"]
    assert any(note.startswith("model:") for note in parameters["notes"])


def test_summary_is_read_after_analyze(cli_run, cli, tmp_path):
    _, folder = cli_run
    copy = tmp_path / "run"
    shutil.copytree(folder, copy)
    assert softgrain.open_run(copy).summary is None
    import subprocess
    # Exit status 3: analyzed, with a quantity the run asks for not measured (too short).
    result = subprocess.run([cli, "analyze", str(copy)], capture_output=True, text=True)
    assert result.returncode in (0, 3), result.stderr
    summary = softgrain.open_run(copy).summary
    assert isinstance(summary, dict) and summary  # its content is analyze's (docs/analysis.md)


def test_a_killed_run_reads_as_far_as_it_went(cli, cli_run, tmp_path):
    scenario_file, complete = cli_run
    run_cli(cli, scenario_file, tmp_path, "--max-steps", "150")
    folder = tmp_path / "small-cell"
    run = softgrain.open_run(folder)
    assert not run.complete
    partial = (folder / "series.csv.partial").read_text().splitlines()
    assert len(run.series["time"]) == len(partial) - 1 > 0
    full = softgrain.open_run(complete).series
    n = len(partial) - 1
    np.testing.assert_array_equal(run.series["kinetic_energy"], full["kinetic_energy"][:n])
    assert len(run.times) < 4 and len(run.times) >= 1
    with pytest.raises(IndexError):
        run.fields(len(run.times))
    # A row being written (no newline yet) is left out, not misread.
    with open(folder / "series.csv.partial", "a") as file:
        file.write("0.123,45,0.00")
    assert len(softgrain.open_run(folder).series["time"]) == n


def test_not_a_run_folder(tmp_path):
    with pytest.raises(softgrain.RunReadError, match="not a run folder"):
        softgrain.open_run(tmp_path)
