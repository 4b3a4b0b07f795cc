"""Loads that machines and buildings see, as sampled records: band-limited random vibration of a
given one-sided PSD, shocks (half-sine, haversine, terminal-peak sawtooth) and sine sweeps
(linear or logarithmic).  Step 16 (Eq. F8) makes the primary's flight exact for a record joined
by straight lines between its samples (:mod:`symimpact.forced.loads.record_flight`).

A record is a force on the main mass [N] or a base acceleration [m/s²] (``kind``), sampled every
``dt`` from t = 0.  Random records are drawn by the spectral representation: cosines at the
frequencies k/T of the record's duration T inside the band, amplitudes √(2·S(fₖ)/T) (so that
their variance is the PSD's integral over the band, Σ S(fₖ)·Δf with Δf = 1/T), phases uniform on
[0, 2π) from NumPy's PCG64 generator seeded by ``seed`` — the same seed gives the same record on
any machine.  With many cosines the values are Gaussian (central limit); the record is periodic
with period T.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import ParameterError
from ...model import checks
from ...model.units import positive_float, si_float

#: What a record's values are: a force on the main mass [N] or the base's acceleration [m/s²].
KINDS = {"force": "N", "base-acceleration": "m/s^2"}
#: Samples a period at the band's top frequency at least: linear interpolation between samples
#: then keeps a cosine's amplitude to (π/10)²/6 ≈ 1.6 % at worst, far less below the top.
SAMPLES_PER_PERIOD = 10
#: The largest record accepted, in samples.
MAX_SAMPLES = 50_000_000
#: A sweep lasts at least this many periods of its lowest frequency (fewer is a transient, with
#: no envelope to read).
SWEEP_PERIODS = 4


@dataclass(frozen=True)
class Record:
    """A sampled load: ``values`` at t = 0, dt, 2dt, … [N or m/s², see ``kind``]."""

    values: np.ndarray
    dt: float
    kind: str = "force"

    @property
    def times(self) -> np.ndarray:
        """The sample times [s]."""
        return self.dt * np.arange(len(self.values))

    @property
    def duration(self) -> float:
        """From the first sample to the last [s]."""
        return self.dt * (len(self.values) - 1)

    @property
    def unit(self) -> str:
        """The values' SI unit."""
        return KINDS[self.kind]


def _kind(kind: Any) -> str:
    return checks.choice("kind", kind, tuple(KINDS))


def _samples(duration: float, dt: float) -> int:
    n = round(duration / dt)
    if abs(n * dt - duration) > 1e-9 * duration:
        raise ParameterError("dt", f"must divide the duration {duration:g} s, got {dt:g} s")
    if n + 1 > MAX_SAMPLES:
        raise ParameterError("dt", f"gives {n + 1:,} samples, more than {MAX_SAMPLES:,}")
    return n


def _band(band: Any) -> tuple[float, float]:
    """(f₁, f₂) [Hz] with 0 ≤ f₁ < f₂: numbers in Hz, or quantities of any frequency unit."""
    f1, f2 = checks.bounds("band", band, "Hz")
    if f1 < 0:
        raise ParameterError("band", f"must be frequencies ≥ 0 Hz, got {f1:g}")
    return f1, f2


