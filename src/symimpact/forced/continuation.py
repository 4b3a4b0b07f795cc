"""Pseudo-arclength continuation of periodic orbits through rigid impacts in a parameter — the
forcing frequency Ω (the frequency-response curve), the clearance d, the force amplitude F0, the
base-motion amplitude X_b or the restitution e: :func:`continue_orbit`.

The unknowns are y = (s, p), s = (x, ẋ, z, ẏ) at the section t = 0, scaled by the starting
orbit's amplitude, velocity amplitude, d/2, and p by a tenth of its range.  A point of the branch
solves P(s; p) − s = 0 (P the stroboscopic map over k periods, :func:`symimpact.forced.monodromy`);
its Jacobian is [monodromy − I | ∂P/∂p], the monodromy carried through flights and impacts and
∂P/∂p by central differences (a parameter derivative: step 1e-6 of the parameter, or of a tenth
of its range where that is larger; ~1e-10 of the map).  Each
step predicts along the branch's unit tangent and corrects by Newton's method with the
pseudo-arclength condition, so the branch is followed around folds.

Along the branch the Floquet multipliers are watched: a real multiplier through +1 where the
tangent's parameter component changes sign is a *fold*, through +1 without a turn a *branch point* (on
the symmetric two-impact orbits: the symmetry-breaking pitchfork from which the asymmetric
orbits grow), a real one through −1 a *period doubling*, a
complex pair through the unit circle a *Neimark–Sacker* point; each is located on the arc by
Brent's method on its test function (the tangent's parameter component, det(monodromy + I), the pair's
modulus − 1).  Where the set of impacts changes (an impact appears or vanishes: a *grazing*) or
the motion starts to chatter, stick or stop impacting, the branch ends there and says why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq

from .. import budgets, checks
from ..errors import MethodNotApplicable, ParameterError, SymimpactError
from ..system import ImpactSystem
from .contact_law import checked, is_rigid
from .forcing import Forcing
from .shooting import MAX_PERIODS, monodromy

#: Newton's corrector stops below this change of the scaled unknowns, or below the map's own
#: noise amplified by the conditioning of the extended Jacobian, cond·NOISE, where that is larger
#: (next to a branch point the Jacobian is nearly singular and no iterate gets closer than it).
TOL = 1e-10
#: The stroboscopic map's rounding relative to the state's scale: ~1e-15 for the closed-form flights
#: and impacts of rigid contact; for a compliant contact the integrator's located steps (rtol 1e-13)
#: move the map by ~1e-12 between neighbouring starts (measured: Newton stalls at 1e-7 where the
#: condition number is 3e5, at 2e-10 where it is 1.4e3).
NOISE = {"rigid": 1e-15, "compliant": 1e-12}
MAX_NEWTON = 8
#: The largest arclength step accepted [scaled unknowns]: one moves the parameter by a tenth of
#: its range (see :func:`continue_orbit`); the default is 0.02.
MAX_STEP = 1.0


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


@dataclass(frozen=True)
class Bifurcation:
    """A located point of a branch: ``kind`` ("fold", "branch-point", "period-doubling",
    "neimark-sacker", "grazing"), ``omega`` [rad/s], ``amplitude`` [m], ``value``: the continued
    parameter's value there (SI)."""

    kind: str
    omega: float
    amplitude: float
    value: float = math.nan


@dataclass
class Branch:
    """A continued branch: its points in order, the located bifurcations, ``period_multiple``
    k, ``stopped``: why the continuation ended (the band's edge, a grazing, …), and ``phase``
    [rad]: the forcing phase φ at t = 0 of its points' states (the section, fixed along it),
    ``parameter``: the continued parameter (see :data:`PARAMETERS`)."""

    points: list[BranchPoint] = field(default_factory=list)
    bifurcations: list[Bifurcation] = field(default_factory=list)
    period_multiple: int = 1
    stopped: str = ""
    phase: float = 0.0
    parameter: str = "omega"


