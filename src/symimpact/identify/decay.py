"""The damper's parameters from a free decay: the primary, tapped, rings down with the impact
mass rattling in its clearance (the paper's own experiment, Sect. 4).

The model is the event-driven simulation of the package, run over the record's samples with no
load (:func:`symimpact.forced.loads.record_response.damper_response`: exact flights, Eq. F8 with
a zero load, i.e. Eq. 7; rigid impacts by Newton's e, Eq. F2, chatter to its accumulation
point and sticking): nothing is linearised.  The tap leaves the primary at x₀ with speed ẋ₀ at
t = 0 and the impact mass at rest in the middle of its clearance (y₀ = x₀, ẏ₀ = 0: a ball that
sat still before the tap); x₀ and ẋ₀ are fitted beside the parameters asked for (nuisance
parameters, reported too, with linearised intervals).  The residual is the record's own quantity (displacement, velocity
or acceleration: the absolute acceleration between impacts), measured minus modelled, at its
samples.

The Jacobian is taken by central differences (step 1e-6 of each parameter's scale: the
simulation is exact to ~1e-13, so the derivative is good to ~1e-7 relative); the fit, the
standard errors and the profile intervals are :func:`symimpact.identify.least_squares.fit`'s.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..forced.loads.record_response import TooManyImpacts, damper_response
from ..forced.loads.records import Record, unit_columns
from ..model.system import ImpactSystem
from ..model.units import si_float
from .least_squares import Fit, Unknown, fit, refine

#: The parameters a decay can fit (named as the options they replace) and the nuisance ones.
FITTABLE = ("e", "zeta", "gap")
NUISANCE = ("x0", "xdot0")
#: Impacts a trial of the fit may take before it is judged a motion no record shows (Thornton's
#: law does not take chatter to its limit: a trial yield speed far below the record's speeds
#: makes sequences of millions of ever-smaller impacts); such a trial's residual is the record
#: itself ten times over, which the fit leaves.
MAX_EVENTS = 100_000
#: The coarsest sampling a fit takes: samples a natural period of the primary.  Between two
#: samples the primary turns through 2π/20 = 18°; an impact's time is then fixed by the kinks
#: it leaves in the samples around it (coarser, the impacts of one half period blur into one).
MIN_SAMPLES_PER_PERIOD = 20
#: The quantities a record may hold, by their SI unit.
QUANTITIES = {"displacement": "m", "velocity": "m/s", "acceleration": "m/s^2"}


@dataclass(frozen=True)
class Decay:
    """A recorded free decay: ``values`` [SI] of ``quantity`` (one of :data:`QUANTITIES`) at
    t = k·``dt`` [s], k = 0, 1, …"""

    values: np.ndarray
    dt: float
    quantity: str

    @property
    def times(self) -> np.ndarray:
        """The sample times [s]."""
        return self.dt * np.arange(self.values.size)


def read_decay(path: Any) -> Decay:
    """A free decay from a CSV file of two columns, time and the primary's displacement,
    velocity or acceleration, each header with its unit in brackets ("time [s]",
    "displacement [mm]" or "acceleration [g]"); samples equally spaced (to 1e-6 of the
    interval) from t = 0."""
    (t_unit, v_unit), data = unit_columns(path, "decay", ("time [s]", "displacement [mm]"))
    t = data[:, 0] * si_float("decay", f"1 {t_unit}", "s")
    for name, unit in QUANTITIES.items():
        try:
            scale, quantity = si_float("decay", f"1 {v_unit}", unit), name
            break
        except ParameterError:
            continue
    else:
        raise ParameterError("decay", f"the second column's unit {v_unit!r} is not a "
                             "displacement, a velocity or an acceleration")  # fmt: skip
    dts = np.diff(t)
    if np.any(dts <= 0):
        raise ParameterError("decay", "time must increase from row to row")
    dt = float(np.mean(dts))
    if abs(t[0]) > 1e-9 * dt:
        raise ParameterError("decay", f"must start at t = 0 (the tap), starts at {t[0]:g} s")
    if np.max(np.abs(dts - dt)) > 1e-6 * dt:
        raise ParameterError("decay", "samples must be equally spaced")
    if t.size < 8:
        raise ParameterError("decay", "needs at least 8 samples")
    return Decay(data[:, 1] * scale, dt, quantity)


def simulated_decay(system: ImpactSystem, e: Any, n: int, dt: float, x0: float,
                    xdot0: float) -> Any:  # fmt: skip
    """The model: ``system`` released from x₀, ẋ₀ with its impact mass at rest in the middle of
    the clearance, ``n`` samples ``dt`` apart, no load (see the module's text)."""
    record = Record(np.zeros(n), dt, "force")
    return damper_response(system, record, e=e, x0=x0, xdot0=xdot0, y0=x0, ydot0=0.0,
                           max_events=MAX_EVENTS)  # fmt: skip


def _modelled(response: Any, quantity: str) -> np.ndarray:
    return {"displacement": response.displacement, "velocity": response.velocity,
            "acceleration": response.acceleration}[quantity]  # fmt: skip


def _initial_state(system: ImpactSystem, data: Decay, zeta: float) -> tuple[float, float]:
    """x₀, ẋ₀ of the primary alone fitted to the record's first natural period (linear least
    squares on the two free responses of Eq. 7): the starts of the nuisance parameters."""
    wn = system.omega_n
    wd = wn * math.sqrt(1.0 - zeta**2)
    t = data.times[: max(8, int(2 * math.pi / wn / data.dt) + 1)]
    env = np.exp(-zeta * wn * t)
    x_a, x_b = env * np.cos(wd * t), env * np.sin(wd * t) / wd  # x from x₀ = 1, from ẋ₀ = 1
    basis = {"displacement": (x_a, x_b)}
    if data.quantity != "displacement":
        d = [np.gradient(b, data.dt) for b in (x_a, x_b)]
        basis["velocity"] = tuple(d)
        basis["acceleration"] = tuple(np.gradient(b, data.dt) for b in d)
    a = np.column_stack(basis[data.quantity])
    sol, *_ = np.linalg.lstsq(a, data.values[: t.size], rcond=None)
    return float(sol[0]), float(sol[1])


def _zeta_start(system: ImpactSystem, data: Decay) -> float:
    """ζ from the record's envelope: the logarithmic decrement of its largest and last peaks
    (with the damper's losses in it, so an upper estimate)."""
    v = np.abs(data.values)
    k = v.size
    first, last = v[: k // 4].max(), v[3 * k // 4 :].max()
    if first <= 0 or last <= 0 or last >= first:
        return 0.01
    # the two maxima are a half to the whole record apart: half, so an upper estimate of ζ
    cycles = 0.5 * data.dt * k * system.omega_n / (2 * math.pi)
    return float(np.clip(math.log(first / last) / (2 * math.pi * max(cycles, 0.5)), 1e-4, 0.5))


def fit_decay(
    system: ImpactSystem,
    data: Decay,
    fitted: Sequence[str] = FITTABLE,
    e: Any = 0.5,
) -> tuple[Fit, Any]:
    """``fitted`` (a subset of :data:`FITTABLE`: the restitution, the primary's ζ, the clearance
    d) and the tap's x₀, ẋ₀ fitted to the record ``data`` of ``system``'s primary with its
    damper; the others (M, K, m, and whichever of e, ζ, d are not fitted) are ``system``'s and
    ``e``'s.  ``e`` a number: Newton's e (its start, if fitted); a
    :class:`~symimpact.forced.contact_law.MaterialRestitution`: Thornton's e(v) (Step 13, Eq.
    F5), whose yield speed is then what "e" in ``fitted`` fits (named ``yield_speed``).
    Returns the fit and the fitted model's response (its impacts, its motion)."""
    from ..forced.contact_law import MaterialRestitution

    thornton = isinstance(e, MaterialRestitution)
    fitted = list(dict.fromkeys(fitted))
    for name in fitted:
        if name not in FITTABLE:
            raise ParameterError("fit", f"{name!r} is not a parameter a decay fits (one of "
                                 f"{', '.join(FITTABLE)})")  # fmt: skip
    e0 = e if thornton else float(e)
    if not thornton and not 0.0 <= e0 <= 1.0:
        raise ParameterError("e", f"must lie in [0, 1], got {e0:g}")
    n, dt = data.values.size, data.dt
    per_period = 2.0 * math.pi / system.omega_n / dt
    if per_period < MIN_SAMPLES_PER_PERIOD:
        raise ParameterError("decay", f"is sampled {per_period:.3g} times a natural period of the "
                             f"primary: at least {MIN_SAMPLES_PER_PERIOD} are needed to see "
                             "when its impacts happen")  # fmt: skip
    zeta0 = system.zeta if "zeta" not in fitted else _zeta_start(system, data)
    x0, v0 = _initial_state(system, data, zeta0)
    amplitude = math.hypot(x0, v0 / system.omega_n)
    if amplitude <= 0.0:
        raise ParameterError("decay", "the record does not move: nothing to fit")
    # Thornton's law: its one parameter, the yield speed, is what fitting the restitution fits
    fitted = ["yield_speed" if thornton and k == "e" else k for k in fitted]
    names = [*fitted, *NUISANCE]

    def unpack(theta: np.ndarray) -> tuple[ImpactSystem, float, float, float]:
        p = dict(zip(names, theta, strict=True))
        changes: dict[str, float] = {}
        if "zeta" in p:
            changes.update(zeta=p["zeta"], C=None)
        if "gap" in p:
            changes["gap"] = p["gap"]
        s = system.with_(**changes) if changes else system
        if "yield_speed" in p:
            return s, MaterialRestitution(p["yield_speed"]), p["x0"], p["xdot0"]
        return s, p.get("e", e0), p["x0"], p["xdot0"]

    def problem(k: int):
        """The residual and its Jacobian on the record's first ``k`` samples."""

        def residual(theta: np.ndarray) -> np.ndarray:
            s, e_, x, v = unpack(theta)
            try:
                model = _modelled(simulated_decay(s, e_, k, dt, x, v), data.quantity)
            except TooManyImpacts:
                return np.full(k, 10.0 * float(np.abs(data.values).max()))
            return data.values[:k] - model

        def jacobian(theta: np.ndarray) -> np.ndarray:
            cols = []
            for j, name in enumerate(names):
                h = 1e-6 * (scales[name] or abs(theta[j]))
                up, dn = theta.copy(), theta.copy()
                up[j] += h
                dn[j] -= h
                if name == "e":  # one-sided at the bounds of e
                    up[j], dn[j] = min(up[j], 1.0), max(dn[j], 0.0)
                cols.append((residual(up) - residual(dn)) / (up[j] - dn[j]))
            return np.column_stack(cols)

        return residual, jacobian

    speed = amplitude * system.omega_n  # the tap's speed: the fastest approach
    scales = {"e": 1.0, "zeta": None, "gap": None, "yield_speed": None, "x0": amplitude,
              "xdot0": amplitude * system.omega_n}  # fmt: skip
    unknowns = [{
        "e": Unknown("e", "1", 0.0, 1.0),
        "zeta": Unknown("zeta", "1", 0.0, 0.99, log=True, span=(1e-7, 0.9)),
        "gap": Unknown("gap", "m", 0.0, math.inf, log=True,
                       span=(1e-3 * amplitude, 100.0 * amplitude)),
        "yield_speed": Unknown("yield_speed", "m/s", 0.0, math.inf, log=True,
                               span=(1e-5 * speed, 10.0 * speed)),
        "x0": Unknown("x0", "m", scale=amplitude),
        "xdot0": Unknown("xdot0", "m/s", scale=amplitude * system.omega_n),
    }[k] for k in names]  # fmt: skip
    grid = {
        "e": [0.1, 0.35, 0.6, 0.85],
        "yield_speed": list(speed * np.geomspace(1e-3, 0.3, 6)),
        "zeta": [zeta0, 0.3 * zeta0],
        "gap": list(amplitude * np.geomspace(0.1, 2.5, 16)),
    }
    # A growing record: its first half natural period holds the first impact (the ball at rest
    # in the middle, the primary reaches its amplitude within a quarter period), where the RSS
    # is smooth enough for a grid of starts to land in the right basin; each window, √2 times
    # longer than the last, starts from its optimum and adds an impact or two (the RSS of a
    # whole record is a landscape of basins, one per impact sequence: from a grid it ends in
    # a wrong one).
    period = 2.0 * math.pi / system.omega_n / dt
    windows = sorted({min(n, max(16, int(period * 0.5 * 2 ** (j / 2)))) for j in range(64)})
    residual, jacobian = problem(windows[0])
    starts = [[*(c[name] for name in fitted), x0, v0] for c in _combinations(grid, fitted)]
    best = None
    for start in _best_starts(residual, starts):
        theta, rss = refine(residual, jacobian, unknowns, start, tol=1e-10)
        if best is None or rss < best[1]:
            best = theta, rss
    theta = best[0]
    for k in windows[1:]:
        residual, jacobian = problem(k)
        theta, _ = refine(residual, jacobian, unknowns, theta, tol=1e-10)
    result = fit(residual, jacobian, unknowns, [theta], tol=1e-9, profiled=fitted)
    s, e_, x, v = unpack(np.array([p.value for p in result.parameters.values()]))
    response = simulated_decay(s, e_, n, dt, x, v)
    if response.impact_times.size == 0 and {"e", "yield_speed", "gap"} & set(fitted):
        result.warnings.append("the fitted motion has no impact: the record does not determine "
                               "e, and bounds the clearance from below only")  # fmt: skip
    leaves = departure(result.residuals, dt, period, system.omega_n,
                       float(np.abs(data.values).max()))  # fmt: skip
    if leaves is not None:
        result.warnings.append(
            f"the fitted motion leaves the record from t ≈ {leaves:.4g} s (its residual "
            "oscillates there at the natural frequency, far above the noise): an impact is not "
            "matched, and the fit may have followed another sequence of impacts, whose errors "
            f"then mean nothing; fit the record up to that time (--until {leaves:.3g})"
        )  # fmt: skip
    return result, response


#: How far above noise a residual's oscillation at the natural frequency must be over one
#: natural period for the fitted motion to be said to leave the record: for white noise of
#: deviation σ each of its two Fourier coefficients over k samples is normal with deviation
#: σ·√(2/k), so an amplitude over DEPARTURE of those happens with probability exp(−DEPARTURE²/2)
#: (1.5e-8 at 6: no false alarm over a record's few hundred periods).
DEPARTURE = 6.0


def departure(residuals: Any, dt: float, period: float, omega: float,
              scale: float) -> float | None:  # fmt: skip
    """The start [s] of the first natural period (``period`` samples ``dt`` apart) over which
    the residuals hold an oscillation at ``omega`` [rad/s] — what a fitted motion that has left
    the record leaves in them — :data:`DEPARTURE` times above what the noise of the record's
    first quarter gives, and above 1e-9 of ``scale`` (the record's size: the simulation's own
    rounding is no departure); None if there is none."""
    r = np.asarray(residuals, float)
    k = max(8, int(period))
    m = r.size // k
    if m < 8:
        return None
    windows = r[: m * k].reshape(m, k)
    t = dt * np.arange(k)
    c, s_ = np.cos(omega * t), np.sin(omega * t)
    amp = 2.0 / k * np.hypot(windows @ c, windows @ s_)
    sigma = float(np.median(np.sqrt(np.mean(windows[: max(2, m // 4)] ** 2, axis=1))))
    bound = max(DEPARTURE * sigma * np.sqrt(2.0 / k), 1e-9 * scale)
    over = np.nonzero(amp > bound)[0]
    return None if over.size == 0 else float(over[0] * k * dt)


def _combinations(grid: dict[str, list[float]], fitted: list[str]) -> list[dict[str, float]]:
    out: list[dict[str, float]] = [{}]
    for name in fitted:
        out = [{**c, name: v} for c in out for v in grid[name]]
    return out


def _best_starts(residual, starts: list[list[float]], keep: int = 4) -> list[list[float]]:
    """The ``keep`` starts of least RSS (the fit refines only those: each start costs a
    Gauss–Newton descent, each step a run of the simulation per parameter and side)."""
    rss = [float(np.sum(residual(np.array(s, float)) ** 2)) for s in starts]
    order = np.argsort(rss)
    return [starts[i] for i in order[:keep]]
