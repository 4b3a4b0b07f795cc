"""Forced response with rigid impacts: :func:`simulate_forced`, and the steady state it reaches.

The simulation is event driven and closed form between events (Step 8's forced flight, Eq. F1;
Step 9's impact law, Eq. F2), with chatter taken to its accumulation point and sticking phases:
the engine of a structure of several modes and dampers (:mod:`symimpact.forced.engine._modal`) run with
one mode of shape 1 and one damper, the primary of the paper.  The steady state is read over the
kept forcing periods: the amplitude max abs(x), the impacts per period, and the period of the
motion from the Poincaré section at t = k·T (the state once per forcing period).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import Any

import numpy as np

from .. import _interrupt, budgets
from .._compiled import compiled
from ..errors import MethodNotApplicable, ParameterError, SymimpactError
from ..free import _stepper
from ..model.checks import bounded, instance, whole_number
from ..model.system import ImpactSystem
from ..model.units import nonnegative_float, si_float
from .contact_law import COMPLIANT, MaterialRestitution, restitution_parameters
from .engine import _compliant, _modal, _rigid
from .forcing import Forcing

#: Chatter is taken to its accumulation point when the remaining impacts would all fall within
#: this fraction of a forcing period (the constant-acceleration limit is then exact to O(Δ²)).
CHATTER = 1e-7
#: The Poincaré section repeats when two of its points agree to this fraction of the state's
#: scale (the motion's amplitude and velocity amplitude): far above the closed-form flight's
#: rounding, far below any physical difference between distinct orbits.
SECTION_RTOL = 1e-6
#: Work budgets (see :mod:`symimpact.budgets`).
MAX_EVENTS, MAX_CONTACTS = budgets.MAX_EVENTS, budgets.MAX_CONTACTS


class TooManyContacts(SymimpactError):
    """A compliant run met more contacts than it was allowed."""


class TooMuchContactWork(SymimpactError):
    """A compliant run's contacts needed more evaluations of their equations than allowed."""


MAX_NATURAL_PERIODS = budgets.MAX_NATURAL_PERIODS
MAX_MULTIPLE = 8


@dataclass(frozen=True)
class Steady:
    """The steady state over the kept periods.

    ``amplitude`` [m]: max abs(x); ``impacts_per_period``: impacts (accumulated chatter counts as
    one) per forcing period; ``periodic``: the Poincaré section repeats; ``period_multiple``: the
    smallest k ≤ 8 with which it repeats (0 when it does not); ``section_spread`` [1]: the largest
    distance between points k periods apart, relative to the state's scale; ``settling``: the
    change from one period to the next shrank more than twofold across the kept window (a
    transient still decaying: the verdict may change with a larger ``discard``).
    """

    amplitude: float
    impacts_per_period: float
    periodic: bool
    period_multiple: int
    section_spread: float
    settling: bool = False
    #: impact events a period: a chatter sequence (the impacts on one wall that accumulate)
    #: counts once, however many of its impacts the run resolved before jumping to their limit
    impact_events_per_period: float = 0.0

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


