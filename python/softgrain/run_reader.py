"""Reading a run folder (``softgrain.open_run``) into NumPy arrays.

Pure Python and NumPy on purpose (zlib is in Python's standard library): the files are CSV,
VTK XML (ASCII, or binary with zlib-compressed appended data: the default,
src/io/vtu_document.h), JSON and the TOML-like run.log, and reading them here needs no
compiled code, so a run can be read on a machine where only the package's Python files are
present. The readers follow the house rule of the C++ ones (src/render/vtu_reader.h, src/analysis/series.h): columns and arrays are
looked up by name, and what is not in the expected form is refused with an error naming the
file, never misread.

A run that is still going, or was killed, is read as far as it is complete:

* ``series`` reads ``series.csv`` or, while the run goes, ``series.csv.partial``; a last line
  without its newline (a row being written) is left out, and ``complete`` says which file
  was read.
* ``times`` and ``fields(i)`` follow ``fields.pvd``, which the run rewrites atomically after
  each snapshot, so every snapshot it lists is whole.
"""

from __future__ import annotations

import json
import os
import struct
import tomllib
import xml.etree.ElementTree as ElementTree
import zlib
from typing import Any, Dict, List, Optional

import numpy as np

__all__ = ["Run", "RunReadError", "open_run"]


class RunReadError(Exception):
    """A file of a run folder is missing or not in the form softgrain writes."""


_VTK_TYPES = {
    "Float64": np.float64,
    "Float32": np.float32,
    "Int32": np.int32,
    "Int64": np.int64,
    "UInt8": np.uint8,
}


class _Appended:
    """The raw <AppendedData> block of a binary .vtu: each appended DataArray is VTK's
    compressed layout at its offset from the byte after '_' (UInt64 header: number of blocks,
    block size, size of a partial last block or 0, the compressed size of each block; then the
    zlib blocks). Only what softgrain writes is read: header_type UInt64, vtkZLibDataCompressor.
    """

    def __init__(self, data: bytes, start: int, root_attributes: Dict[str, str], path: str):
        self.path = path
        self.data = data
        header_type = root_attributes.get("header_type")
        compressor = root_attributes.get("compressor")
        if header_type != "UInt64" or compressor != "vtkZLibDataCompressor":
            raise RunReadError(f"{path}: appended data with header_type '{header_type}' and "
                               f"compressor '{compressor}'; only UInt64 and "
                               "vtkZLibDataCompressor are read")
        self.begin = data.index(b"_", start) + 1

    def _words(self, at: int, count: int, name: str) -> tuple:
        end = at + 8 * count
        if end > len(self.data):
            raise RunReadError(f"{self.path}: DataArray '{name}' is cut short (truncated file)")
        return struct.unpack_from(f"<{count}Q", self.data, at)

    def bytes(self, offset: int, name: str) -> bytes:
        at = self.begin + offset
        blocks, block_size, last_size = self._words(at, 3, name)
        packed_sizes = self._words(at + 24, blocks, name) if blocks else ()
        at += 24 + 8 * blocks
        pieces = []
        for b, packed in enumerate(packed_sizes):
            expected = last_size if b + 1 == blocks and last_size else block_size
            if at + packed > len(self.data):
                raise RunReadError(f"{self.path}: DataArray '{name}' is cut short "
                                   "(truncated file)")
            try:
                piece = zlib.decompress(self.data[at:at + packed])
            except zlib.error as error:
                raise RunReadError(f"{self.path}: DataArray '{name}': block {b}: {error}") \
                    from error
            if len(piece) != expected:
                raise RunReadError(f"{self.path}: DataArray '{name}': block {b} inflates to "
                                   f"{len(piece)} bytes, expected {expected}")
            pieces.append(piece)
            at += packed
        return b"".join(pieces)