#: The parameters :func:`continue_orbit` follows a branch in, with their SI units.
PARAMETERS = {"omega": "rad/s", "gap": "m", "F0": "N", "X_b": "m", "e": ""}


class _Problem:
    """The scaled residual and Jacobian of the continuation at y = (s/scale, p/unit)."""

    def __init__(self, system, forcing, e, periods, scale, unit, parameter="omega"):
        self.system, self.forcing, self.e, self.periods = system, forcing, e, periods
        self.noise = NOISE["rigid" if is_rigid(e) else "compliant"]
        self.scale, self.unit, self.parameter = scale, unit, parameter

    def at(self, value: float):
        """(system, forcing, e) with the continued parameter set to ``value``."""
        f, system, e = self.forcing, self.system, self.e
        if self.parameter == "gap":
            return system.with_(gap=value), f, e
        if self.parameter == "e":
            return system, f, value
        if self.parameter == "omega":
            return system, Forcing(F0=f.F0, X_b=f.X_b, omega=value, phase=f.phase), e
        F0 = value if self.parameter == "F0" else f.F0
        X_b = value if self.parameter == "X_b" else f.X_b
        return system, Forcing(F0=F0, X_b=X_b, omega=f.omega, phase=f.phase), e

    def omega(self, y: np.ndarray) -> float:
        """The forcing frequency at y."""
        return float(y[4] * self.unit) if self.parameter == "omega" else self.forcing.omega

    def evaluate(self, y: np.ndarray):
        """(residual, Jacobian 4×5, monodromy, the simulation) at y, all scaled."""
        s, value = y[:4] * self.scale, y[4] * self.unit
        ps, mono, res = monodromy(*self.at(value), s, self.periods)
        d = 1e-6 * max(abs(value), self.unit)
        plus = monodromy(*self.at(value + d), s, self.periods)[0]
        minus = monodromy(*self.at(value - d), s, self.periods)[0]
        dp = (plus - minus) / (2 * d) * self.unit
        J = np.zeros((4, 5))
        J[:, :4] = (mono - np.eye(4)) * self.scale[None, :] / self.scale[:, None]
        J[:, 4] = dp / self.scale
        return (ps - s) / self.scale, J, mono, res

    def where(self, value: float) -> str:
        """``Ω = 36.2 rad/s``, ``gap = 0.021 m``: the parameter's value in words."""
        name = "Ω" if self.parameter == "omega" else self.parameter
        unit = PARAMETERS[self.parameter]
        return f"{name} = {value:.6g}{' ' + unit if unit else ''}"


def _tangent(J: np.ndarray, previous: np.ndarray | None) -> np.ndarray:
    """The unit null vector of the 4×5 Jacobian, oriented along ``previous``."""
    t = np.linalg.svd(J)[2][-1]
    if previous is not None and float(t @ previous) < 0:
        t = -t
    return t / np.linalg.norm(t)


#: What :func:`_correct` returns when the impacts of the motion changed on the way.
GRAZE = "graze"


def _correct(problem: _Problem, y_pred: np.ndarray, t: np.ndarray, count: float | None = None):
    """Newton on [F(y) = 0, tᵀ(y − y_pred) = 0] from y_pred; None when it fails, GRAZE when an
    iterate impacts other than ``count`` times per period."""
    y = y_pred.copy()
    for _ in range(MAX_NEWTON):
        try:
            r, J, mono, res = problem.evaluate(y)
        except SymimpactError:  # chatter, sticking, no impacts, a state through a wall
            return None
        if count is not None and len(res.impacts) / problem.periods != count:
            return GRAZE
        A = np.vstack([J, t])
        b = np.concatenate([-r, [-(t @ (y - y_pred))]])
        try:
            dy = np.linalg.solve(A, b)
        except np.linalg.LinAlgError:
            return None
        y = y + dy
        if np.max(np.abs(dy)) < max(TOL, problem.noise * np.linalg.cond(A)):
            try:
                r, J, mono, res = problem.evaluate(y)
            except SymimpactError:
                return None
            if count is not None and len(res.impacts) / problem.periods != count:
                return GRAZE
            return y, J, mono, res
    return None


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
    )