@dataclass(frozen=True)
class ForcedResult:
    """Outcome of :func:`simulate_forced` (SI units)."""

    system: ImpactSystem
    forcing: Forcing
    #: Newton's restitution (Eq. F2), a MaterialRestitution (Eq. F5, per impact), or None
    e: Any
    t_end: float
    events: np.ndarray  # (n, 10): columns named by EVENT_COLUMNS
    period_max: np.ndarray  # largest abs(x) in each whole forcing period
    #: what :attr:`energy` is computed from, with the initial state: the engine's final row, its
    #: ledger terms, the contact's elastic energy at the end and at the start
    ledger_terms: tuple = field(repr=False, compare=False)
    final_state: tuple[float, float, float, float]
    initial_state: tuple[float, float, float, float]
    final_stuck: bool
    steady: Steady | None = None
    notes: list[str] = field(default_factory=list)
    #: "rigid", or the compliant law ("cubic", "hertz", "linear", "hunt-crossley")
    contact: str = "rigid"
    #: Hunt–Crossley's χ [s/m] (None for the other laws)
    chi: float | None = None
    #: compliant runs: the state (x, ẋ, z, ẏ) at t = k·T/samples_per_period
    samples: np.ndarray | None = None
    #: compliant runs: the evaluations of the equations of motion the contacts took
    contact_evaluations: int = 0

    @cached_property
    def energy(self) -> dict[str, float]:
        """The energy balance of the run (:func:`_ledger`), formed when first read: the
        continuation's tens of thousands of one-period runs never read it."""
        return _ledger(self.system, self.forcing, self.initial_state, *self.ledger_terms)

    @property
    def impacts(self) -> np.ndarray:
        """Times of the impacts (chatter accumulations included) [s]."""
        kinds = self.events[:, _rigid.E_KIND]
        return self.events[kinds != _rigid.KIND_RELEASE, _rigid.E_T]

    @property
    def impact_displacements(self) -> np.ndarray:
        """The main mass's displacement x at each of :attr:`impacts` (a compliant contact's
        onset) [m]."""
        kinds = self.events[:, _rigid.E_KIND]
        return self.events[kinds != _rigid.KIND_RELEASE, _rigid.E_X]

    def as_dict(self) -> dict[str, Any]:
        return {
            "system": {k: self.system.as_dict()[k] for k in ("M", "K", "C", "m", "gap")},
            "forcing": self.forcing.as_dict(),
            "contact": self.contact,
            **({"chi": self.chi} if self.chi is not None else {}),
            "e": self.e.as_dict() if isinstance(self.e, MaterialRestitution) else self.e,
            "t_end": self.t_end,
            "n_impacts": len(self.impacts),
            # the keys a structure's run has (:meth:`StructureResult.as_dict`): the primary is
            # its one point, the damper its one damper (one schema, docs/guide.md "Results")
            "impacts": {"damper": len(self.impacts)},
            "amplitudes": {} if self.steady is None else {"primary": self.steady.amplitude},
            "energy": self.energy,
            "final_state": list(self.final_state),
            "steady": None if self.steady is None else self.steady.as_dict(),
            "notes": self.notes,
        }


EVENT_COLUMNS = (
    "t",
    "x",
    "xdot_before",
    "ydot_before",
    "side",
    "approach_speed",
    "energy_lost",
    "kind",
    "xdot_after",
    "ydot_after",
)


def simulate_forced(
    system: ImpactSystem,
    forcing: Forcing,
    *,
    contact: str = "rigid",
    e: Any = None,
    chi: Any = None,
    periods: Any = 100,
    discard: Any = None,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    chatter: float = CHATTER,
    samples_per_period: int = 16,
) -> ForcedResult:
    """Forced response of the primary with the impact damper, for ``periods`` forcing periods.

    ``contact="rigid"``: Eq. F1 (forced flight, Step 8) between impacts and Eq. F2 (rigid impact
    law with Newton's coefficient ``e``, Step 9) at them; chatter accumulates to its limit point
    t∞ = t₀ + 2w/(a(1 − e)) and a sticking phase follows while the contact force is compressive.
    ``contact`` "cubic", "hertz", "linear" (the system's law parameters and c1) or
    "hunt-crossley" (the system's k_hz and ``chi`` [s/m], Eq. F4): Eq. F1 in flight, the contact
    phase integrated with the forcing (:mod:`symimpact.forced.engine._compliant`).  With ``discard`` (a
    number of periods) the result's ``steady`` describes the periods after it.
    """
    instance("system", system, ImpactSystem, "an ImpactSystem")
    instance("forcing", forcing, Forcing, "a Forcing")
    e, chi, law = contact_arguments(system, contact, e, chi)
    n_periods = period_count("periods", periods)
    if n_periods < 1:
        raise ParameterError("periods", "must be at least 1")
    n_discard = 0 if discard is None else period_count("discard", discard)
    if discard is not None and n_discard >= n_periods:
        raise ParameterError("discard", f"{n_discard} leaves none of the {n_periods} periods")
    state = [
        si_float(n, v) for n, v in (("x0", x0), ("xdot0", xdot0), ("y0", y0), ("ydot0", ydot0))
    ]
    h = system.gap / 2.0
    if contact == "rigid":
        within_walls("y0", state[0], state[2], h)
    chatter = bounded("chatter", chatter, 0.0)  # a fraction of the forcing period
    samples_per_period = whole_number("samples_per_period", samples_per_period, 16, 4096)
    if samples_per_period % 16:
        raise ParameterError("samples_per_period", "must be a multiple of 16")
    result, _ = _simulate(system, forcing, contact, e, chi, law, state, n_periods, chatter,
                          samples_per_period)  # fmt: skip
    if discard is not None:
        steady = steady_state(result, n_discard)
        notes = []
        if steady.settling:
            notes.append(
                "still settling: the state once per period changes less and less across the kept "
                f"window; discard more than {n_discard} periods for a settled verdict"
            )
        result = replace(result, steady=steady, notes=notes)
    return result