def _read_data_array(element: ElementTree.Element, path: str,
                     appended: Optional[_Appended]) -> np.ndarray:
    """One <DataArray> (ASCII, or appended binary) as a NumPy array, (n, components) when it
    has several."""
    name = element.get("Name")
    dtype = _VTK_TYPES.get(element.get("type", "Float64"))
    if dtype is None:
        raise RunReadError(f"{path}: DataArray '{name}' has type '{element.get('type')}'")
    format_ = element.get("format", "ascii")
    if format_ == "ascii":
        values = np.array((element.text or "").split(), dtype=np.float64).astype(dtype)
    elif format_ == "appended":
        if appended is None:
            raise RunReadError(f"{path}: DataArray '{name}' is appended but the file has no "
                               "<AppendedData>")
        raw = appended.bytes(int(element.get("offset", "0")), name)
        item = np.dtype(dtype).newbyteorder("<")
        if len(raw) % item.itemsize:
            raise RunReadError(f"{path}: DataArray '{name}': {len(raw)} bytes of "
                               f"{element.get('type')}")
        values = np.frombuffer(raw, dtype=item).astype(dtype)
    else:
        raise RunReadError(f"{path}: DataArray '{name}' has format '{format_}'; only ascii "
                           "and appended are read")
    components = int(element.get("NumberOfComponents", "1"))
    if components > 1:
        if values.size % components:
            raise RunReadError(f"{path}: DataArray '{name}' holds {values.size} "
                               f"values, not a multiple of {components} components")
        values = values.reshape(-1, components)
    return values


def _parse_vtu(path: str) -> tuple:
    """The XML root of a .vtu and its appended block (None for an ASCII file). The raw
    binary after <AppendedData> is not XML: the XML before it is parsed, closed by hand."""
    try:
        with open(path, "rb") as file:
            data = file.read()
    except OSError as error:
        raise RunReadError(f"{path}: {error}") from error
    if not data.rstrip().endswith(b"</VTKFile>"):
        raise RunReadError(f"{path}: truncated (no closing </VTKFile>)")
    start = data.find(b"<AppendedData")
    xml = data if start < 0 else data[:start] + b"</VTKFile>"
    try:
        root = ElementTree.fromstring(xml)
    except ElementTree.ParseError as error:
        raise RunReadError(f"{path}: {error}") from error
    if start < 0:
        return root, None
    tag = data[start:data.index(b">", start)]
    if b'encoding="raw"' not in tag:
        raise RunReadError(f"{path}: <AppendedData> is not encoding=\"raw\"")
    return root, _Appended(data, start, root.attrib, path)


def read_vtu(path: str) -> Dict[str, np.ndarray]:
    """A .vtu file softgrain wrote (ASCII or binary), as a dict of NumPy arrays.

    Keys: ``points`` (n, 2) (z dropped), ``connectivity``, ``offsets``, ``types`` (the cells,
    as VTK stores them), then every <PointData> array by its name (``point_data`` order kept
    in ``arrays``). Both encodings give the same arrays, bit for bit. Raises RunReadError
    naming the file on anything unexpected.
    """
    root, appended = _parse_vtu(path)
    piece = root.find("UnstructuredGrid/Piece")
    if piece is None:
        raise RunReadError(f"{path}: no UnstructuredGrid/Piece")
    n_points = int(piece.get("NumberOfPoints", "0"))
    n_cells = int(piece.get("NumberOfCells", "0"))
    result: Dict[str, np.ndarray] = {}
    points_array = piece.find("Points/DataArray")
    if points_array is None:
        raise RunReadError(f"{path}: no Points")
    points = _read_data_array(points_array, path, appended).reshape(-1, 3)
    if len(points) != n_points:
        raise RunReadError(f"{path}: {len(points)} points, NumberOfPoints says {n_points}")
    result["points"] = points[:, :2].copy()
    for array in piece.findall("Cells/DataArray"):
        result[array.get("Name", "")] = _read_data_array(array, path, appended)
    if "types" in result and len(result["types"]) != n_cells:
        raise RunReadError(f"{path}: {len(result['types'])} cell types, NumberOfCells says "
                           f"{n_cells}")
    for array in piece.findall("PointData/DataArray"):
        name = array.get("Name", "")
        values = _read_data_array(array, path, appended)
        if len(values) != n_points:
            raise RunReadError(f"{path}: point array '{name}' has {len(values)} entries for "
                               f"{n_points} points")
        result[name] = values
    return result


