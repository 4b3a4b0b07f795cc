"""Periodic orbits by shooting, through rigid impacts or a compliant contact: :func:`monodromy`
and :func:`shoot`.

The stroboscopic (Poincaré) map P takes the state s = (x, ẋ, z = y − x, ẏ) at t = 0 to the state
k forcing periods later; a period-k orbit is a fixed point of P.  P is evaluated by the
event-driven simulation (Eq. F1 in flight, Eq. F2 at impacts) and its Jacobian — the monodromy
matrix — is carried along it, not differenced: each flight contributes its transition matrix Φ(τ)
(the flight is affine in the state, Step 8's free-decay solutions) and each impact Step 9's
saltation matrix S, which adds to the impact law's Jacobian the effect of arriving earlier or
later.  With a compliant contact (``e`` a :class:`~symimpact.forced.CompliantContact`) each
contact is integrated with its variational equations and the located onsets and exits are
differentiated (:mod:`symimpact.forced.engine._compliant`).  Newton's method on P(s) − s = 0 with the
Jacobian (monodromy − I) converges quadratically from a state near the orbit (a brute-force
steady state, or a closed-form orbit); the eigenvalues of the monodromy are the Floquet
multipliers.

Rigid orbits that chatter and stick are followed too (:func:`rigid_monodromy`): the simulation
takes a chatter sequence to its accumulation point in closed form and the masses then move
together, so the Jacobian is the chain rule of those closed forms (the accumulation time
Δ = 2w/(a(1 − e)), the common speed after it) and of the sticking pair's Φ(τ) of mass M + m; a
sticking phase keeps two of the four directions, so two multipliers vanish.  A section that
falls on a wall (inside a sticking phase) is moved to the middle of the longest free flight and
the state is mapped back.  With a compliant contact every contact of the period is integrated
with its variational equations (the cost is linear in them: a fixed number of evaluations a
contact), within :data:`~symimpact.budgets.SHOOTING_EVALUATIONS_PER_PERIOD` evaluations a period
(no cap on the contacts themselves).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ... import _interrupt, budgets
from ...errors import MethodNotApplicable, ParameterError
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import (
    CompliantContact,
    checked,
    is_rigid,
    restitution_parameters,
    simulation_arguments,
)
from ..engine import _chain, _rigid
from ..forcing import Forcing
from ..simulation import (
    TooManyContacts,
    TooMuchContactWork,
    _simulate,
    contact_arguments,
    impact_counts,
    period_count,
    simulate_forced,
    state_at,
    within_walls,
)

#: Newton stops when the change of the fixed-point residual is below this fraction of the
#: state's scale (amplitude, amplitude·Ω, d/2): the simulation's own rounding is ~1e-14.
TOL = 1e-11
MAX_ITER = budgets.MAX_ITER
#: The longest orbit followed, in forcing periods.
MAX_PERIODS = 64
#: An orbit with more contacts (compliant) or impacts (rigid) than these in a forcing period is
#: not followed: a Newton iterate far from any orbit can set the masses bouncing thousands of
#: times a period, and such a motion chatters rather than impacts (symimpact.budgets).
MAX_IMPACTS_PER_PERIOD = budgets.MAX_IMPACTS_PER_PERIOD


def condition(A: np.ndarray) -> float:
    """The 2-norm condition number of ``A`` (the ratio of its extreme singular values), or
    infinity where A is singular, holds a non-finite entry (a Jacobian whose differences
    overflowed on a stiff contact) or its SVD does not converge: a bound that reads "no
    accuracy" instead of stopping the curve."""
    if not np.all(np.isfinite(A)):
        return math.inf
    try:
        c = float(np.linalg.cond(A))
    except np.linalg.LinAlgError:
        return math.inf
    return c if math.isfinite(c) else math.inf


