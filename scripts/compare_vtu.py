#!/usr/bin/env python3
"""Compares the .vtu files of two run folders by their decoded arrays (scripts/compare-runs.sh).

    /usr/bin/python3 scripts/compare_vtu.py OLD_RUN_FOLDER NEW_RUN_FOLDER

For every fields/*.vtu and contacts/*.vtu (the same file names on both sides): the same
points and cells, the same arrays in the same order (name, type, components), and the same
values. A value written as text by an executable older than [output] field_format (9
significant digits, the only encoding it had) equals the other side's double rounded to 9
significant digits (printf's %.9g, as that writer's std::setprecision(9)); any other pair of
values must be equal exactly. Binary arrays (zlib-compressed appended data,
src/io/vtu_document.h) are decoded first. Standard library only. Prints each difference (up to
10) and exits 1 if there is any.
"""

import glob
import os
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib

_FORMATS = {"Float64": "d", "Float32": "f", "Int32": "i", "Int64": "q", "UInt8": "B"}


def _appended_bytes(data, begin, offset):
    at = begin + offset
    blocks, block_size, last_size = struct.unpack_from("<3Q", data, at)
    sizes = struct.unpack_from(f"<{blocks}Q", data, at + 24)
    at += 24 + 8 * blocks
    out = []
    for packed in sizes:
        out.append(zlib.decompress(data[at:at + packed]))
        at += packed
    return b"".join(out)


def read_arrays(path):
    """[(section, name, type, components, values)] of a .vtu, values as text tokens (ASCII)
    or numbers (binary), and the Piece's counts."""
    with open(path, "rb") as file:
        data = file.read()
    start = data.find(b"<AppendedData")
    root = ElementTree.fromstring(data if start < 0 else data[:start] + b"</VTKFile>")
    begin = data.index(b"_", start) + 1 if start >= 0 else None
    piece = root.find("UnstructuredGrid/Piece")
    arrays = []
    for section in ("Points", "Cells", "PointData"):
        for element in piece.findall(f"{section}/DataArray"):
            kind = element.get("type")
            if element.get("format") == "appended":
                raw = _appended_bytes(data, begin, int(element.get("offset")))
                code = _FORMATS[kind]
                values = list(struct.unpack(f"<{len(raw) // struct.calcsize(code)}{code}", raw))
            else:
                values = (element.text or "").split()
            arrays.append((section, element.get("Name"), kind,
                           element.get("NumberOfComponents", "1"), values))
    return (piece.get("NumberOfPoints"), piece.get("NumberOfCells")), arrays


def same_value(a, b):
    """a, b: a number or a text token. Text against a number: exact, or the old writer's 9
    significant digits; text against text: the same token."""
    if isinstance(a, str) and isinstance(b, str):
        return a == b
    if isinstance(a, str):
        a, b = b, a
    if not isinstance(b, str):
        return a == b or (a != a and b != b)  # NaN on both sides is the same
    token = float(b)
    if token != token:
        return a != a
    return float(a) == token or float(f"{a:.9g}") == token


def compare_file(old, new, report):
    old_counts, old_arrays = read_arrays(old)
    new_counts, new_arrays = read_arrays(new)
    if old_counts != new_counts:
        report(f"{new}: points/cells {new_counts}, old {old_counts}")
        return
    if [a[:4] for a in old_arrays] != [a[:4] for a in new_arrays]:
        report(f"{new}: arrays {[a[:4] for a in new_arrays]}, old {[a[:4] for a in old_arrays]}")
        return
    for (section, name, _, _, a), (_, _, _, _, b) in zip(old_arrays, new_arrays):
        if len(a) != len(b):
            report(f"{new}: {section} {name}: {len(b)} values, old {len(a)}")
            continue
        for i, (x, y) in enumerate(zip(a, b)):
            if not same_value(x, y):
                report(f"{new}: {section} {name}[{i}]: {y}, old {x}")
                break


def main(old_run, new_run):
    differences = []
    for folder in ("fields", "contacts"):
        old_files = sorted(os.path.basename(p) for p in glob.glob(f"{old_run}/{folder}/*.vtu"))
        new_files = sorted(os.path.basename(p) for p in glob.glob(f"{new_run}/{folder}/*.vtu"))
        if old_files != new_files:
            differences.append(f"{folder}/: files {new_files}, old {old_files}")
            continue
        for name in new_files:
            compare_file(f"{old_run}/{folder}/{name}", f"{new_run}/{folder}/{name}",
                         differences.append)
    for line in differences[:10]:
        print("  " + line)
    return 1 if differences else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