def read_pvd(path: str) -> List[tuple]:
    """The (time, file) entries of a .pvd collection, files resolved against its folder."""
    try:
        root = ElementTree.parse(path).getroot()
    except (OSError, ElementTree.ParseError) as error:
        raise RunReadError(f"{path}: {error}") from error
    folder = os.path.dirname(path)
    return [(float(d.get("timestep", "nan")), os.path.join(folder, d.get("file", "")))
            for d in root.iter("DataSet")]


def read_csv_columns(path: str) -> Dict[str, np.ndarray]:
    """A CSV file with a header line, as NumPy arrays by column name.

    Only the lines ending in a newline are read (a line being appended is left out); every
    row must have as many numbers as the header has names.
    """
    try:
        with open(path, encoding="utf-8") as file:
            text = file.read()
    except OSError as error:
        raise RunReadError(f"{path}: {error}") from error
    lines = text.split("\n")[:-1]  # the last piece has no newline: incomplete or empty
    if not lines:
        raise RunReadError(f"{path}: no header line")
    names = lines[0].split(",")
    rows = []
    for number, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != len(names):
            raise RunReadError(f"{path}:{number}: {len(cells)} values for {len(names)} columns")
        try:
            rows.append([float(c) for c in cells])
        except ValueError as error:
            raise RunReadError(f"{path}:{number}: {error}") from error
    table = np.array(rows, dtype=np.float64).reshape(-1, len(names))
    return {name: table[:, k].copy() for k, name in enumerate(names)}


def parse_run_log(path: str) -> Dict[str, Any]:
    """The resolved parameters run.log begins with, as a dict of its TOML-like tables.

    run.log's first lines name the scenario (``scenario``, ``name``, ``threads``,
    ``force_kernel``), then come the tables [time], [output], [discretization], [physics]
    and [[materials]] with every parameter as resolved. The comment lines that follow (the
    model's size, the step estimate, the step control's record) are kept as a list under
    ``notes``.
    """
    try:
        with open(path, encoding="utf-8") as file:
            lines = file.read().splitlines()
    except OSError as error:
        raise RunReadError(f"{path}: {error}") from error
    if not lines or lines[0] != "softgrain run log":
        raise RunReadError(f"{path}: not a softgrain run log")
    result: Dict[str, Any] = {"notes": []}
    table = result
    for line in lines[1:]:
        if not line.strip():
            continue
        if line.startswith("#"):
            result["notes"].append(line[1:].strip())
        elif line.startswith("[["):
            table = {}
            result.setdefault(line.strip("[] "), []).append(table)
        elif line.startswith("["):
            table = result.setdefault(line.strip("[] "), {})
        elif "=" in line:
            key, value = (part.strip() for part in line.split("=", 1))
            try:
                table[key] = tomllib.loads("v = " + value)["v"]
            except tomllib.TOMLDecodeError:
                table[key] = value  # the scenario's path is written as is, unquoted
    return result


