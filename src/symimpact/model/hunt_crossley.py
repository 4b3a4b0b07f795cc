"""One impact under the Hunt–Crossley law K_Hz·δ^{3/2}·(1 + χ·δ̇) (Step 11, Eq. F4), a property of
the contact itself: :func:`hunt_crossley_restitution` (exact, through Lambert's W),
:func:`hunt_crossley_chi` (its inverse: the χ that gives a wanted e) and
:func:`hunt_crossley_impact` (restitution, duration, peak force, largest penetration)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from .units import nonnegative, nonnegative_float, positive, positive_float, si_float

#: Largest z = χ·v₀ the restitution kernel covers to double precision everywhere: above it e equals
#: (1 − exp(−R))/z, R = 1 + z − ln(1 + z), to the last digit (Step 11).
HC_Z_MAX = 1e6


@dataclass(frozen=True)
class HuntCrossleyImpact:
    """One impact under the Hunt–Crossley law K_Hz·δ^{3/2}·(1 + χ·δ̇) (SI units).

    ``restitution`` e [1]; ``duration`` [s]; ``peak_force`` [N] and ``peak_speed_ratio`` s* [1]
    (the rate of penetration at the peak, as a fraction of v₀); ``max_penetration`` [m];
    ``chi_v0`` z = χ·v₀ [1], the one number e depends on.
    """

    restitution: float
    duration: float
    peak_force: float
    peak_speed_ratio: float
    max_penetration: float
    chi_v0: float

    def as_dict(self) -> dict[str, float]:
        return dict(self.__dict__)


def hunt_crossley_impact(m: Any, M: Any, k_hz: Any, chi: Any, v0: Any) -> HuntCrossleyImpact:
    """The impact of two free bodies (reduced mass μ = mM/(m + M)) meeting at speed ``v0`` under
    the Hunt–Crossley law (Step 11, Eq. F4).

    e is the exact root of g(−e·z) = g(z), z = χv₀, g(p) = p − ln(1 + p) (Lambert's W in closed
    form); the penetration and force follow from the phase orbit
    δ^{5/2} = (5μv₀²/(2K_Hz))·(h(z) − s²h(zs)) at the rate of penetration s·v₀; the peak from
    5z(h(z) − s²h(zs)) = 3s; the duration is ∫ μv₀ ds/F(s) over s ∈ [−e, 1], integrated by
    QUADPACK's QAWS with the weight ((1 − s)(s + e))^{−3/5} that carries its end singularities
    (the kernel ``duration_density`` is the smooth rest, written without cancellation at either
    end).  Accuracy: 1e-13 against a direct integration up to z = 3 (e ≈ 0.31); beyond, the
    duration degrades as 1 − e·z → 0 loses digits (3e-9 at z = 20, e = 0.05).
    """
    from scipy.integrate import quad

    from ..generated import fixed_points as fp
    from ..generated import hunt_crossley as hc

    m, M = positive_float("m", m), positive_float("M", M)
    k_hz = positive_float("k_hz", k_hz)
    chi, v0 = nonnegative_float("chi", chi), positive_float("v0", v0)
    z = chi * v0
    if z > HC_Z_MAX:
        raise ParameterError("chi", f"χ·v0 = {z:g} exceeds {HC_Z_MAX:g} (e < 1e-6)")
    e, _ = fp.hunt_crossley_restitution_scalar(chi, v0, 1e-12, 60)
    s_peak, _ = fp.hunt_crossley_peak_speed_ratio_scalar(chi, v0, 1e-13, 60)

    def regular_part(s: float) -> float:  # μv₀/F(s) divided by the weight
        return hc.duration_density_scalar(s, e, m, M, k_hz, chi, v0)

    import warnings

    from scipy.integrate import IntegrationWarning

    with warnings.catch_warnings():  # beyond z ≈ 10 QUADPACK meets the rounding stated above
        warnings.simplefilter("ignore", IntegrationWarning)
        duration, _ = quad(regular_part, -e, 1.0, weight="alg", wvar=(-0.6, -0.6),
                           epsabs=0.0, epsrel=1e-13, limit=200)  # fmt: skip
    return HuntCrossleyImpact(
        restitution=float(e),
        duration=float(duration),
        peak_force=float(hc.force_at_speed_scalar(s_peak, m, M, k_hz, chi, v0)),
        peak_speed_ratio=float(s_peak),
        max_penetration=float(hc.max_penetration_scalar(m, M, k_hz, chi, v0)),
        chi_v0=z,
    )


def hunt_crossley_restitution(chi: Any, v0: Any) -> Any:
    """Coefficient of restitution of the Hunt–Crossley law at approach speed ``v0`` [1], exact
    (Step 11, Eq. F4: the root of g(−e·χv₀) = g(χv₀), any Hertz exponent); arrays broadcast."""
    from ..generated import fixed_points as fp

    chi, v0 = nonnegative("chi", chi), positive("v0", v0)
    if np.any(np.asarray(chi) * np.asarray(v0) > HC_Z_MAX):
        raise ParameterError("chi", f"χ·v0 exceeds {HC_Z_MAX:g} (e < 1e-6)")
    e, _ = fp.hunt_crossley_restitution(chi, v0)
    return e[()] if np.ndim(e) == 0 else e


def hunt_crossley_chi(e: Any, v0: Any) -> float:
    """The χ [s/m] for which the Hunt–Crossley law gives the restitution ``e`` at speed ``v0``
    (Step 11, Eq. F4 inverted: e falls monotonically with z = χv₀; Brent's method on z, then
    χ = z/v₀).  Compare Hunt–Crossley's 3(1 − e)/(2v₀) and Lankarani–Nikravesh's
    3(1 − e²)/(4v₀), which Step 11 shows to be first-order truncations."""
    from scipy.optimize import brentq

    from ..generated import fixed_points as fp

    e = si_float("e", e)
    if not 0.0 < e <= 1.0:
        raise ParameterError("e", f"must lie in (0, 1], got {e:g}")
    v0 = positive_float("v0", v0)
    if e == 1.0:
        return 0.0

    def f(z: float) -> float:
        return fp.hunt_crossley_restitution_scalar(z, 1.0, 1e-12, 60)[0] - e

    hi = 1.0
    while f(hi) > 0.0:
        hi *= 4.0
        if hi > HC_Z_MAX:
            raise ParameterError("e", f"{e:g} needs χ·v0 above {HC_Z_MAX:g}")
    return brentq(f, 0.0, hi, xtol=1e-300, rtol=1e-15) / v0
