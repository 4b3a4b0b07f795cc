"""The contact derived from what a designer knows: the ball (material, diameter) and the cavity
(material, shape), through Step 13 (Eq. F5) — Hertz's stiffness, the impact it gives, the onset of
yield and the restitution of an elastic–plastic impact (Thornton) — and the Hunt–Crossley χ
(Step 11) and linear c₁ (Eq. 35) that reproduce that restitution.

Shapes (text as a designer writes it; diameters with units):

- impactor: ``"steel sphere 20 mm"`` (a sphere of that material and diameter; its mass follows);
- cavity: ``"steel flat"``, ``"steel sphere 40 mm"`` (a convex surface: ball on ball),
  ``"steel spherical cavity 30 mm"`` (concave: the ball inside a spherical seat of that diameter).

Restitution, from the same data: an impact below the yield speed v_y is elastic in Hertz's theory
(e = 1: wave and vibration losses, a few per cent in steel, are not modelled); above it Thornton's
elastic–perfectly-plastic model gives e(v_y/v₀), which falls like v₀^(−1/4).  The model describes a
first impact on fresh surfaces: repeated impacts at one spot work-harden it towards elastic rebound.
Against an elastomer the losses are viscoelastic: e = √R from its rebound resilience R.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any

from .errors import ParameterError
from .generated import closed_forms, contact_fits
from .generated import hertz_contact as hz
from .generated import rigid_impact as ri
from .materials import Material, material
from .units import positive_float

#: A massive cavity body (no M given): M = m·MASSIVE makes μ = mM/(m + M) equal m to rounding.
MASSIVE = 1e17


@dataclass(frozen=True)
class Body:
    """A contacting body: its material, shape and radius of curvature at the contact [m]
    (None for a flat; negative for a concave seat)."""

    material: Material
    shape: str
    radius: float | None
    text: str


_IMPACTOR = re.compile(r"^(?P<mat>.+?)\s+(?P<shape>sphere|ball)\s+(?P<size>\S.*)$", re.I)
_CAVITY = re.compile(
    r"^(?P<mat>.+?)\s+(?:(?P<flat>flat|plate|wall)|(?P<shape>spherical cavity|spherical seat|"
    r"sphere|ball)\s+(?P<size>\S.*))$",
    re.I,
)


def impactor_body(text: str) -> Body:
    """The impactor of ``text``: ``"<material> sphere <diameter>"``."""
    found = _IMPACTOR.match(" ".join(str(text).split()))
    if not found:
        raise ParameterError(
            "impactor", f"cannot read {text!r}: write '<material> sphere <diameter>', e.g. "
            "'steel sphere 20 mm' (spheres only: a cylinder's line contact is not derived)"
        )  # fmt: skip
    d = positive_float("impactor diameter", found["size"], "m")
    return Body(material(found["mat"]), "sphere", d / 2.0, text)


def cavity_body(text: str) -> Body:
    """The cavity of ``text``: ``"<material> flat"``, ``"<material> sphere <diameter>"`` or
    ``"<material> spherical cavity <diameter>"``."""
    found = _CAVITY.match(" ".join(str(text).split()))
    if not found:
        raise ParameterError(
            "cavity", f"cannot read {text!r}: write '<material> flat', '<material> sphere "
            "<diameter>' or '<material> spherical cavity <diameter>'"
        )  # fmt: skip
    mat = material(found["mat"])
    if found["flat"]:
        return Body(mat, "flat", None, text)
    d = positive_float("cavity diameter", found["size"], "m")
    concave = "cavity" in found["shape"].lower() or "seat" in found["shape"].lower()
    return Body(
        mat, "spherical cavity" if concave else "sphere", (-d if concave else d) / 2.0, text
    )


def sphere_mass(body: Body) -> float:
    """Mass of a solid sphere [kg]: ρπD³/6."""
    return body.material.rho * math.pi * (2.0 * body.radius) ** 3 / 6.0


def yield_pressure(mat: Material) -> float | None:
    """Peak Hertz pressure p₀ [Pa] at which ``mat`` first yields: Y divided by the largest
    (σ_r − σ_z)/p₀ on the axis (Step 13's kernel, maximised over the depth by Brent's method;
    1.61·Y at ν = 0.3).  None for a material without a yield strength."""
    if mat.yield_strength is None:
        return None
    from scipy.optimize import minimize_scalar

    best = minimize_scalar(
        lambda z: -hz.axis_stress_difference_scalar(z, mat.nu),
        bounds=(1e-3, 3.0),
        method="bounded",
        options={"xatol": 1e-10},
    )
    return mat.yield_strength / -best.fun


@dataclass(frozen=True)
class DerivedContact:
    """The contact of an impactor in a cavity at the impact speed ``v0`` (SI units).

    ``m`` [kg] impactor mass; ``E_star`` [Pa], ``R`` [m] effective modulus and radius; ``k_hz``
    [N/m^1.5]; ``max_penetration`` [m], ``duration`` [s], ``peak_force`` [N], ``peak_pressure``
    [Pa] of the elastic impact at v0; ``yield_speed`` [m/s] (None: no yield strength);
    ``e`` [1] at v0; ``chi`` [s/m] (Hunt–Crossley) and ``c1`` [N s/m] with ``k1`` [N/m] (the
    linear law fitted over the impact's penetration) that give that e at v0; ``sources``: where
    each value comes from.
    """

    v0: float
    m: float
    E_star: float
    R: float
    k_hz: float
    max_penetration: float
    duration: float
    peak_force: float
    peak_pressure: float
    yield_speed: float | None
    e: float
    chi: float
    k1: float
    c1: float
    sources: dict[str, str] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


def restitution_at(
    impactor: Body, cavity: Body, v0: float, yield_speed: float | None
) -> tuple[float, str]:
    """e at the impact speed v0 and where it comes from (module docstring)."""
    resilient = [b.material for b in (impactor, cavity) if b.material.resilience is not None]
    if resilient:
        mat = min(resilient, key=lambda m: m.resilience)
        return math.sqrt(mat.resilience), f"resilience: √R of {mat.name}, R = {mat.resilience:g}"
    if yield_speed is None or v0 <= yield_speed:
        return 1.0, "elastic: the impact speed is below the yield speed (Step 13)"
    ratio = yield_speed / v0
    return float(hz.thornton_restitution_scalar(ratio)), (
        f"Thornton: the elastic–plastic impact at v_y/v0 = {ratio:.4g} (Step 13)"
    )


def derived_contact(impactor: Any, cavity: Any, v0: Any, M: Any = None) -> DerivedContact:
    """The contact of ``impactor`` (text or :class:`Body`) in ``cavity`` at the impact speed
    ``v0`` [m/s], against a cavity body of mass ``M`` [kg] (None: massive) — Step 13, Eq. F5."""
    imp = impactor if isinstance(impactor, Body) else impactor_body(impactor)
    cav = cavity if isinstance(cavity, Body) else cavity_body(cavity)
    v0 = positive_float("v0", v0, "m/s")
    m = sphere_mass(imp)
    M = m * MASSIVE if M is None else positive_float("M", M, "kg")
    kappa = 0.0 if cav.radius is None else 1.0 / cav.radius
    if cav.radius is not None and cav.radius < 0.0 and -cav.radius <= imp.radius:
        raise ParameterError(
            "cavity", f"a spherical cavity of diameter {-2e3 * cav.radius:g} mm cannot hold a "
            f"sphere of diameter {2e3 * imp.radius:g} mm (the cavity must be larger)"
        )  # fmt: skip
    a, b = imp.material, cav.material
    E_star = float(hz.effective_modulus_scalar(a.E, a.nu, b.E, b.nu))
    R = float(hz.effective_radius_scalar(imp.radius, kappa))
    k_hz = float(hz.hertz_stiffness_scalar(E_star, R))
    delta = float(closed_forms.hertz_max_penetration_scalar(m, M, k_hz, v0))
    pressures = [p for p in (yield_pressure(a), yield_pressure(b)) if p is not None]
    p_y = min(pressures) if pressures else None
    v_y = None if p_y is None else float(hz.yield_speed_scalar(m, M, E_star, R, p_y))
    e, e_source = restitution_at(imp, cav, v0, v_y)
    from .contact import hunt_crossley_chi

    chi = hunt_crossley_chi(e, v0) if e < 1.0 else 0.0
    k1 = float(contact_fits.linear_fit_k1_scalar(k_hz, delta))
    c1 = 0.0 if e >= 1.0 else float(ri.linear_c1_for_restitution_scalar(m, M, k1, e))
    where = f"{imp.text} in {cav.text}"
    sources = {
        "m": f"ρπD³/6 of the {imp.material.name} sphere",
        "E_star": f"Step 13 from E, ν of {a.name} and {b.name}",
        "R": f"Step 13: 1/R = 1/R₁ + 1/R₂ ({where})",
        "k_hz": "Step 13: K_Hz = 4/3·E*·√R",
        "max_penetration": "Eq. 34 (Step 6) at v0",
        "duration": "Eq. 34 (Step 6) at v0",
        "peak_force": "Step 13: K_Hz·δ_max^1.5",
        "peak_pressure": "Step 13: p₀ = (2E*/π)·√(δ_max/R)",
        "yield_speed": "Step 13: p₀ reaches the softer body's yield pressure (von Mises on the axis)"
        if v_y is not None
        else "no yield strength (elastomer): not defined",
        "e": e_source,
        "chi": "Step 11: the Hunt–Crossley χ giving e at v0 (exact)",
        "k1": "Eq. 9's least-squares line over [0, δ_max] (Step 2)",
        "c1": "Step 9: the linear law's c1 giving e with k1 (Eq. 35 inverted)",
        "impactor_material": f"{a.name}: {a.grade}; {a.source}",
        "cavity_material": f"{b.name}: {b.grade}; {b.source}",
    }
    return DerivedContact(
        v0=v0,
        m=m,
        E_star=E_star,
        R=R,
        k_hz=k_hz,
        max_penetration=delta,
        duration=float(closed_forms.hertz_contact_duration_scalar(m, M, k_hz, v0)),
        peak_force=float(hz.impact_peak_force_scalar(m, M, k_hz, v0)),
        peak_pressure=float(hz.peak_pressure_scalar(E_star, R, delta)),
        yield_speed=v_y,
        e=e,
        chi=float(chi),
        k1=k1,
        c1=c1,
        sources=sources,
    )
