"""The system a user works with: one validated, immutable description in SI units."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace
from typing import Any

from ..errors import ParameterError
from ..generated import contact_fits
from .beams import beam_constants
from .units import nonnegative, nonnegative_float, positive, positive_float, si, si_float

CONTACT_LAWS = ("cubic", "hertz", "linear")

#: Table 2 of the paper, and its cubic-law coefficients (Eq. 9).
TABLE2 = {
    "M": "1 kg",
    "K": "100 N/cm",
    "m": "0.25 kg",
    "a": "0.1553 N/cm^3",
    "b": "0.8360 N/cm",
    "c1": "5 N s/cm",
}


@dataclass(frozen=True)
class ImpactSystem:
    """Main mass on a spring and dashpot carrying an impact damper (paper Fig. 1b, Eq. 7–10).

    Every parameter accepts an SI number or a quantity with units (``"100 N/cm"``); the stored
    values are SI floats.

    Parameters
    ----------
    M : main mass [kg].  K : main stiffness [N/m].  m : impact mass [kg].
    gap : clearance d [m]; the masses touch when abs(y − x) = d/2.
    C : main damping [N s/m], or ``zeta``: damping ratio ζ = C/(2√(KM)) [1] (give one, default 0).
        Free flight (Eq. 7) is written for an underdamped main mass, ζ < 1.
    contact : force law during contact: ``"cubic"`` a·δ³ + b·δ (Eq. 9), ``"hertz"`` K_Hz·δ^1.5
        (Eq. 8) or ``"linear"`` k1·δ (Eq. 35).
    a, b : cubic coefficients [N/m³, N/m]; when missing they are fitted to ``k_hz`` over
        [0, ``delta_max``] (21-sample least squares, Eq. 9).
    k_hz : Hertz stiffness [N/m^1.5].  k1 : linear stiffness [N/m] (fitted to ``k_hz`` if missing
        and the law is linear).
    c1 : contact damping [N s/m] (Eq. 10), the force c1·δ̇ acts while the masses touch.
    delta_max : penetration range of the fits [m] (the paper: 2 cm).
    """

    M: Any
    K: Any
    m: Any
    gap: Any
    C: Any = None
    zeta: Any = None
    contact: str = "cubic"
    a: Any = None
    b: Any = None
    k_hz: Any = None
    k1: Any = None
    c1: Any = 0.0
    delta_max: Any = 0.02

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        for name in ("M", "K", "m", "gap", "delta_max"):
            set_(self, name, positive_float(name, getattr(self, name)))
        set_(self, "c1", nonnegative_float("c1", self.c1))
        if self.contact not in CONTACT_LAWS:
            raise ParameterError("contact", f"must be one of {', '.join(CONTACT_LAWS)}")
        critical = 2.0 * math.sqrt(self.K * self.M)
        if self.C is not None and self.zeta is not None:
            C = nonnegative_float("C", self.C)
            zeta = nonnegative_float("zeta", self.zeta)
            if not math.isclose(C, 2 * zeta * math.sqrt(self.K * self.M), rel_tol=1e-9):
                raise ParameterError("zeta", "give C or zeta, not two different dampings")
        elif self.zeta is not None:
            C = 2.0 * nonnegative_float("zeta", self.zeta) * math.sqrt(self.K * self.M)
        else:
            C = nonnegative_float("C", 0.0 if self.C is None else self.C)
        if C >= critical:
            raise ParameterError(
                "C" if self.zeta is None else "zeta",
                f"damping ratio {C / critical:g} ≥ 1: free flight (Eq. 7) is written for an "
                "underdamped main mass",
            )
        set_(self, "C", C)
        set_(self, "zeta", C / critical)
        for name in ("a", "b", "k_hz", "k1"):
            v = getattr(self, name)
            if v is not None:
                set_(self, name, si_float(name, v))
        if self.k_hz is not None:
            set_(self, "k_hz", positive_float("k_hz", self.k_hz))
        # a stiffness given is checked whichever law the run uses: other methods (Eq. 35's
        # duration, the fits) read it too, and a negative one means nothing there either
        if self.k1 is not None:
            positive("k1", self.k1)
        if self.a is not None:
            nonnegative("a", self.a)
        if self.b is not None:
            positive("b", self.b)
        if self.contact == "cubic" or (self.a is None and self.b is None and self.k_hz):
            if self.a is None and self.b is None and self.k_hz is not None:
                set_(self, "a", float(contact_fits.cubic_fit_a(self.k_hz, self.delta_max)))
                set_(self, "b", float(contact_fits.cubic_fit_b(self.k_hz, self.delta_max)))
        if self.contact == "cubic":
            if self.a is None or self.b is None:
                raise ParameterError(
                    "a" if self.a is None else "b",
                    "the cubic contact law needs a and b (or k_hz to fit them)",
                )
            nonnegative("a", self.a)
            positive("b", self.b)
        if self.k1 is None and self.k_hz is not None:
            set_(self, "k1", float(contact_fits.linear_fit_k1(self.k_hz, self.delta_max)))
        if self.contact == "linear":
            if self.k1 is None:
                raise ParameterError("k1", "the linear contact law needs k1 (or k_hz to fit it)")
            positive("k1", self.k1)
        if self.contact == "hertz" and self.k_hz is None:
            raise ParameterError("k_hz", "the Hertz contact law needs k_hz")

    # --- constructors -------------------------------------------------------------------------
    @classmethod
    def from_beam(
        cls,
        E: Any,
        I: Any,
        rho: Any,
        A: Any,
        L: Any,
        m: Any,
        gap: Any,
        zeta: Any = 0.0,
        position: Any = None,
        support: str = "cantilever",
        mode: int = 1,
        **contact: Any,
    ) -> ImpactSystem:
        """System whose K, M and C come from one mode of a beam by Ritz (Eq. 1–6; Eq. F6 for the
        clamped–clamped and simply supported beams, ``support``; ``mode``: which mode).

        ``E`` [Pa], ``I`` [m⁴], ``rho`` [kg/m³], ``A`` [m²], ``L`` [m]; the damper sits at
        ``position`` [m] from the clamp or the left support (default: the cantilever's tip, the
        other beams' midspan); ``zeta`` is the beam's damping
        ratio, C = 2ζ√(KM) (Eq. 6).  K = (K L³/EI)·EI/L³ and M = (M/ρAL)·ρAL with the first-mode
        coefficients referred to the damper position (:func:`symimpact.model.beams.beam_constants`).
        Other keywords go to the constructor.
        """
        K, M = beam_constants(E, I, rho, A, L, position, support, mode)
        return cls(M=M, K=K, m=m, gap=gap, zeta=zeta, **contact)

    def with_(self, **changes: Any) -> ImpactSystem:
        """A copy with some parameters changed (validated again)."""
        base = self.as_dict()
        if "zeta" in changes and "C" not in changes:
            base["C"] = None  # a new damping ratio replaces C
        else:
            base["zeta"] = None  # C (kept or changed) defines the damping
        if self._fitted_a_b() and not ({"a", "b"} & set(changes)):
            base["a"] = base["b"] = None  # refit if k_hz or delta_max changes
        base.update(changes)
        return replace(self, **base)

    def _fitted_a_b(self) -> bool:
        if self.k_hz is None or self.a is None:
            return False
        return self.a == float(contact_fits.cubic_fit_a(self.k_hz, self.delta_max)) and (
            self.b == float(contact_fits.cubic_fit_b(self.k_hz, self.delta_max))
        )

    # --- derived quantities -----------------------------------------------------------------------
    @property
    def omega_n(self) -> float:
        """Natural angular frequency √(K/M) of the main mass [rad/s]."""
        return math.sqrt(self.K / self.M)

    def as_dict(self) -> dict[str, Any]:
        """The parameters as plain SI values (for JSON and tables)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def table2_system(gap: Any = "9 mm", **changes: Any) -> ImpactSystem:
    """The paper's Table 2 system (C from c1 = 5C) with clearance ``gap``; keywords override."""
    params: dict[str, Any] = dict(TABLE2)
    params["C"] = si("c1", params["c1"]) / 5.0
    params.update(changes)
    return ImpactSystem(gap=gap, **params)
