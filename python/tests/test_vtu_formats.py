"""The two encodings of the .vtu files ([output] field_format, src/io/vtu_document.h): the
same run written binary (the default: zlib-compressed appended data) and ASCII reads back to
identical arrays, bit for bit, with VTK's own XML reader (Debian's python3-vtk9, the reader
ParaView uses) and with softgrain's Python reader (open_run(...).fields(i), .contacts(i)),
and the two readers agree with each other. softgrain's C++ reader is checked the same way in
tests/render/test_vtu_formats.cpp."""

import copy
import os

import numpy as np
import pytest
import vtk  # python3-vtk9 (scripts/install-deps.sh): a missing VTK fails, never skips
from vtk.util.numpy_support import vtk_to_numpy

import softgrain
from conftest import run_cli


@pytest.fixture(scope="module")
def runs(tmp_path_factory, cli, small_cell):
    """The small cell run by the command line once per encoding: {format: run folder}."""
    root = tmp_path_factory.mktemp("vtu_formats")
    folders = {}
    for format_ in ("binary", "ascii"):
        d = copy.deepcopy(small_cell)
        d["time"] = {"duration": 0.3}  # the grains touch by the last snapshot
        d["output"]["field_format"] = format_
        scenario_file = root / f"{format_}.toml"
        scenario_file.write_text(softgrain.Scenario.from_dict(d).to_toml())
        run_cli(cli, scenario_file, root / format_)
        folders[format_] = root / format_ / "small-cell"
    return folders


def vtk_arrays(path):
    """Every array of a .vtu as VTK's XML reader gives it: points, cells, point data."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    assert reader.GetErrorCode() == 0, path
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:  # a contact snapshot without contacts
        arrays = {"points": np.zeros((0, 3)), "types": np.zeros(0, np.uint8),
                  "connectivity": np.zeros(0, np.int64), "offsets": np.zeros(0, np.int64)}
    else:
        cells = grid.GetCells()
        # VTK's offsets start with 0; the file's (and softgrain's) are the cells' ends.
        arrays = {"points": vtk_to_numpy(grid.GetPoints().GetData()).copy(),
                  "types": vtk_to_numpy(grid.GetCellTypesArray()).copy(),
                  "connectivity": vtk_to_numpy(cells.GetConnectivityArray()).copy(),
                  "offsets": vtk_to_numpy(cells.GetOffsetsArray())[1:].copy()}
    data = grid.GetPointData()
    for k in range(data.GetNumberOfArrays()):
        arrays[data.GetArrayName(k)] = vtk_to_numpy(data.GetArray(k)).copy()
    return arrays


def files(run, collection):
    return [f for _, f in softgrain.run_reader.read_pvd(str(run / collection))]


def assert_identical(a, b, where):
    assert list(a) == list(b), where
    for name in a:
        assert a[name].dtype == b[name].dtype, (where, name)
        np.testing.assert_array_equal(a[name], b[name], err_msg=f"{where}: {name}")


@pytest.mark.parametrize("collection", ["fields.pvd", "contacts.pvd"])
def test_vtk_reads_binary_and_ascii_to_identical_arrays(runs, collection):
    binary, ascii_ = files(runs["binary"], collection), files(runs["ascii"], collection)
    assert len(binary) == len(ascii_) >= 3
    for b, a in zip(binary, ascii_):
        assert b'format="appended"' in open(b, "rb").read(), b
        assert b"<AppendedData" not in open(a, "rb").read(), a
        vb = vtk_arrays(b)
        assert len(vb["points"]) > 0 or collection == "contacts.pvd"
        assert_identical(vb, vtk_arrays(a), b)


@pytest.mark.parametrize("collection", ["fields", "contacts"])
def test_softgrain_reads_binary_and_ascii_as_vtk_does(runs, collection):
    binary = softgrain.open_run(runs["binary"])
    ascii_ = softgrain.open_run(runs["ascii"])
    read = {"fields": lambda run, i: run.fields(i), "contacts": lambda run, i: run.contacts(i)}
    n = len(binary.times)
    assert n == len(ascii_.times) >= 3
    nonempty = 0
    for i in range(n):
        b, a = read[collection](binary, i), read[collection](ascii_, i)
        assert_identical(b, a, f"{collection} {i}")
        v = vtk_arrays(files(runs["binary"], collection + ".pvd")[i])
        np.testing.assert_array_equal(b["points"], v["points"][:, :2])
        for name in ("connectivity", "offsets", "types"):
            np.testing.assert_array_equal(b[name], v[name])
        for name in set(b) - {"points", "connectivity", "offsets", "types"}:
            np.testing.assert_array_equal(b[name], v[name], err_msg=name)
        nonempty += len(b["points"]) > 0
    assert nonempty > 0


def test_binary_is_the_default_and_smaller(runs, small_cell, cli, tmp_path):
    d = copy.deepcopy(small_cell)
    d["time"] = {"duration": 0.05}
    scenario_file = tmp_path / "default.toml"
    scenario_file.write_text(softgrain.Scenario.from_dict(d).to_toml())
    run_cli(cli, scenario_file, tmp_path)
    first = tmp_path / "small-cell" / "fields" / "000000.vtu"
    assert b'compressor="vtkZLibDataCompressor"' in first.read_bytes()
    assert 'field_format = "binary"' in (tmp_path / "small-cell" / "run.log").read_text()
    last_b = files(runs["binary"], "fields.pvd")[-1]
    last_a = files(runs["ascii"], "fields.pvd")[-1]
    assert 3 * os.path.getsize(last_b) < os.path.getsize(last_a)


def test_a_truncated_binary_file_is_refused_naming_it(runs, tmp_path):
    data = open(files(runs["binary"], "fields.pvd")[-1], "rb").read()
    cut = tmp_path / "cut.vtu"
    cut.write_bytes(data[:len(data) // 2] + b"\n</VTKFile>\n")
    with pytest.raises(softgrain.RunReadError, match="cut.vtu"):
        softgrain.run_reader.read_vtu(str(cut))
