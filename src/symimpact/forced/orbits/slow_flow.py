"""The 1:1 slow flow of the vibro-impact absorber (Step 12, Eq. F5): the responses at one
frequency, the frequency-response curve at a fixed clearance, the backbone and the best clearance.

The slow flow assumes a light impact mass (m ≪ M) and a harmonic primary; Step 10's exact orbits
(:func:`~symimpact.forced.orbits.periodic.periodic_orbits`) do not.  ``tests/test_slow_flow.py`` measures
the difference as m/M grows; the docs' forced-response page prints it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from ...errors import MethodNotApplicable, ParameterError
from ...generated import slow_flow as sf
from ...model.system import ImpactSystem
from ...model.units import si
from ..forcing import Forcing

#: Samples per half period when checking that the impact mass stays between the walls between
#: impacts (the relative motion is a triangle minus a cosine: at most two extremes per half
#: period, each bracketed by 2048 samples to within 1e-6 of d/2).
WALL_SAMPLES = 2048
#: Roots of the quartic whose imaginary part exceeds this share of their modulus are complex
#: (numpy's companion-matrix roots of a real quartic carry about 1e-8 relative in the imaginary
#: part at a double root; farther apart the root is genuinely complex).
IMAG_SHARE = 1e-7


@dataclass(frozen=True)
class SlowFlowResponse:
    """One response of the slow flow at one frequency (SI units).

    ``amplitude`` [m]: the primary's amplitude ξ·d/2.  ``xi``: ξ, the primary's amplitude over
    half the clearance.  ``theta``: Θ, the impact mass's triangle amplitude over half the
    clearance.  ``phase_lag`` [rad]: Δ, the triangle's lag behind the primary.  ``upper``: Θ is
    the larger root of the amplitude relation (the branch the literature keeps).
    ``admissible``: the impact mass stays between the walls between impacts.
    """

    omega: float
    amplitude: float
    xi: float
    theta: float
    phase_lag: float
    upper: bool
    admissible: bool

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


def _restitution(system: Any, forcing: Any, e: Any) -> float:
    """Newton's e of the slow flow's rigid impacts, with the system and forcing checked."""
    from ..contact_law import checked

    return checked(system, forcing, e, rigid_only="the slow flow")[2]


def _constant_base(forcing: Forcing) -> None:
    """The backbone and the best clearance move along frequencies with one X_b and one force
    (Eq. F5): not a reduction's, whose force on the primary grows with Ω² (Forcing.inertia)."""
    if forcing.inertia != 0.0:
        raise ParameterError(
            "inertia", "the slow flow's backbone takes one force over its frequencies; a mode "
            "reduced to a point whose supports drive it by Γφ ≠ 1 has a force that grows with Ω²"
        )  # fmt: skip
    for name in ("V_b", "A_b"):
        if getattr(forcing, name) is not None:
            raise ParameterError(
                name, "the slow flow's backbone takes a constant base displacement X_b; give X_b"
            )


def _between_walls(xi: float, theta: float, delta: float) -> bool:
    """The relative motion Θ·tri(τ − Δ) − ξ·cos τ (in half clearances) stays within ±1 over the
    half period from the impact on the wall +d/2 (Eq. F5's ansatz)."""
    s = np.linspace(0.0, math.pi, WALL_SAMPLES + 1)
    u = theta * (1.0 - 2.0 * s / math.pi) - xi * np.cos(s + delta)
    return bool(np.all(np.abs(u[1:-1]) <= 1.0 + 1e-9))


