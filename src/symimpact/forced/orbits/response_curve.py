"""A frequency-response curve in another response than the displacement: the same branches,
bifurcations and motion without impacts, each point carrying the response (relative
displacement, acceleration between impacts, force into the base or transmissibility,
:mod:`symimpact.forced.responses`) in place of max abs(x), and the peak located again in it.

The curve's orbits are the displacement curve's (:func:`symimpact.forced.frequency_response`):
each point's response is computed along its orbit from its state (Eq. F1 between impacts, Eq. F2
at them); the primary alone and the motion without impacts in closed form (Step 8); the peak by
the same search as the displacement's (:func:`symimpact.forced.orbits.peak.curve_peak`), its trial
orbits measured in the response.  The brute-force sweeps keep no states, so a response curve has
none: they are the displacement curve's cross-check.
"""

from __future__ import annotations

import copy
import dataclasses
import math
from typing import Any

import numpy as np

from ...model.system import ImpactSystem
from ..forcing import Forcing
from ..responses import checked_response, linear_response, orbit_response
from .frf import FrequencyResponse
from .peak import baseline_peak, curve_peak


def response_curve(
    frf: FrequencyResponse, name: str, system: ImpactSystem, forcing: Forcing, e: Any
) -> FrequencyResponse:
    """``frf`` (the curve of ``system`` under ``forcing`` with the contact ``e``) in the response
    ``name`` (:data:`symimpact.forced.responses.RESPONSES`; module text): a new curve whose
    ``amplitude`` fields hold that response [its SI unit], with its located ``peak`` and
    ``baseline_peak``; ``response`` names it.  ``"displacement"`` returns ``frf`` itself."""
    checked_response(name, forcing)
    if name == "displacement":
        return frf

    def measure(state, omega: float, phase: float, periods: int) -> float:
        return orbit_response(name, system, forcing.at(omega, phase), e, state, periods)

    def linear(w):
        return linear_response(name, system, forcing, w)

    out = copy.copy(frf)
    out.response = name
    out.branches = []
    for b in frf.branches:
        k = b.period_multiple
        nb = copy.copy(b)
        nb.points = [dataclasses.replace(p, amplitude=measure(p.state, p.omega, p.phase, k))
                     for p in b.points]  # fmt: skip
        nb.bifurcations = [
            dataclasses.replace(f, amplitude=measure(f.state, f.omega, f.phase, k))
            if f.state is not None
            else dataclasses.replace(f, amplitude=math.nan)
            for f in b.bifurcations
        ]
        out.branches.append(nb)
    out.baseline = np.column_stack([frf.omegas, linear(frf.omegas)])
    out.sweep_up = out.sweep_down = np.zeros((0, 2))
    band = (float(frf.omegas[0]), float(frf.omegas[-1]))
    out.baseline_peak = baseline_peak(system, forcing, band, linear)
    others = frf.coverage.attractors
    out.peak = curve_peak(out.branches, system, forcing, e, band, frf.no_impact, others,
                          measure=measure, linear=linear)  # fmt: skip
    return out
