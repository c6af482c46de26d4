"""Type stubs of the package softgrain (docs/python.md)."""

import os
from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Union, overload

from ._softgrain import ENERGY_FIELDS as ENERGY_FIELDS
from ._softgrain import Scenario as Scenario
from ._softgrain import Simulation as Simulation
from ._softgrain import __version__ as __version__
from .campaign import read_campaign as read_campaign
from .campaign import submit_scenarios as submit_scenarios
from .errors import Error as Error
from .errors import ScenarioError as ScenarioError
from .run_reader import Run as Run
from .run_reader import RunReadError as RunReadError
from .run_reader import open_run as open_run

def resume(checkpoint: Union[str, "os.PathLike[str]"], scenario: Optional[Scenario] = None, *,
           threads: int = 0, output: Optional[Union[str, "os.PathLike[str]"]] = None,
           progress: bool = False) -> Simulation:
    """Continues a run from a checkpoint file; returns a new Simulation."""

_Path = Union[str, "os.PathLike[str]"]

@overload
def run_scenarios(scenarios: Sequence[Scenario], output: _Path, *, parallel: int = 1,
                  threads: int = 1, on_finished: Optional[Callable[[dict], None]] = None,
                  slurm: None = None, executable: Optional[_Path] = None,
                  dry_run: Literal[False] = False) -> List[Dict[str, Any]]:
    """Runs scenarios locally through the campaign's process queue; one outcome dict per
    scenario (name, directory, success, exit_code, signal, seconds)."""

@overload
def run_scenarios(scenarios: Sequence[Scenario], output: _Path, *, parallel: int = 1,
                  threads: int = 1, on_finished: Optional[Callable[[dict], None]] = None,
                  slurm: Dict[str, Any], executable: Optional[_Path] = None,
                  dry_run: bool = False) -> Dict[str, Any]:
    """Submits scenarios to Slurm as one campaign (softgrain sweep --slurm); returns job_id,
    campaign, folder, runs (run folder by scenario name) and output."""