def random_record(
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    duration: Any,
    dt: Any,
    seed: int,
    kind: str = "force",
) -> Record:
    """A band-limited random record of the one-sided PSD ``psd`` [unit²/Hz]: a constant S₀ (flat
    between the band's edges) or a function of frequency [Hz]; ``band`` (f₁, f₂) [Hz],
    ``duration`` T [s], ``dt`` [s] (at least :data:`SAMPLES_PER_PERIOD` samples a period at f₂),
    ``seed`` a whole number.  The spectral representation (module docstring): values
    Σ √(2S(fₖ)/T)/g(fₖ) cos(2πfₖt + φₖ) over fₖ = k/T in the band, summed exactly at the samples
    by one inverse real FFT, g the gain of the straight lines between samples
    (:func:`interpolation_gain`): the load the flights integrate, those lines, then holds each
    line at √(2S(fₖ)/T), its mean square in the band Σ S(fₖ)/T, the PSD's integral over the
    band as a sum of width 1/T (the samples' own mean square is Σ S(fₖ)/(T g(fₖ)²))."""
    kind = _kind(kind)
    f1, f2 = _band(band)
    T = positive_float("duration", duration, "s")
    dt = positive_float("dt", dt, "s")
    seed = checks.whole_number("seed", seed, 0, 2**63 - 1)
    if dt * f2 * SAMPLES_PER_PERIOD > 1.0 + 1e-12:
        raise ParameterError(
            "dt",
            f"must resolve the band's top, {f2:g} Hz, with {SAMPLES_PER_PERIOD} samples a period "
            f"(dt ≤ {1 / (SAMPLES_PER_PERIOD * f2):.4g} s), got {dt:g} s",
        )
    n = _samples(T, dt)
    k = np.arange(math.ceil(f1 * T - 1e-9), math.floor(f2 * T + 1e-9) + 1)
    k = k[k > 0]
    if len(k) == 0:
        raise ParameterError("duration", "holds no frequency k/T inside the band; make it longer")
    f = k / T
    if callable(psd):
        S = np.asarray(psd(f), dtype=float)
        if S.shape != f.shape or not np.all(np.isfinite(S)) or np.any(S < 0):
            raise ParameterError("psd", "must give a finite value ≥ 0 at every frequency")
    else:
        S = np.full(f.shape, si_float("psd", psd))
        if S[0] < 0:
            raise ParameterError("psd", f"must be ≥ 0, got {S[0]:g}")
    phases = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, len(k))
    # each line at its full amplitude in the straight lines between samples (interpolation_gain)
    amplitudes = np.sqrt(2.0 * S / T) / interpolation_gain(f, dt)
    # irfft of X over n samples: x_j = (1/n)·Σ (X_k e^{2πi kj/n} + c.c.), so X_k = n/2·A e^{iφ}
    spectrum = np.zeros(n // 2 + 1, dtype=complex)  # k ≤ f₂T ≤ n/10: inside it
    spectrum[k] = 0.5 * n * amplitudes * np.exp(1j * phases)
    values = np.fft.irfft(spectrum, n)
    return Record(np.append(values, values[0]), dt, kind)  # periodic: the end is the start


#: Shock pulse shapes: value over the pulse as a function of s = t / duration in [0, 1].
SHAPES: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "half-sine": lambda s: np.sin(np.pi * s),
    "haversine": lambda s: 0.5 * (1.0 - np.cos(2.0 * np.pi * s)),
    "sawtooth": lambda s: s,  # terminal peak: rises linearly, drops to zero at the end
}


def shock_record(
    shape: str, peak: Any, pulse: Any, duration: Any, dt: Any, kind: str = "force"
) -> Record:
    """A shock: ``shape`` ("half-sine", "haversine" or "sawtooth", the terminal-peak sawtooth)
    of height ``peak`` [N or m/s²] lasting ``pulse`` [s] from t = 0, then zero up to
    ``duration`` [s] (the free vibration after the pulse: the residual response), sampled
    every ``dt`` [s] (at least 20 samples in the pulse).  The sawtooth's drop is a sample wide."""
    kind = _kind(kind)
    checks.choice("shape", shape, tuple(SHAPES))
    height = si_float("peak", peak)
    td = positive_float("pulse", pulse, "s")
    T = positive_float("duration", duration, "s")
    dt = positive_float("dt", dt, "s")
    if T < td:
        raise ParameterError("duration", f"must cover the pulse, {td:g} s, got {T:g} s")
    if td / dt < 20 - 1e-9:
        raise ParameterError("dt", f"must put at least 20 samples in the pulse, got {td / dt:.3g}")
    n = _samples(T, dt)
    t = dt * np.arange(n + 1)
    s = t / td
    inside = s <= 1.0 + 1e-12
    values = np.where(inside, height * SHAPES[shape](np.clip(s, 0.0, 1.0)), 0.0)
    return Record(values, dt, kind)


def followed_by_rest(record: Record, duration: Any) -> Record:
    """``record`` followed by zeros up to ``duration`` [s] from its start (at least its own
    length), at its sample interval: the free vibration after a shock, whose residual response a
    recorded shock of its own length would leave out (a 20 g, 11 ms half-sine sampled over
    50 ms had given a peak of 58 mm where the pulse followed by rest gives 132 mm).  A record
    whose last value is not 0 falls to 0 over one interval."""
    T = positive_float("duration", duration, "s")
    if T < record.duration * (1.0 - 1e-12):
        raise ParameterError(
            "duration", f"must cover the record, {record.duration:g} s, got {T:g} s"
        )
    n = max(round(T / record.dt) + 1, len(record.values))
    if n > MAX_SAMPLES:
        raise ParameterError("duration", f"gives {n:,} samples, more than {MAX_SAMPLES:,}")
    values = np.zeros(n)
    values[: len(record.values)] = record.values
    return Record(values, record.dt, record.kind)


