"""What an engineer reads off a forced response besides the primary's displacement: its motion
relative to the base, its acceleration, the force it sends into the base and the
transmissibility — for the primary alone in closed form, and along any orbit of the damper.

The primary obeys M ẍ + C(ẋ − ẋ_b) + K(x − x_b) = F0 cos θ between impacts (θ = Ωt + φ, base
motion x_b = X_b cos θ, Step 8, Eq. F1), so

- *relative displacement* x − x_b;
- *acceleration* ẍ = (F0 cos θ − F_T)/M, with the mass M + m while the impact mass sticks to a
  wall; a rigid impact's impulse is a delta in ẍ and is left out: this is the acceleration
  between impacts;
- *transmitted force* F_T = K(x − x_b) + C(ẋ − ẋ_b): what the spring and the damper put into the
  base (the ground under a force);
- *transmissibility*: max abs(F_T)/F0 under a force, max abs(x)/X_b under base motion
  (the textbook force and motion transmissibilities, equal for the primary alone:
  √((1 + (2ζr)²)/((1 − r²)² + (2ζr)²)), r = Ω/ωₙ).

Each response of a motion is its largest absolute value over the motion's periods.  For the
primary alone the steady solution's complex amplitudes give them in closed form
(:func:`linear_response`).  Along an orbit (:func:`orbit_response`) the motion is rebuilt from its
run: rigid impacts exactly (:func:`symimpact.forced.simulation.state_at`, Step 8's flight between
events), sampled at :data:`SAMPLES` points a period and each largest sample refined by Brent's
method between its neighbours; a compliant contact's run records its state on a grid of
:data:`SAMPLES` points a period, whose largest value is low by at most (πh/SAMPLES)²/2 of a
response with harmonics up to h.  A compliant contact's acceleration (its peak inside a contact of
a fraction of a millisecond) is not resolved by that grid and is refused.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from ..errors import MethodNotApplicable, ParameterError
from ..generated import forced_flight as ff
from ..model import checks
from ..model.system import ImpactSystem
from .contact_law import is_rigid, simulation_arguments
from .forcing import Forcing

#: name → (SI unit, what it is)
RESPONSES = {
    "displacement": ("m", "largest absolute displacement of the primary, max abs(x)"),
    "relative-displacement": ("m", "largest displacement relative to the base, max abs(x − x_b)"),
    "acceleration": ("m/s^2", "largest absolute acceleration between impacts, max abs(ẍ)"),
    "force": ("N", "largest force into the base, max abs(K(x − x_b) + C(ẋ − ẋ_b))"),
    "transmissibility": ("1", "max abs(F_T)/F0 under a force, max abs(x)/X_b under base motion"),
}
#: The quantity whose display unit each response is shown in (:mod:`symimpact.model.display`; None:
#: a pure number).
QUANTITY = {"displacement": "x", "relative-displacement": "x", "acceleration": "A_b",
            "force": "F0", "transmissibility": None}  # fmt: skip
#: How each response is named on a plot's axis.
AXIS = {"displacement": "amplitude max |x|", "relative-displacement": "max |x − x_b|",
        "acceleration": "max |ẍ| between impacts", "force": "force into the base max |F_T|",
        "transmissibility": "transmissibility"}  # fmt: skip
#: Samples a forcing period where an orbit's response is looked for (and a compliant run's grid).
SAMPLES = 4096
COMPLIANT_ACCELERATION = (
    "acceleration with a compliant contact: its peak inside a contact is not resolved by "
    f"the run's {SAMPLES} samples a period; use contact rigid (the acceleration between impacts) "
    "or the displacement, relative displacement or force"
)


def checked_response(name: Any, forcing: Forcing, rigid: bool | None = None) -> str:
    """``name`` if it is one of :data:`RESPONSES` that ``forcing`` defines (and, told whether the
    contact is ``rigid``, that its runs resolve), else one line."""
    if name == "acceleration" and rigid is False:
        raise MethodNotApplicable("response", COMPLIANT_ACCELERATION)
    if name not in RESPONSES:
        raise ParameterError("response", f"must be one of {', '.join(RESPONSES)}, got {name!r}")
    if name == "transmissibility":
        has_force = forcing.F0 != 0.0
        has_base = bool(np.any(forcing.base_amplitude(forcing.omega) != 0.0))
        if has_force == has_base:
            raise ParameterError(
                "response",
                "transmissibility is F_T/F0 under a force or max abs(x)/X_b under base motion: "
                "give one of them, not " + ("both" if has_force else "neither"),
            )
    return name


def steady_amplitude(system: ImpactSystem, forcing: Forcing, omega: Any) -> np.ndarray:
    """The primary alone's complex amplitude X̂ = A − iB at the frequencies ``omega`` [rad/s]:
    x = Re(X̂e^{iθ}) = A cos θ + B sin θ, Step 8's steady solution (Eq. F1) [m]."""
    w = np.asarray(omega, dtype=float)
    X_b = forcing.base_amplitude(w)  # constant, or V_b/Ω, A_b/Ω² over the band
    F = forcing.force_amplitude(w)  # F0, and a reduction's inertia times Ω²·X_b
    A = ff.steady_cosine(system.M, system.K, system.C, F, X_b, w)
    B = ff.steady_sine(system.M, system.K, system.C, F, X_b, w)
    return A - 1j * B


