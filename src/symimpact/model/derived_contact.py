"""The contact derived from what a designer knows: the ball (material, diameter) and the cavity
(material, shape), through Step 13 (Eq. F5) — Hertz's stiffness, the impact it gives, the onset of
yield and the restitution of an elastic–plastic impact (Thornton) — and the Hunt–Crossley χ
(Step 11) and linear c₁ (Eq. 35) that reproduce that restitution.

Shapes (text as a designer writes it; diameters with units):

- impactor: ``"steel sphere 20 mm"`` (a sphere of that material and diameter; its mass follows)
  or ``"steel sphere 2 kg"`` (a sphere of that material and mass; its diameter follows);
- cavity: ``"steel flat"``, ``"steel sphere 40 mm"`` (a convex surface: ball on ball),
  ``"steel spherical cavity 30 mm"`` (concave: the ball inside a spherical seat of that diameter),
  ``"steel cylindrical bore 30 mm"`` (the ball in a tube) or ``"steel cylinder 30 mm"`` (on a
  rod): these two touch on an ellipse (Hertz's elliptical contact, :func:`elliptical_hertz`).

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

from ..errors import ParameterError
from ..generated import closed_forms, contact_fits
from ..generated import hertz_contact as hz
from ..generated import rigid_impact as ri
from .materials import Material, material
from .units import converts_to, positive_float, split_quantity

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
    r"sphere|ball|cylindrical bore|cylindrical cavity|bore|cylinder|rod)\s+(?P<size>\S.*))$",
    re.I,
)
#: Cavity shapes: text → (shape, concave).
_SHAPES = {
    "spherical cavity": ("spherical cavity", True),
    "spherical seat": ("spherical cavity", True),
    "sphere": ("sphere", False),
    "ball": ("sphere", False),
    "cylindrical bore": ("cylindrical bore", True),
    "cylindrical cavity": ("cylindrical bore", True),
    "bore": ("cylindrical bore", True),
    "cylinder": ("cylinder", False),
    "rod": ("cylinder", False),
}


def impactor_body(text: str) -> Body:
    """The impactor of ``text``: ``"<material> sphere <diameter>"``, or ``"<material> sphere
    <mass>"``, whose diameter is that of a solid sphere of the material's density ρ,
    D = (6m/(πρ))^(1/3) (:func:`sphere_mass` inverted)."""
    found = _IMPACTOR.match(" ".join(str(text).split()))
    if not found:
        raise ParameterError(
            "impactor", f"cannot read {text!r}: write '<material> sphere <diameter or mass>', "
            "e.g. 'steel sphere 20 mm' or 'steel sphere 2 kg' (spheres only: a cylinder's line "
            "contact is not derived)"
        )  # fmt: skip
    mat = material(found["mat"])
    size = found["size"]
    _, unit = split_quantity("impactor", size)
    if unit and not (converts_to(unit, "m") or converts_to(unit, "kg")):
        raise ParameterError(
            "impactor", f"{size!r}: a sphere is given by its diameter (e.g. '20 mm') or its mass "
            "(e.g. '2 kg')"
        )  # fmt: skip
    if unit and converts_to(unit, "kg"):
        m = positive_float("impactor mass", size, "kg")
        d = (6.0 * m / (math.pi * mat.rho)) ** (1.0 / 3.0)
    else:
        d = positive_float("impactor diameter", size, "m")
    return Body(mat, "sphere", d / 2.0, text)


def cavity_body(text: str) -> Body:
    """The cavity of ``text``: ``"<material> flat"``, ``"<material> sphere <diameter>"``,
    ``"<material> spherical cavity <diameter>"``, ``"<material> cylindrical bore <diameter>"``
    (the ball rolling in a tube) or ``"<material> cylinder <diameter>"`` (on a rod)."""
    found = _CAVITY.match(" ".join(str(text).split()))
    if not found:
        raise ParameterError(
            "cavity", f"cannot read {text!r}: write '<material> flat', '<material> sphere "
            "<diameter>', '<material> spherical cavity <diameter>' or '<material> cylindrical "
            "bore <diameter>'"
        )  # fmt: skip
    mat = material(found["mat"])
    if found["flat"]:
        return Body(mat, "flat", None, text)
    d = positive_float("cavity diameter", found["size"], "m")
    shape, concave = _SHAPES[found["shape"].lower()]
    return Body(mat, shape, (-d if concave else d) / 2.0, text)


def sphere_mass(body: Body) -> float:
    """Mass of a solid sphere [kg]: ρπD³/6."""
    return body.material.rho * math.pi * (2.0 * body.radius) ** 3 / 6.0


@dataclass(frozen=True)
class EllipticalHertz:
    """Hertz's elliptical contact of two bodies whose gap near the touch point is A·x² + B·y²
    (A ≤ B: the relative principal curvatures halved), per unit E* and in powers of the approach
    δ: the force K_Hz·δ^{3/2} with ``k_hz_per_modulus`` = K_Hz/E* [m^0.5], the semi-axes
    a = ``a_per_root``·√δ (along x) and b = k·a, the central pressure
    p₀ = ``p0_per_root``·E*·√δ [1/√m], and the eccentricity² ``m`` = 1 − k²."""

    k_hz_per_modulus: float
    a_per_root: float
    k: float
    p0_per_root: float
    m: float


def elliptical_hertz(A: float, B: float) -> EllipticalHertz:
    """Hertz's elliptical contact (Johnson, *Contact Mechanics*, 1985, §4.2): under
    p = p₀√(1 − x²/a² − y²/b²) a pair of half-spaces of modulus E* displaces by
    (L − Mx² − Ny²)/E* with L = p₀bK(e), M = p₀b(K − E)/(e²a²), N = p₀b(E/k² − K)/(e²a²)
    (K, E: complete elliptic integrals of the parameter e² = 1 − k², k = b/a).  Closing the gap
    δ − Ax² − By² gives B/A = N/M (which fixes e, by Brent's method), δ = L/E*, A = M/E*, and the
    force (2/3)πabp₀ ∝ δ^{3/2}.  Checked against a quadrature of Boussinesq's displacement in
    the tests; as B/A → 1 it tends to Step 13's circular contact with R = 1/(2A)."""
    from scipy.optimize import brentq
    from scipy.special import ellipk

    if not 0.0 < A <= B:
        raise ParameterError("cavity", "the relative curvatures must satisfy 0 < A ≤ B")
    ratio = B / A

    def excess(m: float) -> float:  # N/M − B/A = (K − D)/((1 − m)D) − B/A, from 0 at m = 0
        K = float(ellipk(m))
        D = _k_minus_e_over_m(m)
        return (K - D) / ((1.0 - m) * D) - ratio

    m = brentq(excess, 0.0, 1.0 - 1e-16, xtol=1e-300, rtol=1e-15) if ratio > 1.0 else 0.0
    K = float(ellipk(m))
    c = _k_minus_e_over_m(m)
    k = math.sqrt(1.0 - m)
    a = math.sqrt(c / (A * K))  # a² per unit δ: from A = M/E* = δ(K − E)/(K e² a²)
    return EllipticalHertz(
        k_hz_per_modulus=2.0 * math.pi * a / (3.0 * K),  # (2/3)πab·p₀ with p₀b = E*δ/K
        a_per_root=a,
        k=k,
        p0_per_root=1.0 / (k * a * K),
        m=m,
    )


#: Below this parameter m, (K − E)/m is summed from its series (the difference of the integrals
#: would lose eps/m of its digits).
SERIES_BELOW = 0.1


def _k_minus_e_over_m(m: float) -> float:
    """(K(m) − E(m))/m without cancellation: K − E = (π/2)·Σ_{n≥1} c_n²·2n/(2n − 1)·mⁿ with
    c_n = Π_{j≤n} (2j − 1)/(2j) (the binomial series of both integrals), summed to 1e-17 below
    :data:`SERIES_BELOW`; above it the integrals' difference."""
    from scipy.special import ellipe, ellipk

    if m >= SERIES_BELOW:
        return float((ellipk(m) - ellipe(m)) / m)
    total, c, n, term = 0.0, 1.0, 1, 1.0
    while abs(term) > 1e-17 * abs(total) or n == 1:
        c *= (2 * n - 1) / (2 * n)
        term = c * c * 2 * n / (2 * n - 1) * m ** (n - 1)
        total += term
        n += 1
    return 0.5 * math.pi * total


def curvatures(impactor: Body, cavity: Body) -> tuple[float, float]:
    """(A, B), A ≤ B: half the relative principal curvatures [1/m] of the sphere against the
    cavity (Johnson §4.1: the gap is Ax² + By²); a cylinder curves across its axis only."""
    k1 = 1.0 / impactor.radius
    kc = 0.0 if cavity.radius is None else 1.0 / cavity.radius
    across = k1 + kc
    along = k1 + (kc if cavity.shape in ("sphere", "spherical cavity") else 0.0)
    return 0.5 * min(across, along), 0.5 * max(across, along)


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


#: Hertz's law assumes a contact small beside the radii (a ≪ R, the bodies half-spaces): the
#: contact radius a = √(Rδ) beyond this share of R (a penetration beyond its square, 9 %, of R)
#: is warned of.  The package's bound: elastomer flats under steel balls reach 0.15–0.2 at the
#: impact speeds of dampers, where Hertz is the usual model; 0.3 is beyond that use.
HERTZ_SMALL = 0.3
#: Thornton's elastic–perfectly-plastic restitution (Step 13) is warned of beyond this many
#: times the speed of first yield: the package's stated bound on extrapolating a law that leaves
#: out strain hardening, strain rate and the fully plastic indentation of high speeds.
PLASTIC_RANGE = 100.0


def _yield_text(mat: Material) -> str:
    if mat.yield_strength is None:
        return f", no yield (rebound resilience {mat.resilience:g})" if mat.resilience else ""
    return f", yield strength {mat.yield_strength / 1e6:.4g} MPa"


def _warn_validity(v0: float, delta: float, R: float, v_y: float | None) -> None:
    """One warning for each assumption the impact at v0 leaves behind (:data:`HERTZ_SMALL`,
    :data:`PLASTIC_RANGE`)."""
    import warnings

    a = math.sqrt(R * delta)
    if a > HERTZ_SMALL * R:
        warnings.warn(
            f"at {v0:g} m/s the contact radius √(Rδ) = {a * 1e3:.3g} mm is {a / R:.2g} of R "
            f"(Hertz's law assumes below {HERTZ_SMALL:g}): the stiffness and duration are "
            "extrapolated",
            stacklevel=3,
        )
    if v_y is not None and v0 > PLASTIC_RANGE * v_y:
        warnings.warn(
            f"at {v0:g} m/s the impact is {v0 / v_y:.3g} times the speed of first yield "
            f"({v_y:.3g} m/s): Thornton's elastic–perfectly-plastic e is extrapolated beyond "
            f"{PLASTIC_RANGE:g} times it",
            stacklevel=3,
        )


def derived_contact(impactor: Any, cavity: Any, v0: Any, M: Any = None) -> DerivedContact:
    """The contact of ``impactor`` (text or :class:`Body`) in ``cavity`` at the impact speed
    ``v0`` [m/s], against a cavity body of mass ``M`` [kg] (None: massive) — Step 13, Eq. F5."""
    imp = impactor if isinstance(impactor, Body) else impactor_body(impactor)
    cav = cavity if isinstance(cavity, Body) else cavity_body(cavity)
    v0 = positive_float("v0", v0, "m/s")
    m = sphere_mass(imp)
    M = m * MASSIVE if M is None else positive_float("M", M, "kg")
    if cav.radius is not None and cav.radius < 0.0 and -cav.radius <= imp.radius:
        raise ParameterError(
            "cavity", f"a {cav.shape} of diameter {-2e3 * cav.radius:g} mm cannot hold a "
            f"sphere of diameter {2e3 * imp.radius:g} mm (the cavity must be larger)"
        )  # fmt: skip
    a, b = imp.material, cav.material
    E_star = float(hz.effective_modulus_scalar(a.E, a.nu, b.E, b.nu))
    A, B = curvatures(imp, cav)
    if A == B:  # a circle: Step 13's kernels
        R = float(hz.effective_radius_scalar(imp.radius, 1.0 / cav.radius if cav.radius else 0.0))
        k_hz = float(hz.hertz_stiffness_scalar(E_star, R))
        geometry = "Step 13: 1/R = 1/R₁ + 1/R₂"

        def pressure_at(approach: float) -> float:
            return float(hz.peak_pressure_scalar(E_star, R, approach))

        def approach_at(pressure: float) -> float:
            return float(hz.yield_approach_scalar(E_star, R, pressure))

    else:  # an ellipse: R is the equivalent radius 1/(2√(AB)) that is reported
        ell = elliptical_hertz(A, B)
        R = 0.5 / math.sqrt(A * B)
        k_hz = ell.k_hz_per_modulus * E_star
        geometry = f"Hertz's elliptical contact, b/a = {ell.k:.4g} (R: 1/(2√(AB)))"

        def pressure_at(approach: float) -> float:  # p₀ ∝ √δ for an ellipse too
            return ell.p0_per_root * E_star * math.sqrt(approach)

        def approach_at(pressure: float) -> float:
            return (pressure / (ell.p0_per_root * E_star)) ** 2

    delta = float(closed_forms.hertz_max_penetration_scalar(m, M, k_hz, v0))
    smallest = min(abs(r) for r in (imp.radius, cav.radius) if r)
    if delta >= smallest:
        raise ParameterError(
            "v0", f"{v0:g} m/s presses the bodies {delta * 1e3:.4g} mm together, beyond the "
            f"{smallest * 1e3:g} mm radius: no contact law holds there (Hertz's needs a "
            "penetration far below the radii)"
        )  # fmt: skip
    pressures = [p for p in (yield_pressure(a), yield_pressure(b)) if p is not None]
    p_y = min(pressures) if pressures else None
    if p_y is None:
        v_y = None
    else:  # p₀ reaches p_y at the approach δ_y; Step 13: the impact speed that reaches δ_y
        v_y = float(hz.speed_for_approach_scalar(m, M, k_hz, approach_at(p_y)))
    e, e_source = restitution_at(imp, cav, v0, v_y)
    _warn_validity(v0, delta, R, v_y)
    from .hunt_crossley import hunt_crossley_chi

    chi = hunt_crossley_chi(e, v0) if e < 1.0 else 0.0
    k1 = float(contact_fits.linear_fit_k1_scalar(k_hz, delta))
    c1 = 0.0 if e >= 1.0 else float(ri.linear_c1_for_restitution_scalar(m, M, k1, e))
    where = f"{imp.text} in {cav.text}"
    sources = {
        "m": f"ρπD³/6 of the {imp.material.name} sphere",
        "E_star": f"Step 13 from E, ν of {a.name} and {b.name}",
        "R": f"{geometry} ({where})",
        "k_hz": "Step 13: K_Hz = 4/3·E*·√R",
        "max_penetration": "Eq. 34 (Step 6) at v0",
        "duration": "Eq. 34 (Step 6) at v0",
        "peak_force": "Step 13: K_Hz·δ_max^1.5",
        "peak_pressure": "Step 13: p₀ = (2E*/π)·√(δ_max/R)",
        "yield_speed": "Step 13: p₀ reaches the softer body's yield pressure (von Mises on the "
        "axis of a circular contact; an ellipse's differs by a few per cent)"
        if v_y is not None
        else "no yield strength (elastomer): not defined",
        "e": e_source,
        "chi": "Step 11: the Hunt–Crossley χ giving e at v0 (exact)",
        "k1": "Eq. 9's least-squares line over [0, δ_max] (Step 2)",
        "c1": "Step 9: the linear law's c1 giving e with k1 (Eq. 35 inverted)",
        "impactor_material": f"{a.name}: {a.grade}{_yield_text(a)}; {a.source}",
        "cavity_material": f"{b.name}: {b.grade}{_yield_text(b)}; {b.source}",
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
        peak_pressure=pressure_at(delta),
        yield_speed=v_y,
        e=e,
        chi=float(chi),
        k1=k1,
        c1=c1,
        sources=sources,
    )
