"""Forced response of a structure of several modes carrying several impact dampers with rigid
impacts: :func:`simulate_structure`.

Each mode flies by Step 8's closed form (Eq. F1) under its modal force Fᵢ = F₀·φᵢ(f), f the driven
point; an impact of damper k applies Step 15's law at its point (Eq. F7: the impulse
(1 + e)·μ·ż enters each mode through φᵢ(aₖ)).  The compiled engine is
:mod:`symimpact.forced.engine._modal`, which composes the one-mode flight functions mode by mode; the
paper's primary is its case of one mode of shape 1 and one damper, which
:func:`symimpact.forced.simulate_forced` runs.  Chatter is taken to its accumulation point, and the mass then sticks on its point, the
structure carrying it, until its wall would pull it (Step 15, item 5).

*Impacts at the same instant.*  Two dampers that reach their walls at the same instant are
resolved one after the other, in the order they are listed: the first's impact changes the
point's velocity, and the second's is then found at the same instant (to the search's 4e-16 of
the time) with the velocity the first left.  Each impact loses ½μ(1 − e²)ż² at its own approach
speed, so the pair loses what two impacts in a row lose, not what one impact of their summed
mass would; the energy ledger closes either way.

*Masses that settle together.*  An impact that would release another, stuck, mass from its wall
releases it only if its return would take longer than chatter the engine resolves (Step 9's
test on the speed the impulse gives it and its point's acceleration back): a shorter excursion
is jumped over, as a short chatter is, and the mass stays on its wall.  Two masses that come to
rest on their walls together then stick together, instead of releasing each other at every
closure (:func:`symimpact.forced.engine._modal._returns_at_once`).  A wall met by a mass leaving it at
a speed below the positions' rounding ends that mass's chatter with a plastic closure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import _interrupt, budgets
from ..errors import MethodNotApplicable, ParameterError
from ..free import _stepper
from ..model.checks import flag, instance, whole_number
from ..model.dampers import Damper
from ..model.stops import Stop, check_walls
from ..model.structure import Structure
from ..model.units import nonnegative_float, positive_float, si_float
from .engine import _compliant, _modal, _rigid, _structure_contact
from .simulation import CHATTER

#: Columns of :attr:`StructureResult.events`.
EVENT_COLUMNS = ("t", "x_point", "xdot_point_before", "ydot_before", "side", "approach_speed",
                 "energy_lost", "kind", "xdot_point_after", "ydot_after", "damper")  # fmt: skip
#: Kinds of :attr:`StructureResult.events` (column "kind").
KINDS = {_rigid.KIND_IMPACT: "impact", _rigid.KIND_ACCUMULATION: "accumulation",
         _rigid.KIND_RELEASE: "release", _modal.KIND_ONSET: "contact onset",
         _modal.KIND_EXIT: "contact exit"}  # fmt: skip


@dataclass(frozen=True)
class StructureResult:
    """Outcome of :func:`simulate_structure` (SI units)."""

    structure: Structure
    dampers: tuple[Damper, ...]
    force_at: str
    F0: float
    omega: float
    t_end: float
    #: (n, 11): columns :data:`EVENT_COLUMNS`, one row per impact, accumulation point, release,
    #: or a stop's contact onset or exit (column "kind", :data:`KINDS`; column "damper": the
    #: damper's index, or the number of dampers plus the stop's index)
    events: np.ndarray
    #: the output points (the structure's, in its order)
    points: tuple[str, ...]
    #: (periods, points): the largest abs(x) at each point in each forcing period [m]
    period_max: np.ndarray
    #: the energy ledger (None for a run made without it, ``energy=False``)
    energy: dict[str, float] | None
    #: (t, q…, q̇…, y…, ẏ…, per damper its wall if it ends stuck else 0, per stop the wall it
    #: ends pressing else 0) at the end
    final_state: np.ndarray
    notes: list[str] = field(default_factory=list)
    stops: tuple[Stop, ...] = ()
    #: with ``variational``: ∂(q, q̇, y, ẏ)(t_end)/∂(q, q̇, y, ẏ)(0), the chain of the flights'
    #: transition matrices and the events' saltation matrices; NaN where the motion is not
    #: differentiable so (a mass sticks, or its chatter accumulates)
    monodromy: np.ndarray | None = None
    #: the supports' displacement amplitude X_b [m] (0: fixed supports)
    X_b: float = 0.0

    def contacts(self, stop: str) -> np.ndarray:
        """The times at which stop ``stop``'s contacts begin [s] (a rigid stop's: its impacts and,
        for each chatter sequence, its accumulation point)."""
        names = [s.name for s in self.stops]
        if stop not in names:
            raise ParameterError("stop", f"no stop {stop!r} (the stops: "
                                         f"{', '.join(names) or 'none'})")  # fmt: skip
        row = len(self.dampers) + names.index(stop)
        mine = self.events[:, _modal.E_DAMPER] == row
        kind = self.events[:, _rigid.E_KIND]
        begins = (
            (kind == _modal.KIND_ONSET)
            | (kind == _rigid.KIND_IMPACT)
            | (kind == _rigid.KIND_ACCUMULATION)
        )
        return self.events[mine & begins, _rigid.E_T]

    def impacts(self, damper: str) -> np.ndarray:
        """The times of damper ``damper``'s impacts [s]: the impacts it resolved and, for each
        chatter sequence, its accumulation point (as :attr:`~symimpact.forced.ForcedResult.
        impacts`); a compliant damper's contact onsets."""
        names = [d.name for d in self.dampers]
        if damper not in names:
            raise ParameterError("damper", f"no damper {damper!r} (the dampers: "
                                           f"{', '.join(names)})")  # fmt: skip
        k = names.index(damper)
        mine = self.events[:, _modal.E_DAMPER] == k
        kind = self.events[:, _rigid.E_KIND]
        kept = mine & (kind != _rigid.KIND_RELEASE) & (kind != _modal.KIND_EXIT)
        return self.events[kept, _rigid.E_T]

    def amplitudes(self, discard: Any = 0.5) -> dict[str, float]:
        """Every point's largest abs(x) over the periods kept after the first ``discard`` share
        [m]."""
        share = si_float("discard", discard)
        if not 0.0 <= share < 1.0:
            raise ParameterError("discard", f"must be a share in [0, 1), got {discard!r}")
        n = self.period_max.shape[0]
        kept = self.period_max[int(n * share) :]
        return {p: float(kept[:, j].max()) for j, p in enumerate(self.points)}

    def as_dict(self) -> dict[str, Any]:
        return {
            "dampers": [d.as_dict() for d in self.dampers],
            "force": {"at": self.force_at, "amplitude": self.F0},
            **({"base": {"amplitude": self.X_b}} if self.X_b != 0.0 else {}),
            "omega": self.omega,
            "t_end": self.t_end,
            "stops": [s.as_dict() for s in self.stops],
            "impacts": {d.name: len(self.impacts(d.name)) for d in self.dampers}
            | {s.name: len(self.contacts(s.name)) for s in self.stops},
            "amplitudes": self.amplitudes(),
            "energy": self.energy,
            "notes": self.notes,
        }


