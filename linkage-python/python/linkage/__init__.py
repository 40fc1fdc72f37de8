"""linkage: planar mechanisms from their closure equations — exact
Jacobians, analyses, sweeps through singular poses — with NumPy arrays in
and out.

    >>> import linkage
    >>> bar = linkage.Mechanism.from_file("mechanisms/four_bar.toml")
    >>> pose = bar.analyze()            # at the file's drive
    >>> sweep = bar.sweep(steps=360)    # the whole turn

The errors it raises are in `linkage.errors`, all subclasses of
`LinkageError`.
"""

from . import errors, shards
from ._linkage import SIZES, Designs, Mechanism, Pose, Sensitivities, Sweep
from .errors import (
    AnalysisError,
    BadInputError,
    CannotAssembleError,
    FileError,
    FileMissingError,
    FormatError,
    LinkageError,
    MistakesError,
    NoDesignError,
    NotConvergedError,
    SingularPoseError,
    SizeError,
)

__all__ = [
    "SIZES",
    "Designs",
    "Mechanism",
    "Pose",
    "Sensitivities",
    "Sweep",
    "errors",
    "shards",
    "AnalysisError",
    "BadInputError",
    "CannotAssembleError",
    "FileError",
    "FileMissingError",
    "FormatError",
    "LinkageError",
    "MistakesError",
    "NoDesignError",
    "NotConvergedError",
    "SingularPoseError",
    "SizeError",
]