#: The parameter that sets a compliant law's stiffness (named when a contact cannot be resolved).
_STIFFNESS = {"linear": "k1", "cubic": "a", "hertz": "k_hz", "hunt-crossley": "k_hz"}

#: The closed-form flight (Eq. F1) is the steady solution plus the free decay that corrects the
#: initial state; near an undamped resonance both grow like K/√((K − MΩ²)² + (CΩ)²) and cancel,
#: and the flight keeps about 1e-16 of that ratio as error, relative to the motion (measured
#: against mpmath at 50 digits, C = 0, 20 s of flight: 5.4e-11 at a ratio of 5e5, 3.3e-9 at 5e7,
#: 7.6e-7 at 5e9).  Above this ratio a run is refused rather than wrong by more than ~1e-9.
CANCELLATION = 1e7


def _refuse_cancelling_flight(system: ImpactSystem, forcing: Forcing, contact: str) -> None:
    """Refuse Ω so close to an undamped (or nearly undamped) resonance of the primary — alone,
    or stuck with the impact mass in a rigid run — that Eq. F1 loses its digits (see
    :data:`CANCELLATION`); exactly at the resonance with C = 0 the kernel's resonant branch
    holds and is used."""
    W = forcing.omega
    for mass in (system.M, system.M + system.m) if contact == "rigid" else (system.M,):
        detuning = system.K - mass * W * W
        if system.C == 0.0 and detuning == 0.0:
            continue
        ratio = system.K / math.hypot(detuning, system.C * W)
        if ratio > CANCELLATION:
            wn = math.sqrt(system.K / mass)
            raise ParameterError(
                "omega",
                f"Ω = {W:.15g} rad/s lies within {abs(W / wn - 1):.1e} of the lightly damped "
                f"resonance √(K/{'M' if mass == system.M else '(M + m)'}) = {wn:.15g} rad/s, "
                f"where the closed-form flight cancels to fewer than 9 digits; move Ω by more "
                f"than {0.5 / CANCELLATION:.0e} of it",
            )


def settling_periods(
    system: ImpactSystem, forcing: Forcing, kept: int, most: int, settled: float = 1e-6
) -> int:
    """Forcing periods for the primary's free transient to fall to ``settled`` of its start,
    exp(−ζω_n·t) (ζω_n = C/(2M), Step 8's free decay), plus ``kept``; at most ``most`` (no
    damping: ``most``)."""
    decay = system.C / (2.0 * system.M)  # ζω_n [1/s]
    if not decay > 0:
        return most
    return min(most, math.ceil(-math.log(settled) / decay / forcing.period) + kept)


#: The spacing of doubles at 1 (numpy.finfo(float).eps, read once: 3 µs a call).
_EPS = float(np.finfo(float).eps)


def within_walls(name: str, x: float, y: float, h: float) -> None:
    """Refuse a start of rigid impacts with the impact mass beyond a wall, abs(y − x) > d/2 = h,
    allowing the rounding y − x carries (a few units in the last place of the larger), which a
    clearance far below the motion does not dwarf."""
    slack = h * 1e-12 + 4.0 * _EPS * max(abs(x), abs(y))
    if abs(y - x) > h + slack:
        raise ParameterError(name, f"abs(y0 − x0) must not exceed d/2 = {h:g} m")


