"""Pseudo-arclength continuation of periodic orbits through rigid impacts in a parameter — the
forcing frequency Ω (the frequency-response curve), the clearance d, the force amplitude F0, the
base-motion amplitude X_b or the restitution e: :func:`continue_orbit`.

The unknowns are y = (s, p), s = (x, ẋ, z, ẏ) at the section t = 0, scaled by the starting
orbit's amplitude, velocity amplitude, d/2, and p by a tenth of its range.  A point of the branch
solves P(s; p) − s = 0 (P the stroboscopic map over k periods, :func:`symimpact.forced.monodromy`);
its Jacobian is [monodromy − I | ∂P/∂p], the monodromy carried through flights and impacts and,
for rigid impacts, ∂P/∂p along the same chain (each link's explicit derivative in the parameter:
the generated flight kernels ``forced_*_d_{F0,X_b,Omega,phi}``, the impact law's ``*_d_e``, the
wall's move with d, the chatter's Δ and the end of the k periods in Ω,
:func:`.shooting.rigid_monodromy`); for a compliant contact by central differences (step 1e-6
of the parameter, or of a tenth of its range where that is larger; ~1e-10 of the map).  Each
step predicts along the branch's unit tangent, with the branch's curvature from the tangent's
change over the step before (:func:`_predicted`), and corrects by Newton's method with the
pseudo-arclength condition, so the branch is followed around folds (a located fold's orbit on it).

Along the branch the Floquet multipliers are watched: a real multiplier through +1 where the
tangent's parameter component changes sign is a *fold*, through +1 without a turn a *branch point* (on
the symmetric two-impact orbits: the symmetry-breaking pitchfork from which the asymmetric
orbits grow), a real one through −1 a *period doubling*, a
complex pair through the unit circle a *Neimark–Sacker* point; each is located on the arc by
Brent's method on its test function (the tangent's parameter component, det(monodromy + I), the pair's
modulus − 1).  Where the set of impacts changes (an impact appears or vanishes: a *grazing*)
the grazing is located and the branch goes on with the new impacts where an impacting orbit
continues it.  A located change is a grazing only where the orbit there touches a wall (a
flight turns at it, or an impact's speed vanishes, :data:`GRAZING_MARGIN`); elsewhere Newton
from the predictor merely left the branch, which ends there saying so.  Where no orbit continues
a branch beyond a grazing, the orbits with the new low-speed impact may lie on the same side (a
non-smooth fold): with ``folds`` the branch turns back onto them (:func:`_fold_back`).  A chatter sequence that
accumulates counts as one impact event, so a branch is
followed into and through chatter and sticking (rigid impacts, :func:`.shooting.rigid_monodromy`);
where the motion stops impacting or the corrector fails, the branch ends there and says why.

As the parameter changes the impacts drift in phase; where one comes near the section t = 0 the
section is moved midway between impacts (the same orbit; each point carries its forcing phase).

Branch switching (:func:`branch_starts`, :func:`leave`, :func:`switch_branch`): from a branch
point or a period doubling the branches that cross the traced one are started along the critical
eigenvector and followed away from the point; :func:`orbits_at` gives a branch's orbits at any
value of the parameter exactly.  The walls and the forcing are symmetric, so an asymmetric orbit's
mirror image is an orbit with the same amplitude: points say whether they are asymmetric.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from scipy.optimize import brentq

from ... import _interrupt, budgets
from ...errors import MethodNotApplicable, ParameterError, SymimpactError
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import checked, is_constant, is_rigid, restitution_parameters
from ..engine import _rigid
from ..forcing import Forcing
from ..simulation import CHATTER, impact_counts, state_at
from . import _corrector
from .shooting import (
    MAX_IMPACTS_PER_PERIOD,
    MAX_PERIODS,
    WALL,
    ShootingOrbit,
    _off_the_walls,
    condition,
    mid_free_flight,
    monodromy,
    shoot,
    stroboscopic_map,
)

#: Newton's corrector stops below this change of the scaled unknowns, or below the map's own
#: noise amplified by the conditioning of the extended Jacobian, cond·NOISE, where that is larger
#: (next to a branch point the Jacobian is nearly singular and no iterate gets closer than it).
TOL = 1e-10
#: The stroboscopic map's rounding relative to the state's scale: ~1e-15 for the closed-form flights
#: and impacts of rigid contact; for a compliant contact the integrator's located steps (rtol 1e-13)
#: move the map by ~1e-12 between neighbouring starts (measured: Newton stalls at 1e-7 where the
#: condition number is 3e5, at 2e-10 where it is 1.4e3).
NOISE = {"rigid": 1e-15, "compliant": 1e-12}
#: The largest Newton step accepted as the map's noise amplified by the conditioning (cond·NOISE):
#: a point is then placed to this share of the state's scale at worst.  Beside a singular point
#: (a branch point, a grazing, two branches meeting) cond reaches 1e10, and without this cap
#: Newton's method stopped on states that did not repeat: one 2.7e-4 of the scale off, taken as
#: an asymmetric orbit, at 28.29 rad/s on tests/test_branch_switching.py's curve (its Newton steps
#: were below 1e-7).  There the corrector fails instead and the step is shortened.  A compliant
#: contact's map is noisier (Newton stalls at 1e-7 where cond is 3e5, see NOISE).
STALL = {"rigid": 1e-8, "compliant": 1e-6}
MAX_NEWTON = 8
#: The largest arclength step accepted [scaled unknowns]: one moves the parameter by a tenth of
#: its range (see :func:`continue_orbit`); the default is 0.02.
MAX_STEP = 1.0
#: The drawn curve's bound: between consecutive points a branch departs from the straight line by
#: at most this much in the plane of its figure, the continued parameter in widths of its range
#: and the amplitude relative to its own value (a steep stretch is judged across, not along the
#: amplitude axis).  Estimated from the circle through the last three points: a segment of length
#: s on a curve of curvature κ departs by κs²/8 at its middle.  The step shrinks to keep it, to
#: no less than a sixteenth of the given step (at a kink of max abs(x), where two extremes of x
#: swap, the curvature is unbounded and the bound cannot hold).  The same circle looks back at
#: the segment before: where the curve bends more ahead (towards a fold), the orbit halfway along
#: that segment is found and put in while it lies farther than this from the segment.
CHORD = 1e-3


@dataclass(frozen=True)
class BranchPoint:
    """One orbit of a branch (SI): ``omega`` [rad/s], ``state`` (x, ẋ, z, ẏ) at t = 0,
    ``amplitude`` [m] max abs(x), ``impacts_per_period``, ``multipliers`` (complex Floquet
    multipliers over the orbit's k periods), ``stable`` (all moduli < 1), ``value``: the continued
    parameter's value there (SI; equal to ``omega`` when Ω is continued)."""

    omega: float
    state: tuple[float, float, float, float]
    amplitude: float
    impacts_per_period: float
    multipliers: tuple[complex, ...]
    stable: bool
    value: float = math.nan
    #: the forcing phase φ [rad] at t = 0 of ``state`` (the section; a branch moves its section
    #: away from the impacts as they drift, see :func:`continue_orbit`)
    phase: float = 0.0
    #: the orbit differs from its mirror image x → −x half a period later, an orbit too with
    #: the same amplitude (rigid impacts; False where not examined)
    asymmetric: bool = False
    #: impact events a period, a chatter sequence counting once (:func:`.simulation.impact_counts`):
    #: the orbit's impact sequence, which a branch keeps between grazings
    impact_events_per_period: float = 0.0


@dataclass(frozen=True)
class Bifurcation:
    """A located point of a branch: ``kind`` ("fold", "branch-point", "period-doubling",
    "neimark-sacker", "grazing"), ``omega`` [rad/s], ``amplitude`` [m], ``value``: the continued
    parameter's value there (SI)."""

    kind: str
    omega: float
    amplitude: float
    value: float = math.nan
    #: (x, ẋ, z, ẏ) at t = 0 of the orbit there (SI; interpolated across the bracket where the
    #: corrector cannot land on the point): where :func:`branch_starts` switches branches
    state: tuple[float, float, float, float] | None = field(default=None, compare=False)
    #: the forcing phase φ [rad] at t = 0 of ``state``
    phase: float = field(default=0.0, compare=False)
    #: at a grazing: the impacts a period before it and, where the branch goes on through it,
    #: after it (NaN where it ends there)
    impacts_before: float = field(default=math.nan, compare=False)
    impacts_after: float = field(default=math.nan, compare=False)


@dataclass
class Branch:
    """A continued branch: its points in order, the located bifurcations, ``period_multiple``
    k, ``stopped``: why the continuation ended (the band's edge, a grazing, …), and ``phase``
    [rad]: the forcing phase φ at t = 0 of its first point (each point carries its own section),
    ``parameter``: the continued parameter (see :data:`PARAMETERS`)."""

    points: list[BranchPoint] = field(default_factory=list)
    bifurcations: list[Bifurcation] = field(default_factory=list)
    period_multiple: int = 1
    stopped: str = ""
    phase: float = 0.0
    parameter: str = "omega"
    #: where the branch was found: "" for a start of its own, else e.g. "branch-point of branch 0
    #: at Ω = 24.941 rad/s" (set by the caller that switched onto it), and that Ω [rad/s]
    origin: str = ""
    origin_omega: float = math.nan

    @property
    def mirrored(self) -> bool:
        """Some of its orbits are asymmetric: their mirror images (x → −x half a period later,
        the same amplitude) form a second branch, not traced, that the amplitude curve shares
        (the orbits born at a symmetry-breaking branch point come in such pairs)."""
        return any(p.asymmetric for p in self.points)


#: The parameters :func:`continue_orbit` follows a branch in, with their SI units.
PARAMETERS = {"omega": "rad/s", "gap": "m", "F0": "N", "X_b": "m", "e": ""}


#: The 4×4 identity (the monodromy less it is the map's Jacobian minus the unknowns').
_I4 = np.eye(4)


class _Problem:
    """The scaled residual and Jacobian of the continuation at y = (s/scale, p/unit)."""

    def __init__(self, system, forcing, e, periods, scale, unit, parameter="omega"):
        self.system, self.forcing, self.e, self.periods = system, forcing, e, periods
        self.noise = NOISE["rigid" if is_rigid(e) else "compliant"]
        self.stall = STALL["rigid" if is_rigid(e) else "compliant"]
        self.scale, self.unit, self.parameter = scale, unit, parameter

    def at(self, value: float):
        """(system, forcing, e) with the continued parameter set to ``value``."""
        f, system, e = self.forcing, self.system, self.e
        if self.parameter == "gap":
            return system.with_(gap=value), f, e
        if self.parameter == "e":
            return system, f, value
        if self.parameter == "omega":
            return system, f.at(value), e
        F0 = value if self.parameter == "F0" else f.F0
        X_b = value if self.parameter == "X_b" else f.X_b
        return system, Forcing(F0, X_b, f.omega, phase=f.phase, inertia=f.inertia), e

    @property
    def compiled(self) -> bool:
        """Whether :func:`_correct` runs compiled (:mod:`._corrector`): rigid impacts with ∂P/∂p
        carried, continued in Ω, with a base motion of constant amplitude X_b (or none)."""
        f = self.forcing
        return (self.parameter == "omega" and is_rigid(self.e) and self.carried
                and f.V_b is None and f.A_b is None and f.inertia == 0.0)  # fmt: skip

    def run_parameters(self) -> np.ndarray:
        """The one-mode engine's parameters (:mod:`._rigid`'s layout), as
        :func:`~symimpact.forced.simulation.simulate_forced` sets them for this problem."""
        system, f = self.system, self.forcing
        p = np.zeros(_rigid.N_PARAMS)
        p[_rigid.P_M], p[_rigid.P_K], p[_rigid.P_C] = system.M, system.K, system.C
        p[_rigid.P_m], p[_rigid.P_h] = system.m, system.gap / 2.0
        p[_rigid.P_e], p[_rigid.P_VY] = restitution_parameters(self.e)
        p[_rigid.P_F0], p[_rigid.P_XB] = f.primary_force, f.X_b
        p[_rigid.P_W], p[_rigid.P_PHI], p[_rigid.P_CHAT] = f.omega, f.phase, CHATTER
        return p

    def converged(self, dy: np.ndarray, A: np.ndarray) -> bool:
        """Whether Newton's step ``dy`` on the extended system ``A`` ends the correction: below
        TOL, or below the map's noise amplified by A's conditioning, cond·NOISE, capped at
        STALL."""
        step = float(np.max(np.abs(dy)))
        return step < TOL or step < min(self.noise * condition(A), self.stall)

    def omega(self, y: np.ndarray) -> float:
        """The forcing frequency at y."""
        return float(y[4] * self.unit) if self.parameter == "omega" else self.forcing.omega

    def map(self, value: float, s: np.ndarray, jacobian: bool = True,
            parameter: str | None = None):  # fmt: skip
        """:func:`~symimpact.forced.orbits.shooting.monodromy` at the parameter ``value`` from the
        state ``s``: the system, forcing and contact were checked when the problem was made, so
        only a restitution the Newton step moved (parameter e) is checked again."""
        system, forcing, e = self.at(value)
        if self.parameter == "e":  # a restitution beyond [0, 1] is refused there
            return monodromy(system, forcing, e, s, self.periods, jacobian, parameter)
        state = (float(s[0]), float(s[1]), float(s[2]), float(s[3]))
        return stroboscopic_map(system, forcing, e, state, self.periods, jacobian, parameter)

    #: ∂P/∂p of rigid impacts carried along the monodromy's chain; False: by central
    #: differences as for a compliant contact (what the tests and the benchmark compare it with)
    carried = True

    def evaluate(self, y: np.ndarray):
        """(residual, Jacobian 4×5, monodromy, the simulation) at y, all scaled."""
        s, value = y[:4] * self.scale, y[4] * self.unit
        # ∂P/∂p along the chain: not with an inertia's force F0 + inertia·Ω²·X_b (Forcing)
        if is_rigid(self.e) and self.carried and self.forcing.inertia == 0.0:
            ps, J5, res = self.map(value, s, parameter=self.parameter)
            mono, dp = J5[:, :4], J5[:, 4] * self.unit
        else:  # a compliant contact: by central differences of the map
            ps, mono, res = self.map(value, s)
            d = 1e-6 * max(abs(value), self.unit)
            plus = self.map(value + d, s, jacobian=False)[0]
            minus = self.map(value - d, s, jacobian=False)[0]
            dp = (plus - minus) / (2 * d) * self.unit
        J = np.zeros((4, 5))
        J[:, :4] = (mono - _I4) * self.scale[None, :] / self.scale[:, None]
        J[:, 4] = dp / self.scale
        return (ps - s) / self.scale, J, mono, res

    def where(self, value: float) -> str:
        """``Ω = 36.2 rad/s``, ``gap = 0.021 m``: the parameter's value in words."""
        return self.where_text(self.parameter, value)

    @staticmethod
    def where_text(parameter: str, value: float) -> str:
        """``Ω = 36.2 rad/s`` for ``parameter`` "omega" at ``value``."""
        name = "Ω" if parameter == "omega" else parameter
        unit = PARAMETERS[parameter]
        return f"{name} = {value:.6g}{' ' + unit if unit else ''}"


def _problem(system, forcing, e, s0, periods, bounds, parameter) -> _Problem:
    """The continuation problem through the orbit ``s0``: the state scaled by its amplitude,
    velocity amplitude and d/2, the parameter in units of a tenth of its range (a step of 0.2
    moves it by at most 2 % of it)."""
    h = system.gap / 2.0
    _, _, res0 = monodromy(system, forcing, e, s0, periods, jacobian=False)
    amp = max(float(np.max(res0.period_max)), 1e-3 * h)
    W0 = forcing.omega
    scale = np.array([amp, amp * W0, h, amp * W0])
    return _Problem(system, forcing, e, periods, scale, (bounds[1] - bounds[0]) / 10.0, parameter)


#: A section closer than this share of the forcing period to an impact is moved (rigid impacts):
#: as the parameter changes the impacts drift in phase, and where one crosses the section the
#: state there jumps from before to after it and Newton's method cannot follow.
NEAR_IMPACT = 0.05


def _resection(problem: _Problem, y: np.ndarray, t: np.ndarray, res):
    """The same orbit seen at a section midway between its impacts, where an impact lies within
    NEAR_IMPACT of a period of the current section (t = 0 or the end of the k periods): the state
    at that instant τ of the orbit's simulation ``res`` (:func:`symimpact.forced.simulation.state_at`,
    Eq. F1), the forcing phase moved by Ωτ; with the problem, scaled unknowns, Jacobian,
    monodromy, simulation and tangent there (the tangent oriented with the old one's parameter
    component).  None where nothing needs to move (or a compliant contact, whose states within a
    contact are continuous)."""
    if not is_rigid(problem.e) or len(res.impacts) == 0:
        return None
    T = 2 * math.pi / res.forcing.omega
    total = problem.periods * T
    times = np.sort(np.asarray(res.impacts) % total)
    if min(times[0], total - times[-1]) >= NEAR_IMPACT * T and not res.final_stuck:
        return None  # (a section inside a sticking phase is on the wall: moved too)
    tau = mid_free_flight(res)
    if tau is None:
        return None
    from ..simulation import state_at

    s_new = state_at(res, np.array([tau]))[0]
    f = problem.forcing
    phase = math.remainder(f.phase + res.forcing.omega * tau, 2 * math.pi)
    moved = _Problem(problem.system, f.at(f.omega, phase),
                     problem.e, problem.periods, problem.scale, problem.unit,
                     problem.parameter)  # fmt: skip
    y_new = np.concatenate([s_new / problem.scale, [y[4]]])
    try:
        r, J, mono, res_new = moved.evaluate(y_new)
    except SymimpactError:
        return None
    if np.max(np.abs(r)) > 1e-6:  # not the orbit again (it should agree to the map's rounding)
        return None
    t_new = _tangent(J, None)
    if abs(t[4]) > 1e-9 and (t_new[4] > 0) != (t[4] > 0):
        t_new = -t_new
    return moved, y_new, J, mono, res_new, t_new


def _asymmetric(problem: _Problem, y: np.ndarray, res) -> bool:
    """Whether the orbit at y differs from its mirror image (rigid impacts): the walls at ±d/2
    and the harmonic forcing are symmetric, so x̃(t) = −x(t + T/2) is an orbit too, with the same
    amplitude; it is the orbit itself when −s(T/2) is one of the orbit's own section states
    s(jT) (to 1e-7 of the scale).  From the orbit's simulation (state_at, Eq. F1)."""
    if not is_rigid(problem.e):
        return False
    from ..simulation import state_at

    T = 2 * math.pi / res.forcing.omega
    k = problem.periods
    states = state_at(res, np.array([*(j * T for j in range(k)), T / 2]))
    mirror = -states[-1]
    return not any(np.max(np.abs((mirror - s) / problem.scale)) < 1e-7 for s in states[:-1])


def _tangent(J: np.ndarray, previous: np.ndarray | None) -> np.ndarray:
    """The unit null vector of the 4×5 Jacobian, oriented along ``previous``."""
    t = np.linalg.svd(J)[2][-1]
    if previous is not None and float(t @ previous) < 0:
        t = -t
    return t / np.linalg.norm(t)


#: What :func:`_correct` returns when the impacts of the motion changed on the way.
GRAZE = "graze"


def _correct(problem: _Problem, y_pred: np.ndarray, t: np.ndarray, count: float | None = None,
             start: np.ndarray | None = None):  # fmt: skip
    """Newton on [F(y) = 0, tᵀ(y − y_pred) = 0] from y_pred (or from ``start``, a point of the
    same hyperplane nearer the branch); None when it fails, GRAZE when it lands on an orbit
    that impacts other than ``count`` times per period — with rigid impacts as soon as an
    iterate does (the map's impacts changed on the way: measured on the README's curve, 109 of
    2790 such corrections came back to an orbit with ``count`` impacts, each found again from
    the shorter step the caller then takes, at a third of the cost); with a compliant contact,
    whose contacts a period change smoothly, when it fails after an iterate did."""
    if problem.compiled:
        return _correct_compiled(problem, y_pred, t, count, start)
    y = (y_pred if start is None else start).copy()
    rigid, wandered = is_rigid(problem.e), False
    for _ in range(MAX_NEWTON):
        try:
            r, J, mono, res = problem.evaluate(y)
        except SymimpactError:  # no impacts, a zero-speed impact, a state through a wall
            return GRAZE if wandered else None
        if count is not None and _events(res, problem.periods) != count:
            if rigid:
                return GRAZE
            wandered = True
        A = np.vstack([J, t])
        b = np.concatenate([-r, [-(t @ (y - y_pred))]])
        try:
            dy = np.linalg.solve(A, b)
        except np.linalg.LinAlgError:
            return GRAZE if wandered else None
        y = y + dy
        if problem.converged(dy, A):
            try:
                r, J, mono, res = problem.evaluate(y)
            except SymimpactError:
                return GRAZE if wandered else None
            if count is not None and _events(res, problem.periods) != count:
                return GRAZE
            return y, J, mono, res
    return GRAZE if wandered else None


def _correct_compiled(problem: _Problem, y_pred, t, count, start):
    """:func:`_correct` for rigid impacts in Ω, its Newton steps compiled
    (:func:`._corrector.correct`: the same steps, refusals and stopping rule); the converged
    point evaluated here for its orbit, as the Python steps do."""
    y0 = y_pred if start is None else start
    outcome, y = _interrupt.call(
        _corrector.correct, problem.run_parameters(), np.asarray(y_pred, dtype=float),
        np.asarray(y0, dtype=float), np.asarray(t, dtype=float), problem.scale,
        float(problem.unit), problem.periods, -1.0 if count is None else float(count),
        MAX_IMPACTS_PER_PERIOD * problem.periods, MAX_NEWTON, TOL, problem.noise,
        problem.stall,
    )  # fmt: skip
    if outcome == _corrector.GRAZED:
        return GRAZE
    if outcome != _corrector.CONVERGED:
        return None
    try:
        _, J, mono, res = problem.evaluate(y)
    except SymimpactError:
        return None
    if count is not None and _events(res, problem.periods) != count:
        return GRAZE
    return y, J, mono, res


def _events(res, periods: int) -> float:
    """Impact events a period of the simulation ``res``: an accumulating chatter sequence counts
    once, however many of its impacts were resolved before the jump to its accumulation point."""
    return impact_counts(res.events, -math.inf, math.inf)[1] / periods


def _point(problem: _Problem, y, mono, res) -> BranchPoint:
    lam = np.linalg.eigvals(mono)
    order = np.argsort(-np.abs(lam))
    return BranchPoint(
        omega=problem.omega(y),
        state=tuple(float(c) for c in y[:4] * problem.scale),
        amplitude=float(np.max(res.period_max)),
        impacts_per_period=len(res.impacts) / problem.periods,
        multipliers=tuple(complex(c) for c in lam[order]),
        stable=bool(np.max(np.abs(lam)) < 1.0),
        value=float(y[4] * problem.unit),
        phase=problem.forcing.phase,
        asymmetric=_asymmetric(problem, y, res),
        impact_events_per_period=_events(res, problem.periods),
    )


def _det(A: np.ndarray) -> float:
    """det A of a real matrix; where it overflows (a stiff contact's monodromy holds multipliers
    of 1e200 and more), ±infinity with its sign, which is all the test functions read there."""
    with np.errstate(over="ignore", invalid="ignore"):
        d = float(np.real(np.linalg.det(A)))
    if math.isfinite(d):
        return d
    sign, _ = np.linalg.slogdet(A)
    return float(np.real(sign)) * math.inf if sign != 0 else 0.0


def _tests(t: np.ndarray, mono: np.ndarray) -> dict[str, float]:
    """The test functions whose sign changes mark the bifurcations."""
    lam = np.linalg.eigvals(mono)
    pairs = [abs(c) for c in lam if c.imag > 1e-9 * max(1.0, abs(c))]
    return {
        "fold": float(t[4]),
        "branch-point": _det(mono - np.eye(4)),
        "period-doubling": _det(mono + np.eye(4)),
        "neimark-sacker": (min(pairs, key=lambda a: abs(a - 1.0)) - 1.0) if pairs else math.nan,
    }


@_interrupt.stretch()
def continue_orbit(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    state: Any,
    bounds: tuple[float, float],
    *,
    parameter: str = "omega",
    periods: int = 1,
    direction: int = 1,
    step: float = 0.02,
    max_points: int = budgets.MAX_POINTS,
    folds: int = 0,
) -> Branch:
    """Continue the period-``periods`` orbit through ``state`` = (x, ẋ, z, ẏ) at t = 0 (an orbit
    of ``system`` under ``forcing`` with restitution ``e``, e.g. from
    :func:`symimpact.forced.shoot`) in ``parameter`` — ``"omega"`` (Ω [rad/s], the default),
    ``"gap"`` (d [m]), ``"F0"`` [N], ``"X_b"`` [m] or ``"e"`` — over ``bounds`` = (low, high) in
    SI, first towards increasing values (``direction`` 1) or decreasing (−1); ``step``: the
    arclength step in scaled unknowns (adapted between step/64 and 4·step, and shortened where
    the branch curves so that the drawn line between points stays within :data:`CHORD`);
    ``folds``: at most this many times the branch turns back at a grazing beyond which no orbit
    continues it, onto the orbits with the new impact on the same side (a non-smooth fold,
    :func:`_fold_back`; rigid impacts; 0: the branch ends there, as :func:`.frf.frequency_response`
    has it).  Eq. F1 and F2 along the orbits (Step 8, Step 9)."""
    system, forcing, e = checked(system, forcing, e)
    folds = checks.whole_number("folds", folds, 0, 1000)
    checks.choice("parameter", parameter, tuple(PARAMETERS))
    lo, hi = checks.bounds("bounds", bounds)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    step = checks.bounded("step", step, 0.0, MAX_STEP, open_low=True)
    max_points = checks.whole_number("max_points", max_points, 2, 1_000_000)
    if parameter in ("omega", "gap") and not lo > 0:
        raise ParameterError("bounds", f"{parameter} must stay positive, got low {lo:g}")
    if parameter == "e" and not is_constant(e):
        raise ParameterError(
            "parameter",
            "e is continued for rigid impacts of one restitution; a compliant law or the "
            "materials' e (per impact) set their own",
        )
    if parameter == "e" and not (0 <= lo and hi <= 1):
        raise ParameterError("bounds", f"e must stay within 0–1, got {lo:g}–{hi:g}")
    start = _value_of(parameter, system, forcing, e)
    if not lo <= start <= hi:
        raise ParameterError("bounds", f"must contain the start, {parameter} = {start:g}")
    checks.choice("direction", direction, (1, -1))
    s0 = checks.state("state", state)
    if is_rigid(e) and abs(s0[2]) >= system.gap / 2.0 * (1.0 - WALL):
        # a start on a wall (a sticking phase): the same orbit from a section in free flight
        forcing, s0, _ = _off_the_walls(system, forcing, e, s0, periods)
    problem = _problem(system, forcing, e, s0, periods, (lo, hi), parameter)
    branch = Branch(period_multiple=periods, phase=forcing.phase, parameter=parameter)
    y = np.concatenate([s0 / problem.scale, [start / problem.unit]])
    corrected = _correct(problem, y, np.array([0, 0, 0, 0, 1.0]))
    if corrected is None:
        raise MethodNotApplicable(
            "continuation", f"no orbit through the start at {problem.where(start)}"
        )
    y, J, mono, res = corrected
    t = _tangent(J, np.array([0, 0, 0, 0, float(direction)]))
    moved = _resection(problem, y, t, res)
    if moved is not None:
        problem, y, J, mono, res, t = moved
    point = _point(problem, y, mono, res)
    branch.points.append(point)
    tests = _tests(t, mono)
    tips: list[BranchPoint] = []  # a fold located within the step (:func:`_locate`)
    ds = step
    crossings = 0
    fine = False  # steps below step/16 growing from a fold at a grazing
    turned_back = 0
    before: BranchPoint | None = None  # the point before ``point``: the drawn curve's curvature
    back = None  # (y, t, ds) at ``before``: the step that led to ``point``
    while len(branch.points) < max_points:
        moved = _resection(problem, y, t, res)
        if moved is not None:  # the same orbit, its section moved away from the impacts
            problem, y, J, mono, res, t = moved
            point = _point(problem, y, mono, res)
            back = None  # the section moved: the point before is in the old one
        attempt = _correct(problem, _predicted(y, t, ds, back), t,
                           point.impact_events_per_period)  # fmt: skip
        if attempt is GRAZE and ds > step / 64 and is_rigid(problem.e) and not fine:
            # Newton's iterates met other impacts: beside an orbit that nearly grazes, the
            # basin of Newton's method is as narrow as its distance from grazing, and a shorter
            # step lands on the branch; at the shortest step the grazing is located
            ds *= 0.5
            continue
        if attempt is GRAZE and fine:
            # Newton's iterates left the orbits with these impacts: beside a grazing their region
            # is narrow (an impact's speed, or a flight's distance from a wall, is small); from
            # the point itself, Newton's steps halved to stay within the region walk along the
            # branch to the orbit where there is one
            attempt = _correct_within(problem, y + ds * t, t, y,
                                      point.impact_events_per_period) or GRAZE  # fmt: skip
        if attempt is GRAZE:
            located = _grazing(problem, y, t, ds, point)
            at_lo = located[3]
            if fine and _passes_by(problem, res, located, ds):
                # the orbit at the bracket's end is no nearer a wall than the point was: the
                # predictor's whole step left the narrow region of orbits with these impacts
                # beside the fold, while the bisection's shorter steps stayed on this branch,
                # which goes on from there
                attempt, ds = at_lo, located[1]
        if attempt is GRAZE:
            if (at_lo is not None and is_rigid(problem.e)
                    and _wall_margin(problem, at_lo[3]) > GRAZING_MARGIN):  # fmt: skip
                # no wall is touched where the corrector stops landing with the old impacts:
                # Newton from the predictor leaves the branch there (the branch turns sharply,
                # or another orbit is near), which is no grazing
                branch.stopped = (f"the corrector failed at {problem.where(located[0].value)} "
                                  "(no impact grazes there: the branch turns or meets another "
                                  "orbit within the step)")  # fmt: skip
                return branch
            crossings += 1
            crossed = _cross(problem, y, t, ds, point, branch, located, crossings <= MAX_CROSSINGS,
                             turned_back < folds)  # fmt: skip
            if crossed is None:
                branch.stopped = f"grazing at {problem.where(branch.bifurcations[-1].value)}"
                if crossings > MAX_CROSSINGS:
                    branch.stopped += (f" (after {MAX_CROSSINGS} grazings crossed: impacts keep "
                                       "appearing and vanishing, as before chatter)")  # fmt: skip
                return branch
            y, t, mono, res, point, turned = crossed
            if _rejoins(problem, point):
                # the orbit beyond the grazing is one of period k/2: this branch does not go on
                branch.bifurcations[-1] = replace(branch.bifurcations[-1], impacts_after=math.nan)
                branch.stopped = (f"rejoined the period-{periods // 2} orbits at "
                                  f"{problem.where(point.value)} (across a grazing)")  # fmt: skip
                return branch
            before = back = None
            if turned is not None:
                turned_back += 1
                # the branch turned back at the grazing: the new impact's speed grows in
                # proportion to the distance from it, and the region of orbits with that impact
                # around the branch as its square, so the steps start at a share of the distance
                # and grow by half each (measured at the README's fold at 30.4438 rad/s: the
                # region spans 3e-5 along the tangent 1e-4 from the grazing)
                ds, fine = FOLD_STEP * turned, True
            tests = _tests(t, mono)  # the multipliers jump at a grazing: no test across it
            branch.points.append(point)
            continue
        if attempt is None:
            ds *= 0.5
            if ds < step / 64:
                branch.stopped = (
                    f"the corrector failed at {problem.where(point.value)} (chatter that does not "
                    "accumulate, loss of impacts or a non-smooth turn)"
                )
                return branch
            continue
        y1, J1, mono1, res1 = attempt
        res_here, res = res, res1
        t1 = _tangent(J1, t)
        p1 = _point(problem, y1, mono1, res1)
        if p1.impact_events_per_period != point.impact_events_per_period:  # (the corrector checks)
            branch.bifurcations.append(_grazing(problem, y, t, ds, point)[0])
            branch.stopped = f"grazing at {problem.where(branch.bifurcations[-1].value)}"
            return branch
        if _rejoins(problem, p1):
            branch.stopped = (f"rejoined the period-{periods // 2} orbits at "
                              f"{problem.where(p1.value)}")  # fmt: skip
            return branch
        kappa = _curvature(before, point, p1, hi - lo)
        reach = _chord(point, p1, hi - lo) / ds  # drawn length per unit of step
        if kappa * _chord(point, p1, hi - lo) ** 2 / 8 > CHORD and ds > step / 16:
            ds = max(0.5 * ds, step / 16)  # too far for the drawn curve: a shorter step
            res = res_here
            continue
        # the curve may bend more ahead than it did behind (towards a fold, where the amplitude
        # goes as a square root of the parameter): where the circle through the three points
        # shows the last segment too long for the drawn curve, the orbit halfway along it is
        # found, and while it lies farther than CHORD from the segment it is put in and the half
        # next to ``point`` is looked at in the same way
        # (the circle's estimate lags where the curvature grows: 9e-4 estimated against 1.25e-3
        # found, at 33.74–33.77 rad/s on tests/test_drawn_curve.py's curve, so half the bound
        # sends a segment to the exact check)
        start = before
        if back is not None and kappa * _chord(before, point, hi - lo) ** 2 / 8 > 0.5 * CHORD:
            for _ in range(6):
                got = _between(problem, back, point)
                if got is None or _departure(start, got[0], point, hi - lo) <= CHORD:
                    break
                start, y_mid = got
                branch.points.insert(len(branch.points) - 1, start)
                back = (y_mid, back[1], 0.5 * back[2])
        tests1 = _tests(t1, mono1)
        for kind in ("fold", "branch-point", "period-doubling", "neimark-sacker"):
            a, b = tests[kind], tests1[kind]
            if kind == "branch-point" and (tests["fold"] > 0) != (tests1["fold"] > 0):
                continue  # a multiplier through +1 at a fold is the fold itself
            if math.isfinite(a) and math.isfinite(b) and (a > 0) != (b > 0):
                found = _locate(problem, kind, y, t, ds, a, b, tips)
                if found is not None:
                    branch.bifurcations.append(found)
        branch.points.extend(tips)  # a fold's own orbit, between the two points it lies between
        tips.clear()
        back = (y, t, ds)
        y, t, mono, point, before, tests = y1, t1, mono1, p1, point, tests1
        branch.points.append(point)
        again = _revisited(branch.points, problem, ds)
        if again is not None:
            branch.stopped = (f"back at its own orbits (or their mirror images) of "
                              f"{problem.where(again.value)}: a closed curve")  # fmt: skip
            return branch
        if not lo <= point.value <= hi:
            branch.stopped = f"the range's edge at {problem.where(point.value)}"
            return branch
        ds = min(ds * 1.5, 4 * step)
        fine = fine and ds < step / 16
        if kappa > 0 and reach > 0:  # the next segment within the drawn bound, if it can be
            ds = max(min(ds, 0.9 * math.sqrt(8 * CHORD / kappa) / reach),
                     ds if fine else step / 16)  # fmt: skip
    branch.stopped = f"{max_points} points"
    return branch


def _predicted(y: np.ndarray, t: np.ndarray, ds: float, back: tuple | None) -> np.ndarray:
    """The predictor a step ``ds`` along the branch from y: the second-order Taylor step
    y + ds·t + ds²/2·y'' with y'' ≈ (t − t_back)/ds_back, the change of the unit tangent over the
    step ``back`` = (y, t, ds) that led to y (the tangent step alone, y + ds·t, where there is
    none).  The tangent step's error grows as ds²: on the README's curve (benchmark 6's band) the
    corrector started from residuals of 1e-3–1e-2 of the scale and took five or six one-period
    runs a point; with the second-order step the curve's corrections took 21 992 runs against
    37 710, and the curve 14 s against 21 s."""
    if back is None:
        return y + ds * t
    return y + ds * t + 0.5 * ds * ds * (t - back[1]) / back[2]


def _rejoins(problem: _Problem, point: BranchPoint) -> bool:
    """Whether ``point`` of a branch of period 2k is an orbit of period k (the branch has
    come back to the orbits it doubled from)."""
    k = problem.periods
    return k > 1 and k % 2 == 0 and _repeats(problem.at(point.value), point.state, k // 2,
                                             problem.scale)  # fmt: skip


#: The hyperplane normal that holds the continued parameter (the last of the unknowns).
_PARAMETER_AXIS = np.array([0.0, 0.0, 0.0, 0.0, 1.0])


def _between(problem: _Problem, back: tuple, point: BranchPoint):
    """(the orbit, its unknowns) at the parameter's value halfway between the start y of the
    step ``back`` = (y, t, ds) and ``point`` (the corrector from the unknowns halfway between
    them, the parameter held), or None where it lands elsewhere: another count of impacts, or
    outside the step's parameter range.  The drawn curve's departure is judged there, at the
    segment's middle in the parameter: halfway along the step's arclength, next to the fold at
    31.3286 rad/s of tests/test_drawn_curve.py's curve, the orbit lay at 0.37 of the segment
    and the departure estimated from it, 0.88e-3, fell short of the 1.07e-3 at the middle."""
    y = back[0]
    y_end = np.concatenate([np.asarray(point.state) / problem.scale, [point.value / problem.unit]])
    # the count is not imposed on the iterates (which may wander across a grazing and come
    # back): the orbit found is checked below
    attempt = _correct(problem, 0.5 * (y + y_end), _PARAMETER_AXIS)
    if attempt is None or attempt is GRAZE:
        return None
    y1, _, mono1, res1 = attempt
    middle = _point(problem, y1, mono1, res1)
    lo, hi = sorted((float(y[4] * problem.unit), point.value))
    if middle.impact_events_per_period != point.impact_events_per_period:
        return None
    return (middle, y1) if lo < middle.value < hi else None


def _departure(a: BranchPoint, m: BranchPoint, c: BranchPoint, width: float) -> float:
    """How far the drawn curve through the orbit ``m`` departs from the segment from ``a`` to
    ``c`` at most (:func:`_plane` relative to ``m``): the parabola through the three points
    departs by d/(4f(1 − f)) at its middle, where d is m's distance from the segment and f the
    share of the segment at which m lies (the orbit at the parameter's middle lies off the
    segment's middle in the drawn plane where the segment is steep), f kept within 0.05–0.95."""
    pa, pm, pc = _plane(a, m, width), _plane(m, m, width), _plane(c, m, width)
    chord = pc - pa
    norm = float(np.linalg.norm(chord))
    if not norm:
        return 0.0
    d = abs(float(chord[0] * (pm - pa)[1] - chord[1] * (pm - pa)[0])) / norm
    f = min(max(float((pm - pa) @ chord) / norm**2, 0.05), 0.95)
    return d / (4.0 * f * (1.0 - f))


def _plane(p: BranchPoint, ref: BranchPoint, width: float) -> np.ndarray:
    """``p`` in the drawn plane: its parameter value in ``width``s (its range's), its amplitude
    relative to ``ref``'s (:data:`CHORD`)."""
    return np.array([p.value / width, p.amplitude / max(ref.amplitude, 1e-300)])


def _chord(p: BranchPoint, q: BranchPoint, width: float) -> float:
    """The length of the drawn segment from ``p`` to ``q`` (:func:`_plane` relative to ``p``)."""
    return float(np.linalg.norm(_plane(q, p, width) - _plane(p, p, width)))


def _curvature(a: BranchPoint | None, b: BranchPoint, c: BranchPoint, width: float) -> float:
    """The curvature of the circle through ``a``, ``b``, ``c`` in the drawn plane
    (:func:`_plane` relative to ``b``): 4·area/(product of the sides); 0 without ``a``."""
    if a is None:
        return 0.0
    pa, pb, pc = _plane(a, b, width), _plane(b, b, width), _plane(c, b, width)
    u, v = pa - pb, pc - pb
    sides = np.linalg.norm(u) * np.linalg.norm(v) * np.linalg.norm(pc - pa)
    return float(2.0 * abs(u[0] * v[1] - u[1] * v[0]) / sides) if sides > 0 else 0.0


def _revisited(points: list[BranchPoint], problem: _Problem, ds: float) -> BranchPoint | None:
    """The earlier point (not one of the last four) that the newest one repeats: the same
    parameter and amplitude to a quarter of the step (in the scaled unknowns), the same impacts a
    period and Floquet multipliers within ten steps of each other — the orbit itself, or its
    mirror image (same amplitude and multipliers).  A branch through a pitchfork comes back along
    its mirror images, and one that closes on itself (an isola, or an asymmetric branch joining
    two branch points of the symmetric one) comes back to its start: each ends there."""
    new = points[-1]
    for old in points[:-4]:
        if (abs(old.value - new.value) / problem.unit < 0.25 * ds
                and abs(old.amplitude - new.amplitude) / problem.scale[0] < 0.25 * ds
                and old.impact_events_per_period == new.impact_events_per_period
                and np.max(np.abs(np.array(old.multipliers) - np.array(new.multipliers)))
                < 10 * ds):  # fmt: skip
            return old
    return None


@_interrupt.stretch()
def trace_branch(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    state: Any,
    bounds: tuple[float, float],
    *,
    parameter: str = "omega",
    periods: int = 1,
    step: float = 0.02,
    folds: int = 0,
) -> Branch:
    """The whole branch through ``state`` within ``bounds``: :func:`continue_orbit` towards
    decreasing and towards increasing values of ``parameter`` (each turning back at most
    ``folds`` times at a grazing), joined into one branch in the order of the arclength (the
    decreasing part reversed), with both parts' bifurcations."""
    kw = {"parameter": parameter, "periods": periods, "step": step, "folds": folds}
    down = continue_orbit(system, forcing, e, state, bounds, direction=-1, **kw)
    up = continue_orbit(system, forcing, e, state, bounds, direction=1, **kw)
    joined = Branch(period_multiple=periods, phase=forcing.phase, parameter=parameter)
    joined.points = [*reversed(down.points[1:]), *up.points]
    joined.bifurcations = [*down.bifurcations, *up.bifurcations]
    joined.stopped = f"down: {down.stopped}; up: {up.stopped}"
    return joined


#: The critical multiplier of the bifurcations a new branch leaves from, and the factor on the
#: period of that branch: a branch point's new orbits have the same period, a period doubling's
#: twice the period.
SWITCHES = {"branch-point": (1.0, 1), "period-doubling": (-1.0, 2)}


@dataclass(frozen=True)
class BranchStart:
    """An orbit on a branch that leaves a bifurcation (:func:`branch_starts`): the ``system``,
    ``forcing`` and restitution ``e`` at its parameter value, its ``state`` (x, ẋ, z, ẏ) at t = 0
    and ``periods``, its period in forcing periods."""

    system: ImpactSystem
    forcing: Forcing
    e: Any
    state: tuple[float, float, float, float]
    periods: int


def branch_starts(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    bifurcation: Bifurcation,
    bounds: tuple[float, float],
    *,
    parameter: str = "omega",
    periods: int = 1,
    step: float = 0.02,
) -> list[BranchStart]:
    """The orbits a step away from a branch point or period doubling on the branches that leave
    it (branch switching): ``bifurcation`` located on a period-``periods`` branch of ``system``
    under ``forcing`` (its phase the branch's section; the continued parameter's value is taken
    from the bifurcation) with restitution ``e``.

    At the point the critical Floquet multiplier is +1 (branch point) or −1 (period doubling)
    with eigenvector v of the monodromy.  Over the new branch's period (the same, or twice it
    for a period doubling, where the multiplier of the doubled map is (−1)² = +1) the extended
    Jacobian [M − I | ∂P/∂p] is singular and v, with the parameter held, spans the direction of
    the branch that crosses the old one (for the symmetry-breaking pitchfork of the symmetric
    orbits and for a period doubling the new branch is tangent to v there).  The predictor steps
    ±``step``/8 along (v, 0) in the scaled unknowns (then /4, /2, 1, and /16 to /128: a window
    beside a grazing can be narrow, tests/test_cascades.py) and Newton corrects it in the plane
    normal to it, which the old branch does not cross nearby.  A side gives one start at most;
    a doubling's start that repeats after the old period (the old orbit) is dropped.  Eq. F1, F2."""
    system, forcing, e = checked(system, forcing, e)
    checks.instance("bifurcation", bifurcation, Bifurcation, "a Bifurcation of a traced branch")
    checks.choice("parameter", parameter, tuple(PARAMETERS))
    lo, hi = checks.bounds("bounds", bounds)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    step = checks.bounded("step", step, 0.0, MAX_STEP, open_low=True)
    if bifurcation.kind not in SWITCHES:
        raise ParameterError("bifurcation", f"new branches leave a {' or '.join(SWITCHES)}, "
                             f"not a {bifurcation.kind}")  # fmt: skip
    if bifurcation.state is None:
        raise ParameterError("bifurcation", "carries no orbit state to switch from")
    target, factor = SWITCHES[bifurcation.kind]
    k = periods * factor
    if k > MAX_PERIODS:
        return []
    value = bifurcation.value if math.isfinite(bifurcation.value) else bifurcation.omega
    base = _Problem(system, forcing, e, periods, np.ones(4), 1.0, parameter)
    at = base.at(value)
    s_b = np.array(bifurcation.state, dtype=float)
    try:
        problem = _problem(*at, s_b, k, (lo, hi), parameter)
        _, mono, _ = monodromy(*at, s_b, periods)
    except SymimpactError:
        return []
    lam, vecs = np.linalg.eig(mono)
    v = np.real(vecs[:, int(np.argmin(np.abs(lam - target)))]) / problem.scale
    direction = np.concatenate([v / np.linalg.norm(v), [0.0]])
    y_b = np.concatenate([s_b / problem.scale, [value / problem.unit]])
    if factor == 2:
        # over the old period the point is regular (multiplier −1, not +1): the old branch's
        # tangent there is the null vector of its Jacobian, and the doubled problem's second
        # null direction is taken orthogonal to it, so the hyperplane misses the old branch
        old = _Problem(*at, periods, problem.scale, problem.unit, parameter)
        try:
            t_old = _tangent(old.evaluate(y_b)[1], None)
        except SymimpactError:
            return []
        direction = direction - float(direction @ t_old) * t_old
        direction /= np.linalg.norm(direction)
    starts: list[BranchStart] = []
    for sign in (1.0, -1.0):
        for ds in (step / 8, step / 4, step / 2, step, step / 16, step / 32, step / 64, step / 128):
            got = _correct(problem, y_b + sign * ds * direction, direction)
            if got is None or got is GRAZE:
                continue
            y = got[0]
            if abs(float(direction @ (y - y_b))) < 0.5 * ds:
                continue  # landed back on the old branch
            state = _si_state(problem, y)
            new = problem.at(float(y[4] * problem.unit))
            if factor == 2 and _repeats(new, state, periods, problem.scale):
                continue
            starts.append(BranchStart(*new, state, k))
            break
    return starts


def _repeats(at, state, periods: int, scale: np.ndarray) -> bool:
    """Whether ``state`` comes back after ``periods`` forcing periods (to 1e-8 of ``scale``)."""
    try:
        ps = monodromy(*at, np.array(state), periods, jacobian=False)[0]
    except SymimpactError:
        return False
    return bool(np.max(np.abs((ps - np.array(state)) / scale)) < 1e-8)


def switch_branch(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    bifurcation: Bifurcation,
    bounds: tuple[float, float],
    *,
    parameter: str = "omega",
    periods: int = 1,
    step: float = 0.02,
) -> list[Branch]:
    """The branches that leave ``bifurcation`` (a branch point or period doubling located on a
    period-``periods`` branch; see :func:`branch_starts`), each followed away from it within
    ``bounds`` (:func:`leave`).  Of a symmetry-breaking pitchfork's two starts, mirror images of
    each other with the same amplitude, one branch is traced (``mirrored``).
    Eq. F1, F2 along the orbits (Step 8, Step 9)."""
    starts = branch_starts(system, forcing, e, bifurcation, bounds, parameter=parameter,
                           periods=periods, step=step)  # fmt: skip
    out: list[Branch] = []
    for s in starts:
        amp = orbit_amplitude(s)
        value = _value(parameter, s)
        if any(abs(o.amplitude - amp) <= 1e-8 * amp
               for b in out for o in orbits_at(b, s.system, s.forcing, s.e, value)):  # fmt: skip
            continue  # the other side's orbit: the mirror image of a traced one
        out.append(leave(s, bifurcation, bounds, parameter=parameter, step=step))
    return out


def leave(
    start: BranchStart,
    bifurcation: Bifurcation,
    bounds: tuple[float, float],
    *,
    parameter: str = "omega",
    step: float = 0.02,
) -> Branch:
    """The branch through ``start`` (from :func:`branch_starts`) continued away from the
    ``bifurcation`` it left, within ``bounds``, beginning at the bifurcation itself.  Beyond the
    point it left lies the same family again — a pitchfork's mirror images, or a period
    doubling's orbit shifted by one period — so one way is traced.  Eq. F1, F2 (Step 8, 9)."""
    checks.instance("start", start, BranchStart, "a BranchStart of branch_starts")
    checks.instance("bifurcation", bifurcation, Bifurcation, "a Bifurcation of a traced branch")
    at = bifurcation.value if math.isfinite(bifurcation.value) else bifurcation.omega
    value = _value(parameter, start)
    kw = {"parameter": parameter, "periods": start.periods, "step": step}
    if abs(value - at) <= 1e-9 * max(abs(at), 1e-300):  # no side to tell: both ways
        branch = trace_branch(start.system, start.forcing, start.e, start.state, bounds, **kw)
    else:
        branch = continue_orbit(start.system, start.forcing, start.e, start.state, bounds,
                                direction=1 if value > at else -1, **kw)  # fmt: skip
    system, forcing, e = _Problem(start.system, start.forcing, start.e, start.periods,
                                  np.ones(4), 1.0, parameter).at(at)  # fmt: skip
    forcing = forcing.at(forcing.omega, bifurcation.phase)
    try:
        mono = monodromy(system, forcing, e, np.array(bifurcation.state), start.periods)[1]
    except SymimpactError:
        mono = None
    if mono is not None:
        lam = np.linalg.eigvals(mono)
        lam = lam[np.argsort(-np.abs(lam))]
        branch.points.insert(0, replace(
            branch.points[0], omega=bifurcation.omega, state=bifurcation.state,
            amplitude=bifurcation.amplitude, value=at, phase=bifurcation.phase,
            multipliers=tuple(complex(c) for c in lam), stable=False,  # a multiplier ±1 there
        ))  # fmt: skip
    branch.origin = f"{bifurcation.kind} at {_Problem.where_text(parameter, at)}"
    return branch


def orbit_between(
    p: BranchPoint, q: BranchPoint, value: float, at: tuple, periods: int
) -> ShootingOrbit | None:
    """The orbit at the parameter ``value`` between two consecutive points of a branch: Newton's
    method (:func:`symimpact.forced.shoot`) from the state interpolated between them (from the
    nearer one where the section moved between them), with ``at`` = (system, forcing, e) at
    that value; None where Newton's method fails."""
    f = 0.5 if q.value == p.value else (value - p.value) / (q.value - p.value)
    if p.phase != q.phase:
        p, f = (p if f <= 0.5 else q), 0.0
    guess = np.array(p.state) + f * (np.array(q.state) - np.array(p.state))
    fs = at[1].at(at[1].omega, p.phase)
    try:
        return shoot(at[0], fs, at[2], guess, periods=periods)
    except SymimpactError:
        return None


def _same_phase(a: float | None, b: float | None) -> bool:
    if a is None or b is None:
        return a is b
    return abs(math.remainder(a - b, 2 * math.pi)) < 1e-8


def _value(parameter: str, s: BranchStart) -> float:
    """The continued parameter's value at a start."""
    return _value_of(parameter, s.system, s.forcing, s.e)


def _value_of(parameter: str, system: ImpactSystem, forcing: Forcing, e: Any) -> float:
    """The value of ``parameter`` (one of :data:`PARAMETERS`) in ``system``, ``forcing``, ``e``
    (NaN for e with a compliant contact or the materials' e)."""
    return {"omega": forcing.omega, "gap": system.gap, "F0": forcing.F0, "X_b": forcing.X_b,
            "e": float(e) if is_constant(e) else math.nan}[parameter]  # fmt: skip


def orbit_amplitude(start: BranchStart) -> float:
    """max abs(x) over the orbit of ``start`` [m]."""
    res = monodromy(
        start.system, start.forcing, start.e, np.array(start.state), start.periods, jacobian=False
    )[2]
    return float(np.max(res.period_max))


def orbits_at(
    branch: Branch, system: ImpactSystem, forcing: Forcing, e: Any, value: float
) -> list[ShootingOrbit]:
    """The orbits of ``branch`` at the continued parameter's ``value`` exactly: wherever two
    consecutive points bracket it, Newton's method (:func:`symimpact.forced.shoot`) from the
    state interpolated between them, with ``system``, ``forcing`` (the branch's section phase)
    and ``e`` set to ``value``; an orbit found twice (the same amplitude to 1e-10 and the same
    forcing phase of its first impact, to 1e-8 rad) is listed once.
    Eq. F1, F2 along the orbits (Step 8, Step 9)."""
    checks.instance("branch", branch, Branch, "a traced Branch")
    system, forcing, e = checked(system, forcing, e)
    value = checks.bounded("value", value, -math.inf, math.inf)
    at = _Problem(system, forcing, e, branch.period_multiple, np.ones(4), 1.0,
                  branch.parameter).at(value)  # fmt: skip
    found: list[ShootingOrbit] = []
    for p, q in itertools.pairwise(branch.points):
        lo, hi = sorted((p.value, q.value))
        if not lo <= value <= hi:
            continue
        orbit = orbit_between(p, q, value, at, branch.period_multiple)
        if orbit is None:
            continue
        if not any(abs(o.amplitude - orbit.amplitude) <= 1e-10 * orbit.amplitude
                   and _same_phase(o.impact_phase, orbit.impact_phase) for o in found):  # fmt: skip
            found.append(orbit)
    return found


def _locate(problem, kind, y, t, ds, a, b, tips=None) -> Bifurcation | None:
    """The bifurcation of ``kind`` between y and the step ds along t: Brent's method on the
    step length σ, each σ corrected onto the branch.  A fold's orbit is put in ``tips`` (a
    list) as a point of the branch: the turn in the parameter is drawn where it is, not cut
    across by the segment between the points on either side, and an orbit beyond the last of
    them (the stable five-impact orbit at 29.8756 rad/s on the README's curve, between the fold
    at 29.874 and the point at 29.879) lies on the branch's drawn line."""
    cache = {}

    def at(sigma):
        if sigma not in cache:
            got = _correct(problem, y + sigma * t, t)
            if got is None:
                raise MethodNotApplicable("continuation", "the corrector failed in the bracket")
            y1, J1, mono1, res1 = got
            cache[sigma] = (y1, mono1, res1, _tests(_tangent(J1, t), mono1)[kind])
        return cache[sigma]

    try:
        sigma = brentq(lambda s: at(s)[3] if s > 0 else a, 0.0, ds, xtol=1e-12 * ds)
        y1, mono1, res1, _ = at(sigma)
        if kind == "fold" and tips is not None:
            tips.append(_point(problem, y1, mono1, res1))
        return Bifurcation(kind, problem.omega(y1), float(np.max(res1.period_max)),
                           float(y1[4] * problem.unit), _si_state(problem, y1),
                           problem.forcing.phase)  # fmt: skip
    except (MethodNotApplicable, ValueError):
        pass
    # at a branch point the extended Jacobian itself is singular and the corrector cannot land
    # on it: the test function, Ω and the amplitude are interpolated by cubics through four
    # corrected points across the bracket (error ~ds⁴)
    grid = np.linspace(0.0, ds, 4)
    try:
        rows = [at(g) if g > 0 else None for g in grid]
    except MethodNotApplicable:
        return None
    ys = [y, *(r[0] for r in rows[1:])]
    values = [a, *(r[3] for r in rows[1:])]
    if not np.all(np.isfinite(values)):  # a monodromy that overflowed: nothing to interpolate
        return None
    roots = [
        float(r.real)
        for r in np.roots(np.polyfit(grid, values, 3))
        if abs(r.imag) < 1e-12 * ds and 0.0 <= r.real <= ds
    ]
    if not roots:
        return None
    values = [float(v[4]) * problem.unit for v in ys]
    amps = [float(np.max(r[2].period_max)) for r in rows[1:]]
    amp0 = float(np.max(problem.evaluate(y)[3].period_max))
    sigma = roots[0]
    value = float(np.polyval(np.polyfit(grid, values, 3), sigma))
    state = [float(np.polyval(np.polyfit(grid, [float(v[i]) for v in ys], 3), sigma))
             for i in range(4)]  # fmt: skip
    return Bifurcation(
        kind,
        value if problem.parameter == "omega" else problem.forcing.omega,
        float(np.polyval(np.polyfit(grid, [amp0, *amps], 3), sigma)),
        value,
        _si_state(problem, np.array([*state, 0.0])),
        problem.forcing.phase,
    )


def _si_state(problem: _Problem, y: np.ndarray) -> tuple[float, float, float, float]:
    return tuple(float(c) for c in y[:4] * problem.scale)


def _grazing(problem, y, t, ds, before: BranchPoint):
    """Where the impact count changes between y and ds along t: bisection on the step length
    (the count is a step function of it) to 1e-6 of ds (ds moves Ω by at most 2 % of the band,
    so 2e-8 of the band).  Returns the grazing (the last orbit with the old count), the step
    lengths lo and hi of the final bracket, and the corrected orbit at lo, (y, J, monodromy,
    simulation), None where no step with the old count was corrected."""
    lo, hi = 0.0, ds
    last, at_lo = before, None
    y_lo = y  # the corrected orbit at lo
    while hi - lo > 1e-6 * ds:
        mid = 0.5 * (lo + hi)
        # Newton from the orbit at lo moved along t to mid's hyperplane (tᵀ(y_lo − y − lo·t)
        # = 0): a step of the bracket away from the branch, not the predictor's whole chord
        got = _correct(problem, y + mid * t, t, before.impact_events_per_period,
                       start=y_lo + (mid - lo) * t)  # fmt: skip
        if got is None or got is GRAZE:
            hi = mid
            continue
        at_lo = got
        lo, y_lo = mid, got[0]
    if at_lo is not None:  # the point of the last orbit corrected, formed once
        last = _point(problem, at_lo[0], at_lo[2], at_lo[3])
    found = Bifurcation("grazing", last.omega, last.amplitude, last.value, last.state,
                        last.phase, impacts_before=before.impact_events_per_period)  # fmt: skip
    return found, lo, hi, at_lo


#: A located change of the impacts is a grazing where the orbit found there touches a wall: a
#: flight turns within this fraction of d/2 of a wall, or the square of an impact's relative
#: speed is within this fraction of the fastest's.  Located from the shortest step (a failed
#: step is halved first), the 85 grazings of tests/test_grazing_crossing.py's curves leave
#: ≤ 2.7e-5, most ≤ 1e-9 (measured).
GRAZING_MARGIN = 1e-4


def _wall_margin(problem: _Problem, res) -> float:
    """How far the rigid-impact orbit of the simulation ``res`` (one run of the problem's k
    periods) is from touching a wall: the smaller of (d/2 − abs(z))/(d/2) at the flights'
    turning points of z = y − x (:func:`_turns`) and the square of the slowest impact's relative
    speed over the fastest's.  0 where the orbit chatters or sticks (the accumulation of impacts
    touches with speed zero)."""
    ev = res.events
    kinds = ev[:, _rigid.E_KIND]
    if np.any(kinds != _rigid.KIND_IMPACT):
        return 0.0
    speeds = np.abs(ev[:, _rigid.E_VREL])
    # an impact born at a grazing gains speed as the square root of the distance from it (the
    # turning point it was moves linearly): squared, both sides are measured alike
    margin = float((speeds.min() / speeds.max()) ** 2) if len(speeds) else math.inf
    _, gaps = _turns(problem, res)
    return min(margin, float(gaps.min())) if len(gaps) else margin


def _turns(problem: _Problem, res) -> tuple[np.ndarray, np.ndarray]:
    """The flights' turning points of z = y − x in the simulation ``res`` of the problem's k
    periods (rigid impacts): their instants [s] and their distances from the nearer wall over
    d/2, (d/2 − abs(z))/(d/2).  ż = 0 is bisected between samples at 1/512 of a period where ż
    changes sign away from the walls with no event between (30 times, to 1e-9 of a sample's
    interval: z is flat there, its error ~z̈·(that)², far below the margins looked at)."""
    ev = res.events
    h = problem.system.gap / 2.0
    period = res.forcing.period * problem.periods
    ts = np.linspace(0.0, period, 512 * problem.periods + 1)
    s = state_at(res, ts)
    zdot = s[:, 3] - s[:, 1]
    free = np.abs(s[:, 2]) < h * (1.0 - 1e-9)
    between = np.searchsorted(ev[:, _rigid.E_T], ts)
    i = np.nonzero((zdot[:-1] * zdot[1:] < 0) & free[:-1] & free[1:]
                   & (between[:-1] == between[1:]))[0]  # fmt: skip
    if not len(i):
        return np.zeros(0), np.zeros(0)
    a, b, fa = ts[i], ts[i + 1], zdot[i]
    for _ in range(30):
        c = 0.5 * (a + b)
        r = state_at(res, c)
        same = fa * (r[:, 3] - r[:, 1]) > 0  # the turn lies in [c, b]
        a, b = np.where(same, c, a), np.where(same, b, c)
    return c, (h - np.abs(r[:, 2])) / h


#: A located change of the impacts is no grazing where the orbit at the bracket's end keeps more
#: than this share of the point's margin from the walls (:func:`_wall_margin`): approaching a
#: grazing, the margin falls in proportion to the distance left, which the bisection leaves at
#: 1e-6 of the step.  Measured over the README's curve (462 located changes, every one tested):
#: the shares split into a group at most 0.21 (most below 1e-4) and one from 0.37 to 1, where
#: (checked at 30.4389 rad/s: 1.43e-5 before, 1.24e-5 at the bracket's end) the predictor met
#: a neighbouring orbit.  Applied only in the first steps after a turn at a grazing.
PASSING_SHARE = 0.3

#: The bracket's end is taken as the next point only where it lies this share of the step or more
#: beyond the point (progress along the branch); nearer, the change is treated as a grazing.
PASSING_STEP = 0.25


def _passes_by(problem: _Problem, res, located, ds: float) -> bool:
    """Whether the change of impacts that :func:`_grazing` ``located`` along a step of length
    ``ds`` from the point whose simulation is ``res`` is no grazing (rigid impacts): the point is
    near a wall (its margin at most GRAZING_MARGIN, else nothing grazes) and the orbit at the
    bracket's end lies at least PASSING_STEP·ds along and keeps more than PASSING_SHARE of the
    point's margin."""
    _, lo, _, at_lo = located
    if at_lo is None or not is_rigid(problem.e) or lo < PASSING_STEP * ds:
        return False
    here = _wall_margin(problem, res)
    if not 0 < here <= GRAZING_MARGIN:
        return False
    return _wall_margin(problem, at_lo[3]) > PASSING_SHARE * here


#: At most this many grazings are crossed in one direction of a continuation: near the onset of
#: chatter impacts appear and vanish in a sequence that accumulates (measured: 12 crossings within
#: 0.1 rad/s on the README's system), which the branch does not follow.
MAX_CROSSINGS = 3


def _cross(problem, y, t, ds, before: BranchPoint, branch: Branch, located, go_on: bool = True,
           turn: bool = True):  # fmt: skip
    """Continuation through a grazing: the grazing ``located`` by :func:`_grazing` (listed on
    ``branch``), the orbit just beyond it with its new impacts (Newton from a little past the
    located step, the count free), whose tangent is oriented along t.  Returns (y, t,
    monodromy, simulation, point) on the other side, or None where no impacting orbit
    continues it (the impact mass stops impacting, or Newton's steps fail there)."""
    found, _, hi, _ = located
    branch.bifurcations.append(found)
    if not go_on:
        return None
    for extra in (1e-4, 1e-3, 1e-2, 1e-1):
        got = _correct(problem, y + (hi + extra * ds) * t, t)
        if got is None or got is GRAZE:
            continue
        y1, J1, mono1, res1 = got
        p1 = _point(problem, y1, mono1, res1)
        if p1.impact_events_per_period == before.impact_events_per_period:
            continue
        branch.bifurcations[-1] = replace(found, impacts_after=p1.impact_events_per_period)
        return y1, _tangent(J1, t), mono1, res1, p1, None
    back = _fold_back(problem, y, t, ds, before, located) if turn and is_rigid(problem.e) else None
    if back is not None:
        branch.bifurcations[-1] = replace(found, impacts_after=back[4].impact_events_per_period)
    return back


def _wall_push(problem: _Problem, y0, res0, t, nth: int = 0):
    """The flight's turning point nearest a wall in the orbit y0 (its simulation ``res0``): its
    distance from the wall over d/2 and the gradient of its reach towards the wall within the
    hyperplane normal to t (:func:`_reach_gradient`) with its squared norm, (gap, grad, norm2):
    a step push·gap/norm2·grad puts it (push − 1)·gap past the wall to first order.  ``nth``:
    0 the turning point nearest either wall, 1 the one nearest the other wall (an orbit that
    grazes both walls at once, as the README's symmetric orbits at 30.4438 rad/s do, has two
    such points whose order the rounding decides: on the README's curve the five-impact orbits
    lay beside one of them only).  False where no flight turns (towards that wall), None where
    the gradient meets other impacts or vanishes."""
    times, gaps = _turns(problem, res0)
    if not len(gaps):
        return False
    sides = np.sign(state_at(res0, times)[:, 2])
    nearest = [int(np.flatnonzero(sides == w)[np.argmin(gaps[sides == w])])
               for w in (1.0, -1.0) if np.any(sides == w)]  # fmt: skip
    nearest.sort(key=lambda i: gaps[i])
    if nth >= len(nearest):
        return False
    tau, gap = float(times[nearest[nth]]), float(gaps[nearest[nth]])
    side = float(sides[nearest[nth]])
    grad = _reach_gradient(problem, y0, len(res0.events), tau, side)
    if grad is None:
        return None
    grad = grad - (grad @ t) * t  # within the hyperplane
    norm2 = float(grad @ grad)
    if not norm2 > 0:
        return None
    return gap, grad, norm2


#: The distances behind a grazing (shares of the located step) at which :func:`_fold_back` looks
#: for the orbits with the new impact, and how far past the wall (multiples of the old orbit's
#: distance from it) the turning point is pushed to start Newton's method there.
FOLD_BACK = (0.3, 1.0, 0.1)
FOLD_PUSH = (1.5, 4.0, 1.1)
#: The first step from a fold at a grazing, a share of the distance from it.
FOLD_STEP = 0.25


def _fold_back(problem: _Problem, y, t, ds, before: BranchPoint, located):
    """The branch turned back at a grazing (rigid impacts): where no orbit continues the branch
    beyond the grazing ``located`` along t, the orbits with the new low-speed impact may lie on the
    same side — a non-smooth fold, at which the two branches meet (measured on the README's curve:
    the symmetric four-impact orbits grazing both walls at 30.4438 rad/s meet the asymmetric
    five-impact ones there).  On the hyperplane a share FOLD_BACK of the step behind the grazing, the
    old orbit's flight turning point nearest a wall (:func:`_turns`; then the one nearest the other
    wall, :func:`_wall_push`) is pushed past that wall along the gradient of its distance within the
    hyperplane (central differences of the flight, Eq. F1), and Newton's method starts there, its
    steps kept among the orbits with the new impact (:func:`_correct_within`).  Returns (y, t,
    monodromy, simulation, point, distance from the grazing in the scaled unknowns) of an orbit with
    other impacts, its tangent oriented away from the grazing, or None."""
    _, lo, hi, _ = located
    count = before.impact_events_per_period
    y_graze = y + hi * t
    for share in FOLD_BACK:
        s_back = lo - share * ds  # (behind the point itself where it was near the grazing)
        got = _correct(problem, y + s_back * t, t, count)
        if got is None or got is GRAZE:
            continue
        y0, _, _, res0 = got
        for nth in (0, 1):  # the turning point nearest a wall, then the other wall's
            push_dir = _wall_push(problem, y0, res0, t, nth)
            if push_dir is False and nth == 0:
                return None
            if not push_dir:
                continue
            gap, grad, norm2 = push_dir
            for push in FOLD_PUSH:
                new = _correct_within(problem, y + s_back * t, t, y0 + push * gap / norm2 * grad)
                if new is None:
                    continue
                y1, J1, mono1, res1 = new
                p1 = _point(problem, y1, mono1, res1)
                if p1.impact_events_per_period == count:
                    continue
                return (
                    y1,
                    _tangent(J1, y1 - y_graze),
                    mono1,
                    res1,
                    p1,
                    float(np.linalg.norm(y1 - y_graze)),
                )
    return None


#: The pushes of :func:`orbit_beside_grazing`: how far past the wall (multiples of the turning
#: point's distance from it) Newton's method starts.
BESIDE_PUSH = (1.5, 4.0)


def orbit_beside_grazing(
    system: ImpactSystem, forcing: Forcing, e: Any, state: Any, bounds: tuple[float, float],
    *, periods: int = 1,
) -> tuple[tuple[float, float, float, float], Forcing] | None:  # fmt: skip
    """The orbit with one more impact beside the rigid-impact orbit through ``state`` that nearly
    grazes: the flight's turning point nearest a wall (:func:`_turns`; then the other wall's) is
    pushed past it along the gradient of its reach (:func:`_reach_gradient`, Eq. F1) within the
    hyperplane through the orbit normal to its branch in Ω, and Newton's method starts there, its
    steps kept among the orbits with the new impact (:func:`_correct_within`), as :func:`_fold_back`
    does at a grazing.  Such orbits lie on the same side as the old one near a non-smooth fold
    (measured on the README's curve: beside the asymmetric 13-impact orbits at 30.6901 rad/s, whose
    other half-period's chatter sequence ends 4e-4 of d/2 from its wall, lie the symmetric 14-impact
    ones, stable over 30.6672–30.6768 rad/s).  Returns (the orbit's state at t = 0, the forcing at
    its Ω), or None where the orbit has no turning point, the reach's gradient meets other impacts,
    or Newton's method finds no orbit with other impacts.  ``bounds``: the band in Ω [rad/s] (the
    unknowns' scaling)."""
    system, forcing, e = checked(system, forcing, e)
    if not is_rigid(e):
        raise MethodNotApplicable("orbit_beside_grazing", "flights between rigid impacts only")
    s0 = checks.state("state", state)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    lo, hi = checks.bounds("bounds", bounds)
    if not 0 < lo <= forcing.omega <= hi:
        raise ParameterError("bounds", f"a positive band holding Ω = {forcing.omega:g} rad/s, "
                                       f"got {lo:g}–{hi:g}")  # fmt: skip
    problem = _problem(system, forcing, e, s0, periods, (lo, hi), "omega")
    axis = np.array([0, 0, 0, 0, 1.0])
    got = _correct(problem, np.concatenate([s0 / problem.scale, [forcing.omega / problem.unit]]),
                   axis)  # fmt: skip
    if got is None or got is GRAZE:
        return None
    y0, J, _, res0 = got
    t = _tangent(J, axis)
    count = _events(res0, periods)
    for nth in (0, 1):  # the turning point nearest a wall, then the other wall's
        push_dir = _wall_push(problem, y0, res0, t, nth)
        if not push_dir:
            continue
        gap, grad, norm2 = push_dir
        for push in BESIDE_PUSH:
            new = _correct_within(problem, y0, t, y0 + push * gap / norm2 * grad)
            if new is None:
                continue
            y1, _, _, res1 = new
            if _events(res1, periods) != count:
                return (tuple(float(c) for c in y1[:4] * problem.scale),
                        forcing.at(problem.omega(y1)))  # fmt: skip
    return None


def _correct_within(problem: _Problem, y_pred, t, start, count: float | None = None):
    """Newton on [F(y) = 0, tᵀ(y − y_pred) = 0] from ``start`` kept among the orbits with the
    impact events a period that ``start`` has (None unless that is ``count``, where given): each
    step is halved until its end has the same impacts (:func:`_correct` gives up instead).
    Beside a grazing the new impact's speed goes as the square root of the turning point's
    overreach, so F is steep at the region's edge and a full step from inside leaves it (measured at the README's fold at 30.4438 rad/s: from every push Newton
    undamped fell back to the old orbit; damped it took 6 to 8 steps).  (y, J, monodromy,
    simulation), or None."""
    y = start.copy()
    try:
        r, J, mono, res = problem.evaluate(y)
    except SymimpactError:
        return None
    if count is None:
        count = _events(res, problem.periods)
    elif _events(res, problem.periods) != count:
        return None
    for _ in range(2 * MAX_NEWTON):
        A = np.vstack([J, t])
        b = np.concatenate([-r, [-(t @ (y - y_pred))]])
        try:
            dy = np.linalg.solve(A, b)
        except np.linalg.LinAlgError:
            return None
        lam = 1.0
        while True:
            try:
                r1, J1, mono1, res1 = problem.evaluate(y + lam * dy)
                if _events(res1, problem.periods) == count:
                    break
            except SymimpactError:
                pass
            lam *= 0.5
            if lam < 1e-3:
                return None
        y, r, J, mono, res = y + lam * dy, r1, J1, mono1, res1
        if lam == 1.0 and problem.converged(dy, A):
            return y, J, mono, res
    return None


def _reach_gradient(problem: _Problem, y0, events: int, tau: float, side: float):
    """∂(side·z(τ)/(d/2))/∂y at y0 in the scaled unknowns: how the flight's reach towards the
    wall at ``side`` at the instant τ changes (central differences, steps 1e-7 of the scaled
    unknowns, each a run of the map alone, no Jacobian; None where a step meets other than the
    orbit's ``events``)."""
    h = problem.system.gap / 2.0
    grad = np.zeros(5)
    for j in range(5):
        d = np.zeros(5)
        d[j] = 1e-7
        vals = []
        for sign in (1.0, -1.0):
            y = y0 + sign * d
            try:
                res = monodromy(*problem.at(y[4] * problem.unit), y[:4] * problem.scale,
                                problem.periods, jacobian=False)[2]  # fmt: skip
            except SymimpactError:
                return None
            if len(res.events) != events:
                return None
            vals.append(side * float(state_at(res, np.array([tau]))[0, 2]) / h)
        grad[j] = (vals[0] - vals[1]) / 2e-7
    return grad
