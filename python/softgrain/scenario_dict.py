"""The dict side of softgrain.Scenario: from_dict and to_dict, attached to the compiled class
by the package (softgrain/__init__.py).

A dict goes through TOML text (softgrain.toml_writer) and the command line's reader
(Scenario.from_toml, load_scenario in C++): the same checks, the same messages, and an error's
line is a line of the text to_toml() returns. to_dict() reads that text back with Python's
own TOML reader (tomllib).
"""

from __future__ import annotations

import os
import tomllib
from typing import Any, Dict, Optional

from ._softgrain import Scenario
from .toml_writer import dumps

__all__ = ["from_dict", "to_dict"]


def from_dict(d: Dict[str, Any], base_dir: Optional[str | os.PathLike] = None) -> Scenario:
    """A scenario from a dict with the keys of the TOML file (nested dicts for tables, lists
    of dicts for arrays of tables). ``name`` defaults to 'scenario'; relative file keys
    resolve against ``base_dir`` (default: the working folder). Errors raise
    softgrain.ScenarioError whose ``file`` is '<dict>' and ``line`` a line of the text
    ``to_toml()`` gives for this dict; a value TOML cannot hold raises TypeError."""
    if not isinstance(d, dict):
        raise TypeError(f"from_dict: expected a dict, got {type(d).__name__}")
    if "name" not in d:
        d = {"name": "scenario", **d}
    return Scenario.from_toml(dumps(d), base_dir)


def to_dict(self: Scenario) -> Dict[str, Any]:
    """The scenario's keys as a new dict (change it and pass it to from_dict)."""
    return tomllib.loads(self.to_toml())
