"""Gap classes as the dynamics has them (issue 15, item 4).

- Intervals, shares per mm and the envelope limits on hand-made rows (closed-form answers).
- The Fig. 5 criterion's d_min is a true boundary: the effective-contact condition changes sign
  there, in this simulator and in the independent solve_ivp reference, and it does not move
  with the grid (the old d_min, a bisection between the grid gaps 6 and 7 mm, landed on a thin
  strip at 6.76 mm).
"""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.errors import ParameterError
from symimpact.free.reference import reference_impacts
from symimpact.maps.sweep import (
    arrival_condition,
    envelope_limits,
    fig5_limits,
    gap_intervals,
    in_range_share,
)
from symimpact.model.system import ImpactSystem


def _rows(pattern: str, start_mm: float = 4.0, step_mm: float = 0.1):
    """Rows from a string of classes: I in range, O out of range, N no impact."""
    names = {"I": "in range", "O": "out of range", "N": "no impact"}
    return [
        {"gap": round(start_mm + k * step_mm, 9) * 1e-3, "class": names[c]}
        for k, c in enumerate(pattern)
    ]


def test_intervals_merge_runs_of_one_class_and_keep_single_flips():
    rows = _rows("OOOIIOIIIIN")
    got = [
        (iv["class"], round(iv["from"] * 1e3, 6), round(iv["to"] * 1e3, 6), iv["n"])
        for iv in gap_intervals(rows[::-1])
    ]  # fmt: skip  (any order in)
    assert got == [
        ("out of range", 4.0, 4.2, 3),
        ("in range", 4.3, 4.4, 2),
        ("out of range", 4.5, 4.5, 1),
        ("in range", 4.6, 4.9, 4),
        ("no impact", 5.0, 5.0, 1),
    ]


def test_share_per_mm_counts_the_grid_gaps_of_each_bin():
    rows = _rows("O" * 10 + "IIIIIOIIII" + "I" * 10)  # 4.0–4.9, 5.0–5.9, 6.0–6.9 mm
    shares = in_range_share(rows)
    assert [round(b["from"] * 1e3, 6) for b in shares] == [4.0, 5.0, 6.0]
    assert [b["n"] for b in shares] == [10, 10, 10]
    assert [b["share"] for b in shares] == [0.0, 0.9, 1.0]


def test_envelope_ignores_thin_strips_and_single_flips():
    # in range from 5.0 mm with one out-of-range gap at 5.5 mm; a lone in-range gap at 4.3 mm;
    # out of range again from 8.0 mm, with a lone in-range gap at 8.5 mm
    pattern = "OOOIOOOOOO" + "IIIIIOIIII" + "I" * 20 + "OOOOOIOOOO"
    rows = _rows(pattern)
    d_min, d_max = envelope_limits(rows, share=0.9, window=1e-3)
    # the first gap whose next 1 mm (11 grid gaps) is ≥ 90 % in range: 5.0 mm (10 of 11)
    assert d_min == pytest.approx(5.0e-3)
    # the last gap whose previous 1 mm is ≥ 90 % in range: 8.0 mm (10 of 11)
    assert d_max == pytest.approx(8.0e-3)
    with pytest.raises(ParameterError, match="share"):
        envelope_limits(rows, share=0.0)


READING = dict(M=1, K="100 N/m", m=0.25, C=1, c1="5 N s/m", a="0.1553 N/cm^3", b="0.8360 N/cm")
HORIZON = dict(xdot0=0.5, t_end=20.0)  # the report's reading: Ẋ0 = 0.5 m/s, t' = 200


@pytest.fixture(scope="module")
def fig5():
    system = ImpactSystem(gap="9 mm", **READING)
    return system, fig5_limits(system, np.arange(5.0, 8.01, 0.5) * 1e-3, **HORIZON)


def test_fig5_d_min_is_a_sign_change_of_the_effective_contact_condition(fig5):
    system, res = fig5
    d_min = res["d_min"]
    assert d_min is not None and 6.0e-3 < d_min < 7.0e-3
    assert res["boundaries"][0]["kind"] == "zero"
    below = arrival_condition(system, d_min - 1e-6, **HORIZON)
    above = arrival_condition(system, d_min + 1e-6, **HORIZON)
    assert below > 0 > above  # not effective just below, effective just above


def test_fig5_d_min_agrees_with_the_solve_ivp_reference(fig5):
    """The same sign change in the independent reference (whole motion by DOP853 with events)."""
    system, res = fig5
    signs = []
    for d in (res["d_min"] - 1e-6, res["d_min"] + 1e-6):
        impacts = reference_impacts(system.with_(gap=d), 0.0, 0.5, 0.0, 0.0, 2.0)
        second = impacts[1]  # the impact mass starts at rest: the first contact is the main mass's
        signs.append(np.sign(second["xdot"] * second["ydot"]))
    assert signs == [1.0, -1.0]


def test_fig5_d_min_does_not_depend_on_the_grid(fig5):
    system, res = fig5
    other = fig5_limits(system, np.arange(5.2, 7.9, 0.7) * 1e-3, **HORIZON)
    assert other["d_min"] == pytest.approx(res["d_min"], abs=2e-9)  # Brent's xtol, twice