@dataclass(frozen=True)
class ShootingOrbit:
    """A period-k orbit found by :func:`shoot` (SI units).

    ``state``: (x, ẋ, z, ẏ) at t = 0, the section (forcing phase φ of the :class:`Forcing`);
    ``period_multiple``: k; ``amplitude`` [m]: max abs(x) over the orbit; ``impacts_per_period``;
    ``impact_phase`` [rad]: the forcing phase Ωt + φ of the orbit's first impact on the wall
    +d/2 (or −d/2 when it touches only that one), in (−π, π]; ``impact_speed`` [m/s]: its approach
    speed; ``multipliers``: moduli of the Floquet multipliers (eigenvalues of the monodromy over
    k periods), descending; ``stable``: all < 1; ``iterations``: Newton steps; ``residual``: the
    last abs(P(s) − s), relative to the state's scale.
    """

    state: tuple[float, float, float, float]
    period_multiple: int
    amplitude: float
    impacts_per_period: float
    impact_phase: float | None
    impact_speed: float | None
    multipliers: tuple[float, ...]
    stable: bool
    iterations: int
    residual: float
    #: impact events a period, a chatter sequence counting once (:func:`.simulation.impact_counts`)
    impact_events_per_period: float = 0.0

    def as_dict(self) -> dict[str, Any]:
        """The closed form's JSON keys (impact_phase, amplitude, impact_speed, admissible, stable,
        multipliers) and the shooting's own."""
        return {
            "impact_phase": self.impact_phase,
            "amplitude": self.amplitude,
            "impact_speed": self.impact_speed,
            "admissible": True,  # a simulated motion: it respects every wall by construction
            "stable": self.stable,
            "multipliers": list(self.multipliers),
            "impacts_per_period": self.impacts_per_period,
            "impact_events_per_period": self.impact_events_per_period,
            "period_multiple": self.period_multiple,
            "state": list(self.state),
            "iterations": self.iterations,
            "residual": self.residual,
        }


def monodromy(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    state: Any,
    periods: int = 1,
    jacobian: bool = True,
    parameter: str | None = None,
) -> tuple[np.ndarray, np.ndarray | None, Any]:
    """The stroboscopic map P over ``periods`` forcing periods from ``state`` = (x, ẋ, z, ẏ) at
    t = 0, and its Jacobian.  Rigid impacts (``e`` Newton's restitution): the product of the
    flights' Φ(τ) and the impacts' saltation matrices (Step 8, Step 9) along the simulated
    motion.  A compliant contact (``e`` a :class:`CompliantContact`): the variational equations
    integrated through each contact, the located onsets and exits differentiated
    (:mod:`symimpact.forced.engine._compliant`).  Returns (P(state), Jacobian, the simulation); with
    ``jacobian`` False the Jacobian is not formed (None): the map alone, for differences in a
    parameter.  With ``parameter`` (rigid impacts: omega, gap, F0, X_b or e) the Jacobian has a
    fifth column, ∂P/∂p, carried along the same chain (:func:`rigid_monodromy`)."""
    system, forcing, e = checked(system, forcing, e)
    x, v, z, u = (float(c) for c in checks.state("state", state))
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    if is_rigid(e):
        contact_arguments(system, "rigid", e, None)  # e in [0, 1], or the materials' law
    return stroboscopic_map(system, forcing, e, (x, v, z, u), periods, jacobian, parameter)


def stroboscopic_map(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    state: tuple[float, float, float, float],
    periods: int,
    jacobian: bool = True,
    parameter: str | None = None,
) -> tuple[np.ndarray, np.ndarray | None, Any]:
    """:func:`monodromy` (Step 8's flights and Step 9's saltations along the motion) for
    arguments already checked by it or by the caller's own entry: ``system``, ``forcing`` and
    ``e`` as :func:`~symimpact.forced.contact_law.checked` returns them, ``state`` four floats,
    ``periods`` a whole number in [1, MAX_PERIODS].  The continuation's Newton steps call it
    tens of thousands of times a curve, where checking the same arguments again cost more than
    the compiled run.  A state that is not finite or lies beyond a wall is still refused."""
    x, v, z, u = state
    if not (math.isfinite(x) and math.isfinite(v) and math.isfinite(z) and math.isfinite(u)):
        raise ParameterError("state", f"must be 4 finite numbers (x, ẋ, z, ẏ), got {state}")
    if not is_rigid(e):
        return _compliant_monodromy(system, forcing, e, (x, v, z, u), periods, jacobian)
    within_walls("state", x, x + z, system.gap / 2.0)
    try:  # at most MAX_IMPACTS_PER_PERIOD impacts a period; chatter taken to its accumulation
        res, _ = _simulate(system, forcing, "rigid", e, None, _NO_LAW, [x, v, x + z, u], periods,
                           max_contacts=MAX_IMPACTS_PER_PERIOD * periods)  # fmt: skip
    except TooManyContacts:
        raise MethodNotApplicable(
            "shooting",
            f"more than {MAX_IMPACTS_PER_PERIOD} impacts a period that do not accumulate: a "
            "clearance far below the motion; shooting follows orbits with fewer",
        ) from None
    fx, fv, fy, fu = res.final_state
    if not jacobian:
        return np.array([fx, fv, fy - fx, fu]), None, res
    with np.errstate(divide="ignore", invalid="ignore"):  # a zero-speed impact: refused below
        J = rigid_monodromy(system, forcing, res.e, res.events, res.t_end, res.final_stuck,
                            parameter, (x, v), (fx, fv, fu - fv))  # fmt: skip
    if not np.all(np.isfinite(J)):
        raise MethodNotApplicable(
            "shooting",
            "an impact at zero relative speed (grazing, or a plastic impact, e = 0, that does "
            "not stick) has no saltation: the monodromy is not defined there",
        )
    return np.array([fx, fv, fy - fx, fu]), J, res


