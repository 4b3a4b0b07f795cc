"""The primary with its impact damper under a sampled load — random vibration, a shock, a sine
sweep (:mod:`symimpact.forced.loads.records`) — with rigid impacts: Step 16's exact flight (Eq. F8) on
each interval of the record, Step 9's impact law (Eq. F2) at each impact, chatter accumulated and
sticking followed as in the harmonic simulation (:mod:`symimpact.forced.engine._record_rigid`); or with
a compliant contact (cubic, Hertz, linear, Hunt–Crossley: Eq. 8, 9, 35, F4), whose contact
phases are integrated with the record's load (:mod:`symimpact.forced.engine._record_compliant`).

The response is returned at the record's samples; the impacts, as events, at their own times.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ... import _interrupt
from ...errors import ParameterError, SymimpactError
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import restitution_parameters, simulation_arguments
from ..engine import _compliant as _cp
from ..engine import _record_compliant as _rc
from ..engine import _record_rigid as _rr
from ..simulation import CHATTER, contact_arguments
from .records import Record, record_participation


@dataclass(frozen=True)
class DamperRecordResponse:
    """The primary and its impact damper under a record, at its samples (SI).

    ``displacement`` x [m] and ``velocity`` [m/s] of the main mass (relative to the base under a
    base acceleration), ``acceleration`` its absolute acceleration between impacts [m/s²] (the
    impacts' impulses are instants, not samples), ``base_force`` K·x + C·ẋ [N], the force the spring
    and damper put into the base (Γ times it for a structure's mode reduced to a point,
    :func:`~symimpact.forced.loads.record_flight.primary_response`); ``damper_displacement`` y and
    ``damper_velocity`` of the impact mass (same frame), ``stuck`` True where the two move together;
    ``impact_times`` [s], ``impact_speeds`` (approach speed [m/s]) and ``impact_sides`` (±1) of
    every impact; ``ledger``: the load's work, C's dissipation and the impacts' loss [J], the energy
    at the start and end [J] and the balance's residual relative to the largest of them."""

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
    participation: Any = 1.0,
) -> DamperRecordResponse:
    """The primary of ``system`` (M, K, C) with its impact mass m in a clearance d, under
    ``record`` (a force on the main mass [N], or the base's acceleration [m/s²]), rigid impacts
    with Newton's coefficient ``e`` (Eq. F2), from x0 [m], ẋ0 [m/s], y0 [m], ẏ0 [m/s] at t = 0.
    Between impacts Eq. F8 on each interval of the record (the flight under a load joined by
    straight lines between its samples, exact); ``chatter``: a sequence of impacts on one wall
    whose flights would sum to at most this fraction of a natural period is taken to its
    accumulation point and the masses then stick (see :mod:`symimpact.forced.engine._record_rigid`).
    ``e`` a :class:`~symimpact.forced.contact_law.CompliantContact` in place of a restitution:
    the compliant law of Eq. 8, 9, 35 (the system's parameters and c1) or F4 (χ), each contact
    phase integrated with the record's load (:mod:`symimpact.forced.engine._record_compliant`), the
    contacts' dissipation in the ledger's ``lost_in_impacts``; y0 may then start inside a wall."""
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    checks.instance("record", record, Record, "a Record (symimpact.forced.loads.records)")
    args = simulation_arguments(e)
    contact = args["contact"]
    e, chi, law = contact_arguments(system, contact, args.get("e"), args.get("chi"))
    state = [
        checks.bounded(n, v, unit=u)
        for n, v, u in (("x0", x0, "m"), ("xdot0", xdot0, "m/s"), ("y0", y0, "m"),
                        ("ydot0", ydot0, "m/s"))
    ]  # fmt: skip
    h = system.gap / 2.0
    if contact == "rigid" and abs(state[2] - state[0]) > h * (1.0 + 1e-12):
        raise ParameterError(
            "y0", f"puts the impact mass outside the clearance (|y0 − x0| > {h:g} m)"
        )
    chatter = checks.bounded("chatter", chatter, 0.0)
    max_events = checks.whole_number("max_events", max_events, 1)
    gamma = record_participation(record, participation)
    if len(record.values) < 2:
        raise ParameterError("record", "needs at least two samples")
    M, m, K, C = system.M, system.m, system.K, system.C
    base = record.kind == "base-acceleration"
    e_const, yield_speed = restitution_parameters(e)
    p = np.array([M, m, K, C, h, e_const, chatter, 1.0 if base else 0.0, yield_speed, gamma])
    q = np.ascontiguousarray(record.values, dtype=float)
    s0 = np.array([state[0], state[1], state[2] - state[0], state[3]])
    potential = [0.0, 0.0]  # the contact's elastic energy at the start and the end
    if contact == "rigid":
        status, out, stuck, events, n_ev, ledger, done = _interrupt.call(
            _rr.run, p, q, record.dt, s0, max_events
        )
    else:
        status, out, events, n_ev, ledger, done, _ = _interrupt.call(
            _rc.run, _cp.CODES[contact], law, 0.0 if chi is None else float(chi), p, q,
            record.dt, s0, max_events,
        )  # fmt: skip
        if status in (_rc.TOO_MANY_STEPS, _rc.STEP_UNDERFLOW):
            raise SymimpactError(
                f"a contact near t = {record.dt * (done - 1):g} s took more Runge–Kutta steps "
                "than allowed (a contact far stiffer than the motion's time scale)"
            )
        stuck = np.zeros(len(q))
        for k, row in ((0, out[0]), (1, out[len(q) - 1])):
            delta = abs(row[2]) - h
            if delta > 0.0:
                potential[k] = _cp.contact_potential(contact, law, delta)
    if status == _rr.TOO_MANY_EVENTS:
        raise TooManyImpacts(
            f"more than {max_events:,} impacts and releases by t = {record.dt * (done - 1):g} s; "
            "raise max_events or shorten the record"
        )
    x, v, z, u = out.T
    stuck = stuck.astype(bool)
    mass = np.where(stuck, M + m, M)
    force = K * x + C * v
    acceleration = -force / mass + (1.0 - gamma) * M / mass * q if base else (q - force) / mass
    if contact != "rigid":  # at samples inside a contact its force acts on the primary too
        code, c = _cp.CODES[contact], 0.0 if chi is None else float(chi)
        for i in np.flatnonzero(np.abs(z) > h):
            side = 1.0 if z[i] > 0 else -1.0
            F = _cp._force(code, law, c, side * z[i] - h, side * (u[i] - v[i]))[0]
            acceleration[i] += side * F / M
    ev = events[:n_ev]
    hit = ev[:, _rr.E_KIND] == _rr.KIND_IMPACT

    def energy(i: int) -> float:
        return 0.5 * M * v[i] ** 2 + 0.5 * K * x[i] ** 2 + 0.5 * m * u[i] ** 2

    work, dissipated, lost = (float(a) for a in ledger)
    e0, e1 = energy(0) + potential[0], energy(len(q) - 1) + potential[1]
    scale = max(e0, e1, abs(work), dissipated, lost, 1e-300)
    return DamperRecordResponse(
        times=record.times,
        displacement=x,
        velocity=v,
        acceleration=acceleration,
        base_force=gamma * force,  # (1.0·x is x to the bit)
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
