"""Forced response of the primary with an impact damper (beyond the paper).

- :class:`Forcing`: a force F0·cos(Ωt + φ) on the main mass and/or base motion X_b·cos(Ωt + φ).
- :func:`simulate_forced`: event-driven simulation with rigid impacts (Eq. F1, F2), chatter and
  sticking; its ``steady`` summary (amplitude, impacts per period, period of the motion).
- :func:`periodic_orbits`: the symmetric two-impact periodic motions in closed form (Eq. F3),
  admissibility and stability.
"""

from .forcing import Forcing
from .periodic import PeriodicOrbit, periodic_orbits
from .simulation import ForcedResult, Steady, simulate_forced, steady_state

__all__ = [
    "ForcedResult",
    "Forcing",
    "PeriodicOrbit",
    "Steady",
    "periodic_orbits",
    "simulate_forced",
    "steady_state",
]
