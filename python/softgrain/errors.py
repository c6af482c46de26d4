"""The exceptions of the softgrain module.

Every error the engine reports (a C++ ``sg::Error``, src/core/error.h) reaches Python as a
``softgrain.Error``; one that names a place in a scenario (``file:line: key 'k': message``,
the form src/scenario/toml_reader.h gives every scenario error, or ``file:line:column:
TOML syntax error: ...``) as a ``softgrain.ScenarioError`` carrying those parts, so that a
program can point at the line without parsing the text.
"""

from __future__ import annotations

import re
from typing import Optional

__all__ = ["Error", "ScenarioError", "error_from_message"]


class Error(Exception):
    """An error softgrain reports: bad input, a diverging run, an unreadable file.

    ``message`` is the engine's whole message (also ``str(error)``).
    """

    def __init__(self, message: str):
        super().__init__(message)
        self.message = message


class ScenarioError(Error, ValueError):
    """An error in a scenario, with its place.

    Attributes: ``file`` (the scenario file, or ``<dict>`` for ``Scenario.from_dict``),
    ``line`` (1-based; for a scenario built from a dict, the line of ``to_toml()``'s text),
    ``column`` (syntax errors only, else None), ``key`` (the full key, ``materials[1].poisson``,
    or None for a syntax error) and ``detail`` (what was expected).
    """

    def __init__(self, message: str, file: str, line: int, column: Optional[int],
                 key: Optional[str], detail: str):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.detail = detail


# "<file>:<line>: key '<key>': <detail>" and "<file>:<line>:<column>: <detail>" (syntax).
_KEY_ERROR = re.compile(r"^(?P<file>.+?):(?P<line>\d+): key '(?P<key>[^']*)': (?P<detail>.*)$",
                        re.DOTALL)
_SYNTAX_ERROR = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<column>\d+): (?P<detail>.*)$",
                           re.DOTALL)


def error_from_message(message: str) -> Error:
    """The exception for an engine message: a ScenarioError when it names a scenario place,
    else an Error. (Called by the compiled module's exception translator.)"""
    match = _KEY_ERROR.match(message)
    if match:
        return ScenarioError(message, match["file"], int(match["line"]), None, match["key"],
                             match["detail"])
    match = _SYNTAX_ERROR.match(message)
    if match:
        return ScenarioError(message, match["file"], int(match["line"]), int(match["column"]),
                             None, match["detail"])
    return Error(message)
