# Type stubs of the Python module `limber` (docs/python.md), installed beside the module
# (limber.cpython-*.so) for editors and type checkers; the module's docstrings say the rest.
# tests/python/test_stubs.py checks that every public name, argument and default here is the
# module's, and the other way round.
import os
from typing import Any, Callable, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

_Path = str | os.PathLike[str]
_Floats = npt.NDArray[np.float64]

class CaseError(ValueError):
    """Bad input: a case file, a case dict or an argument limber cannot run."""
    file: str | None
    line: int | None
    column: int | None
    key_path: str | None

class Case:
    """A case read and checked: from load_case or case_from_dict, for run."""
    @property
    def file(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def bodies(self) -> list[str]: ...
    @property
    def joints(self) -> list[str]: ...
    @property
    def flexible_bodies(self) -> list[str]: ...

class BodyResults:
    """One body's series over the ns samples."""
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def position(self) -> _Floats: ...
    @property
    def orientation(self) -> _Floats: ...
    @property
    def modal_coordinates(self) -> _Floats | None: ...
    @property
    def modal_velocities(self) -> _Floats | None: ...
    @property
    def frequencies_hz(self) -> _Floats | None: ...
    @property
    def deflection(self) -> _Floats | None: ...
    @property
    def stress(self) -> dict[str, npt.NDArray[Any]] | None: ...

class JointResults:
    """One joint's reaction on body_j over the ns samples."""
    @property
    def name(self) -> str: ...
    @property
    def type(self) -> str: ...
    @property
    def body_i(self) -> str: ...
    @property
    def body_j(self) -> str: ...
    @property
    def position(self) -> _Floats: ...
    @property
    def force_ground(self) -> _Floats: ...
    @property
    def torque_ground(self) -> _Floats: ...
    @property
    def force_joint(self) -> _Floats: ...
    @property
    def torque_joint(self) -> _Floats: ...
    @property
    def indeterminate(self) -> npt.NDArray[np.bool_]: ...

class Results:
    """A run's results, from run or read_results."""
    @property
    def path(self) -> str | None: ...
    @property
    def status(self) -> str: ...
    @property
    def message(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def case_file(self) -> str: ...
    @property
    def integrator(self) -> str: ...
    @property
    def accuracy(self) -> dict[str, Any]: ...
    @property
    def time(self) -> _Floats: ...
    @property
    def steps(self) -> npt.NDArray[np.int64]: ...
    @property
    def bodies(self) -> dict[str, BodyResults]: ...
    @property
    def joints(self) -> dict[str, JointResults]: ...
    @property
    def drivers(self) -> dict[str, _Floats]: ...
    @property
    def energy(self) -> dict[str, _Floats]: ...
    @property
    def constraints(self) -> dict[str, Any]: ...
    @property
    def hinge_limits(self) -> dict[str, dict[str, Any]]: ...
    @property
    def events(self) -> dict[str, Any]: ...
    @property
    def acceleration_probes(self) -> dict[str, _Floats]: ...
    @property
    def event_peaks(self) -> dict[str, Any] | None: ...

def load_case(path: _Path) -> Case:
    """Reads and checks a case file; raises CaseError at file:line:col."""

def case_from_dict(d: dict[str, Any]) -> Case:
    """A case given as a dict; raises CaseError naming the key path."""

def read_results(path: _Path) -> Results:
    """Reads a results.h5 (or the folder that holds it)."""

def run(
    case_or_path: Case | _Path,
    *,
    integrator: str | None = None,
    step: float | None = None,
    rtol: float | None = None,
    t_end: float | None = None,
    output: _Path | None = None,
    progress: Callable[[float, float], object] | None = None,
    modes: int | None = None,
    formulation: str | None = None,
) -> Results:
    """Runs a mechanism as `limber run` does; results in memory unless output names a folder."""

def modes(case_or_path: Case | _Path, *, output: _Path | None = None) -> dict[str, Any]:
    """The flexible bodies' mode sets: what `limber modes --json` prints."""

def select(
    case_or_path: Case | _Path,
    *,
    output: _Path | None = None,
    keep: float = 0.1,
    target: float | None = None,
    rank_by: str = "peak",
    norm: str = "event",
    static_modes: str = "attachment",
    max_single: int | None = None,
    reference_normal: int = 0,
    keep_step: bool = False,
    whole_run: bool = False,
    max_refinement: int = 8,
    jobs: int = 2,
    integrator: str | None = None,
    step: float | None = None,
    rtol: float | None = None,
    t_end: float | None = None,
    progress: Callable[[float, float], object] | None = None,
    reference: str = "modal",
) -> dict[str, Any]:
    """The seed paper's mode selection: what `limber select --json` prints."""

def sweep(
    case_or_path: Case | _Path,
    *,
    over: Sequence[str],
    output: _Path | None = None,
    reference: str = "tight",
    target: float | None = None,
    norm: str = "rms",
    quantities: Sequence[str] = [],
    jobs: int = 0,
    fresh: bool = False,
    t_end: float | None = None,
    atol: float | None = None,
    max_wall: float | None = None,
    log: Callable[[str], object] | None = None,
) -> dict[str, Any]:
    """A grid of settings against a reference: what `limber sweep --json` prints."""
