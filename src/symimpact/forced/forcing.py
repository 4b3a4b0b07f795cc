"""Harmonic forcing of the primary: a force F0·cos(Ωt + φ) on the main mass, base motion
X_b·cos(Ωt + φ) under its spring and damper, or both (Step 8, Eq. F1).

Base motion is given as a shaker is specified: a displacement amplitude X_b, or a velocity
amplitude V_b or an acceleration amplitude A_b that stays constant over a band, so that
X_b = V_b/Ω or A_b/Ω² at each frequency (the derivatives of X_b·cos(Ωt + φ))."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from ..model.units import positive_float, si_float


@dataclass(frozen=True)
class Forcing:
    """Harmonic forcing (SI floats once built; quantities with units accepted).

    ``F0`` [N]: force amplitude on the main mass.  ``X_b`` [m]: base-motion amplitude (the primary's
    spring and damper attach to the base); or instead ``V_b`` [m/s], the base velocity amplitude
    (X_b = V_b/Ω), or ``A_b`` [m/s²], the base acceleration amplitude (X_b = A_b/Ω²; "0.5 g"
    reads g as the standard gravity 9.80665 m/s²), which :meth:`at` keeps over a band.
    ``omega`` [rad/s]: forcing frequency Ω, or ``freq`` [Hz] instead (Ω = 2πf).  ``phase``
    [rad]: φ, the forcing phase at t = 0.

    ``inertia`` [kg]: (Γ − 1)·M for a structure's mode reduced to a point, which the supports
    drive by Γ = Γᵢφᵢ(a) (Eq. F7: M·ẍ_r + C·ẋ_r + K·x_r = −Γ·M·ẍ_b relative to them), where a
    primary on its base takes Γ = 1.  In the absolute x = x_r + x_b of Eq. F1 that is
    M·ẍ + C·(ẋ − ẋ_b) + K·(x − x_b) = F0·cos θ − (Γ − 1)·M·ẍ_b, a force in phase with the base's
    displacement: :attr:`primary_force` F0 + (Γ − 1)·M·Ω²·X_b is the force amplitude the
    engines and closed forms take; ``F0`` stays the force applied to the primary.
    """

    F0: Any = 0.0
    X_b: Any = 0.0
    omega: Any = None
    freq: Any = None
    phase: Any = 0.0
    V_b: Any = None
    A_b: Any = None
    inertia: Any = 0.0

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
        set_(self, "inertia", si_float("inertia", self.inertia, "kg"))
        given = [k for k in ("V_b", "A_b") if getattr(self, k) is not None]
        if given:
            if len(given) > 1 or self.X_b != 0.0:
                raise ParameterError(given[-1], "give the base motion once: X_b, V_b or A_b")
            name = given[0]
            value = si_float(name, getattr(self, name))
            set_(self, name, value)
            set_(self, "X_b", value / (omega if name == "V_b" else omega * omega))

    def base_amplitude(self, omega: Any) -> Any:
        """X_b [m] at the frequencies ``omega`` [rad/s] (a number or an array): X_b, V_b/Ω or
        A_b/Ω², whichever was given stays constant."""
        if self.V_b is not None:
            return self.V_b / omega
        if self.A_b is not None:
            return self.A_b / (omega * omega)
        return self.X_b + 0.0 * omega

    def force_amplitude(self, omega: Any) -> Any:
        """F0 + inertia·Ω²·X_b(Ω) [N] at the frequencies ``omega`` [rad/s]: the force amplitude on
        the primary, in phase with the base's displacement, that Eq. F1 takes (``inertia``: see
        the class)."""
        if self.inertia == 0.0:
            return self.F0 + 0.0 * omega
        return self.F0 + self.inertia * omega * omega * self.base_amplitude(omega)

    @property
    def primary_force(self) -> float:
        """:meth:`force_amplitude` at this forcing's Ω [N]: F0 itself for a primary on its base."""
        return self.F0 if self.inertia == 0.0 else float(self.force_amplitude(self.omega))

    def at(self, omega: float, phase: float | None = None) -> Forcing:
        """The same forcing at the frequency ``omega`` [rad/s] (and ``phase``, default this
        one's): F0 and whichever of X_b, V_b, A_b was given stay constant (Eq. F1)."""
        if (
            self.V_b is None
            and self.A_b is None
            and isinstance(omega, float)
            and 0.0 < omega < math.inf
            and (phase is None or (isinstance(phase, float) and math.isfinite(phase)))
        ):  # a frequency in SI, as the continuation's Newton steps give it: nothing to convert
            out = object.__new__(Forcing)
            for name, value in (("F0", self.F0), ("X_b", self.X_b), ("omega", float(omega)),
                                ("freq", float(omega) / (2.0 * math.pi)),
                                ("phase", self.phase if phase is None else float(phase)),
                                ("V_b", None), ("A_b", None),
                                ("inertia", self.inertia)):  # fmt: skip
                object.__setattr__(out, name, value)
            return out
        kept = {"V_b": self.V_b} if self.V_b is not None else {}
        kept |= {"A_b": self.A_b} if self.A_b is not None else {}
        return Forcing(
            F0=self.F0,
            X_b=0.0 if kept else self.X_b,
            omega=omega,
            phase=self.phase if phase is None else phase,
            inertia=self.inertia,
            **kept,
        )

    @property
    def period(self) -> float:
        """Forcing period T = 2π/Ω [s]."""
        return 2.0 * math.pi / self.omega

    def as_dict(self) -> dict[str, float]:
        out = {"F0": self.F0, "X_b": self.X_b, "omega": self.omega, "phase": self.phase}
        out |= {k: getattr(self, k) for k in ("V_b", "A_b") if getattr(self, k) is not None}
        if self.inertia != 0.0:
            out["inertia"] = self.inertia
        return out
