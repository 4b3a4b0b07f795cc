"""The restitution e(v) from single impacts: approach and rebound speeds (a pendulum, a
high-speed camera) or drop and rebound heights (a ball dropped on the cavity's material).

Three laws, each fitted to the rebound speeds w_out = e(w)·w (the residual is in the rebound
speed, the quantity measured; m/s):

* ``constant`` — Newton's e (Eq. F2), 0 ≤ e ≤ 1;
* ``thornton`` — e = 1 up to the yield speed v_y and Thornton's elastic–perfectly-plastic
  T(v_y/w) above it (Step 13, Eq. F5): the law ``--e material`` runs, here with v_y fitted;
  its Jacobian ∂w_out/∂v_y = T'(r) = (T − ê)/r, r = v_y/w, from the derived T and ê;
* ``power`` — e = 1 up to v_y and (v_y/w)^α above it: Thornton's high-speed tail is α = 1/4;
  α free covers a contact whose losses grow faster or slower with the speed.

Heights are read as speeds of a free fall, w = √(2·g·h) with the standard gravity (air drag
neglected: for a steel ball of 20 mm from 1 m it takes about 0.2 % of the speed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..forced.loads.records import unit_columns
from ..model.units import si_float
from .least_squares import Fit, Unknown, fit

#: The laws, in the order of ``--law``.
LAWS = ("constant", "thornton", "power")

#: Standard gravity [m/s²] (CGPM 1901), by which drop heights are speeds.
STANDARD_GRAVITY = 9.80665


@dataclass(frozen=True)
class Impacts:
    """Measured impacts: approach speeds ``v_in`` and rebound speeds ``v_out`` [m/s], and what
    the file gave (``"speed"`` or ``"height"``)."""

    v_in: np.ndarray
    v_out: np.ndarray
    given: str = "speed"

    def __post_init__(self) -> None:
        v_in = np.asarray(self.v_in, float).ravel()
        v_out = np.asarray(self.v_out, float).ravel()
        if v_in.size != v_out.size:
            raise ParameterError("impacts", "needs one rebound speed for each approach speed")
        if v_in.size < 2:
            raise ParameterError("impacts", "needs at least two impacts")
        if not (np.all(np.isfinite(v_in)) and np.all(np.isfinite(v_out))):
            raise ParameterError("impacts", "holds a value that is not finite")
        if np.any(v_in <= 0):
            raise ParameterError("impacts", "approach speeds (or drop heights) must be above 0")
        if np.any(v_out < 0):
            raise ParameterError("impacts", "rebound speeds (or heights) are magnitudes: "
                                 "none may be below 0")  # fmt: skip
        object.__setattr__(self, "v_in", v_in)
        object.__setattr__(self, "v_out", v_out)


def fall_speed(height: Any) -> np.ndarray:
    """Speed [m/s] of a free fall from ``height`` [m]: √(2·g·h), g the standard gravity."""
    return np.sqrt(2.0 * STANDARD_GRAVITY * np.asarray(height, float))


def read_impacts(path: Any) -> Impacts:
    """Impacts from a CSV file of two columns, approach then rebound, each header with its unit
    in brackets: speeds ("approach speed [m/s]", "rebound speed [m/s]") or heights ("drop
    height [mm]", "rebound height [mm]"), read as free-fall speeds (:func:`fall_speed`)."""
    (u_in, u_out), data = unit_columns(path, "impacts", ("approach speed [m/s]",
                                                         "rebound speed [m/s]"))  # fmt: skip
    kinds = []
    for unit in (u_in, u_out):
        try:
            kinds.append(("speed", si_float("impacts", f"1 {unit}", "m/s")))
        except ParameterError:
            try:
                kinds.append(("height", si_float("impacts", f"1 {unit}", "m")))
            except ParameterError:
                raise ParameterError("impacts", f"a column's unit {unit!r} is neither a speed "
                                     "nor a height") from None  # fmt: skip
    if kinds[0][0] != kinds[1][0]:
        raise ParameterError("impacts", "give both columns as speeds or both as heights")
    a, b = data[:, 0] * kinds[0][1], data[:, 1] * kinds[1][1]
    if kinds[0][0] == "height":
        if np.any(a <= 0) or np.any(b < 0):
            raise ParameterError("impacts", "heights must be above 0 (a rebound may be 0)")
        a, b = fall_speed(a), fall_speed(b)
    return Impacts(a, b, kinds[0][0])


def restitution(law: str, params: Any, speed: Any) -> np.ndarray:
    """e at approach speeds ``speed`` [m/s] of ``law`` (:data:`LAWS`) with ``params``: (e,),
    (v_y [m/s],) or (v_y [m/s], α)."""
    from ..generated import hertz_contact as hz

    w = np.asarray(speed, float)
    if law == "constant":
        return np.full_like(w, float(params[0]))
    r = np.minimum(float(params[0]) / w, 1.0)
    if law == "thornton":
        return np.where(r >= 1.0, 1.0, hz.thornton_restitution(r))
    if law == "power":
        return r ** float(params[1])
    raise ParameterError("law", f"must be one of {', '.join(LAWS)}")


def _jacobian(law: str, params: np.ndarray, w: np.ndarray) -> np.ndarray:
    """∂(w·e(w))/∂θ, n × p (the residual's Jacobian is its negative)."""
    from ..generated import hertz_contact as hz

    if law == "constant":
        return w[:, None]
    v_y = float(params[0])
    r = np.minimum(v_y / w, 1.0)
    above = r < 1.0
    if law == "thornton":
        rr = np.where(above, r, 0.5)
        slope = (hz.thornton_restitution(rr) - hz.thornton_separation_slope(rr)) / rr
        return np.where(above, slope, 0.0)[:, None]
    alpha = float(params[1])
    rr = np.where(above, r, 1.0)
    d_vy = np.where(above, alpha * rr ** (alpha - 1.0), 0.0)  # w·α·r^(α−1)/w
    d_alpha = np.where(above, w * rr**alpha * np.log(rr), 0.0)
    return np.column_stack([d_vy, d_alpha])


def _unknowns(law: str, data: Impacts) -> list[Unknown]:
    """The law's parameters; the yield speed searched from 1e-9 of the slowest impact (e ≈ 0
    there) to 10 times the fastest (e = 1 at every impact beyond it)."""
    if law == "constant":
        return [Unknown("e", "1", 0.0, 1.0)]
    span = (1e-9 * float(data.v_in.min()), 10.0 * float(data.v_in.max()))
    v_y = Unknown("yield_speed", "m/s", 0.0, math.inf, log=True, span=span)
    return [v_y] if law == "thornton" else [v_y, Unknown("alpha", "1", 0.0, 20.0)]


def _starts(law: str, data: Impacts) -> list[list[float]]:
    """Starts spread over the plausible range: yield speeds from 1e-6 of the slowest impact to
    the fastest (the law is flat e = 1 beyond), exponents 0.05 to 2."""
    e = data.v_out / data.v_in
    if law == "constant":
        return [[float(np.clip(np.median(e), 0.0, 1.0))]]
    ys = np.geomspace(1e-6 * data.v_in.min(), data.v_in.max(), 13)
    if law == "thornton":
        return [[y] for y in ys]
    return [[y, a] for y in ys[::3] for a in (0.05, 0.25, 1.0, 2.0)]


def fit_restitution(data: Impacts, law: str = "constant") -> Fit:
    """The restitution law ``law`` (:data:`LAWS`) fitted to ``data`` by least squares on the
    rebound speeds, with standard errors, 95 % profile intervals and warnings
    (:func:`symimpact.identify.least_squares.fit`)."""
    if law not in LAWS:
        raise ParameterError("law", f"must be one of {', '.join(LAWS)}")
    w, out = data.v_in, data.v_out

    def residual(theta):
        return out - w * restitution(law, theta, w)

    def jacobian(theta):
        return -_jacobian(law, np.asarray(theta, float), w)

    result = fit(residual, jacobian, _unknowns(law, data), _starts(law, data))
    if law != "constant":
        v_y = result.parameters["yield_speed"].value
        if np.all(w <= v_y):
            result.warnings.append(
                f"yield_speed: every approach speed is at or below the fitted {v_y:.4g} m/s, "
                "where the law gives e = 1: the data bound it from below only"
            )  # fmt: skip
    return result


def law_setting(law: str, result: Fit | None) -> str | float:
    """The fitted law as the command line's ``--e`` takes it: a number (constant) or
    ``"thornton <v_y> m/s"``; the power law is refused (the engines run constant e and
    Thornton's law)."""
    if law == "constant":
        return result.parameters["e"].value
    if law == "thornton":
        return f"thornton {result.parameters['yield_speed'].value!r} m/s"
    raise ParameterError("out", "the engines run a constant e or Thornton's law: fit --law "
                         "constant or thornton to write a system file")  # fmt: skip