def contact_arguments(system: ImpactSystem, contact: str, e: Any, chi: Any):
    """(e, chi, the law's parameter vector) for ``contact``, checked: rigid impacts take Newton's
    ``e`` in [0, 1] (Eq. F2) or a :class:`~symimpact.forced.contact_law.MaterialRestitution`
    (Eq. F5, per impact), Hunt–Crossley its ``chi`` [s/m] and k_hz (Eq. F4), the other
    compliant laws their own parameters (Eq. 8, 9, 35); anything else is refused in one line."""
    if not isinstance(contact, str) or (contact != "rigid" and contact not in COMPLIANT):
        raise ParameterError(
            "contact", f"must be rigid or one of {', '.join(COMPLIANT)}, got {contact!r}"
        )
    if contact == "rigid":
        if e is None:
            raise ParameterError("e", "rigid impacts need Newton's coefficient of restitution e")
        if not isinstance(e, MaterialRestitution):
            e = nonnegative_float("e", e)
            if e > 1.0:
                raise ParameterError("e", f"must lie in [0, 1], got {e:g}")
    elif e is not None:
        raise ParameterError("e", f"applies to rigid impacts; contact {contact} sets its own")
    if contact == "hunt-crossley":
        if chi is None:
            raise ParameterError("chi", "the Hunt–Crossley law needs its damping χ [s/m]")
        chi = nonnegative_float("chi", chi)
        if system.k_hz is None:
            raise ParameterError("k_hz", "the Hunt–Crossley law needs the Hertz stiffness k_hz")
    elif chi is not None:
        raise ParameterError("chi", "applies to the Hunt–Crossley contact only")
    return e, chi, _law_parameters(system, contact)


