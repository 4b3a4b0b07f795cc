"""The symmetric two-impact periodic motions in closed form (Step 10, Eq. F3), with their
amplitude, admissibility and stability.

At a fixed forcing phase φ of the first impact, Step 10's conditions are linear in the state after
it (X, V, U); the last one is a·cos φ + b·sin φ = c, solved as φ = atan2(b, a) ± arccos(c/r),
r = √(a² + b²).  Each solution is then checked:

- *amplitude*: max abs(x) over the half period (the other half is its negative), from Step 8's
  flight, sampled and refined where ẋ = 0;
- *admissible*: the impact mass approaches the second wall (U − ẋ(τ⁻) < 0) and touches no wall in
  between (abs(z) < d/2 on (0, τ), z = y − x, refined where ż = 0);
- *slopes*: the amplitude's derivatives in the clearance d and the restitution e, from the
  generated derivatives of the phase residual r(φ) = a·cos φ + b·sin φ − c and of X, V at a fixed
  phase (dφ/dp = −(∂r/∂p)/(∂r/∂φ)), carried to the extreme of x by the flight's transition
  kernels (∂x/∂t = 0 there, so the extreme's moving time does not enter);
- *stable*: the Floquet multipliers all have modulus < 1.  A perturbation of the state
  (x, ẋ, z, ẏ) just after the impact on the wall +d/2 is carried through the flight by its
  transition matrix Φ(τ) (the free-decay solutions of Step 8: the flight is affine in the state)
  and through the next impact by Step 9's saltation matrix S, which adds to the impact law's
  Jacobian the effect of arriving earlier or later.  The second half period is the mirror of the
  first, so the monodromy is (S·Φ)² and the multipliers are the squares of S·Φ's eigenvalues.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...generated import forced_flight as ff
from ...generated import periodic_orbit as po
from ...model.system import ImpactSystem
from ..forcing import Forcing
from .linearised import acceleration, flight_matrix, saltation_matrix

#: Samples per half period for the extremes of x and z before refinement (the flight holds at
#: most a few natural periods per half forcing period in the band of interest; 512 samples
#: bracket every extremum whose neighbours are more than 1/512 of the half period apart).
SAMPLES = 512


@dataclass(frozen=True)
class PeriodicOrbit:
    """One symmetric two-impact orbit (SI units).

    ``impact_phase`` [rad]: forcing phase Ωt + φ at the impact on the wall +d/2.
    ``amplitude`` [m]: max abs(x).  ``impact_speed`` [m/s]: relative approach speed.
    ``X`` [m], ``V``, ``U`` [m/s]: x, ẋ, ẏ after that impact.  ``admissible``: approaches the
    next wall and touches none in between.  ``stable``: every multiplier inside the unit circle.
    ``multipliers``: moduli of the full-period multipliers, sorted descending.
    ``amplitude_slope_gap`` [1]: ∂(amplitude)/∂d, and ``amplitude_slope_e`` [m]:
    ∂(amplitude)/∂e, along the orbit (Eq. F3 differentiated; see the module's docstring).
    """

    impact_phase: float
    amplitude: float
    impact_speed: float
    X: float
    V: float
    U: float
    admissible: bool
    stable: bool
    multipliers: tuple[float, ...]
    amplitude_slope_gap: float
    amplitude_slope_e: float

    def as_dict(self) -> dict[str, Any]:
        d = dict(self.__dict__)
        d["multipliers"] = list(self.multipliers)
        return d


def periodic_orbits(system: ImpactSystem, forcing: Forcing, e: Any) -> list[PeriodicOrbit]:
    """The symmetric two-impact periodic motions of the rigid-impact damper (Eq. F3): zero, one
    or two solutions, each with amplitude, impact speed, admissibility and stability, the
    smaller amplitude first.  Solved from all four conditions of Eq. F3 together, so that no
    determinant of three of them divides (one vanishes at the undamped resonance, others next
    to the damped one)."""
    from ..contact_law import checked

    system, forcing, e = checked(system, forcing, e, rigid_only="the closed form")
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
    a = float(po.phase_cos_coefficient(*args))
    b = float(po.phase_sin_coefficient(*args))
    c = float(po.phase_right_side(*args))
    r = math.hypot(a, b)
    if not (r > 0.0) or abs(c) > r:
        return []
    base, spread = math.atan2(b, a), math.acos(c / r)
    phases = [base + spread] if spread == 0.0 else [base + spread, base - spread]
    orbits = []
    for phi in phases:
        phi = math.remainder(phi, 2.0 * math.pi)
        X = float(po.impact_displacement(*args, phi))
        V = float(po.main_velocity_after(*args, phi))
        U = float(po.impact_mass_velocity_after(*args, phi))
        orbits.append(_describe(system, forcing, e, phi, X, V, U))
    return sorted(orbits, key=lambda o: o.amplitude)


def _flight(system, forcing, phi, X, V, tau):
    """(x, ẋ) a time τ after the first impact (Eq. F1 with the forcing phase φ at it)."""
    args = (system.M, system.K, system.C, forcing.primary_force, forcing.X_b, forcing.omega, phi,
            X, V)  # fmt: skip
    return ff.forced_displacement(tau, *args), ff.forced_velocity(tau, *args)


def _refined_extremes(f, df, t):
    """Values of f at the samples t and at the zeros of df between them (scipy's brentq)."""
    return _extremes_and_times(f, df, t)[0]


def _extremes_and_times(f, df, t):
    """(values, times): f at the samples t and at the zeros of df between them (scipy's
    brentq), and where they are."""
    from scipy.optimize import brentq

    d = df(t)
    idx = np.nonzero(np.sign(d[:-1]) * np.sign(d[1:]) < 0)[0]

    def scalar_df(s):
        return float(df(np.array([s]))[0])

    roots = [
        brentq(scalar_df, t[i], t[i + 1], xtol=1e-15 * t[-1], rtol=4 * np.finfo(float).eps)
        for i in idx
    ]
    times = np.concatenate([t, np.array(roots)])
    return f(times), times


def _describe(system, forcing, e, phi, X, V, U) -> PeriodicOrbit:
    W, h = forcing.omega, system.gap / 2.0
    tau = math.pi / W
    t = np.linspace(0.0, tau, SAMPLES + 1)

    def x_of(s):
        return _flight(system, forcing, phi, X, V, s)[0]

    def v_of(s):
        return _flight(system, forcing, phi, X, V, s)[1]

    values, times = _extremes_and_times(x_of, v_of, t)
    at = int(np.argmax(np.abs(values)))
    amplitude = float(abs(values[at]))
    slopes = _amplitude_slopes(system, forcing, e, phi, X, V, float(times[at]), values[at])
    v1 = float(_flight(system, forcing, phi, X, V, tau)[1])
    approach = -(U - v1)  # towards the wall −d/2: z decreasing

    def z_of(s):
        return h + U * s - (x_of(s) - X)

    def zd_of(s):
        return U - v_of(s)

    inner = t[1:-1]
    z_inner = _refined_extremes(z_of, zd_of, np.concatenate(([t[1]], inner, [t[-2]])))
    slack = 1e-9 * h
    admissible = bool(approach > 0.0 and np.all(np.abs(z_inner) < h - slack))
    moduli = _multipliers(system, forcing, e, phi, X, V, U, tau)
    return PeriodicOrbit(
        impact_phase=phi,
        amplitude=amplitude,
        impact_speed=approach,
        X=X,
        V=V,
        U=U,
        admissible=admissible,
        stable=bool(moduli[0] < 1.0),
        multipliers=tuple(float(m) for m in moduli),
        amplitude_slope_gap=slopes["d"],
        amplitude_slope_e=slopes["e"],
    )


def _amplitude_slopes(system, forcing, e, phi, X, V, t_peak, x_peak) -> dict[str, float]:
    """∂(amplitude)/∂p for p = d, e (Eq. F3 differentiated): the phase's slope from the residual,
    dφ/dp = −(∂r/∂p)/(∂r/∂φ); the state's, dX/dp = ∂X/∂p + ∂X/∂φ·dφ/dp (V alike); carried to the
    extreme of x at ``t_peak`` by the flight's derivatives in (x0, ẋ0, φ) (Eq. F1 differentiated),
    with no term for the extreme's own move since ẋ = 0 there.  At the impact (t = 0 or τ, where
    x = ±X) the slope is X's own."""
    F = forcing.primary_force
    args = (system.M, system.K, system.C, system.m, e, system.gap, F, forcing.X_b,
            forcing.omega)  # fmt: skip
    flight = (t_peak, system.M, system.K, system.C, F, forcing.X_b, forcing.omega, phi,
              X, V)  # fmt: skip
    tau = math.pi / forcing.omega
    interior = 0.0 < t_peak < tau
    r_phi = float(po.phase_residual_d_phi(*args, phi))
    slopes = {}
    for p in ("d", "e"):
        d_phi = -float(getattr(po, f"phase_residual_d_{p}")(*args, phi)) / r_phi
        dX = (
            float(getattr(po, f"impact_displacement_d_{p}")(*args, phi))
            + float(po.impact_displacement_d_phi(*args, phi)) * d_phi
        )
        if not interior:
            slopes[p] = math.copysign(1.0, x_peak) * (1.0 if t_peak == 0.0 else -1.0) * dX
            continue
        dV = (
            float(getattr(po, f"main_velocity_after_d_{p}")(*args, phi))
            + float(po.main_velocity_after_d_phi(*args, phi)) * d_phi
        )
        dx = (
            float(ff.forced_displacement_d_x0(*flight)) * dX
            + float(ff.forced_displacement_d_xdot0(*flight)) * dV
            + float(ff.forced_displacement_d_phi(*flight)) * d_phi
        )
        slopes[p] = math.copysign(1.0, x_peak) * dx
    return slopes


def _multipliers(system, forcing, e, phi, X, V, U, tau):
    """Moduli of the full-period Floquet multipliers, descending: eigenvalues of (S·Φ)² with
    Φ the flight's transition matrix over τ in (x, ẋ, z, ẏ) and S Step 9's saltation matrix at
    the impact on the wall −d/2."""
    x1, v1 = (float(v) for v in _flight(system, forcing, phi, X, V, tau))
    a1 = acceleration(system, forcing, phi + forcing.omega * tau, x1, v1)
    S = saltation_matrix(system, e, U - v1, a1)
    lam = np.linalg.eigvals(S @ flight_matrix(system, tau))
    return np.sort(np.abs(lam) ** 2)[::-1]