def sweep_record(
    amplitude: Any, f_start: Any, f_end: Any, rate: Any, dt: Any, law: str = "linear",
    kind: str = "force",
) -> Record:  # fmt: skip
    """A sine sweep of ``amplitude`` [N or m/s²] from ``f_start`` to ``f_end`` [Hz] (up or down),
    ``law`` "linear" (``rate`` in Hz/s, f = f₀ + rate·t) or "log" (``rate`` in octaves a minute,
    f = f₀·2^(rate·t/60)), phase 2π∫f dt from zero; sampled every ``dt`` [s] (at least
    :data:`SAMPLES_PER_PERIOD` samples a period at the highest frequency), each sample divided by
    the gain of the straight lines between samples at the instantaneous frequency
    (:func:`interpolation_gain`), so the load the flights integrate holds the amplitude."""
    kind = _kind(kind)
    checks.choice("law", law, ("linear", "log"))
    A = si_float("amplitude", amplitude)
    fa = positive_float("f_start", f_start, "Hz")
    fb = positive_float("f_end", f_end, "Hz")
    r = positive_float("rate", rate)
    dt = positive_float("dt", dt, "s")
    if fa == fb:
        raise ParameterError("f_end", "must differ from f_start")
    if dt * max(fa, fb) * SAMPLES_PER_PERIOD > 1.0 + 1e-12:
        raise ParameterError(
            "dt", f"must give {SAMPLES_PER_PERIOD} samples a period at {max(fa, fb):g} Hz"
        )
    sign = 1.0 if fb > fa else -1.0
    c = sign * r / 60.0 * math.log(2.0)  # the log sweep: f = fa·e^{ct}
    T = abs(fb - fa) / r if law == "linear" else math.log(fb / fa) / c
    if T * min(fa, fb) < SWEEP_PERIODS:  # counted before anything is allocated
        raise ParameterError(
            "rate", f"sweeps the band in {T:.3g} s, {T * min(fa, fb):.3g} periods of its lowest "
            f"frequency: a sweep needs at least {SWEEP_PERIODS} (a slower rate)"
        )  # fmt: skip
    if T / dt + 1 > MAX_SAMPLES:
        raise ParameterError(
            "rate", f"sweeps the band in {T:.3g} s, {math.ceil(T / dt) + 1:,} samples of {dt:g} s: "
            f"more than {MAX_SAMPLES:,} (a faster rate, or a coarser --dt)"
        )  # fmt: skip
    n = math.ceil(T / dt)
    t = dt * np.arange(n + 1)
    if law == "linear":
        phase = 2.0 * np.pi * (fa * t + 0.5 * sign * r * t**2)
    else:
        phase = 2.0 * np.pi * fa * np.expm1(c * t) / c
    f = sweep_frequency(t, fa, fb, r, law)
    return Record(A * np.sin(phase) / interpolation_gain(f, dt), dt, kind)


def interpolation_gain(f: Any, dt: float) -> Any:
    """The gain sinc²(f·dt) = (sin(πf·dt)/(πf·dt))² of straight lines joining samples taken every
    ``dt`` [s] on a sine of frequency ``f`` [Hz]: the lines' component at f (the triangle
    kernel's Fourier transform; the rest lies at the images k/dt ± f, above the band).  The
    loads divide their samples by it, so the load the flights integrate (Eq. F8, straight lines
    between samples) carries each frequency at its full amplitude: without it a sine sampled 20
    times a period lost (πf·dt)²/3 = 0.8 % of its amplitude, and a slow sweep stalled 0.5 %
    below the steady peak."""
    return np.sinc(np.asarray(f, dtype=float) * dt) ** 2


def sweep_frequency(record_times: np.ndarray, f_start: float, f_end: float, rate: float,
                    law: str = "linear") -> np.ndarray:  # fmt: skip
    """The instantaneous frequency [Hz] of :func:`sweep_record`'s sweep at ``record_times`` [s]."""
    sign = 1.0 if f_end > f_start else -1.0
    if law == "linear":
        return f_start + sign * rate * record_times
    return f_start * np.exp(sign * rate / 60.0 * math.log(2.0) * record_times)


@dataclass(frozen=True)
class KanaiTajimi:
    """The Kanai–Tajimi PSD of ground acceleration [(m/s²)²/Hz], called with frequencies [Hz]:
    white noise of level ``s0`` filtered by a ground layer of natural frequency ``f_g`` [Hz] and
    damping ratio ``zeta_g``, S(f) = s0·(1 + 4ζ²r²)/((1 − r²)² + 4ζ²r²) with r = f/f_g (the
    absolute acceleration of the layer's oscillator under white noise at its base).  Build it
    with :func:`kanai_tajimi`, which checks the values."""

    s0: float
    f_g: float
    zeta_g: float

    def __call__(self, f: np.ndarray) -> np.ndarray:
        r2 = (np.asarray(f, dtype=float) / self.f_g) ** 2
        z2 = 4.0 * self.zeta_g * self.zeta_g
        return self.s0 * (1.0 + z2 * r2) / ((1.0 - r2) ** 2 + z2 * r2)