def _simulate(system, forcing, contact, e, chi, law, state, n_periods, chatter=CHATTER,
              samples_per_period=16, variational=False, max_contacts=None,
              max_work=None):  # fmt: skip
    """The checked run of :func:`simulate_forced` from ``state`` = (x, ẋ, y, ẏ) at t = 0 (a
    compliant run may start inside a wall), and, compliant with ``variational``, the Jacobian Ψ of
    the final (x, ẋ, y, ẏ) with respect to ``state`` (:mod:`symimpact.forced.engine._compliant`; None
    with rigid impacts, whose chain is built from the event log); ``max_contacts`` in place of
    :data:`MAX_CONTACTS`; ``max_work`` (evaluations of the contacts' equations) in place of
    :data:`symimpact.budgets.RHS_BUDGET`, met with :class:`TooMuchContactWork`."""
    _refuse_cancelling_flight(system, forcing, contact)
    h = system.gap / 2.0
    p = np.zeros(_rigid.N_PARAMS)
    p[_rigid.P_M], p[_rigid.P_K], p[_rigid.P_C] = system.M, system.K, system.C
    p[_rigid.P_m], p[_rigid.P_h] = system.m, h
    p[_rigid.P_e], p[_rigid.P_VY] = restitution_parameters(e)
    p[_rigid.P_F0], p[_rigid.P_XB] = forcing.primary_force, forcing.X_b
    p[_rigid.P_W], p[_rigid.P_PHI], p[_rigid.P_CHAT] = forcing.omega, forcing.phase, chatter
    t_end = n_periods * forcing.period
    natural = t_end * math.sqrt(system.K / system.M) / (2.0 * math.pi)
    if not natural <= MAX_NATURAL_PERIODS:
        raise ParameterError(
            "periods",
            f"{n_periods} forcing periods at Ω = {forcing.omega:.3g} rad/s last "
            f"{natural:.3g} natural periods of the primary; at most {MAX_NATURAL_PERIODS:.0e}",
        )
    samples = None
    psi = None
    potential = potential0 = 0.0
    work = 0
    if contact == "rigid":
        status, events, n_ev, period_max, ledger, final = _interrupt.call(
            _modal.one_mode_run, p, np.array(state, dtype=float), t_end,
            max_contacts or MAX_EVENTS, False, True,
        )  # fmt: skip
    else:
        status, events, period_max, ledger, final, samples, psi, work = _compliant.run(
            contact,
            law,
            chi,
            p,
            state,
            t_end,
            max_contacts or MAX_CONTACTS,
            samples_per_period,
            variational,
            max_work or _compliant.RHS_BUDGET,
        )
        n_ev = len(events)
        z0 = state[2] - state[0]
        if abs(z0) > h:  # begun inside a wall: the contact's elastic energy is the start's too
            potential0 = _compliant.contact_potential(contact, law, abs(z0) - h)
        if final is not None and final[5]:
            side = 1.0 if final[3] > final[1] else -1.0
            delta = side * (final[3] - final[1]) - h
            potential = _compliant.contact_potential(contact, law, delta)
    if status in (_compliant.TOO_MANY_STEPS, _compliant.STEP_UNDERFLOW):
        raise ParameterError(
            _STIFFNESS.get(contact, "k_hz"),
            f"the {contact} contact's time scale is out of proportion to the motion: a contact "
            f"needs more than {_compliant.MAX_CONTACT_STEPS:,} steps or steps below 1e-15 of "
            "the time (a contact this stiff is contact rigid with its restitution; else check "
            "the masses and the clearance)",
        )
    if status == _compliant.GRAZED:
        raise MethodNotApplicable(
            "shooting", "a contact begins at zero approach speed (a grazing onset): the orbit's "
            "derivatives do not exist there")  # fmt: skip
    if status == _compliant.UNRESOLVED:
        raise ParameterError(
            _STIFFNESS.get(contact, "k_hz"),
            f"the {contact} contact is too stiff for its orbit's derivatives: a contact's exit "
            "rate falls below the state's precision (its duration is a vanishing share of the "
            "period); use contact rigid with this contact's restitution",
        )
    if status == _compliant.TOO_MUCH_WORK and max_work:
        raise TooMuchContactWork(
            f"the contacts of {n_periods} periods need more than {max_work:,} evaluations"
        )
    if status == _compliant.TOO_MUCH_WORK:
        raise SymimpactError(
            f"the contacts of {n_periods} periods need more than {_compliant.RHS_BUDGET:,} "
            "evaluations (long, stiff contacts): shorten the run or use contact rigid"
        )
    if status == _rigid.TOO_MANY_EVENTS and (contact != "rigid" or max_contacts):
        raise TooManyContacts(
            f"more than {max_contacts or MAX_CONTACTS:,} contacts in {n_periods} periods, each "
            "integrated: "
            "shorten the run or use contact rigid"
        )
    if status == _rigid.TOO_MANY_EVENTS:
        raise SymimpactError(
            f"more than {MAX_EVENTS:,} impacts in {n_periods} periods: raise the chatter "
            "fraction or shorten the run"
        )
    events = events[:n_ev].copy()
    result = ForcedResult(
        system=system,
        forcing=forcing,
        e=e,
        t_end=float(final[0]),
        events=events,
        period_max=period_max[:n_periods],
        ledger_terms=(final, ledger, potential, potential0),
        final_state=(float(final[1]), float(final[2]), float(final[3]), float(final[4])),
        initial_state=tuple(state),
        final_stuck=bool(final[5]) if contact == "rigid" else False,
        contact=contact,
        chi=chi,
        samples=samples,
        contact_evaluations=int(work),
    )
    return result, psi


def _law_parameters(system: ImpactSystem, contact: str) -> np.ndarray:
    """The compliant law's parameters as the stepper's vector, refused in one line when
    missing."""
    if contact == "rigid":
        return np.zeros(0)
    if contact == "cubic" and (system.a is None or system.b is None):
        raise ParameterError("a", "the cubic contact law needs a and b (or k_hz to fit them)")
    if contact == "linear" and system.k1 is None:
        raise ParameterError("k1", "the linear contact law needs k1 (or k_hz to fit it)")
    if contact == "hertz" and system.k_hz is None:
        raise ParameterError("k_hz", "the Hertz contact law needs k_hz")
    return _stepper.pack(system, 0.0, 0.0, 0.0)


def period_count(name: str, value: Any) -> int:
    """A whole number of forcing periods, 0 to 10⁷ (``periods``, ``discard``)."""
    v = si_float(name, value)
    if v != int(v) or v < 0:
        raise ParameterError(name, f"must be a whole number of periods, got {v:g}")
    if v > 10_000_000:
        raise ParameterError(name, f"{v:g} periods is more than 10^7")
    return int(v)