#: The rigid contact's law parameters: none (what :func:`contact_arguments` gives for "rigid").
_NO_LAW = np.zeros(0)


def rigid_monodromy(
    system: ImpactSystem,
    forcing: Forcing,
    e: float,
    events: np.ndarray,
    t_end: float,
    final_stuck: bool,
    parameter: str | None = None,
    start: tuple[float, float] = (0.0, 0.0),
    end_state: tuple[float, float, float] = (0.0, 0.0, 0.0),
) -> np.ndarray:
    """The Jacobian of the rigid stroboscopic map along a simulated motion (``events``: the
    simulation's event log, to ``t_end`` [s]), in the state (x, ẋ, z, ẏ); with ``parameter``
    (one of omega, gap, F0, X_b, e) a fifth column, the map's derivative in it, ∂P/∂p; it
    needs the primary's ``start`` (x, ẋ) at t = 0 and ``end_state`` (x, ẋ, ż) at ``t_end``.

    * A flight: Step 8's Φ(τ) (mass M); an impact: Step 9's saltation matrix (Eq. F2).
    * Chatter taken to its accumulation point (the simulation's model, :mod:`._rigid`): after the
      impact at t₀ that starts it, with separation speed w = −s(ẏ − ẋ) and relative acceleration
      a = −s·ẍ towards the wall s, the primary flies Δ = 2w/(a(1 − e)) alone and the pair then
      moves at the common speed v_c = (M ẋ + m ẏ)/(M + m).  Its Jacobian is the chain rule of
      these closed forms in (t₀, the state after the impact), with t₀'s own dependence on the
      state before it (δt₀ = −δz/ż): the timing is carried, not differenced.
    * A sticking phase: the pair, mass M + m, flies with Φ(τ) of that mass; z stays ±d/2 and
      ẏ = ẋ, so the phase keeps two of the four directions (the monodromy loses rank 2).  The
      perturbation is carried at fixed times: at the accumulation point t∞ the state's change
      less the sticking vector field times δt∞.
    * A release (s·ẍ turns positive): the vector fields on both sides agree there (ẍ = 0 and
      ẏ = ẋ), so its saltation is the identity.

    ∂P/∂p is carried by the same chain with the parameter's explicit terms at each link: each
    flight's derivative at its fixed start (the generated
    kernels ``forced_*_d_{F0,X_b,Omega,phi}``, compiled: :func:`._rigid.flight_parameter_terms`),
    an impact's through its time (the wall at d/2) and its law (``*_velocity_after_d_e``), the
    chatter's Δ, and in Ω the end of the k periods, T = 2πk/Ω.

    The chain runs compiled (:func:`._chain.rigid_jacobian`, numba): a tangent vector carried
    over hundreds of periods (the Lyapunov exponent) or a Newton step of the continuation costs
    little more than the simulation it follows.
    """
    if parameter is not None and parameter not in _chain.PARAMETERS:
        raise ValueError(f"parameter: one of {', '.join(_chain.PARAMETERS)}, got {parameter!r}")
    which = -1 if parameter is None else _chain.PARAMETERS.index(parameter)
    p = np.zeros(_rigid.N_PARAMS)
    p[_rigid.P_M], p[_rigid.P_K], p[_rigid.P_C] = system.M, system.K, system.C
    p[_rigid.P_m], p[_rigid.P_h] = system.m, system.gap / 2.0
    p[_rigid.P_e], p[_rigid.P_VY] = restitution_parameters(e)
    p[_rigid.P_F0], p[_rigid.P_XB] = forcing.primary_force, forcing.X_b
    p[_rigid.P_W], p[_rigid.P_PHI] = forcing.omega, forcing.phase
    events = np.ascontiguousarray(np.reshape(events, (-1, _rigid.N_EVENT_COLS)), dtype=float)
    J = _chain.rigid_jacobian(p, events, float(t_end), bool(final_stuck), which,
                              np.array(start, dtype=float), np.array(end_state, dtype=float))  # fmt: skip
    return J if parameter is not None else J[:, :4]


