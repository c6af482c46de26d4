"""Type stubs of the compiled module softgrain._softgrain (python/src/)."""

import os
from typing import Any, Callable, Dict, List, Optional, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, "os.PathLike[str]"]

__version__: str
ENERGY_FIELDS: List[str]

class Scenario:
    """A checked scenario (docs/scenario.md lists every key)."""

    @staticmethod
    def from_file(path: _Path) -> "Scenario":
        """Reads and checks a scenario file, as `softgrain run` does."""
    @staticmethod
    def from_dict(d: Dict[str, Any], base_dir: Optional[_Path] = None) -> "Scenario":
        """A scenario from a dict with the keys of the TOML file; name defaults to
        'scenario'; relative file keys resolve against base_dir."""
    @staticmethod
    def from_toml(text: str, base_dir: Optional[_Path] = None) -> "Scenario":
        """A scenario from TOML text."""
    def to_dict(self) -> Dict[str, Any]:
        """The scenario's keys as a new dict."""
    def to_toml(self) -> str:
        """The scenario as TOML text; from_toml of it builds the same model."""
    def info(self, timing: bool = True) -> Dict[str, Any]:
        """What `softgrain info` prints, as a dict (builds the model); with timing and a
        damped body, 'integrators': each integrator's stable step and measured cost;
        'integrator_choice': the integrator the run steps with (with the reason when [time]
        names none: docs/scenario.md "Integrators")."""
    @property
    def name(self) -> str:
        """The run name (the run folder is <output root>/<name>)."""
    @property
    def duration(self) -> float:
        """Simulated time."""
    @property
    def source(self) -> str:
        """The scenario file ('<dict>' for one built in memory)."""
    @property
    def base_dir(self) -> str:
        """The folder relative file keys resolve against."""

class Simulation:
    """A run of a scenario, stepped from Python (in memory, or writing the run folder
    exactly as `softgrain run` does)."""

    def __init__(self, scenario: Scenario, threads: int = 0, output: Optional[_Path] = None,
                 progress: bool = False) -> None:
        """Builds the model (and with an output root, the run folder and run.log)."""
    @staticmethod
    def resume(checkpoint: _Path, scenario: Optional[Scenario] = None, *, threads: int = 0,
               output: Optional[_Path] = None, progress: bool = False) -> "Simulation":
        """Continues a run from a checkpoint file (softgrain.resume)."""
    @staticmethod
    def _resume(checkpoint: _Path, scenario: Scenario, threads: int = 0,
                output: Optional[_Path] = None, progress: bool = False) -> "Simulation": ...
    def step(self) -> None:
        """One accepted step (the GIL released)."""
    def run(self, until: Optional[float] = None, every: int = 1,
            callback: Optional[Callable[["Simulation"], Optional[bool]]] = None) -> bool:
        """Steps until `until` (default: the duration), calling callback(sim) every `every`
        steps; a callback returning False stops the run (run() then returns False)."""
    def close(self) -> None:
        """Ends the run (final outputs if it reached its duration); idempotent."""
    def checkpoint(self, path: _Path) -> None:
        """Writes the state to `path` and the scenario to `path`.toml."""
    def __enter__(self) -> "Simulation":
        """The Simulation itself."""
    def __exit__(self, *args: Any) -> None:
        """close()."""
    @property
    def time(self) -> float:
        """Simulated time of the present state."""
    @property
    def step_count(self) -> int:
        """Steps taken since t = 0."""
    @property
    def dt(self) -> float:
        """The step the next step() takes."""
    @property
    def last_dt(self) -> float:
        """The last step taken (0 before the first)."""
    @property
    def duration(self) -> float:
        """The scenario's duration."""
    @property
    def reached_end(self) -> bool:
        """True once the run has reached its duration."""
    @property
    def closed(self) -> bool:
        """True once the run is closed."""
    @property
    def directory(self) -> Optional[str]:
        """The run folder, None without outputs."""
    @property
    def scenario(self) -> Scenario:
        """The scenario run."""
    @property
    def threads(self) -> int:
        """OpenMP threads asked for (0: OpenMP's count)."""
    @property
    def nodes(self) -> Dict[str, npt.NDArray[Any]]:
        """Read-only zero-copy views: ref_x, ref_y, ux, uy, vx, vy, fx, fy, mass (float64),
        body (int32)."""
    @property
    def rigid(self) -> Dict[str, npt.NDArray[Any]]:
        """Read-only zero-copy views: body (int32), x, y, theta, vx, vy, omega, fx, fy,
        torque (float64)."""
    @property
    def energy(self) -> np.ndarray:
        """Read-only zero-copy 0-d structured view of the energy ledger (ENERGY_FIELDS)."""
    @property
    def energy_residual(self) -> float:
        """The ledger's balance residual."""
    def node_positions(self) -> npt.NDArray[np.float64]:
        """Physical node positions (n, 2): a new array."""
    def node_velocities(self) -> npt.NDArray[np.float64]:
        """Physical node velocities (n, 2): a new array."""
    def bodies(self) -> Dict[str, Any]:
        """Per body (new arrays): name, rigid, x, y, vx, vy, theta."""
    def __repr__(self) -> str:
        """Name, time, step count, run folder (or 'in memory'), closed."""

def _run_process_queue(jobs: List[Any], parallel: int,
                       on_finished: Optional[Callable[[Dict[str, Any]], None]] = None) -> Any:
    """Runs jobs as child processes through the campaign's queue; (completed, outcomes)."""
