"""Sine sweeps through the band on the primary with its impact damper: the envelope of the
displacement against the sweep's instantaneous frequency (the largest abs(x) over each of its
periods), swept up and down, with and without the damper — the run-up a machine makes through
its resonance, beside the steady curve of ``frf``.  Each sweep is a record of
:func:`symimpact.forced.loads.sweep_record`; the response is exact for it (Eq. F8 on each
interval, Eq. F2 at each impact).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise
from typing import Any

import numpy as np

from ..system import ImpactSystem
from ..units import positive_float
from .loads import sweep_frequency, sweep_record
from .record_flight import primary_response
from .record_response import damper_response
from .simulation import CHATTER


def envelope(
    displacement: np.ndarray, frequency: np.ndarray, dt: float
) -> tuple[np.ndarray, np.ndarray]:
    """(instantaneous frequency [Hz], largest abs(x) [m]) over each period of a sweep whose
    instantaneous frequency at the samples is ``frequency``: the periods follow one another,
    each 1/f long at its start."""
    starts = [0]
    t = 0.0
    n = len(displacement)
    while True:
        t += 1.0 / frequency[min(starts[-1], n - 1)]
        i = round(t / dt)
        if i >= n:
            break
        starts.append(i)
    centres, peaks = [], []
    for a, b in pairwise(starts):
        centres.append(frequency[(a + b) // 2])
        peaks.append(np.max(np.abs(displacement[a : b + 1])))
    return np.array(centres), np.array(peaks)


@dataclass(frozen=True)
class SweepResult:
    """Envelopes of a sweep up and down (SI): for each direction, the instantaneous frequency
    [Hz] at the middle of each period and the largest abs(x) [m] over it with and without the
    damper; ``peak``/``baseline_peak`` the largest of each direction."""

    up: dict[str, np.ndarray]
    down: dict[str, np.ndarray]

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
        return out


def sweep_response(
    system: ImpactSystem, amplitude: Any, f_low: Any, f_high: Any, rate: Any, dt: Any, *,
    e: Any, law: str = "linear", kind: str = "force", chatter: Any = CHATTER,
) -> SweepResult:  # fmt: skip
    """Sweeps of ``amplitude`` [N, or m/s² for a base acceleration] from ``f_low`` to ``f_high``
    [Hz] and back down (two runs from rest), ``rate`` in Hz/s (``law`` "linear") or octaves a
    minute ("log"), sampled every ``dt`` [s]; rigid impacts with ``e`` (Eq. F2; the flight
    Eq. F8 on each interval of the record)."""
    f_low = positive_float("f_low", f_low, "Hz")
    f_high = positive_float("f_high", f_high, "Hz")
    rate = positive_float("rate", rate)
    out = {}
    for name, (fa, fb) in (("up", (f_low, f_high)), ("down", (f_high, f_low))):
        record = sweep_record(amplitude, fa, fb, rate, dt, law, kind)
        freq = sweep_frequency(record.times, fa, fb, rate, law)
        ours = damper_response(system, record, e=e, chatter=chatter)
        alone = primary_response(system, record)
        f, a = envelope(ours.displacement, freq, record.dt)
        _, b = envelope(alone.displacement, freq, record.dt)
        out[name] = {"frequency": f, "envelope": a, "baseline": b}
    return SweepResult(out["up"], out["down"])