def _modal_parameters(structure: Structure, force_at: str, F0: float, omega: float,
                      phase: float, X_b: float = 0.0) -> np.ndarray:  # fmt: skip
    """One row of the one-mode engine's parameter layout per mode: Mᵢ, Kᵢ = ωᵢ²Mᵢ,
    Cᵢ = 2ζᵢωᵢMᵢ, Fᵢ = F₀φᵢ(f) + MᵢΓᵢΩ²X_b (Step 15, item 1; the second term the supports'
    motion X_b·cos(Ωt + φ) seen from the modes relative to them: the inertia −MᵢΓᵢẍ_b)."""
    pm = np.zeros((len(structure.modes), _rigid.N_PARAMS))
    for i, mode in enumerate(structure.modes):
        pm[i, _rigid.P_M] = mode.mass
        pm[i, _rigid.P_K] = mode.omega**2 * mode.mass
        pm[i, _rigid.P_C] = 2.0 * mode.zeta * mode.omega * mode.mass
        pm[i, _rigid.P_F0] = F0 * mode.shape[force_at]
        if X_b != 0.0:
            pm[i, _rigid.P_F0] += mode.mass * mode.participation * omega**2 * X_b
        pm[i, _rigid.P_W], pm[i, _rigid.P_PHI] = omega, phase
    return pm


