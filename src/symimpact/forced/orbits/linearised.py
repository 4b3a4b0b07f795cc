"""The pieces of a linearised motion through rigid impacts, shared by the closed-form orbits'
stability (:mod:`symimpact.forced.orbits.periodic`) and shooting (:mod:`symimpact.forced.orbits.shooting`):
the flight's transition matrix Φ(τ) (Step 8), the primary's acceleration (Eq. F1) and Step 9's
saltation matrix S, all in the state (x, ẋ, z = y − x, ẏ)."""

from __future__ import annotations

import math

import numpy as np

from ...generated import rigid_impact as ri
from ...model.system import ImpactSystem
from ..engine import _rigid
from ..forcing import Forcing


def flight_matrix(system: ImpactSystem, tau: float) -> np.ndarray:
    """Φ(τ) of a flight of τ [s] of the primary (mass M): one flight of
    :func:`flight_matrices`."""
    return flight_matrices(system, np.array([tau]), np.array([system.M]))[0]


def flight_matrices(system: ImpactSystem, taus: np.ndarray, masses: np.ndarray) -> np.ndarray:
    """Φ(τ) of many flights at once: x, ẋ from unit displacement and unit velocity without
    forcing (Step 8, Eq. F1, the kernels compiled; the flight is affine in the state); z = y − x
    moves by ẏτ − (x(τ) − x0); ẏ is constant.  ``taus`` [s] and the moving ``masses`` [kg] (M,
    or M + m in a sticking phase) of equal length; returned, shape (n, 4, 4)."""
    taus = np.ascontiguousarray(taus, dtype=float)
    masses = np.ascontiguousarray(masses, dtype=float)
    return _rigid.flight_matrices(taus, masses, float(system.K), float(system.C))


def acceleration(
    system: ImpactSystem,
    forcing: Forcing,
    theta: float,
    x: float,
    v: float,
    mass: float | None = None,
) -> float:
    """ẍ [m/s²] of the primary in flight at forcing phase θ = Ωt + φ (Eq. F1: its spring and
    damper on the moving base X_b·cos θ, the force F0·cos θ); ``mass`` [kg]: the moving mass (M,
    or M + m in a sticking phase).  Its partial derivative in time is Ω times its value at θ + π/2
    with x = ẋ = 0 (every forcing term is a combination of cos θ and sin θ)."""
    W = forcing.omega
    mass = system.M if mass is None else mass
    xb, vb = forcing.X_b * math.cos(theta), -forcing.X_b * W * math.sin(theta)
    return (
        forcing.primary_force * math.cos(theta) - system.K * (x - xb) - system.C * (v - vb)
    ) / mass


def saltation_matrix(system: ImpactSystem, e: float, zdot: float, a: float) -> np.ndarray:
    """Step 9's saltation matrix at an impact with restitution ``e``, relative velocity ż = ẏ − ẋ
    [m/s] and primary acceleration ``a`` [m/s²] just before it."""
    M, C, m = system.M, system.C, system.m
    kM = ri.saltation_main_gain_scalar(m, M, e)
    km = ri.saltation_impact_gain_scalar(m, M, e)
    return np.array(
        [
            [1, 0, kM, 0],
            [0, 1 - kM, ri.saltation_main_velocity_z_scalar(m, M, e, C, zdot, a), kM],
            [0, 0, -e, 0],
            [0, km, ri.saltation_impact_velocity_z_scalar(m, M, e, zdot, a), 1 - km],
        ]
    )
