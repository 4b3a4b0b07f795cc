"""Every number the documentation's report summary states about results is the one the code
computes (issue 15, item 5; the summary moved from the README to ``docs/reproduction.md``).

Each test recomputes a claim of that page and checks that the page carries the computed value,
formatted as the page writes it.  A change in the code that moves a number fails here until the
page says the new number.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from symimpact.generated import closed_forms

from symimpact.maps.sweep import fig5_limits, gap_range
from symimpact.report import contact_stage, forced_stage, paper, vibration_stage

README = (Path(__file__).resolve().parents[1] / "docs" / "reproduction.md").read_text(
    encoding="utf-8"
)
TEXT = " ".join(README.split())  # line breaks as spaces


def says(fragment: str) -> bool:
    return " ".join(fragment.split()) in TEXT


@pytest.fixture(scope="module")
def chosen():
    stated = vibration_stage._table3_runs(vibration_stage.STATED)
    reading, _ = vibration_stage._choose_reading(stated)
    return reading, vibration_stage._table3_runs(reading)


def test_table1_claims():
    rows = contact_stage.table1_rows()
    hertz_02 = next(r for r in rows if r[0] == 0.2 and r[1] == "Hertz, Eq. 34")
    assert hertz_02[4] == "= (truncated)"
    assert says(f"({hertz_02[2]:.5f} → {hertz_02[3]:.4f})")
    offsets = {
        f"{r[2] - r[3]:.4f}" for r in rows if r[1] == "perturbation Eq. 31 as printed, B/A = −M/m"
    }
    assert len(offsets) == 1
    assert says(f"sits {offsets.pop()} s below Eq. 31 as printed with B/A = −M/m")
    errors = [r[6] for r in rows if r[1] in ("Hertz, Eq. 34", "linear, Eq. 35")
              or r[1].startswith("perturbation")]  # fmt: skip
    assert says(f"the closed forms err by {min(errors):.0f}–{max(errors):.0f} % at K = 1000 N/m")


def test_table2_as_printed_moves_the_main_mass_by_what_the_readme_says():
    s = vibration_stage.STATED.system(9.0)
    from symimpact.model.units import si

    amplitude_mm = si("xdot0", vibration_stage.STATED.xdot0) / s.omega_n * 1e3
    assert says(f"moves the main mass {amplitude_mm:.2f} mm")


def test_reading_claims(chosen):
    reading, runs = chosen
    assert (reading.K, reading.c1, reading.xdot0) == ("100 N/m", "5 N s/m", "5 dm/s")
    assert says("K = 100 N/m, c₁ = 5 N s/m, Ẋ₀ = 0.5 m/s")
    rows = vibration_stage.table3_rows(runs)
    agree = sum(r[1] == r[2] for r in rows)
    assert says(f"the gap class agrees at {agree} of 9 gaps of Table 3")
    ratios = [r[9] / r[10] for r in rows if r[9] is not None]
    assert says(
        f"{min(ratios):.0f}–{max(ratios):.0f} times the printed one at Table 3's gaps "
        f"(median {np.median(ratios):.0f})"
    )


def test_gap_range_claims(chosen):
    reading, _ = chosen
    system = reading.system(9.0)
    horizon = dict(xdot0=reading.xdot0, t_end=vibration_stage.T_PRIME_END / system.omega_n)
    hi = vibration_stage.GAP_SPAN_MM[1]
    f5 = fig5_limits(system, vibration_stage._grid_mm(0.5) * 1e-3, **horizon)
    assert says(f"gives d_min = {f5['d_min'] * 1e3:.2f} mm (paper {paper.GAP_RANGE['d_min']} mm)")
    assert f5["d_max"] is None
    assert says(f"no d_max up to {hi:g} mm (paper {paper.GAP_RANGE['d_max']} mm)")
    rng = gap_range(system, vibration_stage._grid_mm(0.1) * 1e-3, progress=False, **horizon)
    out = [r["gap"] for r in rng["rows"] if r["class"] != "in range"]
    assert says(f"out-of-range gaps are scattered up to {max(out) * 1e3:.1f} mm")
    assert says("on a 0.1 mm grid")


def test_forced_section_claims(chosen):
    """The report's forced section: e of the paper's linear contact and how long that contact
    lasts against the resonant forcing period, as the README states them."""
    reading, _ = chosen
    s = reading.system(9.0)
    k1 = float(paper.FIT["k1"])
    e = float(closed_forms.linear_restitution(s.m, s.M, k1, s.c1))
    share = (
        float(closed_forms.linear_contact_duration(s.m, s.M, k1, s.c1)) * s.omega_n / (2 * math.pi)
    )
    assert says(f"k₁ = {k1:g} N/m, c₁ = {s.c1:g} N s/m: e = {e:.4f}")
    assert says(f"that contact lasts {share * 100:.1f} % of the resonant forcing period")
    assert says(
        f"under F0 = {forced_stage.F0:g} N over {forced_stage.BAND[0]:g}–{forced_stage.BAND[1]:g} ω_n"
    )
    gaps = ", ".join(f"{g:g}" for g in forced_stage.GAPS_MM[:-1])
    assert says(f"at d = {gaps} and {forced_stage.GAPS_MM[-1]:g} mm")
    ratios = ", ".join(f"{r:g}" for r in forced_stage.MASS_RATIOS[:-1])
    assert says(f"m/M = {ratios} and {forced_stage.MASS_RATIOS[-1]:g}")