def _energy(pm: np.ndarray, md: np.ndarray, q, v, u, stops: tuple[Stop, ...] = (),
            Sphi: Any = None, pressed: Any = (), vb: float = 0.0) -> float:  # fmt: skip
    """Σ(½Mᵢq̇ᵢ² + ½Kᵢqᵢ²) + Σ½mₖ(ẏₖ − ẋ_b)² + Σ½k₁(w·xₛ − g)² over the stops pressed on their
    wall w (``vb``: the supports' speed ẋ_b; the modes are relative to them)."""
    M, K = pm[:, _rigid.P_M], pm[:, _rigid.P_K]
    out = 0.5 * np.sum(M * v * v + K * q * q) + 0.5 * np.sum(md * (u - vb) * (u - vb))
    for j, (s, w) in enumerate(zip(stops, pressed, strict=True)):
        if w != 0:
            out += 0.5 * s.k1 * (w * float(Sphi[j] @ q) - s.gap) ** 2
    return float(out)


def simulate_structure(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega: Any,
                       periods: Any = 400, phase: Any = 0.0, state: Any = None,
                       chatter: Any = CHATTER, stops: Any = (),
                       variational: bool = False, base: Any = 0.0,
                       energy: bool = True) -> StructureResult:  # fmt: skip
    """Simulate ``structure`` with ``dampers`` (a sequence of :class:`~symimpact.model.dampers.
    Damper`) under the force F₀cos(Ωt + φ) at point ``force_at`` [N, rad/s, rad] for ``periods``
    forcing periods, from rest (on the supports: the masses centred on their points, moving
    with them) or from ``state`` = (q…, q̇…, y…, ẏ…) (modal coordinates, then each damper's
    absolute displacement and velocity).  Eq. F1 per mode, Eq. F7 at each impact.

    Chatter is taken to its accumulation point and the mass then sticks on its point until its
    wall would pull it (Step 15, item 5).  A damper with a compliant contact law (linear, Hertz,
    Hunt–Crossley: :mod:`symimpact.model.dampers`) presses its wall with the law's force, which
    enters the modes through their shapes (Eq. F7); its contact phases are integrated over the
    whole state (:mod:`symimpact.forced.engine._structure_contact`), its onsets and exits logged
    (kinds "contact onset", "contact exit"), and :meth:`StructureResult.impacts` gives its
    onsets.  Rigid dampers beside compliant ones fly through a contact phase as free masses and
    meet their walls there by Eq. F7 at once (:mod:`symimpact.forced.engine._structure_contact`).
    A linear stop acts in the contact phases by its law, its onsets and exits located there; a
    rigid stop by Newton's law at its point there (the structure's effective mass at the point,
    Step 15), its impacts located as onsets are.  A rigid damper's chatter accumulates in a
    contact phase as in flight, and its mass then rides on its point; a rigid stop's chatter
    accumulates there too, and its wall then holds the point; each until its wall would pull.
    ``stops``: a sequence of :class:`~symimpact.model.stops.Stop`, walls fixed to the ground,
    rigid or with a linear contact law; a pressed linear stop adds its spring and dashpot to the
    structure, whose flight stays closed form (:mod:`symimpact.model.stops`).  A structure with
    stops may carry no damper.  Refused in one line: an undamped mode driven at its own
    frequency (Eq. F1 cancels there, as in :func:`~symimpact.forced.simulate_forced`), and a
    run whose contact phase cannot be integrated (a contact too stiff for its time scale).
    ``variational``: carry the state's Jacobian (:attr:`StructureResult.monodromy`).

    ``base``: the supports' displacement amplitude X_b [m], moving as X_b·cos(Ωt + φ) (with or
    without the force).  The modal coordinates are then relative to the supports, each mode
    loaded by the inertia −MᵢΓᵢẍ_b (Eq. F7 with its participation factor Γᵢ); the dampers'
    displacements stay absolute, and a damper's point, the point its clearance is measured
    from, moves at x_b + Σφᵢqᵢ, as do the output points (:attr:`StructureResult.period_max`: the
    absolute amplitudes the bare structure's :meth:`~symimpact.model.structure.Structure.
    base_transmissibility` gives).  A stop's wall, fixed to the moving ground, is met by the
    point's displacement relative to it, Σφᵢqᵢ.  The energy ledger is then the one seen from
    the supports (the masses' speeds relative to them).

    ``energy``: keep the energy ledger (:attr:`StructureResult.energy`); without it the flights'
    work and dissipation are not integrated, a part of a run's cost (benchmark 10: the median of
    its eight 10-mode runs 1.2 times as fast without it), and ``energy`` is None.  The motion is
    the same to the bit."""
    structure = instance("structure", structure, Structure, "a Structure")
    energy = flag("energy", energy)
    dampers = tuple(dampers) if isinstance(dampers, (list, tuple)) else dampers
    stops = tuple(stops) if isinstance(stops, (list, tuple)) else stops
    if not isinstance(stops, tuple):
        raise ParameterError("stops", "must be a list of Stop")
    if not isinstance(dampers, tuple) or not (dampers or stops):
        raise ParameterError("dampers", "must be a non-empty list of Damper (or give stops)")
    for d in dampers:
        instance("dampers", d, Damper, "a Damper")
        structure._point(d.at)
    for st in stops:
        instance("stops", st, Stop, "a Stop")
        structure._point(st.at)
    names = [d.name for d in dampers] + [st.name for st in stops]
    if len(set(names)) < len(names):
        raise ParameterError("dampers", "two dampers or stops have the same name")
    check_walls(structure, stops)
    point = structure._point(force_at)
    F0 = nonnegative_float("F0", F0, "N")
    X_b = si_float("base", base, "m")
    if not math.isfinite(X_b):
        raise ParameterError("base", f"must be a finite displacement amplitude, got {base!r}")
    if X_b != 0.0 and not any(m.participation != 0.0 for m in structure.modes):
        raise ParameterError("base", "no mode of the structure has a participation factor: its "
                                     "supports' motion drives nothing (modal data give none; a beam or a "
                                     "finite-element model does)")  # fmt: skip
    omega = positive_float("omega", omega, "rad/s")
    phase = si_float("phase", phase)
    n_periods = whole_number("periods", periods, 1)
    chat = nonnegative_float("chatter", chatter)
    N, K = len(structure.modes), len(dampers)
    for mode in structure.modes:
        if mode.zeta == 0.0 and abs(omega / mode.omega - 1.0) < 5e-8 and omega != mode.omega:
            raise ParameterError("omega", f"within 5e-8 of the undamped mode {mode.number} "
                                          f"({mode.omega:.10g} rad/s): Eq. F1 cancels there")  # fmt: skip
    if state is None:  # at rest on the supports: the masses centred on their points, with them
        x0 = np.zeros(2 * N + 2 * K)
        x0[2 * N : 2 * N + K] = X_b * math.cos(phase)
        x0[2 * N + K :] = -X_b * omega * math.sin(phase)
    else:
        x0 = np.array(state, dtype=float).ravel()
        if x0.shape != (2 * N + 2 * K,) or not np.all(np.isfinite(x0)):
            raise ParameterError("state", f"must be {2 * N + 2 * K} finite numbers (q, q̇ of "
                                          f"{N} modes, y, ẏ of {K} dampers)")  # fmt: skip
    pm = _modal_parameters(structure, point, F0, omega, phase, X_b)
    Phi = structure.shapes([d.at for d in dampers]).reshape(K, N)
    Sphi = structure.shapes([st.at for st in stops]).reshape(len(stops), N)
    sg = np.array([st.gap for st in stops])
    sside = np.array([st.walls for st in stops], dtype=np.int64)
    sk = np.array([st.k1 for st in stops])
    sc = np.array([st.c1 for st in stops])
    srig = np.array([st.contact == "rigid" for st in stops], dtype=np.int64)
    se = np.array([st.e if st.contact == "rigid" else 0.0 for st in stops])
    md = np.array([d.m for d in dampers])
    hd = np.array([d.gap / 2.0 for d in dampers])
    ed = np.array([d.e for d in dampers])
    Pout = structure.shapes()
    q0, v0 = x0[:N].copy(), x0[N : 2 * N].copy()
    y0, u0 = x0[2 * N : 2 * N + K].copy(), x0[2 * N + K :].copy()
    t_end = n_periods * 2.0 * math.pi / omega
    natural = t_end * max(m.omega for m in structure.modes) / (2.0 * math.pi)
    if not natural <= budgets.MAX_NATURAL_PERIODS:
        raise ParameterError("periods", f"{n_periods} forcing periods last {natural:.3g} periods "
                                        f"of the highest mode; at most "
                                        f"{budgets.MAX_NATURAL_PERIODS:.0e}")  # fmt: skip
    law = np.array([-1 if d.rigid else _compliant.CODES[d.contact] for d in dampers],
                   dtype=np.int64)  # fmt: skip
    status, events, n_ev, period_max, ledger, final, G = _alternation(
        pm, Phi, md, hd, ed, law, dampers, chat, Sphi, sg, sside, sk, sc, srig, se, q0, v0, y0,
        u0, Pout, X_b, t_end, bool(variational), energy,
    )  # fmt: skip
    events = events[:n_ev]
    if status == _modal.SINGULAR_STUCK:
        raise MethodNotApplicable(
            "simulate_structure",
            f"at t = {events[-1][_rigid.E_T]:.6g} s a mass sticks and the structure carrying it "
            f"is undamped and resonant at Ω {omega:.6g} rad/s: its closed-form flight does not "
            "exist",
        )
    if status == _rigid.TOO_MANY_EVENTS:
        raise ParameterError("periods", f"more than {budgets.MAX_EVENTS} impacts in "
                                        f"{n_periods} periods; ask for fewer periods")  # fmt: skip
    pressed0 = [_pressed(st, float(Sphi[j] @ q0)) for j, st in enumerate(stops)]
    for st, w in zip(stops, pressed0, strict=True):
        if w != 0 and st.contact == "rigid":
            raise ParameterError("state", f"puts the point of stop {st.name!r} beyond its rigid "
                                          "wall")  # fmt: skip
    vb0 = -X_b * omega * math.sin(phase)
    vb1 = -X_b * omega * math.sin(omega * float(final[0]) + phase)
    e0 = _energy(pm, md, q0, v0, u0, stops, Sphi, pressed0, vb0)
    qf, vf = final[1 : 1 + N], final[1 + N : 1 + 2 * N]
    uf = final[1 + 2 * N + K : 1 + 2 * N + 2 * K]
    e1 = _energy(pm, md, qf, vf, uf, stops, Sphi, final[1 + 2 * N + 3 * K :], vb1)
    e0 += _pressing(dampers, Phi, q0, y0, X_b * math.cos(phase))
    e1 += _pressing(dampers, Phi, qf, final[1 + 2 * N : 1 + 2 * N + K],
                    X_b * math.cos(omega * float(final[0]) + phase))  # fmt: skip
    work, d_c, d_imp, d_stops = (float(x) for x in ledger)
    residual = (e1 - e0) - (work - d_c - d_imp - d_stops)
    scale = max(abs(work), d_c + d_imp + d_stops, e0, e1, 1e-300)
    energy = {"initial": e0, "final": e1, "forcing_work": work, "dissipated_C": d_c,
              "dissipated_impacts": d_imp, "dissipated_stops": d_stops, "residual": residual,
              "relative_residual": abs(residual) / scale} if energy else None  # fmt: skip
    return StructureResult(structure, dampers, point, F0, omega, t_end, events,
                           structure.points, period_max[:n_periods], energy, final,
                           stops=stops, monodromy=G if variational else None,
                           X_b=X_b)  # fmt: skip


