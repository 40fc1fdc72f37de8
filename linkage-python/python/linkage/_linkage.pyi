"""Type stubs of the extension module `linkage._linkage` (re-exported by
`linkage`)."""

from os import PathLike
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

Values = Union[float, Sequence[float], npt.NDArray[np.float64]]

SIZES: list[tuple[int, int]]

class Pose:
    """A pose with its velocities and accelerations."""

    u: npt.NDArray[np.float64]
    udot: npt.NDArray[np.float64]
    uddot: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    vdot: npt.NDArray[np.float64]
    vddot: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    point_velocities: npt.NDArray[np.float64]
    point_accelerations: npt.NDArray[np.float64]
    residual: float
    rcond: float
    iterations: int
    u_names: list[str]
    v_names: list[str]
    point_names: list[str]
    def __getitem__(self, name: str) -> Union[float, npt.NDArray[np.float64]]: ...

class Sweep:
    """The poses of a sweep, one row per pose."""

    v: npt.NDArray[np.float64]
    vdot: npt.NDArray[np.float64]
    u: npt.NDArray[np.float64]
    udot: npt.NDArray[np.float64]
    uddot: npt.NDArray[np.float64]
    rcond: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    point_velocities: npt.NDArray[np.float64]
    point_accelerations: npt.NDArray[np.float64]
    events: list[dict[str, Any]]
    complete: bool
    u_names: list[str]
    v_names: list[str]
    point_names: list[str]
    def __len__(self) -> int: ...
    def __getitem__(self, name: str) -> npt.NDArray[np.float64]: ...

class Sensitivities:
    """The exact derivatives of a pose by the parameters."""

    u: npt.NDArray[np.float64]
    udot: npt.NDArray[np.float64]
    uddot: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    point_velocities: npt.NDArray[np.float64]
    point_accelerations: npt.NDArray[np.float64]
    parameter_names: list[str]
    u_names: list[str]
    point_names: list[str]

class Designs:
    """The certified designs of a synthesis, best first."""

    parameters: npt.NDArray[np.float64]
    parameter_names: list[str]
    free: list[str]
    rms_error: npt.NDArray[np.float64]
    largest_error: npt.NDArray[np.float64]
    start: list[int]
    drivers: npt.NDArray[np.float64]
    errors: npt.NDArray[np.float64]
    poses: npt.NDArray[np.float64]
    certified_from: npt.NDArray[np.float64]
    certified_to: npt.NDArray[np.float64]
    transmission: npt.NDArray[np.float64]
    transmission_at: npt.NDArray[np.float64]
    starts: int
    failed_starts: int
    refused: int
    def __len__(self) -> int: ...
    def design(self, k: int) -> Mechanism: ...

class Mechanism:
    """A planar mechanism made at run time."""

    @staticmethod
    def from_text(
        equations: str, parameters: Mapping[str, float], name: str = "Mechanism"
    ) -> Mechanism: ...
    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> Mechanism: ...
    @staticmethod
    def from_toml(text: str, name: str = "<text>") -> Mechanism: ...
    @staticmethod
    def from_topology(text: str, name: str = "<topology>") -> Mechanism: ...
    @staticmethod
    def from_pyslvs(
        expression: str, inputs: Sequence[tuple[int, int]], name: str = "Mechanism"
    ) -> Mechanism: ...
    @staticmethod
    def from_pylinkage(linkage: Union[str, Mapping[str, Any]]) -> Mechanism: ...
    @property
    def name(self) -> str: ...
    @property
    def m(self) -> int: ...
    @property
    def f(self) -> int: ...
    @property
    def u_names(self) -> list[str]: ...
    @property
    def v_names(self) -> list[str]: ...
    @property
    def point_names(self) -> list[str]: ...
    @property
    def parameters(self) -> dict[str, float]: ...
    @property
    def drive(self) -> Optional[dict[str, dict[str, float]]]: ...
    @property
    def file_text(self) -> Optional[str]: ...
    @property
    def topology_text(self) -> Optional[str]: ...
    def set_parameter(self, name: str, value: float) -> None: ...
    def with_parameters(self, **values: float) -> Mechanism: ...
    def analyze(
        self,
        v: Optional[Values] = None,
        vdot: Optional[Values] = None,
        vddot: Optional[Values] = None,
        u: Optional[Values] = None,
    ) -> Pose: ...
    def sensitivities(
        self,
        v: Optional[Values] = None,
        vdot: Optional[Values] = None,
        vddot: Optional[Values] = None,
        u: Optional[Values] = None,
        params: Optional[Sequence[str]] = None,
    ) -> Sensitivities: ...
    def sweep(
        self,
        steps: Optional[int] = None,
        start: Optional[Values] = None,
        stop: Optional[Values] = None,
        rate: Optional[Values] = None,
        u: Optional[Values] = None,
    ) -> Sweep: ...
    def extremes(
        self,
        quantities: Optional[Sequence[str]] = None,
        zeros: bool = False,
        steps: Optional[int] = None,
        start: Optional[Values] = None,
        stop: Optional[Values] = None,
        rate: Optional[Values] = None,
        u: Optional[Values] = None,
    ) -> list[dict[str, Any]]: ...
    def tolerance(
        self,
        tolerances: Mapping[str, Union[float, tuple[str, float]]],
        quantities: Optional[Sequence[str]] = None,
        samples: int = 0,
        random_state: int = 1,
        steps: Optional[int] = None,
        start: Optional[Values] = None,
        stop: Optional[Values] = None,
        rate: Optional[Values] = None,
        u: Optional[Values] = None,
    ) -> dict[str, Any]: ...
    def synthesize(
        self,
        *,
        free: Mapping[str, tuple[float, float]],
        targets: Any,
        path: Optional[str] = None,
        function: Optional[str] = None,
        timing: str = "free",
        drivers: Optional[Values] = None,
        precision_points: bool = False,
        starts: int = 64,
        random_state: int = 1,
        first: int = 0,
        distinct: bool = True,
        enough: Optional[int] = None,
        min_transmission: Optional[float] = None,
        at: Optional[float] = None,
        none_is_error: bool = True,
    ) -> Designs: ...
    def assemble(self, v: Optional[Values] = None) -> npt.NDArray[np.float64]: ...
    def svg(self, width: float = 640.0) -> str: ...
    def _repr_svg_(self) -> Optional[str]: ...