def _energy(system: ImpactSystem, forcing: Forcing, t: float, s) -> float:
    """½Mẋ² + ½K(x − x_b)² + ½mẏ² at time t."""
    xb = forcing.X_b * math.cos(forcing.omega * t + forcing.phase)
    return (
        0.5 * system.M * s[1] ** 2 + 0.5 * system.K * (s[0] - xb) ** 2 + 0.5 * system.m * s[3] ** 2
    )


def _ledger(system, forcing, state0, final, ledger, potential=0.0, potential0=0.0):
    """The energy balance: E(end) − E(0) = work of the forcing − dissipation by C − impact loss
    (rigid) or the contact's damping (compliant); ``potential`` and ``potential0``: the contact's
    elastic energy when the run ends, and when it starts, in contact."""
    e0 = _energy(system, forcing, 0.0, state0) + potential0
    e1 = _energy(system, forcing, float(final[0]), [final[1], final[2], final[3], final[4]])
    e1 += potential
    work, d_c, d_imp = (float(v) for v in ledger)
    residual = (e1 - e0) - (work - d_c - d_imp)
    scale = max(abs(work), d_c + d_imp, e0, e1, 1e-300)
    return {
        "initial": e0,
        "final": e1,
        "forcing_work": work,
        "dissipated_C": d_c,
        "dissipated_impacts": d_imp,
        "residual": residual,
        "relative_residual": abs(residual) / scale,
    }


def state_at(result: ForcedResult, times: np.ndarray) -> np.ndarray:
    """The state (x, ẋ, z = y − x, ẏ) at the given times [s], rebuilt from the event log: the
    closed-form flight (Eq. F1) from the last event before each time, with the mass M + m in a
    sticking phase.  At an event's time the state after it is returned.  Compiled
    (:func:`symimpact.forced.engine._rigid.states_at`): the continuation asks for a few states at every
    point, where the vectorised NumPy kernels cost 0.4 ms a call in overhead."""
    times = np.asarray(times, dtype=float)
    if result.samples is not None:
        return _sampled(result, times)
    sysm, f = result.system, result.forcing
    shape = times.shape
    out = _rigid.states_at(
        np.ascontiguousarray(result.events, dtype=float), times.reshape(-1),
        np.asarray(result.initial_state, dtype=float), bool(result.final_stuck),
        sysm.gap / 2.0, sysm.M, sysm.m, sysm.K, sysm.C, f.primary_force, f.X_b, f.omega,
        f.phase,
    )  # fmt: skip
    return out.reshape(*shape, 4) if shape else out[0]


def _sampled(result: ForcedResult, times: np.ndarray) -> np.ndarray:
    """A compliant run's recorded states at ``times`` (each on its sample grid k·T/n)."""
    n = (result.samples.shape[0] - 1) // max(len(result.period_max), 1)
    dt = result.forcing.period / n
    k = np.rint(times / dt).astype(int)
    if np.any(np.abs(times - k * dt) > 1e-9 * result.forcing.period) or np.any(
        (k < 0) | (k >= result.samples.shape[0])
    ):
        raise MethodNotApplicable(
            "state_at", f"a compliant run records the state at k·T/{n} only (its sample grid)"
        )
    return result.samples[k]


#: Candidate section phases: sixteen per period; the one farthest from every impact is used.
_SECTION_PHASES = np.arange(16) / 16.0