def _pressing(dampers: tuple[Damper, ...], Phi: np.ndarray, q, y, x_b: float) -> float:
    """The elastic energy stored in the compliant dampers' contacts [J]."""
    lq, _ = _law_parameters(dampers)
    out = 0.0
    for k, d in enumerate(dampers):
        delta = abs(float(y[k]) - x_b - float(Phi[k] @ q)) - d.gap / 2.0
        if not d.rigid and delta > 0.0:
            out += _compliant.contact_potential(d.contact, lq[k], delta)
    return out


def _law_parameters(dampers: tuple[Damper, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Each compliant damper's law in the stepper's parameter layout, and its χ."""
    lq = np.zeros((len(dampers), _stepper.N_PARAMS))
    for k, d in enumerate(dampers):
        lq[k, _stepper.P_k1], lq[k, _stepper.P_c1], lq[k, _stepper.P_khz] = d.k1, d.c1, d.k_hz
    return lq, np.array([d.chi for d in dampers])


def _alternation(pm, Phi, md, hd, ed, law, dampers, chat, Sphi, sg, sside, sk, sc, srig, se, q0,
                 v0, y0, u0, Pout, X_b, t_end, variational, energy):  # fmt: skip
    """The modal engine's closed-form flights and rigid events, alternating with the compliant
    dampers' contact phases (:mod:`symimpact.forced.engine._structure_contact`): (status, events, their
    count, period maxima, ledger, final, G) as :func:`symimpact.forced.engine._modal.run` returns
    them."""
    N, K = len(q0), len(y0)
    lq, chi = _law_parameters(dampers)
    # the stops as the contact phases read them: φ at the point, gap, k₁, c₁, walls, rigid, e,
    # the wall a rigid one holds its point on (set in a phase)
    stp = np.column_stack([Sphi.reshape(len(sg), N), sg, sk, sc, sside, srig, se,
                           np.zeros(len(sg))]).astype(float)  # fmt: skip
    scale = float(np.min(hd)) if K else 1.0
    peak = float(np.max(np.abs(Phi))) if K else 1.0
    fastest = max(float(np.max(np.sqrt(pm[:, _rigid.P_K] / pm[:, _rigid.P_M]))), pm[0, _rigid.P_W])
    atol = np.concatenate([np.full(N, 1e-14 * scale / peak),
                           np.full(N, 1e-14 * scale / peak * fastest),
                           np.full(K, 1e-14 * scale), np.full(K, 1e-14 * scale * fastest)])  # fmt: skip
    t = 0.0
    q, v, y, u = q0, v0, y0, u0
    logs, total, ledger, period_max = [], 0, np.zeros(4), None
    # the wall each rigid mass rides on, and each rigid stop holds its point on, as a contact
    # phase ends (or 0)
    riding, held = np.zeros(K), np.zeros(len(sg))
    while True:
        status, events, n_ev, pmx, led, final, G = _interrupt.call(
            _modal.run, pm, Phi, md, hd, ed, np.zeros(K), law, chat, Sphi, sg, sside, sk, sc,
            srig, se, q, v, y, u, Pout, X_b, t, t_end, budgets.MAX_EVENTS - total, variational,
            riding, held, energy,
        )  # fmt: skip
        logs.append(events[:n_ev])
        total += n_ev
        ledger += led
        period_max = pmx if period_max is None else np.maximum(period_max, pmx)
        if status != _modal.CONTACT:
            break
        onset = events[n_ev - 1]
        k, s = int(onset[_modal.E_DAMPER]), float(onset[_rigid.E_SIDE])
        t = float(final[0])
        riding = final[1 + 2 * N + 2 * K : 1 + 2 * N + 3 * K].copy()
        q, v = final[1 : 1 + N].copy(), final[1 + N : 1 + 2 * N].copy()
        y, u = (
            final[1 + 2 * N : 1 + 2 * N + K].copy(),
            final[1 + 2 * N + K : 1 + 2 * N + 2 * K].copy(),
        )
        walls0 = final[1 + 2 * N + 3 * K :].copy()
        st, t, state, rise, found, n_found, _, walls, riding = _structure_contact.phase(
            pm, Phi, md, hd, law, lq, chi, stp, X_b, Pout, t, q, v, y, u, k, s, t_end, period_max,
            atol, ed, chat * 2.0 * math.pi / pm[0, _rigid.P_W], walls0, riding,
        )  # fmt: skip
        if st != 0:
            raise MethodNotApplicable("simulate_structure", f"at t = {t:.6g} s the contact of "
                                      f"damper {dampers[k].name!r} is too stiff for the "
                                      "integrator's steps (its time scale is below 1e-14 of "
                                      "the period, or it takes 2e6 steps)")  # fmt: skip
        held = np.where(srig != 0, walls, 0.0)
        ledger += rise
        rows = np.zeros((n_found, _modal.N_MODAL_EVENT_COLS))
        for j, (te, kd, side, kind, rate, xa, va, ua, va1, ua1, lost) in enumerate(found):
            rows[j, [_rigid.E_T, _rigid.E_X, _rigid.E_XD, _rigid.E_YD, _rigid.E_SIDE]] = (
                te,
                xa,
                va,
                ua,
                side,
            )
            rows[j, [_rigid.E_VREL, _rigid.E_KIND, _rigid.E_XD1, _rigid.E_YD1, _rigid.E_LOST]] = (
                abs(rate),
                kind,
                va1,
                ua1,
                lost,
            )
            rows[j, _modal.E_DAMPER] = kd
        logs.append(rows)
        total += n_found
        q, v = state[:N], state[N : 2 * N]
        y, u = state[2 * N : 2 * N + K], state[2 * N + K :]
        if t >= t_end:
            final = np.concatenate([[t], state, riding, walls])
            status = _rigid.OK
            break
        if total + 2 > budgets.MAX_EVENTS:
            status = _rigid.TOO_MANY_EVENTS
            break
    if len(logs) > 1:
        G = np.full_like(G, np.nan)
    events = np.concatenate(logs) if logs else np.zeros((0, _modal.N_MODAL_EVENT_COLS))
    return status, events, len(events), period_max, ledger, final, G


def _pressed(st: Stop, x: float) -> int:
    """The wall a stop's point at x presses at the start (the engine's rule), or 0 (a rigid
    stop's point starts beyond its wall only if the state says so: it is then held there)."""
    if st.walls >= 0 and x > st.gap:
        return 1
    if st.walls <= 0 and x < -st.gap:
        return -1
    return 0
