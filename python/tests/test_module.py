"""The package itself: its version is the command line's, it ships its type stubs, and every
public name carries a docstring."""

import inspect
import pathlib
import re
import subprocess

import softgrain
from conftest import REPOSITORY


def test_version_is_the_project_version():
    cmake = (REPOSITORY / "CMakeLists.txt").read_text()
    version = re.search(r"project\(softgrain VERSION (\S+)", cmake).group(1)
    assert softgrain.__version__ == version


def test_version_matches_the_command_line(cli):
    # The command line has no --version yet on every branch: when it has, they must agree.
    done = subprocess.run([cli, "--version"], capture_output=True, text=True)
    if done.returncode == 0:
        assert softgrain.__version__ in done.stdout


def test_stubs_ship_with_the_package():
    folder = pathlib.Path(softgrain.__file__).parent
    for name in ("__init__.pyi", "_softgrain.pyi", "py.typed"):
        assert (folder / name).exists(), name
    stub = (folder / "_softgrain.pyi").read_text()
    for name in ("class Scenario", "class Simulation", "def from_dict", "def run(",
                 "def checkpoint", "def nodes", "def energy"):
        assert name in stub


def public_members(obj):
    inherited = set(dir(Exception)) if issubclass(obj, Exception) else set()
    for name, member in inspect.getmembers(obj):
        if not name.startswith("_") and name not in inherited:
            yield name, member


def test_every_public_name_has_a_docstring():
    missing = []
    for name in softgrain.__all__:
        obj = getattr(softgrain, name)
        if isinstance(obj, (str, list)):
            continue
        if not (obj.__doc__ or "").strip():
            missing.append(name)
        if inspect.isclass(obj):
            for member_name, member in public_members(obj):
                if not (getattr(member, "__doc__", "") or "").strip():
                    missing.append(f"{name}.{member_name}")
    assert not missing, missing
