"""Random vibration of the primary with its impact damper: the statistics designers report.

Each realisation is one record of :func:`symimpact.forced.loads.records.random_record` (the spectral
representation, its own seed), run with the damper (:func:`damper_response`) and without it
(:func:`primary_response`, Eq. F8 alone) on the *same* record, so the reduction is a paired
comparison.  Statistics are taken after ``settle`` seconds (the start-up transient left out).

- RMS of the main mass's displacement (relative to the base under a base acceleration), velocity,
  absolute acceleration between impacts and force into the base, the mean over realisations with
  a 95 % confidence interval from Student's t on the logarithms of the realisations' values
  (they are independent: independent phases; the interval stays positive);
- the reduction 1 − RMS/RMS_alone, per realisation, with its interval likewise;
- the displacement's PSD by Welch's method (Hann windows of ``segment`` seconds, half overlap;
  the resolution 1/segment Hz), averaged over realisations, with and without the damper.

The seed of realisation i is drawn from ``numpy.random.SeedSequence([seed, i])``: the same seed
gives the same records whatever the order in which realisations are run.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import signal, stats

from ...errors import ParameterError
from ...model import checks
from ...model.structure import Structure
from ...model.system import ImpactSystem
from ...model.units import positive_float
from ..contact_law import restitution_or_law
from ..simulation import CHATTER
from .record_cost import Estimate, record_estimate
from .record_flight import primary_response
from .record_response import damper_response
from .records import Record, random_record

#: The responses whose statistics are reported (attribute names of the responses).
KEYS = ("displacement", "velocity", "acceleration", "base_force")
#: Their SI units.
UNITS = {"displacement": "m", "velocity": "m/s", "acceleration": "m/s^2", "base_force": "N"}
#: The settling time's default: the primary's free decay to 1e-3 of its amplitude, ln(1000)/(ζω_n).
SETTLE_DECAY = 1e-3


def realisation_seed(seed: int, i: int) -> int:
    """The seed of realisation ``i`` of an ensemble seeded by ``seed`` (independent of the order
    and the executor that runs them)."""
    return int(np.random.SeedSequence([seed, i]).generate_state(1, np.uint64)[0]) >> 1


def default_settle(system: ImpactSystem) -> float:
    """ln(1/SETTLE_DECAY)/(ζω_n) [s]: the primary alone forgets its start to 1e-3 by then."""
    if system.zeta <= 0:
        raise ParameterError("settle", "an undamped primary never settles: give --settle")
    return math.log(1.0 / SETTLE_DECAY) / (system.zeta * system.omega_n)


@dataclass(frozen=True)
class RandomStatistics:
    """Statistics of an ensemble of random-vibration runs (SI; see the module docstring).

    ``rms``, ``baseline_rms``: {key: mean over realisations}; ``rms_ci95``, ``reduction_ci95``:
    {key: (lo, hi)}; ``reduction``: {key: mean of 1 − rms/baseline}; ``per_realisation``:
    {key: array of each realisation's RMS}, likewise ``baseline_per_realisation``;
    ``psd_frequency`` [Hz], ``psd`` and ``baseline_psd`` [m²/Hz] of the displacement;
    ``impacts_per_second``: the mean rate of impacts; ``peak``, ``baseline_peak``: {key: the
    largest abs(value) of each realisation (at the samples, after ``settle``)}, whose spread over
    the realisations is the peak's distribution over records of this duration."""

    rms: dict[str, float]
    rms_ci95: dict[str, tuple[float, float]]
    baseline_rms: dict[str, float]
    reduction: dict[str, float]
    reduction_ci95: dict[str, tuple[float, float]]
    per_realisation: dict[str, np.ndarray]
    baseline_per_realisation: dict[str, np.ndarray]
    psd_frequency: np.ndarray
    psd: np.ndarray
    baseline_psd: np.ndarray
    psd_resolution: float
    impacts_per_second: float
    peak: dict[str, np.ndarray]
    baseline_peak: dict[str, np.ndarray]
    realisations: int
    seed: int
    settle: float
    duration: float

    def as_dict(self) -> dict[str, Any]:
        """The JSON of ``symimpact random --json`` (SI)."""
        return {
            "rms": dict(self.rms),
            "rms_ci95": {k: list(v) for k, v in self.rms_ci95.items()},
            "baseline_rms": dict(self.baseline_rms),
            "reduction": dict(self.reduction),
            "reduction_ci95": {k: list(v) for k, v in self.reduction_ci95.items()},
            "ci95": INTERVAL,
            "impacts_per_second": self.impacts_per_second,
            "peak": {k: _spread(v) for k, v in self.peak.items()},
            "baseline_peak": {k: _spread(v) for k, v in self.baseline_peak.items()},
            "psd_resolution": self.psd_resolution,
            "realisations": self.realisations,
            "seed": self.seed,
            "settle": self.settle,
            "duration": self.duration,
        }


def _spread(values: np.ndarray) -> dict[str, float]:
    """Mean, median and largest of the realisations' ``values`` (a peak's distribution)."""
    return {"mean": float(np.mean(values)), "median": float(np.median(values)),
            "max": float(np.max(values))}  # fmt: skip


#: What the intervals are, in the JSON beside them.
INTERVAL = (
    "95 % confidence interval of the mean over the realisations: the spread of the simulated "
    "records (how far the mean of these records may lie from that of infinitely many), the mean "
    "times e^(±h) with h Student's t half-width on the values' logarithms (RMS) or on those of "
    "1 − reduction; not a bound on one record's RMS"
)
#: The most realisations an ensemble runs, in one process or as a map (the command line's cap
#: too): 1e6 records of 100 s are some 1e8 s of simulated time.
MAX_REALISATIONS = 1_000_000
#: Below this many realisations a warning says that the intervals are wide and rest on few
#: records (Student's t with 7 degrees of freedom is 2.36 standard errors, 20 % wider than 1.96).
FEW_REALISATIONS = 8


def _interval(values: np.ndarray, ceiling: float | None = None) -> tuple[float, float]:
    """95 % confidence interval of the mean of independent positive ``values`` (an RMS), or of
    values below ``ceiling`` (a reduction 1 − RMS/RMS₀ < 1): the mean times e^(±h), h the
    half-width of Student's t on the logarithms of the values (of ``ceiling − value``), so the
    interval never leaves the quantity's domain (an RMS interval of 2 realisations had reached −0.0066 m).  For a small
    spread it is the ordinary t-interval of the mean to first order in the coefficient of
    variation.  It measures the spread of the simulated records: how far the mean of these
    realisations may lie from the mean of infinitely many."""
    n = len(values)
    v = np.asarray(values, dtype=float) if ceiling is None else ceiling - np.asarray(values)
    if n < 2 or not np.all(v > 0):
        return (math.nan, math.nan)
    half = float(stats.t.ppf(0.975, n - 1) * np.std(np.log(v), ddof=1) / math.sqrt(n))
    mean = float(np.mean(v))  # the mean scaled by e^(∓half): a factor, never a sign change
    lo, hi = mean * math.exp(-half), mean * math.exp(half)
    return (lo, hi) if ceiling is None else (ceiling - hi, ceiling - lo)


def _settle(system: ImpactSystem, settle: Any) -> float:
    """The settling time [s]: ``settle`` checked, or :func:`default_settle` where it is None."""
    if settle is None:
        return default_settle(system)
    return checks.bounded("settle", settle, 0.0, unit="s")


def modal_random_rms(
    structure: Structure,
    point: str,
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    modes: Any = None,
) -> dict[str, float]:
    """The RMS of the bare ``structure``'s response at ``point`` to a stationary base
    acceleration of one-sided PSD ``psd`` [(m/s²)²/Hz, a constant or a function of f in Hz] over
    ``band`` (f₁, f₂) [Hz], in closed form: σ² = ∫|H(f)|²S(f) df, with T(Ω) the base
    transmissibility (Eq. F7 in the frequency domain, each mode with its participation Γᵢ:
    :meth:`~symimpact.model.structure.Structure.base_transmissibility`) and H = (T − 1)/Ω² for
    the displacement relative to the supports [m], (T − 1)/Ω for its velocity [m/s] and T for
    the absolute acceleration [m/s²].  ``modes``: the mode numbers kept (default all), e.g.
    ``(1,)`` for what a one-mode reduction of mode 1 describes.  The integral by adaptive
    Gauss–Kronrod with the natural frequencies in the band as break points (relative error
    1e-10)."""
    from dataclasses import replace

    from scipy.integrate import quad

    checks.instance("structure", structure, Structure, "a Structure")
    point = structure._point(point)
    lo, hi = checks.bounds("band", band, "Hz")
    if lo <= 0.0:
        raise ParameterError("band", f"must start above 0 Hz, got {lo:g}")
    kept = structure.modes if modes is None else tuple(
        m for m in structure.modes if m.number in {int(k) for k in modes}
    )  # fmt: skip
    if not kept:
        raise ParameterError("modes", f"no mode {tuple(modes)} in the structure")
    one = replace(structure, modes=kept)

    def level(f: float) -> float:
        return float(np.asarray(psd(np.array([f])))[0]) if callable(psd) else float(psd)

    gains = {
        "displacement": lambda W, T: abs(T - 1.0) / (W * W),
        "velocity": lambda W, T: abs(T - 1.0) / W,
        "acceleration": lambda W, T: abs(T),
    }
    breaks = [m.frequency for m in kept if lo < m.frequency < hi]
    out = {}
    for key, gain in gains.items():

        def integrand(f: float, gain=gain) -> float:
            W = 2.0 * math.pi * f
            return gain(W, complex(one.base_transmissibility(point, W))) ** 2 * level(f)

        value = quad(integrand, lo, hi, points=breaks or None, epsabs=0.0, epsrel=1e-10,
                     limit=2000)[0]  # fmt: skip
        out[key] = math.sqrt(value)
    return out


def realisation_record(
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    duration: float,
    dt: float,
    seed: int,
    i: int,
    *,
    settle: float,
    kind: str = "force",
) -> Record:
    """The load of realisation ``i``: ``settle`` [s] (to the sample at or after it) and
    ``duration`` [s] of :func:`~symimpact.forced.loads.records.random_record`."""
    n_settle = math.ceil(settle / dt - 1e-9)
    return random_record(psd, band, (n_settle + round(duration / dt)) * dt, dt,
                         realisation_seed(seed, i), kind)  # fmt: skip


def ensemble_estimate(
    system: ImpactSystem,
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    duration: float,
    dt: float,
    *,
    e: Any,
    realisations: int,
    seed: int = 0,
    settle: Any = None,
    kind: str = "force",
    segment: Any = None,
    welch: bool = True,
    chatter: Any = CHATTER,
    participation: Any = 1.0,
) -> Estimate:
    """The time an ensemble of ``realisations`` takes on this machine, from a piece of the
    first realisation (:func:`~symimpact.forced.loads.record_cost.record_estimate`), with the time
    of drawing its record and of its statistics (``welch``: its PSD too); the arguments those of
    :func:`random_statistics`."""
    settle = _settle(system, settle)
    n = checks.whole_number("realisations", realisations, 1, MAX_REALISATIONS)
    segment = None if segment is None else positive_float("segment", segment, "s")
    start = time.perf_counter()
    record = realisation_record(psd, band, duration, dt, seed, 0, settle=settle, kind=kind)
    drawn = time.perf_counter() - start
    runs = record_estimate(system, record, n, e=restitution_or_law(e), chatter=chatter,
                           participation=participation)  # fmt: skip
    # the statistics of a realisation, timed on the primary's response (as long as the damper's)
    alone = primary_response(system, record, participation=participation)
    start = time.perf_counter()
    _statistics(alone, alone, np.empty(0), settle, dt, duration, segment, welch)
    return runs.plus(n * (drawn + time.perf_counter() - start))


def realisation(
    system: ImpactSystem,
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    duration: float,
    dt: float,
    seed: int,
    i: int,
    *,
    e: Any,
    settle: float,
    kind: str = "force",
    segment: float | None = None,
    chatter: float = CHATTER,
    welch: bool = True,
    participation: float = 1.0,
) -> dict[str, Any]:
    """One realisation: {"rms": {key: value}, "baseline": {key: value}, "impacts": n,
    "psd": (f, with, without)} over the record after ``settle`` (no "psd" without ``welch``);
    ``participation``: Γ of the primary in a base record (:func:`damper_response`)."""
    record = realisation_record(psd, band, duration, dt, seed, i, settle=settle, kind=kind)
    ours = damper_response(system, record, e=e, chatter=chatter, participation=participation)
    alone = primary_response(system, record, participation=participation)
    return _statistics(ours, alone, ours.impact_times, settle, dt, duration, segment, welch)


def _statistics(
    ours: Any, alone: Any, impact_times: np.ndarray, settle: float, dt: float, duration: float,
    segment: float | None, welch: bool,
) -> dict[str, Any]:  # fmt: skip
    """:func:`realisation`'s dict from the responses with the damper and without it."""
    n_settle = math.ceil(settle / dt - 1e-9)  # the settling time, to the sample at or after it
    keep = np.arange(len(ours.displacement)) >= n_settle
    out: dict[str, Any] = {"rms": {}, "baseline": {}, "peak": {}, "baseline_peak": {}}
    for key in KEYS:
        out["rms"][key] = float(np.sqrt(np.mean(getattr(ours, key)[keep] ** 2)))
        out["peak"][key] = float(np.max(np.abs(getattr(ours, key)[keep])))
        out["baseline_peak"][key] = float(np.max(np.abs(getattr(alone, key)[keep])))
        out["baseline"][key] = float(np.sqrt(np.mean(getattr(alone, key)[keep] ** 2)))
    out["impacts"] = int(np.sum(impact_times >= n_settle * dt))
    if not welch:
        return out
    nper = max(8, round((segment or duration / 8) / dt))
    f, p_with = signal.welch(ours.displacement[keep], fs=1.0 / dt, nperseg=min(nper, keep.sum()))
    _, p_alone = signal.welch(alone.displacement[keep], fs=1.0 / dt, nperseg=min(nper, keep.sum()))
    out["psd"] = (f, p_with, p_alone)
    return out


def random_statistics(
    system: ImpactSystem,
    psd: float | Callable[[np.ndarray], np.ndarray],
    band: tuple[Any, Any],
    duration: Any,
    dt: Any,
    *,
    e: Any,
    realisations: Any = 8,
    seed: Any = 0,
    settle: Any = None,
    kind: str = "force",
    segment: Any = None,
    chatter: Any = CHATTER,
    participation: Any = 1.0,
) -> RandomStatistics:
    """Statistics of ``realisations`` runs of ``duration`` [s] each (after ``settle`` [s], by
    default :func:`default_settle`) under band-limited random loads of one-sided PSD ``psd``
    [N²/Hz for a force, (m/s²)²/Hz for a base acceleration] over ``band`` (f₁, f₂) [Hz], sampled
    every ``dt`` [s]; rigid impacts with ``e`` (Eq. F2), or the compliant law ``e`` names (a
    :class:`~symimpact.forced.contact_law.CompliantContact`), the flight Eq. F8.  ``segment`` [s]:
    Welch's segment length (default an eighth of ``duration``).  ``participation``: Γ, the
    primary's participation in a base record (1 for a primary on its base; Γᵢφᵢ(a) for mode i
    of a structure reduced to its point a, Eq. F7; :func:`damper_response`)."""
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    T = positive_float("duration", duration, "s")
    dt = positive_float("dt", dt, "s")
    n = checks.whole_number("realisations", realisations, 1, MAX_REALISATIONS)
    seed = checks.whole_number("seed", seed, 0, 2**63 - 1)
    e = restitution_or_law(e)
    settle = _settle(system, settle)
    seg = None if segment is None else positive_float("segment", segment, "s")
    gamma = checks.bounded("participation", participation)
    if seg is not None and seg > T:
        raise ParameterError("segment", f"must fit in the duration, {T:g} s, got {seg:g} s")
    runs = [
        realisation(system, psd, band, T, dt, seed, i, e=e, settle=settle, kind=kind,
                    segment=seg, chatter=chatter, participation=gamma)
        for i in range(n)
    ]  # fmt: skip
    return combine(runs, seed=seed, settle=settle, duration=T)


def combine(
    runs: list[dict[str, Any]], *, seed: int, settle: float, duration: float
) -> RandomStatistics:
    """The ensemble's statistics from its realisations (:func:`realisation`'s dicts); fewer
    than :data:`FEW_REALISATIONS` are warned of."""
    if len(runs) < FEW_REALISATIONS:
        import warnings

        warnings.warn(
            f"{len(runs)} realisation{'s' if len(runs) != 1 else ''}: the 95 % intervals rest on "
            f"few records (give --realisations {FEW_REALISATIONS} or more for intervals a "
            "design can quote)",
            stacklevel=2,
        )
    per = {k: np.array([r["rms"][k] for r in runs]) for k in KEYS}
    base = {k: np.array([r["baseline"][k] for r in runs]) for k in KEYS}
    reduction = {k: 1.0 - per[k] / base[k] for k in KEYS}
    spectra = [r["psd"] for r in runs if "psd" in r]
    f = spectra[0][0] if spectra else np.zeros(0)
    return RandomStatistics(
        rms={k: float(np.mean(per[k])) for k in KEYS},
        rms_ci95={k: _interval(per[k]) for k in KEYS},
        baseline_rms={k: float(np.mean(base[k])) for k in KEYS},
        reduction={k: float(np.mean(reduction[k])) for k in KEYS},
        reduction_ci95={k: _interval(reduction[k], ceiling=1.0) for k in KEYS},
        per_realisation=per,
        baseline_per_realisation=base,
        psd_frequency=f,
        psd=np.mean([p[1] for p in spectra], axis=0) if spectra else np.zeros(0),
        baseline_psd=np.mean([p[2] for p in spectra], axis=0) if spectra else np.zeros(0),
        psd_resolution=float(f[1] - f[0]) if len(f) > 1 else math.nan,
        impacts_per_second=float(np.mean([r["impacts"] for r in runs]) / duration),
        peak={k: np.array([r.get("peak", {}).get(k, math.nan) for r in runs]) for k in KEYS},
        baseline_peak={
            k: np.array([r.get("baseline_peak", {}).get(k, math.nan) for r in runs]) for k in KEYS
        },
        realisations=len(runs),
        seed=seed,
        settle=settle,
        duration=duration,
    )