def slow_flow_responses(system: ImpactSystem, forcing: Forcing, e: Any) -> list[SlowFlowResponse]:
    """Every response of the 1:1 slow flow at ``forcing.omega`` for the system's clearance
    (the real roots Θ of Eq. F5's quartic with ξ ≥ the activation threshold), largest amplitude
    first.  The forcing's phase plays no part (only the moduli balance)."""
    e = _restitution(system, forcing, e)
    args = (
        system.M,
        system.K,
        system.C,
        system.m,
        e,
        system.gap,
        forcing.primary_force,
        forcing.X_b,
        forcing.omega,
    )
    coefficients = [float(getattr(sf, f"response_quartic_{p}")(*args)) for p in (4, 3, 2, 1, 0)]
    if not any(coefficients):
        return []
    rho = float(sf.rho(e))
    out = []
    for root in np.roots(coefficients):
        if abs(root.imag) > IMAG_SHARE * abs(root) or root.real <= 0.0:
            continue
        theta = float(root.real)
        xi = math.sqrt((theta - 1.0) ** 2 + (rho * theta) ** 2)
        if xi == 0.0:
            continue
        delta = math.atan2(rho * theta, theta - 1.0)
        upper = theta * (1.0 + rho * rho) >= 1.0
        out.append(
            SlowFlowResponse(
                omega=forcing.omega,
                amplitude=xi * system.gap / 2.0,
                xi=xi,
                theta=theta,
                phase_lag=delta,
                upper=upper,
                admissible=_between_walls(xi, theta, delta),
            )
        )
    return sorted(out, key=lambda r: -r.amplitude)


@dataclass(frozen=True)
class Backbone:
    """The slow flow's backbone over ξ (arrays, SI): ``omega`` [rad/s] Ω_b(ξ), ``clearance`` [m]
    d_b(ξ), the clearance whose resonance peak sits there, and ``amplitude`` [m] = ξ·d_b/2."""

    xi: np.ndarray
    omega: np.ndarray
    clearance: np.ndarray
    amplitude: np.ndarray


def backbone(system: ImpactSystem, forcing: Forcing, e: Any, xi: Any) -> Backbone:
    """Eq. F5's backbone at the ratios ``xi`` (each above the activation threshold); the
    forcing's amplitude sets the clearances, its frequency plays no part."""
    e = _restitution(system, forcing, e)
    _constant_base(forcing)
    xi = np.asarray(si("xi", xi), dtype=float)
    threshold = float(sf.activation_amplitude_ratio(e))
    if not np.all(np.isfinite(xi)) or np.any(xi <= threshold):
        raise ParameterError("xi", f"must exceed the activation threshold {threshold:.6g}")
    omega = sf.backbone_frequency(system.M, system.K, system.m, e, xi)
    clearance = sf.backbone_clearance(
        system.M, system.K, system.C, system.m, e, forcing.F0, forcing.X_b, xi
    )
    return Backbone(xi=xi, omega=omega, clearance=clearance, amplitude=xi * clearance / 2.0)


@dataclass(frozen=True)
class BestClearance:
    """The slow flow's best clearance (SI): ``clearance`` [m], the largest d_b(ξ) on the backbone;
    ``amplitude`` [m], the primary's resonance peak with it; ``omega`` [rad/s] where the peak
    sits; ``xi`` at it."""

    clearance: float
    amplitude: float
    omega: float
    xi: float


def best_clearance(system: ImpactSystem, forcing: Forcing, e: Any) -> BestClearance:
    """The clearance that makes the primary's resonance peak smallest (Eq. F5): the largest
    backbone clearance d_b(ξ), by bounded Brent in log ξ.  A larger clearance leaves the
    absorber inactive at the resonance."""
    e = _restitution(system, forcing, e)
    _constant_base(forcing)
    if system.C == 0.0:
        raise MethodNotApplicable(
            "slow-flow", "without primary damping the backbone clearance grows without bound"
        )
    threshold = float(sf.activation_amplitude_ratio(e))

    def minus_clearance(log_xi: float) -> float:
        xi = math.exp(log_xi)
        return -float(
            sf.backbone_clearance(
                system.M, system.K, system.C, system.m, e, forcing.F0, forcing.X_b, xi
            )
        )

    lo = math.log(threshold * (1.0 + 1e-9)) if threshold > 0.0 else math.log(1e-9)  # e = 1
    # d_b rises from the threshold and falls like 1/ξ for large ξ: scan, then refine
    grid = np.linspace(lo, lo + math.log(1e6), 241)
    values = np.array([minus_clearance(g) for g in grid])
    i = int(np.argmin(values))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    res = minimize_scalar(minus_clearance, bounds=(a, b), method="bounded",
                          options={"xatol": 1e-12})  # fmt: skip
    xi = math.exp(res.x)
    d = -res.fun
    omega = float(sf.backbone_frequency(system.M, system.K, system.m, e, xi))
    return BestClearance(clearance=d, amplitude=xi * d / 2.0, omega=omega, xi=xi)
