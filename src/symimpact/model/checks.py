"""Arguments of the public functions checked as the command line checks its options: a wrong type
or value is a :class:`~symimpact.errors.ParameterError` naming the argument, never Python's own
TypeError, AttributeError or ValueError from deep inside a computation.

Numbers go through :mod:`symimpact.model.units` (quantities with units accepted where a physical value
is); these add what is not a unit's business: whole numbers, choices, flags, states and the
model's own objects.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import ParameterError
from .units import si_float


def whole_number(name: str, value: Any, low: int = 0, high: int | None = None) -> int:
    """``value`` as an int in [low, high]: an int, or a float with no fraction (2.0); a bool, a
    string, a fraction (1.5) or a non-number is refused."""
    if isinstance(value, (bool, np.bool_)) or isinstance(value, str):
        raise ParameterError(name, f"must be a whole number, got {value!r}")
    if isinstance(value, (int, np.integer)):
        v = int(value)
    else:
        try:
            f = float(value)
        except (TypeError, ValueError, OverflowError):
            raise ParameterError(name, f"must be a whole number, got {value!r}") from None
        if not np.isfinite(f) or f != int(f):
            raise ParameterError(name, f"must be a whole number, got {value!r}")
        v = int(f)
    if v < low or (high is not None and v > high):
        span = f"{low} to {high}" if high is not None else f"≥ {low}"
        raise ParameterError(name, f"must be a whole number {span}, got {v}")
    return v


def flag(name: str, value: Any) -> bool:
    """``value`` as a bool: True or False only (not 0, 1 or "yes")."""
    if not isinstance(value, (bool, np.bool_)):
        raise ParameterError(name, f"must be True or False, got {value!r}")
    return bool(value)


def choice(name: str, value: Any, options: tuple[Any, ...]) -> Any:
    """``value`` if it is one of ``options`` (compared by equality, types kept)."""
    try:
        ok = any(value == o and type(value) is type(o) for o in options)
    except Exception:  # an array compared with a scalar, an object without ==
        ok = False
    if not ok:
        raise ParameterError(name, f"must be one of {', '.join(map(repr, options))}, got {value!r}")
    return value


def bounded(name: str, value: Any, low: float | None = None, high: float | None = None,
            *, open_low: bool = False, unit: str | None = None) -> float:  # fmt: skip
    """A finite float (units read by :func:`symimpact.model.units.si_float`) in [low, high], or in
    (low, high] with ``open_low``."""
    v = si_float(name, value, unit)
    if low is not None and (v < low or (open_low and v == low)):
        raise ParameterError(
            name, f"must be {'above' if open_low else 'at least'} {low:g}, got {v:g}"
        )
    if high is not None and v > high:
        raise ParameterError(name, f"must be at most {high:g}, got {v:g}")
    return v


def state(name: str, value: Any, size: int = 4, what: str = "(x, ẋ, z, ẏ)") -> np.ndarray:
    """``size`` finite numbers (SI) as a float array."""
    if value is None or isinstance(value, (str, bytes, dict)):
        raise ParameterError(name, f"must be {size} finite numbers {what}, got {value!r}")
    try:
        s = np.array([si_float(name, c) for c in value], dtype=float)
    except TypeError:
        raise ParameterError(name, f"must be {size} finite numbers {what}, got {value!r}") from None
    if s.shape != (size,):
        raise ParameterError(name, f"must be {size} finite numbers {what}, got {len(s)}")
    return s


def numbers(name: str, value: Any) -> np.ndarray:
    """A sequence of finite numbers (SI; quantities with units accepted) as a 1-D float array."""
    if value is None or isinstance(value, (str, bytes, dict)) or np.ndim(value) != 1:
        raise ParameterError(name, f"must be a sequence of numbers, got {value!r}")
    try:
        return np.array([si_float(name, v) for v in value], dtype=float)
    except TypeError:
        raise ParameterError(name, f"must be a sequence of numbers, got {value!r}") from None


def bounds(name: str, value: Any, unit: str | None = None) -> tuple[float, float]:
    """(low, high): two finite numbers with low < high (quantities read in ``unit`` where it is
    given, :func:`symimpact.model.units.si_float`)."""
    if value is None or isinstance(value, (str, bytes, dict)):
        raise ParameterError(name, f"must be (low, high), got {value!r}")
    try:
        parts = list(value)
    except TypeError:
        raise ParameterError(name, f"must be (low, high), got {value!r}") from None
    if len(parts) != 2:
        raise ParameterError(name, f"must be (low, high), got {len(parts)} values")
    lo, hi = (si_float(name, p, unit) for p in parts)
    if not lo < hi:
        raise ParameterError(name, f"must have low < high, got {lo:g}, {hi:g}")
    return lo, hi


def instance(name: str, value: Any, cls: type, what: str) -> Any:
    """``value`` if it is a ``cls`` (one of the package's objects), else refused naming ``what``
    to build."""
    if not isinstance(value, cls):
        raise ParameterError(name, f"must be {what}, got {type(value).__name__}")
    return value