def _tests(t: np.ndarray, mono: np.ndarray) -> dict[str, float]:
    """The test functions whose sign changes mark the bifurcations."""
    lam = np.linalg.eigvals(mono)
    pairs = [abs(c) for c in lam if c.imag > 1e-9 * max(1.0, abs(c))]
    return {
        "fold": float(t[4]),
        "branch-point": float(np.real(np.linalg.det(mono - np.eye(4)))),
        "period-doubling": float(np.real(np.linalg.det(mono + np.eye(4)))),
        "neimark-sacker": (min(pairs, key=lambda a: abs(a - 1.0)) - 1.0) if pairs else math.nan,
    }


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
) -> Branch:
    """Continue the period-``periods`` orbit through ``state`` = (x, ẋ, z, ẏ) at t = 0 (an orbit
    of ``system`` under ``forcing`` with restitution ``e``, e.g. from
    :func:`symimpact.forced.shoot`) in ``parameter`` — ``"omega"`` (Ω [rad/s], the default),
    ``"gap"`` (d [m]), ``"F0"`` [N], ``"X_b"`` [m] or ``"e"`` — over ``bounds`` = (low, high) in
    SI, first towards increasing values (``direction`` 1) or decreasing (−1); ``step``: the
    arclength step in scaled unknowns (adapted between step/64 and 4·step).  Eq. F1 and F2 along
    the orbits (Step 8, Step 9)."""
    system, forcing, e = checked(system, forcing, e)
    checks.choice("parameter", parameter, tuple(PARAMETERS))
    lo, hi = checks.bounds("bounds", bounds)
    periods = checks.whole_number("periods", periods, 1, MAX_PERIODS)
    step = checks.bounded("step", step, 0.0, MAX_STEP, open_low=True)
    max_points = checks.whole_number("max_points", max_points, 2, 1_000_000)
    if parameter in ("omega", "gap") and not lo > 0:
        raise ParameterError("bounds", f"{parameter} must stay positive, got low {lo:g}")
    if parameter == "e" and not is_rigid(e):
        raise ParameterError(
            "parameter",
            "e is continued for rigid impacts; a compliant law sets its own restitution",
        )
    if parameter == "e" and not (0 <= lo and hi <= 1):
        raise ParameterError("bounds", f"e must stay within 0–1, got {lo:g}–{hi:g}")
    start = {"omega": forcing.omega, "gap": system.gap, "F0": forcing.F0, "X_b": forcing.X_b,
             "e": float(e) if is_rigid(e) else math.nan}[parameter]  # fmt: skip
    if not lo <= start <= hi:
        raise ParameterError("bounds", f"must contain the start, {parameter} = {start:g}")
    checks.choice("direction", direction, (1, -1))
    s0 = checks.state("state", state)
    h = system.gap / 2.0
    _, _, res0 = monodromy(system, forcing, e, s0, periods)
    amp = max(float(np.max(res0.period_max)), 1e-3 * h)
    W0 = forcing.omega
    scale = np.array([amp, amp * W0, h, amp * W0])
    # the parameter in units of a tenth of its range: a step of 0.2 moves it by at most 2 % of it
    problem = _Problem(system, forcing, e, periods, scale, (hi - lo) / 10.0, parameter)
    branch = Branch(period_multiple=periods, phase=forcing.phase, parameter=parameter)
    y = np.concatenate([s0 / scale, [start / problem.unit]])
    corrected = _correct(problem, y, np.array([0, 0, 0, 0, 1.0]))
    if corrected is None:
        raise MethodNotApplicable(
            "continuation", f"no orbit through the start at {problem.where(start)}"
        )
    y, J, mono, res = corrected
    t = _tangent(J, np.array([0, 0, 0, 0, float(direction)]))
    point = _point(problem, y, mono, res)
    branch.points.append(point)
    tests = _tests(t, mono)
    ds = step
    while len(branch.points) < max_points:
        attempt = _correct(problem, y + ds * t, t, point.impacts_per_period)
        if attempt is GRAZE:
            branch.bifurcations.append(_grazing(problem, y, t, ds, point))
            branch.stopped = f"grazing at {problem.where(branch.bifurcations[-1].value)}"
            return branch
        if attempt is None:
            ds *= 0.5
            if ds < step / 64:
                branch.stopped = (
                    f"the corrector failed at {problem.where(point.value)} (chatter, sticking, "
                    "loss of impacts or a non-smooth turn)"
                )
                return branch
            continue
        y1, J1, mono1, res1 = attempt
        t1 = _tangent(J1, t)
        p1 = _point(problem, y1, mono1, res1)
        if p1.impacts_per_period != point.impacts_per_period:  # (the corrector checks it)
            branch.bifurcations.append(_grazing(problem, y, t, ds, point))
            branch.stopped = f"grazing at {problem.where(branch.bifurcations[-1].value)}"
            return branch
        tests1 = _tests(t1, mono1)
        for kind in ("fold", "branch-point", "period-doubling", "neimark-sacker"):
            a, b = tests[kind], tests1[kind]
            if kind == "branch-point" and (tests["fold"] > 0) != (tests1["fold"] > 0):
                continue  # a multiplier through +1 at a fold is the fold itself
            if math.isfinite(a) and math.isfinite(b) and (a > 0) != (b > 0):
                found = _locate(problem, kind, y, t, ds, a, b)
                if found is not None:
                    branch.bifurcations.append(found)
        y, t, mono, point, tests = y1, t1, mono1, p1, tests1
        branch.points.append(point)
        if not lo <= point.value <= hi:
            branch.stopped = f"the range's edge at {problem.where(point.value)}"
            return branch
        ds = min(ds * 1.5, 4 * step)
    branch.stopped = f"{max_points} points"
    return branch


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
) -> Branch:
    """The whole branch through ``state`` within ``bounds``: :func:`continue_orbit` towards
    decreasing and towards increasing values of ``parameter``, joined into one branch in the
    order of the arclength (the decreasing part reversed), with both parts' bifurcations."""
    kw = {"parameter": parameter, "periods": periods, "step": step}
    down = continue_orbit(system, forcing, e, state, bounds, direction=-1, **kw)
    up = continue_orbit(system, forcing, e, state, bounds, direction=1, **kw)
    joined = Branch(period_multiple=periods, phase=forcing.phase, parameter=parameter)
    joined.points = [*reversed(down.points[1:]), *up.points]
    joined.bifurcations = [*down.bifurcations, *up.bifurcations]
    joined.stopped = f"down: {down.stopped}; up: {up.stopped}"
    return joined