def linear_response(name: str, system: ImpactSystem, forcing: Forcing, omega: Any) -> np.ndarray:
    """``name`` (:data:`RESPONSES`) of the primary alone in its steady state at the frequencies
    ``omega`` [rad/s] (Step 8's steady solution, Eq. F1: x = A cos θ + B sin θ, so x = Re(X̂e^{iθ})
    with X̂ = A − iB; x_b = X_b cos θ; F_T = Re((K + iΩC)(X̂ − X_b)e^{iθ}))."""
    checked_response(name, forcing)
    w = np.asarray(omega, dtype=float)
    X_b = forcing.base_amplitude(w)
    X = steady_amplitude(system, forcing, w)
    relative = np.abs(X - X_b)
    force = np.abs(system.K + 1j * w * system.C) * relative
    if name == "displacement":
        return np.abs(X)
    if name == "relative-displacement":
        return relative
    if name == "acceleration":
        return w * w * np.abs(X)
    if name == "force":
        return force
    return force / abs(forcing.F0) if forcing.F0 != 0.0 else np.abs(X) / np.abs(X_b)


def _values(name: str, system: ImpactSystem, forcing: Forcing, t: np.ndarray, s: np.ndarray):
    """``name``'s signed value at the times ``t`` [s] of states ``s`` (rows x, ẋ, z, ẏ)."""
    theta = forcing.omega * t + forcing.phase
    X_b = float(forcing.base_amplitude(forcing.omega))
    xb, vb = X_b * np.cos(theta), -forcing.omega * X_b * np.sin(theta)
    x, v = s[:, 0], s[:, 1]
    force = system.K * (x - xb) + system.C * (v - vb)
    if name == "displacement":
        return x
    if name == "relative-displacement":
        return x - xb
    if name == "acceleration":
        h = system.gap / 2.0
        stuck = (np.abs(np.abs(s[:, 2]) - h) <= 1e-12 * h) & (s[:, 3] == v)
        return (forcing.primary_force * np.cos(theta) - force) / np.where(
            stuck, system.M + system.m, system.M
        )
    if name == "force":
        return force
    if forcing.F0 != 0.0:
        return force / abs(forcing.F0)
    return x / abs(X_b)


def orbit_response(
    name: str,
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    state: Any,
    periods: int = 1,
) -> float:
    """``name`` (:data:`RESPONSES`) of the motion from ``state`` = (x, ẋ, z, ẏ) at t = 0 (the
    forcing phase of ``forcing``) over ``periods`` forcing periods, with rigid impacts of
    restitution ``e`` or the compliant contact ``e`` (module text: Eq. F1 between impacts,
    Eq. F2 at them)."""
    from .simulation import simulate_forced

    checked_response(name, forcing)
    rigid = is_rigid(e)
    if name == "acceleration" and not rigid:
        raise MethodNotApplicable("response", COMPLIANT_ACCELERATION)
    x, v, z, u = (float(c) for c in state)
    res = simulate_forced(system, forcing, **simulation_arguments(e), periods=periods,
                          x0=x, xdot0=v, y0=x + z, ydot0=u,
                          samples_per_period=16 if rigid else SAMPLES)  # fmt: skip
    return _largest(name, res, 0, periods)


def steady_response(name: str, result: Any, discard: int) -> float:
    """``name`` (:data:`RESPONSES`) of a run (:func:`symimpact.forced.simulate_forced`) over its
    periods after the first ``discard`` (module text; a compliant run recorded at
    :data:`SAMPLES` samples a period)."""
    from .simulation import ForcedResult

    checks.instance("result", result, ForcedResult, "a ForcedResult (from simulate_forced)")
    checked_response(name, result.forcing)
    n = len(result.period_max)
    discard = checks.whole_number("discard", discard, 0, n - 1)
    if result.samples is not None:
        if name == "acceleration":
            raise MethodNotApplicable("response", COMPLIANT_ACCELERATION)
        if (result.samples.shape[0] - 1) // max(n, 1) != SAMPLES:
            raise MethodNotApplicable(
                "response",
                f"a compliant run's response needs its state at {SAMPLES} samples a period "
                "(simulate_forced(..., samples_per_period=SAMPLES))",
            )
    return _largest(name, result, discard, n - discard)


def _largest(name: str, res: Any, first: int, periods: int) -> float:
    """The largest abs(``name``) of the run ``res`` over ``periods`` periods from period
    ``first``: SAMPLES samples a period, the largest refined by Brent's method (rigid impacts,
    the state rebuilt exactly), or the largest sample (a compliant run's grid)."""
    from .simulation import state_at

    system, forcing = res.system, res.forcing
    n = periods * SAMPLES
    t = (first * SAMPLES + np.arange(n + 1)) * (forcing.period / SAMPLES)
    s = state_at(res, t)
    values = np.abs(_values(name, system, forcing, t, s))
    best = int(np.argmax(values))
    if res.samples is not None:
        return float(values[best])

    def minus(time: float) -> float:
        one = np.array([time])
        return -float(abs(_values(name, system, forcing, one, state_at(res, one))[0]))

    lo, hi = t[max(best - 1, 0)], t[min(best + 1, n)]
    found = minimize_scalar(minus, bounds=(lo, hi), method="bounded",
                            options={"xatol": 1e-12 * forcing.period})  # fmt: skip
    return max(float(values[best]), -float(found.fun))


def response_unit(name: str) -> str:
    """The SI unit of ``name``."""
    return RESPONSES[name][0]


def response_key(name: str) -> str:
    """The name the response ``name``'s values carry in JSON and CSV: ``amplitude`` for the
    displacement, else the response's own (``force``, ``relative_displacement``, …)."""
    return "amplitude" if name == "displacement" else name.replace("-", "_")


def shown_response(name: str, value: Any) -> Any:
    """``value`` [SI] of the response ``name`` in its display unit (a transmissibility as it is)."""
    from ..model.display import shown

    quantity = QUANTITY[name]
    return value if quantity is None else shown(quantity, value)


__all__ = [
    "RESPONSES",
    "checked_response",
    "linear_response",
    "orbit_response",
    "response_unit",
    "steady_response",
]
