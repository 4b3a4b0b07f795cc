"""Shocks on the primary with its impact damper: the figures designers report.

*Shock.*  The peak displacement of the main mass with and without the damper, and the
shock-response spectrum of the main mass's motion (maximax absolute acceleration of small
single-degree-of-freedom oscillators of damping ratio ζ mounted on it: the shock an equipment on
the structure feels) with and without the damper.  With impacts the main mass's velocity jumps, so
its acceleration holds impulses; the oscillators are therefore driven through their spring and
damper by the mass's displacement and velocity, W'' + 2ζω(W' − ẋ_b) + ω²(W − x_b) = 0, which hold
no impulses: the load ω²x_b + 2ζωẋ_b joined by straight lines between samples, Eq. F8 exact on
each interval, the absolute acceleration −ω²(W − x_b) − 2ζω(W' − ẋ_b) read at the samples.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import ParameterError
from ...model import checks
from ...model.system import ImpactSystem
from ..simulation import CHATTER
from .record_flight import _march, primary_response
from .record_response import damper_response
from .records import Record

#: The SRS's oscillators: damping ratio 5 % (Q = 10), the usual one in shock specifications.
SRS_ZETA = 0.05
#: An oscillation at f rises between two samples by up to (2πf·dt)²/8 of its size: above
#: 2πf·dt = 0.3 that is more than 1.1 %, and such frequencies are refused.
SRS_TOP = 0.3


def base_motion(record: Record) -> tuple[np.ndarray, np.ndarray]:
    """(x_b, ẋ_b) [m, m/s] at the samples of a base-acceleration record, from rest at t = 0:
    the acceleration's straight lines integrated exactly, ẋ_b += dt(a₀ + a₁)/2,
    x_b += dt·ẋ_b + dt²(2a₀ + a₁)/6."""
    a, dt = record.values, record.dt
    dv = 0.5 * dt * (a[:-1] + a[1:])
    v = np.concatenate(([0.0], np.cumsum(dv)))
    dx = dt * v[:-1] + dt * dt * (2.0 * a[:-1] + a[1:]) / 6.0
    return np.concatenate(([0.0], np.cumsum(dx))), v


def srs_oscillators(frequencies: Any, zeta: Any, dt: float) -> tuple[np.ndarray, float]:
    """The SRS's ``frequencies`` [Hz] and ``zeta``, checked: at least one, each above 0 and at
    most :data:`SRS_TOP`/(2π·dt) (a peak read at samples every ``dt`` [s] within 1 %), and
    0 ≤ ζ < 1."""
    f = checks.numbers("frequencies", frequencies)
    if f.size == 0:
        raise ParameterError("frequencies", "give at least one oscillator frequency")
    z = checks.bounded("zeta", zeta, 0.0, 1.0)
    if z >= 1.0:
        raise ParameterError("zeta", "must be below 1 (underdamped)")
    if np.any(f <= 0):
        raise ParameterError("frequencies", "must be above 0 Hz")
    top = SRS_TOP / (2.0 * math.pi * dt)
    if np.max(f) > top:
        raise ParameterError(
            "frequencies",
            f"reach {np.max(f):g} Hz, where samples every {dt:g} s miss a peak by more than 1 %: "
            f"at most {top:.4g} Hz, or a finer record",
        )
    return f, z


def motion_srs(
    displacement: np.ndarray, velocity: np.ndarray, dt: float, frequencies: Any,
    zeta: Any = SRS_ZETA, after: tuple[float, float, float, float] | None = None,
) -> np.ndarray:  # fmt: skip
    """Maximax absolute acceleration [m/s²] of oscillators at ``frequencies`` [Hz] (damping
    ratio ``zeta``) on a base moving with ``displacement`` [m] and ``velocity`` [m/s] sampled
    every ``dt`` [s], from relative rest (module docstring; Eq. F8 with the load
    ω²x_b + 2ζωẋ_b).  ``after`` = (x, ẋ, ωp, ζp): beyond the samples the base vibrates freely
    from x, ẋ (relative to a base that moves on at constant speed, or rests) with ωp, ζp, and
    the residual response then is read too (:func:`residual_maximax`)."""
    f, z = srs_oscillators(frequencies, zeta, dt)
    xb = np.ascontiguousarray(displacement, dtype=float)
    vb = np.ascontiguousarray(velocity, dtype=float)
    out = np.empty(len(f))
    for j, fn in enumerate(f):
        w = 2.0 * math.pi * fn
        load = w * w * xb + 2.0 * z * w * vb
        W, Wd = _march(1.0, w * w, 2.0 * z * w, load, dt, xb[0], vb[0])
        out[j] = np.max(np.abs(w * w * (W - xb) + 2.0 * z * w * (Wd - vb)))
        if after is not None:  # the residual response beyond the samples
            out[j] = max(out[j], residual_maximax(W[-1] - xb[-1], Wd[-1] - vb[-1], w, z, *after))
    return out


#: The residual of a motion that does not decay (an undamped primary or oscillator) is read
#: over this many periods of its slowest term.
RESIDUAL_PERIODS = 200


def _poles(w: float, z: float) -> tuple[complex, complex]:
    """The roots of s² + 2ζωs + ω² (kept apart by 1e-9 of ω where they meet: ζ = 1)."""
    root = complex(z * z - 1.0) ** 0.5
    if abs(root) < 1e-9:
        root = 1e-9 + 0j
    return -z * w + w * root, -z * w - w * root


def residual_maximax(r0: float, rd0: float, w: float, z: float, x0: float, v0: float,
                     wp: float, zp: float) -> float:  # fmt: skip
    """The largest absolute acceleration [m/s²] of an oscillator (ω [rad/s], ζ) after the
    samples end, on a primary that then vibrates freely: the primary from x0 [m], v0 [m/s] with
    natural frequency ωp and damping ratio ζp (the load over, its damper out of reach or at
    rest), the oscillator from its relative state r0 = W − y [m], rd0 [m/s].  In closed form:
    y(τ) = Σ a_k e^{λ_k τ} (λ the primary's poles), r'' + 2ζωr' + ω²r = −ÿ so
    r = Σ b_k e^{λ_k τ} + Σ d_k e^{μ_k τ} with b_k = −a_k λ_k²/(λ_k² + 2ζωλ_k + ω²) and d from
    r0, rd0; the acceleration −ω²r − 2ζωr' is read on a grid of 256 points in the shorter of
    the two periods (a peak missed by at most (2π/256)²/8 = 7.5e-5 of its height) until the
    terms' envelopes fall below the largest value read."""
    lam = _poles(wp, zp)
    mu = _poles(w, z)
    if abs(lam[0] - mu[0]) < 1e-9 * w or abs(lam[0] - mu[1]) < 1e-9 * w:
        mu = _poles(w * (1.0 + 1e-9), z)  # a double root (ζ = ζp, ω = ωp): kept apart
    a1 = (v0 - lam[1] * x0) / (lam[0] - lam[1])
    a = (a1, x0 - a1)
    b = [-a[k] * lam[k] ** 2 / (lam[k] ** 2 + 2.0 * z * w * lam[k] + w * w) for k in range(2)]
    r_rest = r0 - b[0] - b[1]
    rd_rest = rd0 - b[0] * lam[0] - b[1] * lam[1]
    d1 = (rd_rest - mu[1] * r_rest) / (mu[0] - mu[1])
    d = (d1, r_rest - d1)
    nu = np.array([lam[0], lam[1], mu[0], mu[1]])
    amp = np.array([b[0], b[1], d[0], d[1]])
    coef = -(w * w + 2.0 * z * w * nu) * amp  # the acceleration's terms
    fastest = max(abs(lam[0]), abs(mu[0]), w, wp)
    h = 2.0 * math.pi / fastest / 256.0
    best, start, chunk = 0.0, 0.0, 4096
    size, rate = np.abs(coef), nu.real
    # an undamped primary or oscillator (C = 0, ζ = 0) never decays: read RESIDUAL_PERIODS of the
    # slowest term at most
    slowest = min(min(abs(v.imag) for v in nu if abs(v.imag) > 0.0), min(w, wp))
    horizon = RESIDUAL_PERIODS * 2.0 * math.pi / slowest
    while True:
        tau = start + h * np.arange(chunk)
        acc = (coef[None, :] * np.exp(tau[:, None] * nu[None, :])).sum(axis=1).real
        best = max(best, float(np.max(np.abs(acc))))
        start = tau[-1] + h
        if float(np.sum(size * np.exp(rate * start))) < best or start > horizon:
            return best


@dataclass(frozen=True)
class ShockResult:
    """A shock on the primary with and without its damper (SI): ``peak`` and ``baseline_peak``
    the largest abs(x) [m] (relative to the base under a base acceleration), ``peak_acceleration``
    and ``baseline_peak_acceleration`` the largest absolute acceleration between impacts
    [m/s²], ``frequency`` [Hz], ``srs`` and ``baseline_srs`` [m/s²] (module docstring),
    ``impacts`` the number of impacts."""

    peak: float
    baseline_peak: float
    peak_acceleration: float
    baseline_peak_acceleration: float
    frequency: np.ndarray
    srs: np.ndarray
    baseline_srs: np.ndarray
    impacts: int
    zeta: float

    def as_dict(self) -> dict[str, Any]:
        """The JSON of ``symimpact shock --json`` (SI)."""
        return {
            "peak": self.peak,
            "baseline_peak": self.baseline_peak,
            "peak_acceleration": self.peak_acceleration,
            "baseline_peak_acceleration": self.baseline_peak_acceleration,
            "impacts": self.impacts,
            "srs_zeta": self.zeta,
            "srs": [
                {"frequency": float(f), "response": float(a), "baseline": float(b)}
                for f, a, b in zip(self.frequency, self.srs, self.baseline_srs, strict=True)
            ],
        }


def shock_response(
    system: ImpactSystem, record: Record, *, e: Any, frequencies: Any,
    zeta: Any = SRS_ZETA, chatter: Any = CHATTER, participation: Any = 1.0,
) -> ShockResult:  # fmt: skip
    """``record`` (a shock of :func:`~symimpact.forced.loads.records.shock_record`, or any record) on
    ``system`` with rigid impacts of restitution ``e`` (Eq. F2, flight Eq. F8; or the compliant
    law of a :class:`~symimpact.forced.contact_law.CompliantContact`) and on the
    primary alone; the SRS of the main mass's absolute motion at ``frequencies`` [Hz], over the
    record and the residual response after it (the primary vibrating freely from its last
    sample, in closed form: :func:`residual_maximax`; exact once the damper no longer
    impacts, which a record followed by enough rest, :func:`~.loads.followed_by_rest`, gives).
    After the last sample the load is 0.  ``participation``: Γ of the primary in a base record
    (:func:`~symimpact.forced.loads.record_response.damper_response`; a structure's mode reduced
    to a point)."""
    srs_oscillators(frequencies, zeta, record.dt)  # refused before the runs, not after
    ours = damper_response(system, record, e=e, chatter=chatter, participation=participation)
    alone = primary_response(system, record, participation=participation)
    if record.kind == "base-acceleration":
        xb, vb = base_motion(record)
    else:
        xb = vb = np.zeros(len(record.values))
    wp = system.omega_n
    zp = system.C / (2.0 * math.sqrt(system.K * system.M))
    ends = [(r.displacement[-1], r.velocity[-1], wp, zp) for r in (ours, alone)]
    srs = motion_srs(ours.displacement + xb, ours.velocity + vb, record.dt, frequencies, zeta,
                     after=ends[0])  # fmt: skip
    base = motion_srs(alone.displacement + xb, alone.velocity + vb, record.dt, frequencies, zeta,
                      after=ends[1])  # fmt: skip
    return ShockResult(
        peak=float(np.max(np.abs(ours.displacement))),
        baseline_peak=float(np.max(np.abs(alone.displacement))),
        peak_acceleration=float(np.max(np.abs(ours.acceleration))),
        baseline_peak_acceleration=float(np.max(np.abs(alone.acceleration))),
        frequency=checks.numbers("frequencies", frequencies),
        srs=srs,
        baseline_srs=base,
        impacts=len(ours.impact_times),
        zeta=float(zeta),
    )
