"""The package's own errors: every one is a ``ValueError`` that names what went wrong."""

from __future__ import annotations

from collections.abc import Sequence


class SymimpactError(ValueError):
    """Base class of every error symimpact raises on bad input or an impossible request."""


#: Characters that break a line (str.splitlines), written as escapes in an error's one line.
_BREAKS = str.maketrans({c: repr(c)[1:-1] for c in "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"})


class ParameterError(SymimpactError):
    """A parameter is invalid: ``parameter`` names it, ``reason`` says why, in one line (a line
    break in either, e.g. a key of a user's file, is written as its escape: ``\\n``)."""

    def __init__(self, parameter: str, reason: str) -> None:
        self.parameter = parameter
        self.reason = reason
        super().__init__(f"{parameter}: {reason}".translate(_BREAKS))

    def __reduce__(self):  # rebuilt from its fields when it crosses a process boundary
        return (type(self), (self.parameter, self.reason))


class MethodNotApplicable(SymimpactError):
    """A method (e.g. a closed form) has no real answer for the given parameters."""

    def __init__(self, method: str, reason: str) -> None:
        self.method = method
        self.reason = reason
        super().__init__(f"method {method!r} does not apply: {reason}")

    def __reduce__(self):
        return (type(self), (self.method, self.reason))


class ConvergenceError(SymimpactError):
    """An iteration did not converge; ``history`` holds the last iterates."""

    def __init__(self, what: str, history: Sequence[float]) -> None:
        self.what = what
        self.history = list(history)
        tail = ", ".join(f"{v:.6g}" for v in self.history[-5:])
        super().__init__(f"{what} did not converge; last iterates: {tail}")

    def __reduce__(self):
        return (type(self), (self.what, self.history))