def steady_state(result: ForcedResult, discard: int) -> Steady:
    """The steady state over the periods after ``discard`` (see :class:`Steady`).

    The Poincaré section is taken once per forcing period at the fraction of the period farthest
    from every impact in the kept window (a section at an impact would see the state before it in
    one period and after it in the next)."""
    instance("result", result, ForcedResult, "a ForcedResult (from simulate_forced)")
    n = len(result.period_max)
    discard = whole_number("discard", discard, 0, n - 1)
    amplitude = float(np.max(result.period_max[discard:n]))
    T = result.forcing.period
    t0, t1 = discard * T, n * T
    times = result.impacts
    kept = times[(times >= t0) & (times < t1)]
    fractions = (kept / T) % 1.0
    if len(fractions):
        gaps = np.abs(_SECTION_PHASES[:, None] - fractions[None, :])
        gaps = np.minimum(gaps, 1.0 - gaps).min(axis=1)
        offset = float(_SECTION_PHASES[int(np.argmax(gaps))])
    else:
        offset = 0.0
    sec = state_at(result, (np.arange(discard, n) + offset) * T)
    w = result.forcing.omega
    scale = np.array([amplitude, amplitude * w, result.system.gap, amplitude * w])
    rel = sec / np.where(scale > 0, scale, 1.0)
    multiple, spread = 0, math.inf
    for k in range(1, MAX_MULTIPLE + 1):
        if len(rel) <= 2 * k:
            break
        d = float(np.max(np.abs(rel[k:] - rel[:-k])))
        if k == 1:
            spread = d
        if d <= SECTION_RTOL:
            multiple, spread = k, d
            break
    settling = multiple != 1 and _settling(rel)
    if settling:
        # a transient spiralling in (complex multipliers) can come back within SECTION_RTOL
        # after k periods while the period-to-period step still shrinks: not a period-k motion
        multiple = 0
    # impacts are counted over whole periods between sections (the phase farthest from every
    # impact), never at a period's start where an impact at a boundary would fall on either side
    # by rounding (a run started on an orbit impacts exactly there)
    if n - discard >= 2:
        lo, hi, counted = (discard + offset) * T, (n - 1 + offset) * T, n - discard - 1
    else:
        lo, hi, counted = t0, t1, n - discard
    impacts, events = impact_counts(result.events, lo, hi)
    return Steady(
        amplitude=amplitude,
        impacts_per_period=impacts / counted,
        impact_events_per_period=events / counted,
        periodic=multiple > 0,
        period_multiple=multiple,
        section_spread=spread,
        settling=settling,
    )


def impact_counts(events: np.ndarray, lo: float, hi: float) -> tuple[int, int]:
    """(impacts, impact events) with times in [lo, hi) of an event table (:data:`EVENT_COLUMNS`).

    Impacts: every impact the run resolved, an accumulation of chatter counting as one.  Impact
    events: the same with each chatter sequence counted once — the impacts on one wall since the
    last release or impact on the other wall, when an accumulation ends them.  The second does
    not depend on how many impacts of a sequence are resolved before the jump to its limit
    (:data:`CHATTER`); the first does."""
    if not len(events):
        return 0, 0
    kind = np.ascontiguousarray(events[:, _rigid.E_KIND])
    side = np.ascontiguousarray(events[:, _rigid.E_SIDE])
    inside = (events[:, _rigid.E_T] >= lo) & (events[:, _rigid.E_T] < hi)
    absorbed = _absorbed(kind, side, float(_rigid.KIND_RELEASE), float(_rigid.KIND_ACCUMULATION))
    impacts = inside & (kind != _rigid.KIND_RELEASE)
    return int(np.count_nonzero(impacts)), int(np.count_nonzero(impacts & ~absorbed))


@compiled
def _absorbed(kind, side, release, accumulation):
    """The impacts a later accumulation on their wall ends (a run on one wall since the last
    release or impact on the other wall), one pass (runs have ~1e5 events)."""
    out = np.zeros(kind.shape[0], dtype=np.bool_)
    start = -1  # first index of the current run of impacts on one wall, -1: none
    for i in range(kind.shape[0]):
        if kind[i] == release:
            start = -1
        elif kind[i] == accumulation:
            if start >= 0 and side[start] == side[i]:
                out[start:i] = True
            start = -1
        else:
            if start >= 0 and side[start] != side[i]:
                start = -1
            if start < 0:
                start = i
    return out


def _settling(rel: np.ndarray) -> bool:
    """Whether the period-to-period change of the section shrinks more than twofold from the
    first to the last quarter of the kept window (medians, so that a chaotic motion's scatter
    does not count as a trend)."""
    if len(rel) < 9:
        return False
    step = np.max(np.abs(np.diff(rel, axis=0)), axis=1)
    q = len(step) // 4
    first, last = float(np.median(step[:q])), float(np.median(step[-q:]))
    return last < 0.5 * first
