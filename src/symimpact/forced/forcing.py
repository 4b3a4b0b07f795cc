"""Harmonic forcing of the primary: a force F0·cos(Ωt + φ) on the main mass, base motion
X_b·cos(Ωt + φ) under its spring and damper, or both (Step 8, Eq. F1)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from ..units import positive_float, si_float


@dataclass(frozen=True)
class Forcing:
    """Harmonic forcing (SI floats once built; quantities with units accepted).

    ``F0`` [N]: force amplitude on the main mass.  ``X_b`` [m]: base-motion amplitude (the primary's
    spring and damper attach to the base).  ``omega`` [rad/s]: forcing frequency Ω, or ``freq``
    [Hz] instead (Ω = 2πf).  ``phase`` [rad]: φ, the forcing phase at t = 0.
    """

    F0: Any = 0.0
    X_b: Any = 0.0
    omega: Any = None
    freq: Any = None
    phase: Any = 0.0

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        if (self.omega is None) == (self.freq is None):
            raise ParameterError("omega", "give the forcing frequency once: omega or freq")
        # a frequency with units is read by what it counts, angle or cycles (units.ANGULAR):
        # omega "5.41 Hz" is 34.0 rad/s, freq "324.7 rpm" is 5.41 Hz
        if self.omega is not None:
            omega = positive_float("omega", self.omega)
        else:
            omega = 2.0 * math.pi * positive_float("freq", self.freq)
        set_(self, "omega", omega)
        set_(self, "freq", omega / (2.0 * math.pi))
        set_(self, "F0", si_float("F0", self.F0))
        set_(self, "X_b", si_float("X_b", self.X_b))
        set_(self, "phase", si_float("phase", self.phase))

    @property
    def period(self) -> float:
        """Forcing period T = 2π/Ω [s]."""
        return 2.0 * math.pi / self.omega

    def as_dict(self) -> dict[str, float]:
        return {"F0": self.F0, "X_b": self.X_b, "omega": self.omega, "phase": self.phase}