#: (x, ẋ, z, ẏ) from (x, ẋ, y, ẏ): z = y − x; and back
_TO_Z = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [-1, 0, 1, 0], [0, 0, 0, 1]], dtype=float)
_FROM_Z = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [1, 0, 1, 0], [0, 0, 0, 1]], dtype=float)


def _compliant_monodromy(system, forcing, contact: CompliantContact, state, periods, jacobian):
    """:func:`monodromy` through compliant contacts: one compiled run carrying Ψ (a start
    inside a wall begins in contact)."""
    x, v, z, u = state
    _, chi, law = contact_arguments(system, contact.law, None, contact.chi)
    n = period_count("periods", periods)
    budget = budgets.SHOOTING_EVALUATIONS_PER_PERIOD
    try:
        res, psi = _simulate(system, forcing, contact.law, None, chi, law, [x, v, x + z, u], n,
                             variational=jacobian, max_work=budget * n)  # fmt: skip
    except TooMuchContactWork:
        raise MethodNotApplicable(
            "shooting",
            f"the contacts of one period need more than {budget:.0e} evaluations of their "
            "equations (each contact integrated with its variational equations): use contact "
            "rigid with this contact's restitution",
        ) from None
    fx, fv, fy, fu = res.final_state
    J = _TO_Z @ psi @ _FROM_Z if jacobian else None
    return np.array([fx, fv, fy - fx, fu]), J, res


@_interrupt.stretch()
def shoot(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    start: Any,
    periods: int = 1,
    tol: float = TOL,
    max_iter: int = MAX_ITER,
) -> ShootingOrbit:
    """The period-``periods`` orbit near ``start`` = (x, ẋ, z, ẏ) at t = 0: Newton's method on
    P(s) − s = 0 with the monodromy of :func:`monodromy` (rigid impacts, Eq. F1, F2)."""
    system, forcing, e = checked(system, forcing, e)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    s = checks.state("start", start)
    tol = checks.bounded("tol", tol, 0.0, 1.0, open_low=True)
    max_iter = checks.whole_number("max_iter", max_iter, 1, 1000)
    h = system.gap / 2.0
    rigid = is_rigid(e)
    shift = 0.0
    if rigid and abs(s[2]) >= h * (1.0 - WALL):
        forcing, s, shift = _off_the_walls(system, forcing, e, s, periods)
    it = 0
    for it in range(1, max_iter + 1):  # noqa: B007 (the count is reported)
        ps, J, res = monodromy(system, forcing, e, s, periods)
        amp = float(np.max(res.period_max)) if len(res.period_max) else abs(s[0])
        scale = np.array([amp, amp * forcing.omega, h, amp * forcing.omega])
        scale = np.where(scale > 0, scale, 1.0)
        if len(res.events) == 0:
            raise MethodNotApplicable(
                "shooting",
                "the motion does not impact: the impact mass floats between the walls (a "
                "neutral drift, multipliers 1) and the primary follows its linear response",
            )
        r = ps - s
        try:
            step = np.linalg.solve(J - np.eye(4), -r)
        except np.linalg.LinAlgError:
            raise MethodNotApplicable(
                "shooting", "the monodromy has a multiplier 1 (a fold): Newton cannot proceed"
            ) from None
        # a compliant contact: no step longer than the state's scale (a full Newton step from a
        # poor start can throw the masses metres through the walls, a motion of thousands of
        # contacts a period)
        if not rigid:
            step = step / max(1.0, float(np.max(np.abs(step / scale))))
        size = float(np.max(np.abs(step / scale)))  # converged on the step Newton asked for
        # a step that would put the impact mass through a wall is halved until it does not
        while rigid and abs(s[2] + step[2]) > h and np.max(np.abs(step / scale)) > tol:
            step = 0.5 * step
        if rigid and abs(s[2] + step[2]) > h:  # halved to nothing: Newton presses on the wall
            raise MethodNotApplicable(
                "shooting",
                "Newton's steps press the impact mass into a wall (an orbit that sticks or "
                "chatters there, which shooting does not follow)",
            )
        s = s + step
        # a compliant map carries ~1e-12 of noise (continuation.NOISE), amplified by the
        # conditioning of (monodromy − I)
        scaled = (J - np.eye(4)) * scale[None, :] / scale[:, None]
        floor = tol if rigid else max(tol, 1e-12 * condition(scaled))
        if size <= floor:
            break
    else:
        raise MethodNotApplicable(
            "shooting", f"Newton did not converge in {max_iter} steps from this start"
        )
    ps, J, res = monodromy(system, forcing, e, s, periods)
    impacts, events = impact_counts(res.events, -math.inf, math.inf)
    residual = float(np.max(np.abs((ps - s) / scale)))
    section = s
    if shift:  # the state at the given section: the orbit's own motion, Eq. F1
        section = state_at(res, np.array([res.t_end - shift]))[0]
    moduli = np.sort(np.abs(np.linalg.eigvals(J)))[::-1]
    ev = res.events
    right = ev[ev[:, _rigid.E_SIDE] > 0] if len(ev) else ev
    first = right[0] if len(right) else (ev[0] if len(ev) else None)
    phase = speed = None
    if first is not None:
        phase = math.remainder(forcing.omega * first[_rigid.E_T] + forcing.phase, 2 * math.pi)
        speed = float(first[_rigid.E_VREL])
    return ShootingOrbit(
        state=tuple(float(c) for c in section),
        period_multiple=periods,
        amplitude=float(np.max(res.period_max)),
        impacts_per_period=impacts / periods,
        impact_phase=phase,
        impact_speed=speed,
        multipliers=tuple(float(m) for m in moduli),
        stable=bool(moduli[0] < 1.0),
        iterations=it,
        residual=residual,
        impact_events_per_period=events / periods,
    )


