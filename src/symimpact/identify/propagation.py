"""The identified parameters' uncertainty carried into the answer a designer reads: the peak of
the frequency-response curve over samples of the parameters.

The fit gives each parameter's value and their covariance (Gauss–Newton, at the optimum:
:mod:`symimpact.identify.least_squares`).  Here the parameters are drawn from that normal
distribution, each draw kept only inside the physics' bounds (0 ≤ e ≤ 1, 0 < ζ < 1, d > 0:
a truncated normal, by rejection), and the whole curve (:func:`symimpact.forced.orbits.frf.
frequency_response`) is computed at each draw: the peak is not a smooth function of the
parameters (a branch appears, a window closes), so its spread is sampled, not linearised.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..model.system import ImpactSystem

#: The parameters a draw may vary, and their bounds (the physics').
VARIED = {"e": (0.0, 1.0), "zeta": (0.0, 1.0), "gap": (0.0, np.inf)}


@dataclass(frozen=True)
class PeakSpread:
    """The peak over ``draws`` (one row a draw of ``names``, SI): each draw's ``peaks`` [m] (NaN
    where its curve traced no stable motion), their median and the interval holding the middle
    95 % of them."""

    names: list[str]
    draws: np.ndarray
    peaks: np.ndarray
    seed: int

    @property
    def median(self) -> float:
        return float(np.nanmedian(self.peaks))

    @property
    def ci95(self) -> tuple[float, float]:
        lo, hi = np.nanpercentile(self.peaks, [2.5, 97.5])
        return float(lo), float(hi)

    def as_dict(self) -> dict[str, Any]:
        """The JSON form (SI)."""
        return {"parameters": self.names, "seed": self.seed, "samples": int(self.peaks.size),
                "draws": self.draws.tolist(),
                "peaks": [None if np.isnan(p) else float(p) for p in self.peaks],
                "median": self.median, "ci95": list(self.ci95)}  # fmt: skip


def parameter_draws(names: list[str], values: Any, covariance: Any, n: int,
                    seed: int = 0) -> np.ndarray:  # fmt: skip
    """``n`` draws (n × k, SI) of the parameters ``names`` (of :data:`VARIED`) from the normal
    distribution of mean ``values`` and ``covariance``, each inside the bounds of
    :data:`VARIED` (rejection; refused if fewer than 1 in 100 draws are inside)."""
    for name in names:
        if name not in VARIED:
            raise ParameterError("propagate", f"varies {', '.join(VARIED)}, not {name!r}")
    values = np.asarray(values, float)
    cov = np.asarray(covariance, float)
    lo = np.array([VARIED[k][0] for k in names])
    hi = np.array([VARIED[k][1] for k in names])
    rng = np.random.default_rng(seed)
    kept: list[np.ndarray] = []
    for _ in range(100):
        batch = rng.multivariate_normal(values, cov, size=n, method="eigh")
        kept.extend(batch[np.all((batch > lo) & (batch < hi), axis=1)])
        if len(kept) >= n:
            return np.array(kept[:n])
    raise ParameterError("propagate", "fewer than 1 in 100 draws of the parameters lie inside "
                         "their bounds (0 ≤ e ≤ 1, 0 < ζ < 1, d > 0)")  # fmt: skip


def peak_spread(system: ImpactSystem, forcing: Any, e: Any, omegas: Any, names: list[str],
                draws: np.ndarray, seed: int = 0, **options: Any) -> PeakSpread:  # fmt: skip
    """The located peak of the curve over ``omegas`` at each draw of ``names`` (``draws``, from
    :func:`parameter_draws`), the other parameters ``system``'s and ``e``; ``options`` as
    :func:`~symimpact.forced.orbits.frf.frequency_response` takes them."""
    from ..forced.orbits.frf import frequency_response

    peaks = []
    for row in draws:
        p = dict(zip(names, row, strict=True))
        changes = {k: float(v) for k, v in p.items() if k in ("zeta", "gap")}
        s = system.with_(**changes) if changes else system
        curve = frequency_response(s, forcing, float(p.get("e", e)) if "e" in p else e, omegas,
                                   **options)  # fmt: skip
        peaks.append(np.nan if curve.peak is None else curve.peak.amplitude)
    return PeakSpread(list(names), np.asarray(draws, float), np.array(peaks), seed)