class Run:
    """A run folder (``softgrain run`` or ``softgrain.Simulation`` with an output folder).

    Read lazily: each property reads its file when first asked for (``series`` and the
    snapshot list again each time, so that a run still going is followed).
    """

    def __init__(self, folder: str | os.PathLike):
        self.folder = os.fspath(folder)
        if not os.path.isdir(self.folder):
            raise RunReadError(f"{self.folder}: not a folder")
        if not any(os.path.exists(os.path.join(self.folder, f))
                   for f in ("run.log", "series.csv", "series.csv.partial")):
            raise RunReadError(f"{self.folder}: not a run folder (no run.log, no series.csv)")

    def _path(self, name: str) -> str:
        return os.path.join(self.folder, name)

    @property
    def complete(self) -> bool:
        """True once the run reached its duration (series.csv.partial renamed series.csv)."""
        return os.path.exists(self._path("series.csv"))

    @property
    def series(self) -> Dict[str, np.ndarray]:
        """series.csv as NumPy arrays by column name (time, step, dt, the energy ledger, then
        per driven body B: B_fx, B_fy, B_x, B_y). While the run goes: the rows written so far
        (series.csv.partial)."""
        for name in ("series.csv", "series.csv.partial"):
            if os.path.exists(self._path(name)):
                return read_csv_columns(self._path(name))
        raise RunReadError(f"{self.folder}: no series.csv (nor series.csv.partial)")

    @property
    def parameters(self) -> Dict[str, Any]:
        """The scenario as resolved, read from run.log (``parse_run_log``)."""
        return parse_run_log(self._path("run.log"))

    @property
    def summary(self) -> Optional[Dict[str, Any]]:
        """analysis/summary.json (written by ``softgrain analyze``) as a dict, its units
        included as written; None if the run has not been analysed."""
        path = self._path(os.path.join("analysis", "summary.json"))
        if not os.path.exists(path):
            return None
        try:
            with open(path, encoding="utf-8") as file:
                return json.load(file)
        except (OSError, ValueError) as error:
            raise RunReadError(f"{path}: {error}") from error

    def _snapshots(self, collection: str) -> List[tuple]:
        path = self._path(collection)
        return read_pvd(path) if os.path.exists(path) else []

    @property
    def times(self) -> np.ndarray:
        """Times of the field snapshots written so far (fields.pvd)."""
        return np.array([t for t, _ in self._snapshots("fields.pvd")], dtype=np.float64)

    def _entry(self, collection: str, index: int) -> str:
        entries = self._snapshots(collection)
        if not -len(entries) <= index < len(entries):
            raise IndexError(f"{self.folder}: snapshot {index} of {collection}, which lists "
                             f"{len(entries)}")
        return entries[index][1]

    def fields(self, index: int) -> Dict[str, np.ndarray]:
        """Snapshot ``index`` of fields.pvd (negative: from the end): ``points`` (n, 2), the
        cells (``connectivity``, ``offsets``, ``types``) and every nodal array by name
        (displacement and velocity (n, 3), von_mises, pressure, strain_rate, body_id, ...)."""
        return read_vtu(self._entry("fields.pvd", index))

    def contacts(self, index: int) -> Dict[str, np.ndarray]:
        """Snapshot ``index`` of contacts.pvd: one point per contact with its arrays (force,
        gap, rates, ...), as ``fields``. Raises RunReadError for a run without contacts."""
        if not os.path.exists(self._path("contacts.pvd")):
            raise RunReadError(f"{self.folder}: no contacts.pvd (a run without contact laws)")
        return read_vtu(self._entry("contacts.pvd", index))

    def grains(self, index: int) -> Dict[str, np.ndarray]:
        """grains/NNNNNN.csv of snapshot ``index``: per body its index ``body``, centre of
        mass ``x``, ``y``, velocity ``vx``, ``vy`` and ``area``."""
        vtu = os.path.basename(self._entry("fields.pvd", index))
        path = self._path(os.path.join("grains", os.path.splitext(vtu)[0] + ".csv"))
        columns = read_csv_columns(path)
        if "body" in columns:
            columns["body"] = columns["body"].astype(np.int64)
        return columns

    def __repr__(self) -> str:
        state = "complete" if self.complete else "incomplete"
        return f"softgrain.Run({self.folder!r}, {state}, {len(self.times)} snapshots)"


def open_run(folder: str | os.PathLike) -> Run:
    """Opens a run folder for reading (see ``Run``)."""
    return Run(folder)