#: A start this close to a wall (a share of d/2) is at the wall: stuck there, or at an impact.
WALL = 1e-9


def mid_free_flight(res) -> float | None:
    """The instant [s] in the middle of the longest free flight of a rigid run ``res`` taken as
    one period of an orbit (the flights between its events, the last wrapping to the first; a
    flight that a release ends is a sticking phase, not free); None where every flight sticks."""
    ev, total = res.events, res.t_end
    times = np.concatenate([ev[:, _rigid.E_T], [ev[0, _rigid.E_T] + total]])
    kinds = ev[:, _rigid.E_KIND]
    stuck = np.append(kinds[1:] == _rigid.KIND_RELEASE, res.final_stuck)
    gaps = np.where(stuck, -1.0, np.diff(times))
    i = int(np.argmax(gaps))
    if gaps[i] <= 0.0:
        return None
    return float((times[i] + 0.5 * gaps[i]) % total)


def _off_the_walls(system, forcing, e, s, periods) -> tuple[Forcing, np.ndarray, float]:
    """A start at a wall (a sticking phase, or an impact), seen from a section in the middle of
    the longest free flight of the motion from it instead: the forcing with its phase moved by
    Ωτ, the state at τ (Eq. F1), and τ [s].  At the wall the map from the section begins with
    an impact at zero relative speed (no saltation), and Newton's steps there press into it."""
    _, _, res = monodromy(system, forcing, e, s, periods, jacobian=False)
    if len(res.events) == 0:
        return forcing, s, 0.0
    tau = mid_free_flight(res)
    if tau is None:
        raise MethodNotApplicable(
            "shooting", "the masses never separate: the motion sticks for the whole period"
        )
    moved = forcing.at(forcing.omega, math.remainder(forcing.phase + forcing.omega * tau,
                                                      2 * math.pi))  # fmt: skip
    return moved, state_at(res, np.array([tau]))[0], tau


def settled_state(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    warmup: int = 300,
    start: Any = (0.0, 0.0, 0.0, 0.0),
) -> tuple[tuple[float, float, float, float], Any]:
    """Where a brute-force run settles: the state (x, ẋ, z, ẏ) after ``warmup`` forcing periods
    of the event-driven simulation (Eq. F1, F2; chatter and sticking allowed) from ``start``, at
    the forcing phase of t = 0, and the contact to shoot with from it."""
    system, forcing, e = checked(system, forcing, e)
    x, v, z, u = (float(c) for c in checks.state("start", start))
    res = simulate_forced(system, forcing, **simulation_arguments(e), periods=warmup, x0=x,
                          xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
    fx, fv, fy, fu = res.final_state
    return (fx, fv, fy - fx, fu), res.e if is_rigid(e) else e


def shoot_from_rest(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    warmup: int = 300,
    periods: int = 1,
    start: Any = (0.0, 0.0, 0.0, 0.0),
) -> ShootingOrbit:
    """The orbit a brute-force run settles near: :func:`settled_state` after ``warmup`` forcing
    periods from ``start`` = (x, ẋ, z, ẏ), then :func:`shoot` from it (the same forcing phase: a
    whole number of periods)."""
    system, forcing, e = checked(system, forcing, e)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    state, law = settled_state(system, forcing, e, warmup, start)
    return shoot(system, forcing, law, state, periods)