def _locate(problem, kind, y, t, ds, a, b) -> Bifurcation | None:
    """The bifurcation of ``kind`` between y and the step ds along t: Brent's method on the
    step length σ, each σ corrected onto the branch."""
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
        y1, _, res1, _ = at(sigma)
        return Bifurcation(kind, problem.omega(y1), float(np.max(res1.period_max)),
                           float(y1[4] * problem.unit))  # fmt: skip
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
    return Bifurcation(
        kind,
        value if problem.parameter == "omega" else problem.forcing.omega,
        float(np.polyval(np.polyfit(grid, [amp0, *amps], 3), sigma)),
        value,
    )


def _grazing(problem, y, t, ds, before: BranchPoint) -> Bifurcation:
    """Where the impact count changes between y and ds along t: bisection on the step length
    (the count is a step function of it) to 1e-6 of ds (ds moves Ω by at most 2 % of the band,
    so 2e-8 of the band); the last orbit with the old count."""
    lo, hi = 0.0, ds
    last = before
    while hi - lo > 1e-6 * ds:
        mid = 0.5 * (lo + hi)
        got = _correct(problem, y + mid * t, t, before.impacts_per_period)
        if got is None or got is GRAZE:
            hi = mid
            continue
        last = _point(problem, got[0], got[2], got[3])
        lo = mid
    return Bifurcation("grazing", last.omega, last.amplitude, last.value)
