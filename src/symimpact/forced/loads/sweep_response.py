"""Sine sweeps through the band on the primary with its impact damper: the envelope of the
displacement against the sweep's instantaneous frequency (the largest abs(x) over each of its
periods), swept up and down, with and without the damper — the run-up a machine makes through
its resonance, beside the steady curve of ``frf`` (:func:`steady_curve`: the continued branches'
stable orbits and the motion without impacts, and the linear curve without the damper, at the
sweep's amplitude).  Each sweep is a record of :func:`symimpact.forced.loads.records.sweep_record`; the
response is exact for it (Eq. F8 on each interval, Eq. F2 at each impact).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...model import checks
from ...model.system import ImpactSystem
from ...model.units import positive_float
from ..contact_law import restitution_or_law
from ..forcing import Forcing
from ..orbits.frf import frequency_response
from ..orbits.response_curve import response_curve
from ..responses import linear_response
from ..simulation import CHATTER
from .record_cost import PIECE_SAMPLES, Estimate, record_estimate
from .record_flight import primary_response
from .record_response import damper_response
from .records import sweep_frequency, sweep_record


def envelope(
    displacement: np.ndarray, frequency: np.ndarray, dt: float,
    velocity: np.ndarray | None = None, impacts: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """(instantaneous frequency [Hz], largest abs(x) [m]) over each period of a sweep whose
    instantaneous frequency at the samples is ``frequency``: the periods follow one another,
    each 1/f long at its start.  With the ``velocity`` [m/s] at the samples, the largest value
    is read between them too, on the cubic through x and ẋ at the two samples beside the
    largest one (its error (ω·dt)⁴/384 of the amplitude, 1e-5 at 25 samples a period, where the
    samples alone miss up to 1 − cos(ω·dt/2), 0.7 %); not across an interval that holds one of
    the ``impacts`` [s] (where ẋ jumps)."""
    starts = [0]
    t = 0.0
    n = len(displacement)
    while True:
        t += 1.0 / frequency[min(starts[-1], n - 1)]
        i = round(t / dt)
        if i >= n:
            break
        starts.append(i)
    if len(starts) < 2:
        return np.zeros(0), np.zeros(0)
    s = np.array(starts)
    a, b = s[:-1], s[1:]
    ax = np.abs(np.asarray(displacement, dtype=float))
    # the largest |x| over [a, b) of each period (the last period's slice ends at its b) …
    inner = np.maximum.reduceat(ax[: s[-1] + 1], a)
    # … and its first sample: the first j in [a, b) that holds it, or b where |x(b)| is larger
    j = np.arange(s[-1])
    period = np.searchsorted(s, j, side="right") - 1
    first = np.full(len(a), -1)
    holds = np.flatnonzero(ax[j] == inner[period])
    seen, where = np.unique(period[holds], return_index=True)
    first[seen] = holds[where]
    later = ax[b] > inner
    i = np.where(later | (first < 0), b, first)
    peak = np.maximum(inner, ax[b])
    if velocity is not None:
        v = np.asarray(velocity, dtype=float)
        x = np.asarray(displacement, dtype=float)
        hits = np.sort(np.asarray(impacts, dtype=float)) if impacts is not None else np.zeros(0)
        for k in (i - 1, i):  # the intervals beside the largest sample
            ok = (k >= 0) & (k < n - 1)
            k = np.where(ok, k, 0)
            t0, t1 = k * dt, (k + 1) * dt
            if len(hits):  # not across an interval that holds an impact
                h = np.searchsorted(hits, t0)
                ok &= ~((h < len(hits)) & (hits[np.minimum(h, len(hits) - 1)] <= t1))
            cubic = _hermite_peaks(x[k], v[k], x[k + 1], v[k + 1], dt)
            peak = np.where(ok, np.maximum(peak, cubic), peak)
    return np.asarray(frequency)[(a + b) // 2], peak


def _hermite_peaks(
    x0: np.ndarray, v0: np.ndarray, x1: np.ndarray, v1: np.ndarray, h: float
) -> np.ndarray:
    """The largest abs of each cubic Hermite interpolant through (x0, ẋ0) and (x1, ẋ1) over an
    interval of h [s]: at its ends, and where its derivative, a quadratic in u = s/h, is 0."""
    # p(u) = x0 + h v0 u + c2 u² + c3 u³
    c2 = 3.0 * (x1 - x0) - h * (2.0 * v0 + v1)
    c3 = 2.0 * (x0 - x1) + h * (v0 + v1)
    best = np.maximum(np.abs(x0), np.abs(x1))
    qa, qb, qc = 3.0 * c3, 2.0 * c2, h * v0
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = qb * qb - 4.0 * qa * qc
        r = np.sqrt(np.maximum(disc, 0.0))
        q = -0.5 * (qb + np.where(qb >= 0.0, r, -r))
        quadratic = qa != 0.0
        real = quadratic & (disc >= 0.0)  # a quadratic without real roots has none
        roots = (
            np.where(quadratic, np.where(real, q / qa, np.nan),
                     np.where(qb != 0.0, -qc / qb, np.nan)),
            np.where(real & (q != 0.0), qc / q, np.nan),
        )  # fmt: skip
        for u in roots:
            inside = (u > 0.0) & (u < 1.0)
            u = np.where(inside, u, 0.0)
            value = np.abs(x0 + u * (h * v0 + u * (c2 + u * c3)))
            best = np.where(inside, np.maximum(best, value), best)
    return best


#: frequencies of the steady curve over the sweep's band (the continuation steps between them;
#: the curve's peak is located between them, not sampled)
STEADY_POINTS = 41
#: frequencies of the primary alone's steady curve (closed form) over the band
LINEAR_POINTS = 801


@dataclass(frozen=True)
class SteadyCurve:
    """The steady response at the sweep's amplitude (SI, frequencies in Hz): ``stable``, rows
    (frequency, max abs(x), branch index) of the continued branches' stable orbits; ``unstable``
    the same for the unstable ones; ``no_impact`` rows (frequency, max abs(x)) of the motion
    without impacts where it exists; ``linear`` rows (frequency, max abs(x)) of the primary
    alone; ``peak``/``peak_frequency``: the located largest stable amplitude (None where the
    band holds none)."""

    stable: np.ndarray
    unstable: np.ndarray
    no_impact: np.ndarray
    linear: np.ndarray
    peak: float | None
    peak_frequency: float | None


def steady_curve(
    system: ImpactSystem, amplitude: Any, f_low: float, f_high: float, *, e: Any,
    kind: str = "force", points: int = STEADY_POINTS, participation: float = 1.0,
) -> SteadyCurve:  # fmt: skip
    """The curve of ``frf`` (:func:`symimpact.forced.orbits.frf.frequency_response`, without its
    brute-force sweeps: the sweep drawn beside it is the brute force) for a harmonic load of the
    sweep's ``amplitude`` — a force F0 [N] on the main mass, or a base acceleration A_b [m/s²]
    that stays constant over the band (X_b = A_b/Ω²), the amplitude then of x − x_b as in the
    sweep — at ``points`` frequencies from ``f_low`` to ``f_high`` [Hz]; rigid impacts with ``e``
    (Eq. F2); ``participation`` Γ of a base-driven primary (the forcing's inertia (Γ − 1)·M,
    :class:`~symimpact.forced.Forcing`)."""
    lo, hi = sorted((f_low, f_high))
    omegas = 2.0 * np.pi * np.linspace(lo, hi, points)
    forcing = (
        Forcing(F0=amplitude, omega=omegas[0])
        if kind == "force"
        else Forcing(A_b=amplitude, omega=omegas[0], inertia=(participation - 1.0) * system.M)
    )
    frf = frequency_response(system, forcing, e, omegas, sweeps=False)
    if kind != "force":  # a record's x under a base acceleration is relative to the base
        frf = response_curve(frf, "relative-displacement", system, forcing, e)
    rows: dict[bool, list[tuple[float, float, int]]] = {True: [], False: []}
    for i, b in enumerate(frf.branches):
        for p in b.points:
            rows[bool(p.stable)].append((p.omega / (2.0 * np.pi), p.amplitude, i))
    # the linear curve in closed form (Eq. F1's steady part) on a fine grid: a lightly damped
    # resonance is narrower than the continuation's frequency step
    fine = 2.0 * np.pi * np.linspace(lo, hi, LINEAR_POINTS)
    linear = linear_response(frf.response, system, forcing, fine)
    base = frf.baseline
    f = base[:, 0] / (2.0 * np.pi)
    inside = np.zeros(len(f), dtype=bool)
    for a, b in frf.no_impact:
        inside |= (base[:, 0] >= a) & (base[:, 0] <= b)
    peak = frf.peak
    return SteadyCurve(
        stable=np.array(rows[True]).reshape(-1, 3),
        unstable=np.array(rows[False]).reshape(-1, 3),
        no_impact=np.column_stack([f[inside], base[inside, 1]]),
        linear=np.column_stack([fine / (2.0 * np.pi), linear]),
        peak=None if peak is None else float(peak.amplitude),
        peak_frequency=None if peak is None else float(peak.omega / (2.0 * np.pi)),
    )


@dataclass(frozen=True)
class SweepResult:
    """Envelopes of a sweep up and down (SI): for each direction, the instantaneous frequency
    [Hz] at the middle of each period and the largest abs(x) [m] over it with and without the
    damper; ``peak``/``baseline_peak`` the largest of each direction; ``steady`` the steady
    curve at the sweep's amplitude (:func:`steady_curve`), or None."""

    up: dict[str, np.ndarray]
    down: dict[str, np.ndarray]
    steady: SteadyCurve | None = None

    def as_dict(self) -> dict[str, Any]:
        """The JSON of ``symimpact sweep-sine --json`` (SI)."""
        out: dict[str, Any] = {}
        for name, d in (("up", self.up), ("down", self.down)):
            out[name] = {
                "peak": float(np.max(d["envelope"])),
                "peak_frequency": float(d["frequency"][np.argmax(d["envelope"])]),
                "baseline_peak": float(np.max(d["baseline"])),
                "baseline_peak_frequency": float(d["frequency"][np.argmax(d["baseline"])]),
                "envelope": [
                    {"frequency": float(f), "envelope": float(a), "baseline": float(b)}
                    for f, a, b in zip(d["frequency"], d["envelope"], d["baseline"], strict=True)
                ],
            }
        if self.steady is not None:
            c = self.steady
            out["steady"] = {
                "peak": c.peak,
                "peak_frequency": c.peak_frequency,
                "stable": [
                    {"frequency": float(f), "amplitude": float(a), "branch": int(b)}
                    for f, a, b in c.stable
                ],
                "no_impact": [
                    {"frequency": float(f), "amplitude": float(a)} for f, a in c.no_impact
                ],
            }
        return out


