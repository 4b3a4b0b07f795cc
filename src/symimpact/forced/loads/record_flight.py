"""The primary's exact flight over a sampled load (Step 16, Eq. F8): on each interval of the
record the load is a straight line and the flight is closed form (the generated
``sampled_load.ramp_state``), so a record of any length is one recurrence, exact for the record
as sampled — no time step to choose, no integration error.

Without the damper this is the baseline the random, shock and sweep responses are compared with
(:func:`primary_response`), and the shock-response spectrum of a record (:func:`srs`): the largest
absolute acceleration of single-degree-of-freedom oscillators under it as a base acceleration.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._compiled import compiled
from ...errors import ParameterError
from ...generated import sampled_load as _sl
from ...model import checks
from ...model.system import ImpactSystem
from .records import Record, record_participation

_ramp_state = compiled(_sl.ramp_state_scalar)


@compiled
def _march(M, K, C, p, dt, x0, v0):
    """x, ẋ at every sample of the load p (one flight of Eq. F8 per interval)."""
    n = len(p)
    x = np.empty(n)
    v = np.empty(n)
    x[0], v[0] = x0, v0
    for i in range(n - 1):
        x[i + 1], v[i + 1] = _ramp_state(dt, M, K, C, p[i], (p[i + 1] - p[i]) / dt, x[i], v[i])
    return x, v


@dataclass(frozen=True)
class RecordResponse:
    """The primary alone under a record, at its samples (SI): ``displacement`` x [m] (relative to
    the base under a base acceleration), ``velocity`` [m/s] likewise, ``acceleration`` [m/s²]
    the main mass's absolute acceleration, ``base_force`` [N] the force the spring and damper
    put into the base (K·x + C·ẋ, x relative to the base; Γ times it for a structure's mode
    reduced to a point with participation Γ = Γᵢφᵢ(a): the mode's share of the supports'
    reaction, Γᵢ·Kᵢqᵢ + Γᵢ·Cᵢq̇ᵢ, its base shear)."""

    times: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    base_force: np.ndarray


def primary_response(
    system: ImpactSystem, record: Record, x0: Any = 0.0, xdot0: Any = 0.0,
    participation: Any = 1.0,
) -> RecordResponse:  # fmt: skip
    """The primary of ``system`` (M, K, C; the damper left out) under ``record``, from x0 [m],
    ẋ0 [m/s] at t = 0: Eq. F8 on each interval.  A force record p drives M ẍ + C ẋ + K x = p; a
    base acceleration a_b drives the displacement relative to the base with p = −Γ·M·a_b, Γ the
    ``participation`` (1 for a primary on its base; Γᵢφᵢ(a) for mode i of a structure reduced
    to its point a, Eq. F7), and the absolute acceleration is ẍ + a_b."""
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    checks.instance("record", record, Record, "a Record (symimpact.forced.loads.records)")
    x0 = checks.bounded("x0", x0, unit="m")
    v0 = checks.bounded("xdot0", xdot0, unit="m/s")
    gamma = record_participation(record, participation)
    if system.C >= 2.0 * math.sqrt(system.K * system.M):
        raise ParameterError("system", "Eq. F8 is written for an underdamped primary (ζ < 1)")
    M, K, C = system.M, system.K, system.C
    base = record.kind == "base-acceleration"
    p = -(gamma * M) * record.values if base else record.values
    x, v = _march(M, K, C, np.ascontiguousarray(p, dtype=float), record.dt, x0, v0)
    force = K * x + C * v
    if base:
        acceleration = -force / M + (1.0 - gamma) * record.values
    else:
        acceleration = (record.values - force) / M
    return RecordResponse(record.times, x, v, acceleration, gamma * force)  # 1.0·x is x


def srs(record: Record, frequencies: Any, zeta: Any = 0.05) -> np.ndarray:
    """The shock-response spectrum of ``record`` (a base acceleration [m/s²]): at each natural
    frequency [Hz] of ``frequencies``, the largest absolute acceleration [m/s²] of an oscillator
    of damping ratio ``zeta`` (default 5 %, the usual Q = 10) on the base, from rest, over the
    record (maximax: during the pulse and after it, as long as the record runs).  The peak is
    read at the samples, each exact by Eq. F8; between two of them an oscillation at f can rise
    by up to (2πf·dt)²/8 of its size, so frequencies above 0.3/(2π·dt) (1.1 %) are refused."""
    if record.kind != "base-acceleration":
        raise ParameterError("record", "an SRS is of a base acceleration record")
    f = checks.numbers("frequencies", frequencies)
    if f.size == 0:
        raise ParameterError("frequencies", "give at least one oscillator frequency")
    z = checks.bounded("zeta", zeta, 0.0, 1.0)
    if z >= 1.0:
        raise ParameterError("zeta", "must be below 1 (underdamped)")
    if np.any(f <= 0):
        raise ParameterError("frequencies", "must be above 0 Hz")
    top = 0.3 / (2.0 * math.pi * record.dt)
    if np.max(f) > top:
        raise ParameterError(
            "frequencies",
            f"reach {np.max(f):g} Hz, where samples every {record.dt:g} s miss a peak by more "
            f"than 1 %: at most {top:.4g} Hz, or a finer record",
        )
    out = np.empty(len(f))
    a = np.ascontiguousarray(record.values, dtype=float)
    for j, fn in enumerate(f):
        w = 2.0 * math.pi * fn
        x, v = _march(1.0, w * w, 2.0 * z * w, -a, record.dt, 0.0, 0.0)
        out[j] = np.max(np.abs(w * w * x + 2.0 * z * w * v))
    return out
