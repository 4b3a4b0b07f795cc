"""Units at the boundary: plain SI numbers or quantities with units, turned into SI floats.

Every public entry point passes its parameters through :func:`si`, so ``"100 N/cm"``,
``"7.5 cm/s"``, ``"9 mm"``, ``"1000 N/m^1.5"`` or a :mod:`pint` quantity are accepted wherever a
number in SI units is.  pint is imported only when a value carries units, so the numeric core and
``import symimpact`` never pay for it.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal
from functools import lru_cache
from pathlib import Path
from typing import Any

from ..errors import ParameterError

#: SI unit of every named parameter (what a plain number means).
#: The unit of a one-sided acceleration PSD; "g^2/Hz" in it is standard gravity squared per hertz.
ACCELERATION_PSD = "(m/s^2)^2/Hz"

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
    "chi": "s/m",
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
    "F0": "N",
    "X_b": "m",
    "V_b": "m/s",
    "A_b": "m/s^2",
    "omega": "rad/s",
    "freq": "Hz",
    "phase": "rad",
    "e": "dimensionless",
    "periods": "dimensionless",
    "discard": "dimensionless",
    # range options of the command line, named as typed
    "omega-range": "rad/s",
    "freq-range": "Hz",
    "gaps": "m",
    "mass-ratios": "dimensionless",
}


#: SI values may not exceed the upper magnitude, and positive parameters (masses, stiffnesses,
#: the gap: scales and divisors) may not fall below the lower one.  The range holds every
#: physical input (an I of 1e-24 m^4 for a micro-beam, a cubic coefficient a of 1e18 N/m^3 for
#: steel) and keeps the closed forms, whose terms reach the 8th power of a parameter, clear of
#: overflow and underflow.
MAGNITUDE = (1e-30, 1e30)


@lru_cache(maxsize=1)
def _registry():
    """pint's unit registry, imported on first use.

    pint imports dask's graph machinery when dask is installed (it is, for the Dask executor):
    a quarter of a second of a command's start-up for nothing, since no quantity here holds a
    dask array.  So dask is hidden from pint's import check unless something already imported
    it."""
    import sys

    hide = "dask" not in sys.modules
    if hide:
        sys.modules["dask"] = None  # type: ignore[assignment]  # importlib then finds no dask
    try:
        import pint
    finally:
        if hide:
            del sys.modules["dask"]
    try:  # pint caches its parsed definitions on disk: 0.04 s instead of 0.2 s from the 2nd run
        ureg = pint.UnitRegistry(cache_folder=":auto:")
    except Exception:  # no writable cache folder, or a damaged cache file: parse every time
        ureg = pint.UnitRegistry()
    try:  # "rev/s", as on a tachometer (pint knows revolution, rpm and turn, not rev)
        ureg.define("rev = revolution")
    except Exception:  # a pint that defines it already
        pass
    return ureg


#: Characters read as a minus sign: the ASCII hyphen-minus and every Unicode minus or dash that
#: text copied from a PDF or a word processor carries in its place.
MINUS_SIGNS = "-\u2212\u2010\u2011\u2012\u2013\u2014\u2015\ufe58\ufe63\uff0d\u2796"
PLUS_SIGNS = "+\uff0b"
#: Longest text read as a quantity (a number and its unit): longer text is refused, not parsed.
MAX_TEXT = 100

_SIGN = f"[{re.escape(MINUS_SIGNS + PLUS_SIGNS)}]"
_NUMBER = re.compile(
    rf"\s*(?P<sign>{_SIGN}?)\s*(?P<mantissa>\d+(?:\.\d*)?|\.\d+)"
    rf"(?:[eE](?P<esign>{_SIGN}?)(?P<exponent>\d{{1,4}}))?"
)
#: A unit: names (letters, µ, Ω, °, %), products (space, *, ·), quotients (/), powers (^ or **
#: with a signed decimal exponent) and parentheses; "1/s" is allowed as a reciprocal.
_UNIT_TOKEN = re.compile(
    r"[A-Za-zµμΩ°%]+|\(|\)|\*\*|[*·/^]|\s+|(?<=\^|\*)[+-]?\d+(?:\.\d+)?|1(?=\s*/)"
)


def split_quantity(name: str, text: str) -> tuple[float, str]:
    """The number and the unit of a quantity written as text, read strictly.

    One number, then optionally a unit: one sign (any Unicode minus or dash reads as a minus),
    digits with at most one decimal point, an optional exponent, and nothing else numeric
    outside the unit's exponents.  Refused, each with a reason naming ``name``: a decimal comma
    ("use a decimal point"), numbers side by side or digit groups ("1 500"), operators and
    expressions ("2**1024", "1+2"), text longer than :data:`MAX_TEXT` characters, and text with
    no number.  Returns (value, unit text); the unit text is empty for a bare number.
    """
    if len(text) > MAX_TEXT:
        raise ParameterError(name, f"text of {len(text)} characters; at most {MAX_TEXT} are read")
    m = _NUMBER.match(text)
    if m is None:
        if re.match(rf"\s*{_SIGN}?\s*(nan|inf)", text, re.IGNORECASE):
            raise ParameterError(name, f"must be finite, got {text!r}")
        raise ParameterError(name, f"cannot read {text!r}: it does not start with a number")
    rest = text[m.end() :]
    if re.match(r",\d", rest):
        raise ParameterError(name, f"{text!r}: use a decimal point, not a comma")
    unit = rest.strip()
    if unit[:1].isdigit() or unit[:1] == ".":
        raise ParameterError(
            name, f"{text!r}: one number expected, found numbers side by side (no digit groups)"
        )
    if unit and not unit[:1].isalpha() and unit[:1] not in "µμΩ°%(/":
        raise ParameterError(name, f"{text!r}: a plain number expected, not an expression")
    pos = 0
    while pos < len(unit):
        t = _UNIT_TOKEN.match(unit, pos)
        if t is None:
            raise ParameterError(name, f"{text!r}: unexpected {unit[pos]!r} in the unit {unit!r}")
        pos = t.end()
    sign = -1.0 if m["sign"] and m["sign"] in MINUS_SIGNS else 1.0
    number = m["mantissa"]
    if m["exponent"] is not None:
        esign = "-" if m["esign"] and m["esign"] in MINUS_SIGNS else ""
        number += f"e{esign}{m['exponent']}"
    value = float(number)
    if value == float("inf"):
        raise ParameterError(name, f"{text!r} is beyond the largest float (about 1.8e308)")
    return sign * value, unit


def units_alike(name: str, text: str, parts: list[str]) -> None:
    """Refuse a range whose values mix quantities with units and bare numbers: in "6 mm:12 mm:2"
    or "5 mm:40" the bare number would be read as SI (2 m, 40 m)."""
    units = [split_quantity(name, p.strip())[1] if p.strip() else "" for p in parts]
    if any(units) and not all(units):
        bare = [p.strip() for p, u in zip(parts, units, strict=True) if not u]
        raise ParameterError(
            name,
            f"range {text!r} mixes values with and without units ({', '.join(bare)} has "
            "none); give every value its unit, or none (SI)",
        )


def _pint_factor(unit_text: str, si_unit: str) -> tuple[str, str]:
    """What pint says of ``unit_text`` against ``si_unit``: ("ok", factor as shortest decimal
    text), ("unit", reason) or ("dimension", dimensionality)."""
    ureg = _registry()  # first: it imports pint without dask
    import pint

    try:
        parsed = ureg.parse_units("1" + unit_text if unit_text.startswith("/") else unit_text)
    except Exception as exc:  # pint raises assorted error types on malformed or unknown units
        return "unit", str(exc)
    target = ureg.parse_units(si_unit)
    if _angle_count(target)[1] or _angle_count(parsed)[1]:
        return _angular_factor(parsed, target, unit_text, si_unit)
    try:
        factor = ureg.Quantity(1.0, parsed).to(si_unit).magnitude
    except pint.errors.DimensionalityError:
        return "dimension", str(ureg.Quantity(1.0, parsed).dimensionality)
    return "ok", f"{float(factor):.15g}"  # pint computes 1/0.01³ as 999999.9999999999


#: The two units of a frequency: an angle per time (Ω) and cycles per time (f = Ω/2π).
ANGULAR = ("rad/s", "Hz")


def _angle_count(unit: Any) -> tuple[float, float, dict[str, float]]:
    """(power of the hertz, power of the angle, the other root units) of a pint unit, the angle
    counted as a dimension of its own.

    pint takes the radian as dimensionless, so to it Hz, rad/s and 1/s are all 1/s, and
    N²/(rad/s) is N² s = N²/Hz.  Here every factor of the unit is read by what it counts: a
    radian, degree, revolution (rpm, turn, cycle) is an angle, kept as a power of radians; a
    hertz counts cycles per second, 2π rad/s each; the second, metre, newton, ... are what pint
    says they are.  The powers are sums over the factors, wherever they stand: numerator,
    denominator or power (N²/Hz has angle power −1, (rad/s)² power 2)."""
    ureg = _registry()
    hertz, angle, rest = 0.0, 0.0, {}
    for name, power in unit._units.items():
        root = dict(ureg.Quantity(1.0, name).to_root_units().units._units)
        a = root.pop("radian", 0.0)
        if "hertz" in name:  # a cycle per second: 2π rad/s
            a += 1.0
            hertz += power
        angle += a * power
        for k, v in root.items():
            rest[k] = rest.get(k, 0.0) + v * power
    return hertz, angle, {k: v for k, v in rest.items() if v != 0}


def _angular_factor(parsed: Any, target: Any, unit_text: str, si_unit: str) -> tuple[str, str]:
    """The factor from ``parsed`` to ``target`` where either counts an angle (a frequency, or a
    PSD per frequency), by :func:`_angle_count`: "324.7 rpm" in Hz is 5.41, not 34.0 (pint's
    answer); "0.02 N^2/(rad/s)" in N²/Hz is 2π·0.02.  pint's factor (the radian as 1, the hertz as
    1/s) times 2π for each hertz the unit has more than the target.  A unit that names no angle
    where the target counts one (1/s for a frequency, N² s for a force PSD) is ambiguous and
    refused."""
    h_user, a_user, rest_user = _angle_count(parsed)
    h_target, a_target, rest_target = _angle_count(target)
    if rest_user != rest_target:
        return "dimension", str(_registry().Quantity(1.0, parsed).dimensionality)
    if a_user != a_target:
        if a_user == 0 and si_unit in ANGULAR:
            return "unit", (
                f"{unit_text!r} is a rate that names no angle: write rad/s (or deg/s, rpm) for an "
                "angular frequency, Hz for cycles per second"
            )
        if a_user == 0:
            per = si_unit.rsplit("/", 1)
            hint = f": write {per[0]}/Hz or {per[0]}/(rad/s)" if per[-1] == "Hz" else ""
            return "unit", (
                f"{unit_text!r} names no frequency where {si_unit} counts one, and per hertz "
                f"and per rad/s differ by 2π{hint}"
            )
        return "dimension", f"an angle to the power {a_user:g} where {si_unit} has {a_target:g}"
    factor = float(_registry().Quantity(1.0, parsed).to(target).magnitude)
    if h_user == h_target:  # the same count of cycles: pint's factor, as for any unit
        return "ok", repr(factor) if si_unit in ANGULAR else f"{factor:.15g}"
    return "ok", repr(factor * (2.0 * math.pi) ** (h_user - h_target))  # 2π: no short decimal


class _FactorFile:
    """pint's answers for unit texts already met, kept on disk between runs.

    A command that reads "100 N/m" would otherwise import pint and build its registry (a quarter
    of a second of start-up) to learn a factor it computed the run before.  The file is keyed by
    pint's definitions file (path, size and modification time): a new pint, or an edited
    definitions file, starts a new table.  Writes go through a temporary file and a rename, so
    concurrent map workers never see half a file; any failure (no cache folder, a read-only
    home, a damaged file) falls back to asking pint."""

    def __init__(self) -> None:
        self.entries: dict[str, list[str]] | None = None
        self.path: Path | None = None
        self.key = ""

    def _open(self) -> dict[str, list[str]]:
        if self.entries is not None:
            return self.entries
        self.entries = {}
        try:
            import importlib.util
            import json
            import os

            spec = importlib.util.find_spec("pint")
            if spec is None or spec.origin is None:
                return self.entries
            definitions = Path(spec.origin).with_name("default_en.txt")
            st = definitions.stat()
            # the reading rules' version, then pint's definitions: a change of either starts anew
            self.key = f"{_RULES}|{definitions}|{st.st_size}|{st.st_mtime_ns}"
            home = os.environ.get("XDG_CACHE_HOME") or os.path.join(Path.home(), ".cache")
            self.path = Path(home) / "symimpact" / "unit-factors.json"
            if self.path.is_file():
                stored = json.loads(self.path.read_text(encoding="utf-8"))
                if stored.get("pint") == self.key and isinstance(stored.get("factors"), dict):
                    self.entries = {
                        k: v
                        for k, v in stored["factors"].items()
                        if isinstance(v, list) and len(v) == 2 and v[0] in _FACTOR_KINDS
                    }
        except Exception:  # an unreadable cache only costs the time it was meant to save
            self.path = None
        return self.entries

    def get(self, unit_text: str, si_unit: str) -> tuple[str, str]:
        entries = self._open()
        key = f"{unit_text}\x00{si_unit}"
        if key in entries:
            kind, info = entries[key]
            return kind, info
        kind, info = _pint_factor(unit_text, si_unit)
        entries[key] = [kind, info]
        if self.path is not None and len(entries) <= _MAX_STORED_FACTORS:
            self._save()
        return kind, info

    def _save(self) -> None:
        import json

        from ..io import _temporary_beside

        assert self.path is not None
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            with _temporary_beside(self.path, "unit cache", ".json") as tmp:
                Path(tmp).write_text(
                    json.dumps({"pint": self.key, "factors": self.entries}, ensure_ascii=False),
                    encoding="utf-8",
                )
        except Exception:  # a cache that cannot be written only costs the time it saves
            pass


_FACTOR_KINDS = ("ok", "unit", "dimension")
#: Version of the rules that turn pint's answers into factors (2: frequencies by what they count,
#: frequency units in any power, :func:`_angle_count`); part of the stored table's key.
_RULES = 4
#: Unit texts kept on disk at most (a fuzzing session must not grow the file without bound).
_MAX_STORED_FACTORS = 2000
_FACTOR_FILE = _FactorFile()


@lru_cache(maxsize=512)
def _factor(unit_text: str, si_unit: str) -> tuple[str, Any]:
    """("ok", Decimal factor to ``si_unit``), ("unit", reason) or ("dimension", dimensionality)
    for a unit written as text.  pint answers the first time a unit text is met; the answer is
    kept on disk (:class:`_FactorFile`) and in memory, so a column of cells in one unit, and the
    next command, do not ask pint again."""
    kind, info = _FACTOR_FILE.get(unit_text, si_unit)
    return (kind, Decimal(info)) if kind == "ok" else (kind, info)


def converts_to(unit_text: str, si_unit: str) -> bool:
    """Whether the unit written as ``unit_text`` (no number) converts to ``si_unit``: how a
    designer's phrase whose size may be of two kinds (a sphere's diameter or its mass) is read."""
    return _factor(unit_text, si_unit)[0] == "ok"


def _unit_to_si(name: str, text: str, number: float, unit_text: str, unit: str) -> float:
    """``number`` in ``unit_text`` as a float in the SI ``unit``.

    The shortest representations of the number and of the factor are multiplied in decimal, so
    a value written with a prefix gives the float of the SI number typed by hand: "9 mm" is
    0.009 and "0.1553 N/cm^3" is 155300.0, not 0.009000000000000001 and 155299.99999999997."""
    kind, info = _factor(unit_text, unit)
    if kind == "unit":
        raise ParameterError(name, f"cannot read the unit of {text!r} ({info})")
    if kind == "dimension":
        raise ParameterError(name, f"{text!r} has dimension {info}, expected units of {unit}")
    return float(Decimal(repr(number)) * info)


def _to_si(name: str, q: Any, unit: str) -> Any:
    """A pint quantity (a number or an array with units) in the SI ``unit``, multiplied in
    decimal like :func:`_unit_to_si`."""
    import numpy as np

    kind, info = _factor(str(q.units), unit)
    if kind == "unit":
        raise ParameterError(name, f"cannot read the unit of {q!r} ({info})")
    if kind == "dimension":
        raise ParameterError(name, f"{q!r} has dimension {info}, expected units of {unit}")
    scaled = np.vectorize(lambda v: float(Decimal(repr(float(v))) * info), otypes=[float])
    return scaled(np.asarray(q.magnitude, dtype=float))


def si(name: str, value: Any, unit: str | None = None) -> Any:
    """Parameter ``name`` as an SI float (or float array), checked to be finite.

    ``value`` is a number, an array, a string with units or a pint quantity; ``unit`` defaults to
    the parameter's entry in :data:`SI_UNITS`.  Raises :class:`ParameterError` naming ``name`` for
    a malformed unit, a wrong dimension, a non-numeric value, NaN or infinity.
    """
    import numpy as np

    # a plain number (bool is not one: it is refused below): the same checks without NumPy's
    # arrays (0.5 µs, not 5)
    if type(value) in (float, int, np.float64):
        try:
            v = float(value)
        except OverflowError:
            raise ParameterError(
                name, "an integer beyond the largest float (about 1.8e308)"
            ) from None
        if not math.isfinite(v):
            raise ParameterError(name, f"must be finite, got {value!r}")
        if abs(v) > MAGNITUDE[1]:
            _out_of_range(name, abs(v), unit or SI_UNITS.get(name, "dimensionless"))
        return v
    if value is None:
        raise ParameterError(name, "is required")
    unit = unit or SI_UNITS.get(name, "dimensionless")
    if isinstance(value, str):
        number, unit_text = split_quantity(name, value)
        if unit_text in ("g", "gn", "g0") and unit == "m/s^2":  # an acceleration: not grams
            unit_text = "standard_gravity"
        elif unit == ACCELERATION_PSD:  # g²/Hz, as vibration specifications write it
            unit_text = re.sub(r"(?<![A-Za-z_])(gn|g0|g)(?![A-Za-z_0-9])", "standard_gravity",
                               unit_text)  # fmt: skip
        # a bare number written as text means SI; a unit is read by pint, without the number
        value = _unit_to_si(name, value, number, unit_text, unit) if unit_text else number
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
    if arr.size and np.abs(arr).max() > MAGNITUDE[1]:
        _out_of_range(name, np.abs(arr).max(), unit)
    return float(arr) if arr.ndim == 0 else arr


def _out_of_range(name: str, extreme: float, unit: str) -> None:
    raise ParameterError(
        name,
        f"{extreme:g} {unit} lies outside the magnitudes the package computes with "
        f"({MAGNITUDE[0]:g} to {MAGNITUDE[1]:g} in SI units)",
    )


def positive(name: str, value: Any, unit: str | None = None) -> Any:
    """:func:`si`, then require every value > 0."""
    import numpy as np

    v = si(name, value, unit)
    if type(v) is float:
        if not v > 0:
            raise ParameterError(name, f"must be positive, got {_show(v)}")
        if v < MAGNITUDE[0]:
            _out_of_range(name, v, unit or SI_UNITS.get(name, "dimensionless"))
        return v
    arr = np.asarray(v)
    if np.any(arr <= 0):
        raise ParameterError(name, f"must be positive, got {_show(v)}")
    if arr.size and arr.min() < MAGNITUDE[0]:  # a scale or a divisor: no vanishing values
        _out_of_range(name, arr.min(), unit or SI_UNITS.get(name, "dimensionless"))
    return v


def nonnegative(name: str, value: Any, unit: str | None = None) -> Any:
    """:func:`si`, then require every value ≥ 0."""
    import numpy as np

    v = si(name, value, unit)
    if type(v) is float:
        if v < 0:
            raise ParameterError(name, f"must not be negative, got {_show(v)}")
        return v
    if np.any(np.asarray(v) < 0):
        raise ParameterError(name, f"must not be negative, got {_show(v)}")
    return v


def _show(v: Any) -> str:
    import numpy as np

    if isinstance(v, float):
        return f"{v:g}"
    arr = np.asarray(v)
    bad = arr.ravel()
    return f"array with min {bad.min():g}" if bad.size else "an empty array"


def _one(name: str, v: Any) -> float:
    import numpy as np

    if type(v) is float:
        return v
    if np.size(v) == 0:
        raise ParameterError(name, "got no value")
    if np.ndim(v) != 0:
        raise ParameterError(name, f"expected one number, got an array of shape {np.shape(v)}")
    return float(v)


def si_float(name: str, value: Any, unit: str | None = None) -> float:
    """:func:`si` for a parameter that takes one number (an array is refused)."""
    return _one(name, si(name, value, unit))


def positive_float(name: str, value: Any, unit: str | None = None) -> float:
    """:func:`positive` for a parameter that takes one number (an array is refused)."""
    return _one(name, positive(name, value, unit))


def nonnegative_float(name: str, value: Any, unit: str | None = None) -> float:
    """:func:`nonnegative` for a parameter that takes one number (an array is refused)."""
    return _one(name, nonnegative(name, value, unit))
