"""Nonlinear least squares with what an identification owes its reader: standard errors, 95 %
profile-likelihood intervals, the correlation matrix and a warning for every parameter the data
do not determine.

The model is a residual vector r(θ) (measured − modelled, in the data's SI unit) and its
Jacobian J = ∂r/∂θ.  At the optimum θ̂ (:func:`scipy.optimize.least_squares`, trust region
with the parameters' bounds):

* **standard errors**: Cov(θ̂) ≈ s²·(JᵀJ)⁻¹ with s² = RSS/(n − p) (Gauss–Newton, the residuals
  taken as independent with one variance);
* **profile intervals**: the set of θⱼ whose profile RSSⱼ(θⱼ) = min over the others of RSS is
  below RSS·(1 + F₀.₉₅(1, n − p)/(n − p)).  For a model linear in θ this is exactly the
  t-interval θ̂ ± t₀.₉₇₅(n − p)·se, and it stays right where the model is not (an interval
  that is not symmetric, or reaches a bound).  The profile is followed out from the optimum in
  quarter standard errors, each point refitted from the nearest one solved and from the
  optimum; where its least RSS jumps (the residuals have several basins, as a decay's have, one
  per sequence of impacts) a warning says so and that end is the linearised one;
* **identifiability**: a direction of θ along which the residuals do not change (a singular
  value of J below 1e-8 of the largest, each parameter scaled by its value) leaves the
  parameters in it undetermined; two parameters correlated beyond ρ = ±0.99 are determined
  only together.  Each is said in one warning.

A parameter may be fitted on a log scale (``log=True``: positive, spanning decades); its
standard error is then carried to the parameter by the delta method, se(θ) = θ·se(ln θ), and its
profile interval, which does not depend on the scale, is exact.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ParameterError

#: A direction whose singular value is below this fraction of the largest (the parameters
#: scaled by their values) does not change the residuals: its parameters are not determined.
#: 1e-8 is √(machine ε)·~1e2: the Jacobian's columns are exact (derived), so anything above is
#: a real, if weak, sensitivity.
SINGULAR = 1e-8
#: Two parameters correlated beyond this are determined only together (a warning).
CORRELATED = 0.99
#: The confidence of the intervals.
LEVEL = 0.95


@dataclass(frozen=True)
class Parameter:
    """One fitted parameter: ``value`` (SI, ``unit``), its standard error ``stderr`` and its 95 %
    profile interval ``ci95`` (lo, hi); a side is None where the profile never reaches the
    threshold (the data bound it on one side only), and ``stderr`` is None where the parameter
    is not determined."""

    name: str
    unit: str
    value: float
    stderr: float | None
    ci95: tuple[float | None, float | None]

    def as_dict(self) -> dict[str, Any]:
        """``{"value", "stderr", "ci95": [lo, hi], "unit"}`` (SI; None where undetermined)."""
        return {"value": self.value, "stderr": self.stderr, "ci95": list(self.ci95),
                "unit": self.unit}  # fmt: skip


@dataclass(frozen=True)
class Fit:
    """A least-squares fit: its parameters, their correlation (in the order of ``parameters``),
    the residuals at the optimum (SI, the data's unit), the degrees of freedom n − p and the
    warnings (one sentence each)."""

    parameters: dict[str, Parameter]
    correlation: np.ndarray
    residuals: np.ndarray
    dof: int
    warnings: list[str] = field(default_factory=list)
    #: {name: (k, 2) array of (value SI, profile RSS)}: the points the interval search evaluated,
    #: sorted, the optimum among them; and the RSS threshold of the 95 % interval.
    profiles: dict[str, np.ndarray] = field(default_factory=dict)
    threshold: float = math.nan

    @property
    def rss(self) -> float:
        """Residual sum of squares."""
        return float(self.residuals @ self.residuals)

    @property
    def residual_rms(self) -> float:
        """√(RSS/n), in the data's unit."""
        return math.sqrt(self.rss / self.residuals.size)

    @property
    def aic(self) -> float:
        """Akaike's criterion n·ln(RSS/n) + 2p, to compare models fitted to the same data."""
        n, p = self.residuals.size, len(self.parameters)
        return n * math.log(max(self.rss, 1e-300) / n) + 2 * p

    def values(self) -> dict[str, float]:
        """{name: value} (SI)."""
        return {k: v.value for k, v in self.parameters.items()}

    def as_dict(self) -> dict[str, Any]:
        """The JSON form: ``parameters``, ``correlation`` (nested {name: {name: ρ}}),
        ``residual_rms``, ``dof``, ``warnings``."""
        names = list(self.parameters)
        rho = self.correlation
        return {
            "parameters": {k: p.as_dict() for k, p in self.parameters.items()},
            "correlation": {
                a: {b: _plain(rho[i, j]) for j, b in enumerate(names)} for i, a in enumerate(names)
            },
            "residual_rms": self.residual_rms,
            "dof": self.dof,
            "warnings": list(self.warnings),
        }


def _plain(x: float) -> float | None:
    return None if not np.isfinite(x) else float(x)


@dataclass(frozen=True)
class Unknown:
    """A parameter to fit: its ``name`` and SI ``unit``, its ``lower``/``upper`` bounds (SI: the
    physics', where an interval may end), whether it is fitted on a log scale (``log``:
    positive, spanning decades), and the ``span`` (lo, hi) searched within them (SI; None: the
    bounds), past which the data no longer change (an interval reaching it is open there)."""

    name: str
    unit: str
    lower: float = -math.inf
    upper: float = math.inf
    log: bool = False
    span: tuple[float, float] | None = None
    #: A typical magnitude (SI) for a parameter that is not on a log scale and may be near 0
    #: (an initial displacement): the scale its sensitivity is judged at.
    scale: float = 0.0

    def to_internal(self, value: float) -> float:
        return math.log(value) if self.log else value

    def to_value(self, internal: float) -> float:
        return math.exp(internal) if self.log else internal

    def internal_bounds(self) -> tuple[float, float]:
        """The searched range, internal (the span within the bounds)."""
        lo, hi = self.lower, self.upper
        if self.span is not None:
            lo, hi = max(lo, self.span[0]), min(hi, self.span[1])
        if not self.log:
            return lo, hi
        return (math.log(lo) if lo > 0 else -math.inf), (math.log(hi) if math.isfinite(hi)
                                                          else math.inf)  # fmt: skip

    def closes(self, internal: float) -> bool:
        """Whether an interval may end at the internal value ``internal`` (a bound of the
        physics, not of the searched span)."""
        value = self.to_value(internal)
        return value == self.lower or value == self.upper


def fit(
    residual: Callable[[np.ndarray], np.ndarray],
    jacobian: Callable[[np.ndarray], np.ndarray],
    unknowns: Sequence[Unknown],
    starts: Sequence[Sequence[float]],
    tol: float = 1e-15,
    profiled: Sequence[str] | None = None,
) -> Fit:
    """The least-squares fit of ``residual`` (θ ↦ r, SI values θ in the order of ``unknowns``)
    with its Jacobian ``jacobian`` (θ ↦ ∂r/∂θ, n × p), from the best of ``starts`` (each a θ);
    see the module's text for the errors, intervals and warnings.  ``tol``: the relative
    tolerance of the optimum and of the intervals' ends (1e-15: exact Jacobians; a Jacobian
    of differences is good to ~1e-7, below which a tighter one only costs runs).  ``profiled``:
    the parameters whose intervals are profiled (default all); the others' (nuisance
    parameters) are the linearised θ ± t₀.₉₇₅·se."""
    unknowns = list(unknowns)
    p = len(unknowns)
    n = int(np.asarray(residual(np.asarray(starts[0], float))).size)
    if n <= p:
        raise ParameterError("data", f"has {n} values for {p} fitted parameters: needs more "
                             "values than parameters")  # fmt: skip

    theta, chain, r_phi, j_phi, bounds = _internal(residual, jacobian, unknowns, n)
    best = None
    for start in starts:
        sol = _solve(r_phi, j_phi, _start(unknowns, start, bounds), bounds, range(p), tol)
        if best is None or sol[1] < best[1]:
            best = sol
    phi, rss = best
    r = r_phi(phi)
    dof = n - p
    s2 = rss / dof
    jac = j_phi(phi)
    warnings: list[str] = []
    cov_phi, undetermined = _covariance(jac, phi, unknowns, s2)
    values = theta(phi)
    se = np.array([math.sqrt(max(cov_phi[i, i], 0.0)) * float(chain(phi)[i]) for i in range(p)])
    sd = np.sqrt(np.clip(np.diag(cov_phi), 0, None))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov_phi / np.outer(sd, sd)
    for i in undetermined:
        corr[i, :] = corr[:, i] = np.nan
        warnings.append(f"{unknowns[i].name} is not determined by the data: the residuals do "
                        "not change with it at the optimum")  # fmt: skip
    for i in range(p):
        for j in range(i + 1, p):
            if abs(corr[i, j]) > CORRELATED:
                warnings.append(f"{unknowns[i].name} and {unknowns[j].name} are correlated "
                                f"(ρ = {corr[i, j]:+.4f}): the data determine them together, "
                                "not each apart")  # fmt: skip
    threshold = rss * (1.0 + _f_quantile(dof) / dof)
    params: dict[str, Parameter] = {}
    profiles: dict[str, np.ndarray] = {}
    for i, u in enumerate(unknowns):
        step = sd[i] if i not in undetermined and sd[i] > 0 else 0.1 * max(abs(phi[i]), 1.0)
        seen: dict[float, float] = {float(phi[i]): rss}
        if profiled is not None and u.name not in profiled:
            t = math.sqrt(_f_quantile(dof))
            ends = [float(np.clip(phi[i] + side * t * sd[i], *bounds[:, i])) for side in (-1, 1)]
        else:
            ends = [_profile_end(r_phi, j_phi, phi, i, bounds, threshold, step, side, seen, tol)
                    for side in (-1.0, 1.0)]  # fmt: skip
        profiles[u.name] = np.array([(u.to_value(x), seen[x]) for x in sorted(seen)])
        for k, side in enumerate((-1.0, 1.0)):
            jump = _jump(seen, phi[i], side, threshold - rss, step)
            if jump is not None and ends[k] is not None and i not in undetermined:
                t = math.sqrt(_f_quantile(dof))
                ends[k] = float(np.clip(phi[i] + side * t * sd[i], *bounds[:, i]))
                warnings.append(
                    f"{u.name}: its profile could not be followed past {u.to_value(jump):.6g} "
                    "(the least RSS with it held jumps there: the residuals have many basins, "
                    "e.g. one per sequence of impacts); the 95 % interval's end "
                    f"{'below' if side < 0 else 'above'} is the linearised one"
                )  # fmt: skip
        lo, hi = (None if x is None or (x in bounds[:, i] and not u.closes(x)) else u.to_value(x)
                  for x in ends)  # fmt: skip
        if i not in undetermined and (lo is None or hi is None):
            side = "below" if lo is None else "above"
            warnings.append(f"{u.name}: the data do not bound it {side} (its 95 % interval is "
                            "open on that side)")  # fmt: skip
        params[u.name] = Parameter(u.name, u.unit, float(values[i]),
                                   None if i in undetermined else float(se[i]), (lo, hi))  # fmt: skip
    return Fit(params, corr, r, dof, warnings, profiles, threshold)


def refine(
    residual: Callable[[np.ndarray], np.ndarray],
    jacobian: Callable[[np.ndarray], np.ndarray],
    unknowns: Sequence[Unknown],
    start: Sequence[float],
    tol: float = 1e-15,
) -> tuple[np.ndarray, float]:
    """The least-squares optimum θ (SI) reached from ``start`` and its RSS, without the errors
    and intervals of :func:`fit` (a stage of a fit that continues, e.g. over a growing record)."""
    unknowns = list(unknowns)
    n = int(np.asarray(residual(np.asarray(start, float))).size)
    theta, _, r_phi, j_phi, bounds = _internal(residual, jacobian, unknowns, n)
    phi, rss = _solve(r_phi, j_phi, _start(unknowns, start, bounds), bounds,
                      range(len(unknowns)), tol)  # fmt: skip
    return theta(phi), rss


def _internal(residual, jacobian, unknowns: list[Unknown], n: int):
    """The problem in the internal parameters φ (ln θ for a log-scale one): φ ↦ θ, dθ/dφ, the
    residual and its Jacobian (n × p), and the bounds (2 × p)."""

    def theta(phi: np.ndarray) -> np.ndarray:
        return np.array([u.to_value(x) for u, x in zip(unknowns, phi, strict=True)])

    def chain(phi: np.ndarray) -> np.ndarray:  # dθ/dφ
        return np.array([math.exp(x) if u.log else 1.0 for u, x in zip(unknowns, phi, strict=True)])

    def r_phi(phi: np.ndarray) -> np.ndarray:
        return np.asarray(residual(theta(phi)), float)

    def j_phi(phi: np.ndarray) -> np.ndarray:
        return np.asarray(jacobian(theta(phi)), float).reshape(n, len(unknowns)) * chain(phi)

    return theta, chain, r_phi, j_phi, np.array([u.internal_bounds() for u in unknowns]).T


def _start(unknowns: list[Unknown], start: Sequence[float], bounds: np.ndarray) -> np.ndarray:
    """A start θ in the internal parameters, inside the searched range."""
    return np.clip([u.to_internal(float(s)) for u, s in zip(unknowns, start, strict=True)],
                   *_inside(bounds))  # fmt: skip


def _jump(seen: dict[float, float], centre: float, side: float, allowance: float,
          step: float) -> float | None:  # fmt: skip
    """Where the profile points ``seen`` on ``side`` of ``centre`` rise by more than half the
    ``allowance`` (threshold − least RSS) within 1e-3 of ``step``: a discontinuity of the model,
    not the data's verdict (None if there is none)."""
    xs = sorted((x for x in seen if (x - centre) * side >= 0), key=lambda x: abs(x - centre))
    for a, b in itertools.pairwise(xs):
        if abs(b - a) < 1e-3 * step and seen[b] - seen[a] > 0.5 * allowance:
            return b
    return None


def _inside(bounds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Bounds for a start: the open interval's inside (least_squares needs a feasible start)."""
    lo, hi = bounds
    return np.where(np.isfinite(lo), lo, -np.inf), np.where(np.isfinite(hi), hi, np.inf)


def _solve(r_phi, j_phi, phi0, bounds, free, tol=1e-15) -> tuple[np.ndarray, float]:
    """Minimise the RSS over the ``free`` internal parameters, the others held at ``phi0``'s."""
    from scipy.optimize import least_squares

    free = list(free)
    if not free:
        r = r_phi(phi0)
        return phi0, float(r @ r)

    def r_free(x):
        phi = phi0.copy()
        phi[free] = x
        return r_phi(phi)

    def j_free(x):
        phi = phi0.copy()
        phi[free] = x
        return j_phi(phi)[:, free]

    lo, hi = bounds[0][free], bounds[1][free]
    x0 = np.clip(phi0[free], lo, hi)
    sol = least_squares(r_free, x0, jac=j_free, bounds=(lo, hi), method="trf", x_scale="jac",
                        xtol=tol, ftol=tol, gtol=tol, max_nfev=2000)  # fmt: skip
    phi = phi0.copy()
    phi[free] = sol.x
    r = r_phi(phi)
    return phi, float(r @ r)


def _covariance(jac, phi, unknowns, s2) -> tuple[np.ndarray, list[int]]:
    """s²·(JᵀJ)⁺ in the internal parameters, and the parameters in directions J does not see."""
    p = jac.shape[1]
    scale = np.array(
        [1.0 if u.log else max(abs(x), u.scale, 1e-300) for u, x in zip(unknowns, phi, strict=True)]
    )
    js = jac * scale  # each parameter relative to its value (log ones already are)
    _, sv, vt = np.linalg.svd(js, full_matrices=False)
    keep = sv > SINGULAR * (sv[0] if sv.size and sv[0] > 0 else 1.0)
    undetermined = sorted({int(np.argmax(np.abs(vt[k]))) for k in range(p) if not keep[k]})
    inv = (vt[keep].T / sv[keep] ** 2) @ vt[keep]
    return s2 * inv * np.outer(scale, scale), undetermined


def _f_quantile(dof: int) -> float:
    from scipy.stats import f

    return float(f.ppf(LEVEL, 1, dof))


def _profile_end(r_phi, j_phi, phi, i, bounds, threshold, step, side, seen,
                 tol=1e-15) -> float | None:  # fmt: skip
    """Where the profile RSS of internal parameter ``i`` reaches ``threshold`` on ``side`` of
    ``phi[i]`` (None if it stays below it up to the bound or for 90 steps); every point
    evaluated is put in ``seen`` {internal value: profile RSS}."""
    from scipy.optimize import brentq

    others = [k for k in range(phi.size) if k != i]
    solved = {float(phi[i]): phi.copy()}  # internal value → the others' optimum there
    lo_b, hi_b = bounds[0][i], bounds[1][i]
    limit = lo_b if side < 0 else hi_b

    def excess(x: float) -> float:
        x = float(x)
        if x in seen:  # evaluated once: the profile by local minimisation depends on its
            return seen[x] - threshold  # start, so a bracket keeps its signs
        # started from the nearest point solved, and from the optimum: the least of the two
        # (on a landscape of basins, as a decay's, a far start lands in another basin)
        best = None
        for near in {min(solved, key=lambda k: abs(k - x)), float(phi[i])}:
            trial = solved[near].copy()
            trial[i] = x
            sol, rss = _solve(r_phi, j_phi, trial, bounds, others, tol)
            if best is None or rss < best[1]:
                best = sol, rss
        solved[x], seen[x] = best
        return best[1] - threshold

    # out from the optimum in steps of a quarter standard error, each 1.5 times the last (the
    # interval's end is near 2 standard errors where the model is near linear), each point
    # started from the last: the valley of the profile followed, not jumped across
    inner, h = phi[i], 0.25 * step
    for _ in range(90):
        outer = phi[i] + side * h
        at_bound = (side < 0 and outer <= limit) or (side > 0 and outer >= limit)
        if at_bound:
            outer = limit
            if not math.isfinite(outer) or excess(outer) < 0:
                return outer if math.isfinite(outer) else None
            break
        if excess(outer) > 0:
            break
        inner, h = outer, 1.5 * h
    else:
        return None
    if excess(inner) >= 0.0:  # an exact fit (RSS ≈ 0): the threshold is at the optimum's noise
        return float(inner)
    return float(brentq(excess, min(inner, outer), max(inner, outer), xtol=1e-14,
                        rtol=max(4e-15, tol)))  # fmt: skip
