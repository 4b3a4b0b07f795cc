"""The primary with its impact damper under a sampled load — random vibration, a shock, a sine
sweep (:mod:`symimpact.forced.loads`) — with rigid impacts: Step 16's exact flight (Eq. F8) on
each interval of the record, Step 9's impact law (Eq. F2) at each impact, chatter accumulated and
sticking followed as in the harmonic simulation (:mod:`symimpact.forced._record_rigid`).

The response is returned at the record's samples; the impacts, as events, at their own times.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import _interrupt, checks
from ..errors import ParameterError, SymimpactError
from ..system import ImpactSystem
from . import _record_rigid as _rr
from .loads import Record
from .simulation import CHATTER


@dataclass(frozen=True)
class DamperRecordResponse:
    """The primary and its impact damper under a record, at its samples (SI).

    ``displacement`` x [m] and ``velocity`` [m/s] of the main mass (relative to the base under a
    base acceleration), ``acceleration`` its absolute acceleration between impacts [m/s²] (the
    impacts' impulses are instants, not samples), ``base_force`` K·x + C·ẋ [N], the force the
    spring and damper put into the base; ``damper_displacement`` y and ``damper_velocity`` of
    the impact mass (same frame), ``stuck`` True where the two move together; ``impact_times``
    [s], ``impact_speeds`` (approach speed [m/s]) and ``impact_sides`` (±1) of every impact;
    ``ledger``: the load's work, C's dissipation and the impacts' loss [J], the energy at the
    start and end [J] and the balance's residual relative to the largest of them."""

    times: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    base_force: np.ndarray
    damper_displacement: np.ndarray
    damper_velocity: np.ndarray
    stuck: np.ndarray
    impact_times: np.ndarray
    impact_speeds: np.ndarray
    impact_sides: np.ndarray
    ledger: dict[str, float]


class TooManyImpacts(SymimpactError):
    """The run met more events than allowed."""


def damper_response(
    system: ImpactSystem,
    record: Record,
    *,
    e: Any,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    chatter: Any = CHATTER,
    max_events: Any = 20_000_000,
) -> DamperRecordResponse:
    """The primary of ``system`` (M, K, C) with its impact mass m in a clearance d, under
    ``record`` (a force on the main mass [N], or the base's acceleration [m/s²]), rigid impacts
    with Newton's coefficient ``e`` (Eq. F2), from x0 [m], ẋ0 [m/s], y0 [m], ẏ0 [m/s] at t = 0.
    Between impacts Eq. F8 on each interval of the record (the flight under a load joined by
    straight lines between its samples, exact); ``chatter``: a sequence of impacts on one wall
    whose flights would sum to at most this fraction of a natural period is taken to its
    accumulation point and the masses then stick (see :mod:`symimpact.forced._record_rigid`)."""
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    checks.instance("record", record, Record, "a Record (symimpact.forced.loads)")
    e = checks.bounded("e", e, 0.0, 1.0)
    state = [
        checks.bounded(n, v, unit=u)
        for n, v, u in (("x0", x0, "m"), ("xdot0", xdot0, "m/s"), ("y0", y0, "m"),
                        ("ydot0", ydot0, "m/s"))
    ]  # fmt: skip
    h = system.gap / 2.0
    if abs(state[2] - state[0]) > h * (1.0 + 1e-12):
        raise ParameterError(
            "y0", f"puts the impact mass outside the clearance (|y0 − x0| > {h:g} m)"
        )
    chatter = checks.bounded("chatter", chatter, 0.0)
    max_events = checks.whole_number("max_events", max_events, 1)
    if len(record.values) < 2:
        raise ParameterError("record", "needs at least two samples")
    M, m, K, C = system.M, system.m, system.K, system.C
    base = record.kind == "base-acceleration"
    p = np.array([M, m, K, C, h, e, chatter, 1.0 if base else 0.0])
    q = np.ascontiguousarray(record.values, dtype=float)
    s0 = np.array([state[0], state[1], state[2] - state[0], state[3]])
    status, out, stuck, events, n_ev, ledger, done = _interrupt.call(
        _rr.run, p, q, record.dt, s0, max_events
    )
    if status == _rr.TOO_MANY_EVENTS:
        raise TooManyImpacts(
            f"more than {max_events:,} impacts and releases by t = {record.dt * (done - 1):g} s; "
            "raise max_events or shorten the record"
        )
    x, v, z, u = out.T
    stuck = stuck.astype(bool)
    mass = np.where(stuck, M + m, M)
    force = K * x + C * v
    acceleration = -force / mass if base else (q - force) / mass
    ev = events[:n_ev]
    hit = ev[:, _rr.E_KIND] == _rr.KIND_IMPACT

    def energy(i: int) -> float:
        return 0.5 * M * v[i] ** 2 + 0.5 * K * x[i] ** 2 + 0.5 * m * u[i] ** 2

    work, dissipated, lost = (float(a) for a in ledger)
    e0, e1 = energy(0), energy(len(q) - 1)
    scale = max(e0, e1, abs(work), dissipated, lost, 1e-300)
    return DamperRecordResponse(
        times=record.times,
        displacement=x,
        velocity=v,
        acceleration=acceleration,
        base_force=force,
        damper_displacement=x + z,
        damper_velocity=u,
        stuck=stuck,
        impact_times=ev[hit, _rr.E_T],
        impact_speeds=ev[hit, _rr.E_VREL],
        impact_sides=ev[hit, _rr.E_SIDE].astype(int),
        ledger={
            "work": work,
            "dissipated": dissipated,
            "lost_in_impacts": lost,
            "energy_start": e0,
            "energy_end": e1,
            "residual": abs(e1 - e0 - work + dissipated + lost) / scale,
        },
    )
