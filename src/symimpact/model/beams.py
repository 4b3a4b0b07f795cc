"""Beams as primaries: the modes of a cantilever, a clamped–clamped or a simply supported
Euler–Bernoulli beam, each referred to the damper's point, and the point's static flexibility.

The cantilever's modes are Step 1's (paper Eq. 3–6, kernels ``ritz.*``), the other two beams'
Step 14's (Eq. F6, kernels ``beam_modes.*``); each mode's mass and stiffness are referred to the
point r along the beam (the displacement there is the mode's coordinate): M = ρAL·∫φ²dξ/φ(ξ)²,
K = ω²M, ω = (βL)²·√(EI/(ρAL⁴)).  When the supports move by x_b, each mode is driven as
by a base motion Γ·x_b (Step 15, Eq. F7, kernels ``modal_structure.*``): Γ = φ(ξ)∫φdξ/∫φ²dξ
referred to the point, and the mode moves the share MΓ²/(ρAL) = (∫φdξ)²/∫φ²dξ of the beam's
mass (its effective modal mass).  A mode with a node at the point does not move it: its M and K
are infinite there, and it cannot be the primary of a damper placed at that point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..generated import beam_modes as _bm
from ..generated import modal_structure as _ms
from ..generated import ritz as _ritz
from .units import positive_float


@dataclass(frozen=True)
class Support:
    """A beam's ends, as kernels: its roots βL, its mode shape φ(βL, ξ), its modal mass
    M/(ρAL) and stiffness K·L³/(EI) at ξ, its static flexibility at ξ (× L³/(EI)), and where a
    damper sits by default (ξ = r/L)."""

    roots: tuple[float, ...]
    shape: Any
    mass: Any
    stiffness: Any
    flexibility: Any
    default_xi: float
    #: Γ(βL, ξ) referred to the point and the effective-mass share (βL) (Eq. F7)
    participation: Any
    mass_share: Any


SUPPORTS: dict[str, Support] = {
    "cantilever": Support(_ritz.BETA_L, _ritz.mode_shape, _ritz.mass_coefficient,
                          _ritz.stiffness_coefficient, _bm.static_flexibility_cantilever, 1.0,
                          _ms.participation_cantilever,
                          _ms.mass_share_cantilever),
    "clamped-clamped": Support(_bm.BETA_L_CLAMPED_CLAMPED, _bm.mode_shape_clamped_clamped,
                               _bm.mass_coefficient_clamped_clamped,
                               _bm.stiffness_coefficient_clamped_clamped,
                               _bm.static_flexibility_clamped_clamped, 0.5,
                               _ms.participation_clamped_clamped,
                               _ms.mass_share_clamped_clamped),
    "simply-supported": Support(_bm.BETA_L_SIMPLY_SUPPORTED, _bm.mode_shape_simply_supported,
                                _bm.mass_coefficient_simply_supported,
                                _bm.stiffness_coefficient_simply_supported,
                                _bm.static_flexibility_simply_supported, 0.5,
                                _ms.participation_simply_supported,
                                _ms.mass_share_simply_supported),
}  # fmt: skip
#: Modes each support's roots are emitted for.
MAX_MODES = min(len(s.roots) for s in SUPPORTS.values())
#: |φ(ξ)| below this share of the mode's largest value counts as a node at the point.
NODE = 1e-9


@dataclass(frozen=True)
class BeamMode:
    """One mode of a beam referred to a point (SI)."""

    number: int
    #: root βL of the frequency equation [1]
    beta_L: float
    #: natural angular frequency ω = (βL)²·√(EI/(ρAL⁴)) [rad/s]
    omega: float
    #: modal mass referred to the point [kg] (inf at a node)
    M: float
    #: modal stiffness referred to the point, ω²M [N/m] (inf at a node)
    K: float
    #: the mode shape at the point, φ(ξ), in the normalisation of its step (∫φ²dξ = 1, or 1/2
    #: for the simply supported beam's sin βLξ)
    shape: float
    #: participation factor Γ referred to the point: the supports' motion x_b drives the mode as
    #: a base motion Γ·x_b (Eq. F7) [1] (0 at a node)
    participation: float = math.nan
    #: share of the beam's mass the mode moves under base excitation, MΓ²/(ρAL) (Eq. F7) [1]
    mass_share: float = math.nan

    @property
    def frequency(self) -> float:
        """Natural frequency ω/2π [Hz]."""
        return self.omega / (2.0 * math.pi)

    @property
    def node(self) -> bool:
        """True when the mode does not move the point."""
        return not math.isfinite(self.M)

    def as_dict(self) -> dict[str, Any]:
        return {"mode": self.number, "beta_L": self.beta_L, "omega": self.omega,
                "frequency": self.frequency, "M": None if self.node else self.M,
                "K": None if self.node else self.K, "shape": self.shape, "node": self.node,
                "participation": self.participation, "mass_share": self.mass_share}  # fmt: skip


def _support(support: Any) -> str:
    if support not in SUPPORTS:
        raise ParameterError("support", f"one of {', '.join(SUPPORTS)}, got {support!r}")
    return support


def _point(support: str, L: float, position: Any) -> float:
    """ξ = r/L of the damper (default: the cantilever's tip, the other beams' midspan)."""
    if position is None:
        return SUPPORTS[support].default_xi
    r = positive_float("position", position)
    if r > L * (1 + 1e-12):
        raise ParameterError("position", f"{r:g} m lies beyond the beam length L = {L:g} m")
    return min(r / L, 1.0)


def beam_modes(support: str, E: Any, I: Any, rho: Any, A: Any, L: Any, position: Any = None,
               n: Any = 1) -> list[BeamMode]:  # fmt: skip
    """The first ``n`` modes (at most :data:`MAX_MODES`) of the ``support`` beam (Young's
    modulus ``E`` [Pa], second moment ``I`` [m⁴], density ``rho`` [kg/m³], section ``A`` [m²],
    length ``L`` [m]) referred to the point ``position`` [m from the clamp or the left support]
    (Eq. 5–6 for the cantilever, Eq. F6 for the clamped–clamped and simply supported beams),
    each with its participation factor and effective-mass share (Eq. F7)."""
    support = _support(support)
    E, I, rho, A, L = (positive_float(k, v) for k, v in
                       zip("E I rho A L".split(), (E, I, rho, A, L), strict=True))  # fmt: skip
    if not isinstance(n, int) or isinstance(n, bool) or not 1 <= n <= MAX_MODES:
        raise ParameterError("modes", f"a whole number from 1 to {MAX_MODES}, got {n!r}")
    xi = _point(support, L, position)
    kernels = SUPPORTS[support]
    scale = math.sqrt(E * I / (rho * A * L**4))
    modes = []
    for i, bl in enumerate(kernels.roots[:n], start=1):
        phi = float(kernels.shape(bl, xi))
        omega = bl * bl * scale
        # the shapes' largest values are of order 1 (≤ 2): a node where φ is below NODE
        share = float(kernels.mass_share(bl))
        if abs(phi) < NODE:
            M = K = math.inf
            gamma = 0.0
        else:
            M = float(kernels.mass(bl, xi)) * rho * A * L
            K = float(kernels.stiffness(bl, xi)) * E * I / L**3
            gamma = float(kernels.participation(bl, xi))
        # a symmetric beam's antisymmetric modes: ∫φdξ is zero but for rounding
        share = 0.0 if share < 1e-14 else share
        modes.append(BeamMode(i, float(bl), omega, M, K, phi, gamma, share))
    return modes


def static_flexibility(support: str, E: Any, I: Any, L: Any, position: Any = None) -> float:
    """The beam's static deflection at the point under a unit force there [m/N], from its
    statics (Eq. F6: two cubics joined at the point): the limit of Σ 1/K_i over all modes."""
    support = _support(support)
    E, I, L = (positive_float(k, v) for k, v in zip("E I L".split(), (E, I, L), strict=True))
    xi = _point(support, L, position)
    return float(SUPPORTS[support].flexibility(xi)) * L**3 / (E * I)


def beam_constants(E: Any, I: Any, rho: Any, A: Any, L: Any, position: Any = None,
                   support: str = "cantilever", mode: Any = 1) -> tuple[float, float]:  # fmt: skip
    """(K [N/m], M [kg]) of one Ritz mode referred to the damper position (Eq. 5–6; Eq. F6 for
    the clamped–clamped and simply supported beams): the primary a damper at that point sees."""
    modes = beam_modes(support, E, I, rho, A, L, position, mode)
    m = modes[-1]
    if m.node or not (np.isfinite(m.K) and m.K > 0 and m.M > 0):
        raise ParameterError(
            "position",
            f"mode {m.number} of the {support} beam has a node at the damper's point: it does "
            "not move the damper (choose another point or mode)",
        )
    return m.K, m.M
