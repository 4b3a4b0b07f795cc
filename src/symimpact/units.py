"""Units at the boundary: plain SI numbers or quantities with units, turned into SI floats.

Every public entry point passes its parameters through :func:`si`, so ``"100 N/cm"``,
``"7.5 cm/s"``, ``"9 mm"``, ``"1000 N/m^1.5"`` or a :mod:`pint` quantity are accepted wherever a
number in SI units is.  pint is imported only when a value carries units, so the numeric core and
``import symimpact`` never pay for it.
"""

from __future__ import annotations

from decimal import Decimal
from functools import lru_cache
from typing import Any

import numpy as np

from .errors import ParameterError

#: SI unit of every named parameter (what a plain number means).
SI_UNITS: dict[str, str] = {
    "M": "kg",
    "m": "kg",
    "K": "N/m",
    "C": "N*s/m",
    "c1": "N*s/m",
    "zeta": "dimensionless",
    "gap": "m",
    "a": "N/m^3",
    "b": "N/m",
    "k1": "N/m",
    "k_hz": "N/m^1.5",
    "delta_max": "m",
    "x0": "m",
    "y0": "m",
    "xdot0": "m/s",
    "ydot0": "m/s",
    "v0": "m/s",
    "t_end": "s",
    "E": "Pa",
    "I": "m^4",
    "rho": "kg/m^3",
    "A": "m^2",
    "L": "m",
    "position": "m",
    "restitution": "dimensionless",
    "ba": "dimensionless",
    "mass_ratio": "dimensionless",
}


@lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def _to_si(name: str, value: Any, unit: str) -> Any:
    ureg = _registry()
    import pint

    try:
        q = ureg.Quantity(value) if isinstance(value, str) else value
    except Exception as exc:  # pint's parser raises assorted error types on malformed text
        raise ParameterError(name, f"cannot read {value!r} as a quantity ({exc})") from None
    if not isinstance(q, ureg.Quantity):
        raise ParameterError(name, f"cannot read {value!r} as a quantity")
    try:
        factor = ureg.Quantity(1.0, q.units).to(unit).magnitude
    except pint.errors.DimensionalityError:
        raise ParameterError(
            name, f"{value!r} has dimension {q.dimensionality}, expected units of {unit}"
        ) from None
    # Multiply in decimal the shortest representations of magnitude and factor, so a value
    # written with a prefix gives the float of the SI number typed by hand: "9 mm" is 0.009 and
    # "0.1553 N/cm^3" is 155300.0, not 0.009000000000000001 and 155299.99999999997.
    exact = Decimal(f"{float(factor):.15g}")  # pint computes 1/0.01³ as 999999.9999999999
    scaled = np.vectorize(lambda v: float(Decimal(repr(float(v))) * exact), otypes=[float])
    return scaled(np.asarray(q.magnitude, dtype=float))


def si(name: str, value: Any, unit: str | None = None) -> Any:
    """Parameter ``name`` as an SI float (or float array), checked to be finite.

    ``value`` is a number, an array, a string with units or a pint quantity; ``unit`` defaults to
    the parameter's entry in :data:`SI_UNITS`.  Raises :class:`ParameterError` naming ``name`` for
    a malformed unit, a wrong dimension, a non-numeric value, NaN or infinity.
    """
    if value is None:
        raise ParameterError(name, "is required")
    unit = unit or SI_UNITS.get(name, "dimensionless")
    if isinstance(value, str):
        try:
            value = float(value)  # a bare number written as text means SI
        except ValueError:
            value = _to_si(name, value, unit)
    elif hasattr(value, "dimensionality"):
        value = _to_si(name, value, unit)
    if isinstance(value, bool):
        raise ParameterError(name, f"expected a number, got {value!r}")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(name, f"expected a number, got {value!r}") from None
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, f"must be finite, got {value!r}")
    return float(arr) if arr.ndim == 0 else arr


def positive(name: str, value: Any, unit: str | None = None) -> Any:
    """:func:`si`, then require every value > 0."""
    v = si(name, value, unit)
    if np.any(np.asarray(v) <= 0):
        raise ParameterError(name, f"must be positive, got {_show(v)}")
    return v


def nonnegative(name: str, value: Any, unit: str | None = None) -> Any:
    """:func:`si`, then require every value ≥ 0."""
    v = si(name, value, unit)
    if np.any(np.asarray(v) < 0):
        raise ParameterError(name, f"must not be negative, got {_show(v)}")
    return v


def _show(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:g}"
    arr = np.asarray(v)
    bad = arr.ravel()
    return f"array with min {bad.min():g}" if bad.size else "an empty array"
