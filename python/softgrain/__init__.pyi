"""Type stubs of the package softgrain (docs/python.md)."""

import os
from typing import Optional, Union

from ._softgrain import ENERGY_FIELDS as ENERGY_FIELDS
from ._softgrain import Scenario as Scenario
from ._softgrain import Simulation as Simulation
from ._softgrain import __version__ as __version__
from .campaign import read_campaign as read_campaign
from .campaign import run_scenarios as run_scenarios
from .errors import Error as Error
from .errors import ScenarioError as ScenarioError
from .run_reader import Run as Run
from .run_reader import RunReadError as RunReadError
from .run_reader import open_run as open_run

def resume(checkpoint: Union[str, "os.PathLike[str]"], scenario: Optional[Scenario] = None, *,
           threads: int = 0, output: Optional[Union[str, "os.PathLike[str]"]] = None,
           progress: bool = False) -> Simulation:
    """Continues a run from a checkpoint file; returns a new Simulation."""
