"""The envelope of the non-periodic bands (issue 80, item 6): the curve's sweeps' motions that
impact and do not repeat, each given by the lowest and the highest of its kept periods' largest
|x|, in the JSON (``not_periodic``) and shaded on the figure.

The README's system with e = 0.95 (issue 81's case): beside its resonance near 30.8 rad/s the
sweeps land on motions that do not repeat, whose largest excursions wander from period to period.
"""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.frf import (
    SWEEP_KEPT,
    SWEEP_MAX,
    SWEEP_SETTLED,
    _sweep_runs,
    frequency_response,
)
from symimpact.forced.simulation import settling_periods, simulate_forced
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
FORCING = Forcing(F0=2.0, omega=30.0)
E = 0.95
BAND = np.arange(30.6, 31.0 + 1e-9, 0.05)


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, FORCING, E, BAND, multistart=0, jumps=0, starts=2)


def test_every_swept_motion_that_does_not_repeat_is_listed_with_its_range(curve):
    rows = curve.as_dict()["not_periodic"]
    assert rows, "the band holds motions that do not repeat"
    swept = {("up", w): a for w, a in curve.sweep_up} | {
        ("down", w): a for w, a in curve.sweep_down
    }
    for r in rows:
        assert 0.0 < r["displacement_low"] <= r["displacement_high"]
        # the highest is the sweep's own amplitude at that Ω, the same number the figure dots
        assert r["displacement_high"] == swept[(r["sweep"], r["omega"])]
    # and none of a motion that repeats: the up sweep's own verdicts, run again
    up = _sweep_runs(SYSTEM, FORCING, E, BAND)
    listed = {r["omega"] for r in rows if r["sweep"] == "up"}
    assert listed == {p.omega for p in up if not p.periodic and p.impacts_per_period > 0}


def test_the_range_is_that_of_the_kept_periods_of_the_sweeps_run():
    """Each Ω's run again, by hand, from the state the sweep reached at the Ω before (from rest at
    the first): the range is the lowest and highest of the largest |x| of its last SWEEP_KEPT
    periods (not of the transient before them), and run on for ten times as long from its end
    the motion still does not repeat."""
    up = _sweep_runs(SYSTEM, FORCING, E, BAND)
    checked = 0
    for before, p in zip([None, *up[:-1]], up, strict=True):
        if p.periodic or p.impacts_per_period == 0:
            continue
        x, v, z, u = (0.0, 0.0, 0.0, 0.0) if before is None else before.state
        f = FORCING.at(p.omega)
        n = settling_periods(SYSTEM, f, SWEEP_KEPT, SWEEP_MAX, SWEEP_SETTLED)
        run = simulate_forced(SYSTEM, f, e=E, periods=n, x0=x, xdot0=v, y0=x + z, ydot0=u)
        kept = run.period_max[n - SWEEP_KEPT : n]
        assert len(kept) == SWEEP_KEPT
        assert (p.low, p.amplitude) == (float(kept.min()), float(kept.max()))  # the same runs
        x, v, z, u = p.state
        more = simulate_forced(SYSTEM, f, e=E, periods=10 * SWEEP_KEPT, discard=0,
                               x0=x, xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
        assert not more.steady.periodic
        checked += 1
    assert checked


def test_the_figure_shades_the_envelope(curve, tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from symimpact.report.plots import draw_frf

    fig, ax = plt.subplots()
    draw_frf(ax, curve)
    labels = [h.get_label() for h in ax.get_legend_handles_labels()[0]]
    assert sum("do not repeat (sweeps)" in t for t in labels) == 1  # one legend entry
    shaded = [c for c in ax.collections if "do not repeat (sweeps)" in str(c.get_label())]
    assert shaded
    plt.close(fig)
