"""A dict of scenario keys written as TOML text (Scenario.from_dict reads the dict through it).

Written here rather than with toml++'s formatter, which prints every float with 17
significant digits (0.14999999999999999 for 0.15): Python's repr of a float is the shortest
text that reads back as the same double, so the text is both exact and as a person writes it.
The layout is the scenario files': plain keys first, then each table ([shear_cell]), then
each array of tables ([[materials]]), keys in the dict's order; a table inside an array of
tables follows its element ([grains.drive] after [[grains]]), as TOML defines.
"""

from __future__ import annotations

import json
import math
import os
import re
from typing import Any, Dict, List

__all__ = ["dumps"]

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def dumps(d: Dict[str, Any]) -> str:
    """The TOML text of `d` (keys are strings; values numbers, strings, booleans, lists,
    dicts, NumPy values or paths). Raises TypeError naming the key of a value TOML cannot
    hold."""
    lines: List[str] = []
    _table(lines, d, [])
    return "\n".join(lines).lstrip("\n") + "\n"


def _key(key: Any, where: List[str]) -> str:
    if not isinstance(key, str):
        raise TypeError(f"scenario keys are strings; got {key!r}"
                        + (f" in '{where[0]}'" if where else ""))
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key, ensure_ascii=False)


def _plain(value: Any) -> Any:
    """NumPy values as Python ones, paths as strings."""
    if hasattr(value, "__fspath__"):
        return os.fspath(value)
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        return value.tolist()
    return value


def _is_array_of_tables(value: Any) -> bool:
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(
        isinstance(_plain(v), dict) for v in value)


def _value(value: Any, where: str) -> str:
    value = _plain(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # JSON's escapes are TOML's
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_key(k, [where])} = {_value(v, f'{where}.{k}')}"
                               for k, v in value.items()) + "}"
    raise TypeError(f"scenario key '{where}': a {type(value).__name__} cannot be written in "
                    "TOML (numbers, strings, booleans, lists and dicts can)")


def _table(lines: List[str], d: Dict[str, Any], path: List[str], where: str = "") -> None:
    """Writes table `d`, whose header path is `path` (keys, for [a.b] headers); `where` names
    it in messages (materials[1])."""
    if not isinstance(d, dict):
        raise TypeError(f"'{where}': expected a dict, got {type(d).__name__}")
    later = []
    for key, value in d.items():
        name = _key(key, [where] if where else [])
        full = f"{where}.{key}" if where else key
        plain = _plain(value)
        if isinstance(plain, dict) or _is_array_of_tables(plain):
            later.append((name, full, plain))
        else:
            lines.append(f"{name} = {_value(value, full)}")
    for name, full, value in later:
        header = ".".join(path + [name])
        if isinstance(value, dict):
            lines += ["", f"[{header}]"]
            _table(lines, value, path + [name], full)
        else:
            for index, item in enumerate(value):
                lines += ["", f"[[{header}]]"]
                _table(lines, _plain(item), path + [name], f"{full}[{index}]")