def kanai_tajimi(s0: Any, f_g: Any, zeta_g: Any) -> KanaiTajimi:
    """:class:`KanaiTajimi` of level ``s0`` [(m/s²)²/Hz], ground frequency ``f_g`` [Hz] and
    damping ratio ``zeta_g`` (> 0), checked."""
    s0 = si_float("psd", s0)
    if s0 < 0:
        raise ParameterError("psd", f"must be ≥ 0, got {s0:g}")
    fg = positive_float("f_g", f_g, "Hz")
    zg = checks.bounded("zeta_g", zeta_g, 0.0, None)
    if zg <= 0:
        raise ParameterError("zeta_g", "must be above 0")
    return KanaiTajimi(s0, fg, zg)


def unit_columns(
    path: Any, name: str, example: tuple[str, str]
) -> tuple[tuple[str, str], np.ndarray]:
    """((unit, unit), rows) of a CSV file of two numeric columns whose headers give their units
    in brackets (``example``: two such headers, for the refusal); refused naming ``name``."""
    import csv
    import re

    from ...io import input_text

    try:
        rows = list(csv.reader(input_text(path, name).splitlines()))
    except csv.Error as err:
        raise ParameterError(name, f"{str(path)!r} is not a CSV table ({err})") from None
    if len(rows) < 3 or len(rows[0]) != 2:
        raise ParameterError(name, "needs a header of two columns and at least two rows")
    units = [re.search(r"\[(.+)\]", h) for h in rows[0]]
    if not all(units):
        raise ParameterError(name, "each column's header must give its unit in brackets, "
                             f"e.g. '{example[0]}', '{example[1]}'")  # fmt: skip
    try:
        data = np.array([[float(a), float(b)] for a, b in rows[1:] if a.strip()])
    except ValueError:
        raise ParameterError(name, "holds a value that is not a number") from None
    if not np.all(np.isfinite(data)):
        raise ParameterError(name, "holds a value that is not finite")
    return (units[0].group(1).strip(), units[1].group(1).strip()), data


def read_record(path: str | Any, kind: str | None = None) -> Record:
    """A recorded time history from a CSV file of two columns, time and value, each header with
    its unit in brackets ("time [s]", "acceleration [g]" or "force [N]"): a force [N] or a base
    acceleration [m/s², "g" standard gravity], told by the unit (or ``kind``).  The samples must
    start at t = 0 and be equally spaced (to 1e-6 of the interval), as Eq. F8's recurrence
    takes them."""
    (t_unit, v_unit), data = unit_columns(path, "record", ("time [s]", "acceleration [g]"))
    t = data[:, 0] * si_float("record", f"1 {t_unit}", "s")
    if kind is None:
        try:
            scale, kind = si_float("record", f"1 {v_unit}", "N"), "force"
        except ParameterError:
            scale, kind = si_float("record", f"1 {v_unit}", "m/s^2"), "base-acceleration"
    else:
        kind = _kind(kind)
        scale = si_float("record", f"1 {v_unit}", KINDS[kind])
    dts = np.diff(t)
    if np.any(dts <= 0):
        raise ParameterError("record", "time must increase from row to row")
    if abs(t[0]) > 1e-9 * dts[0]:
        raise ParameterError("record", f"must start at t = 0, starts at {t[0]:g} s")
    dt = float(np.mean(dts))
    if np.max(np.abs(dts - dt)) > 1e-6 * dt:
        raise ParameterError("record", f"samples must be equally spaced; intervals from "
                             f"{dts.min():g} to {dts.max():g} s")  # fmt: skip
    return Record(data[:, 1] * scale, dt, kind)


def record_participation(record: Record, participation: Any) -> float:
    """The participation Γ of the primary in the base's motion, checked: a finite number, other
    than 1 only for a base record (a force on the primary has no participation to carry); see
    :func:`~symimpact.forced.loads.record_response.damper_response`."""
    gamma = checks.bounded("participation", participation)
    if gamma != 1.0 and record.kind != "base-acceleration":
        raise ParameterError(
            "participation", f"is how the base's motion drives the primary; the record is a "
            f"{record.kind}, not a base acceleration: leave it at 1"
        )  # fmt: skip
    return gamma