def sweep_estimate(
    system: ImpactSystem, amplitude: Any, f_low: Any, f_high: Any, rate: Any, dt: Any, *,
    e: Any, law: str = "linear", kind: str = "force", chatter: Any = CHATTER,
    participation: Any = 1.0,
) -> Estimate:  # fmt: skip
    """The time of :func:`sweep_response`'s two sweeps (not its steady curve) on this machine:
    pieces of the sweep up from its start and from where it crosses the primary's natural
    frequency (:func:`~symimpact.forced.loads.record_cost.record_estimate`), the time of drawing it
    and of its envelopes."""
    f_low = positive_float("f_low", f_low, "Hz")
    f_high = positive_float("f_high", f_high, "Hz")
    rate = positive_float("rate", rate)
    start = time.perf_counter()
    record = sweep_record(amplitude, f_low, f_high, rate, dt, law, kind)
    freq = sweep_frequency(record.times, f_low, f_high, rate, law)
    drawn = time.perf_counter() - start
    # pieces from the start and from half a piece before the primary's natural frequency
    crossing = int(np.searchsorted(freq, system.omega_n / (2.0 * np.pi)))
    runs = record_estimate(system, record, 2, e=restitution_or_law(e), chatter=chatter,
                           starts=(0, crossing - PIECE_SAMPLES // 2),
                           participation=participation)  # fmt: skip
    # the envelopes, timed on the primary's response (as long as the damper's)
    alone = primary_response(system, record, participation=participation)
    start = time.perf_counter()
    envelope(alone.displacement, freq, record.dt, alone.velocity, np.zeros(0))
    return runs.plus(2 * drawn + 4 * (time.perf_counter() - start))


def sweep_response(
    system: ImpactSystem, amplitude: Any, f_low: Any, f_high: Any, rate: Any, dt: Any, *,
    e: Any, law: str = "linear", kind: str = "force", chatter: Any = CHATTER,
    steady: bool = False, participation: Any = 1.0,
) -> SweepResult:  # fmt: skip
    """Sweeps of ``amplitude`` [N, or m/s² for a base acceleration] from ``f_low`` to ``f_high``
    [Hz] and back down (two runs from rest), ``rate`` in Hz/s (``law`` "linear") or octaves a
    minute ("log"), sampled every ``dt`` [s]; rigid impacts with ``e`` (Eq. F2; the flight
    Eq. F8 on each interval of the record), or the compliant law of a
    :class:`~symimpact.forced.contact_law.CompliantContact`; with ``steady``, the steady curve of ``frf`` at the
    same amplitude over the band beside them (:func:`steady_curve`).  ``participation``: Γ of
    the primary in a base sweep (:func:`~symimpact.forced.loads.record_response.damper_response`),
    the steady curve's too."""
    gamma = checks.bounded("participation", participation)
    f_low = positive_float("f_low", f_low, "Hz")
    f_high = positive_float("f_high", f_high, "Hz")
    rate = positive_float("rate", rate)
    out = {}
    for name, (fa, fb) in (("up", (f_low, f_high)), ("down", (f_high, f_low))):
        record = sweep_record(amplitude, fa, fb, rate, dt, law, kind)
        freq = sweep_frequency(record.times, fa, fb, rate, law)
        ours = damper_response(system, record, e=e, chatter=chatter, participation=gamma)
        alone = primary_response(system, record, participation=gamma)
        f, a = envelope(ours.displacement, freq, record.dt, ours.velocity, ours.impact_times)
        _, b = envelope(alone.displacement, freq, record.dt, alone.velocity)
        out[name] = {"frequency": f, "envelope": a, "baseline": b}
    curve = (steady_curve(system, amplitude, f_low, f_high, e=e, kind=kind, participation=gamma)
             if steady else None)  # fmt: skip
    return SweepResult(out["up"], out["down"], curve)
