"""The exceptions linkage raises: one base, `LinkageError`, and a class for
each way an analysis or an input can fail. Their messages are the Rust
library's, word for word."""


class LinkageError(Exception):
    """Every error linkage raises."""


class MistakesError(LinkageError, ValueError):
    """A mechanism's text (a mechanism file, a topology, the equations) has
    mistakes; the message shows every one, located by line and column."""


class BadInputError(LinkageError, ValueError):
    """An argument is out of its range: a NaN or an infinity, the wrong
    number of values, an unknown name, a setting out of range."""


class SingularPoseError(LinkageError):
    """Ψ_u is singular (or too ill-conditioned to solve with) at the pose:
    a dead centre, a limit position, a change point."""


class NotConvergedError(LinkageError):
    """Newton–Raphson used its iterations without meeting its tolerances."""


class CannotAssembleError(LinkageError):
    """The mechanism cannot be assembled at the drivers' values: its links
    cannot close."""


class NoDesignError(LinkageError):
    """A synthesis certified no design: a target out of reach, or every
    candidate refused (the message gives the closest one's reason)."""


class SizeError(LinkageError):
    """The mechanism's sizes (m, f), or the parameters asked for, are more
    than this build analyses at run time (see `linkage.SIZES`)."""


class AnalysisError(LinkageError):
    """An analysis failed otherwise: values outside the equations' domain,
    numbers too small for f64, a drive whose assembly does not reach its
    start."""


class FileError(LinkageError, OSError):
    """A file could not be read, or is not the kind asked for."""


class FileMissingError(FileError, FileNotFoundError):
    """The file named is not there."""


class FormatError(LinkageError, ValueError):
    """Another tool's mechanism (pyslvs's expression, pylinkage's JSON)
    could not be read or represented."""
