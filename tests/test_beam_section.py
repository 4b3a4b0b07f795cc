"""A beam in a structure file named as a designer names it: its ``material`` (E and ρ from the
materials table) and its ``section`` ("50 mm x 10 mm", thickness along the motion, or "round
20 mm"), checked against the textbook formulas: A = bh, I = bh³/12; A = πd²/4, I = πd⁴/64; and
a cantilever's first frequency (βL)²/(2π)·√(EI/(ρAL⁴)), βL = 1.875104 (the root of
cos βL·cosh βL = −1)."""

import math

import pytest
from scipy.optimize import brentq

from symimpact.errors import ParameterError
from symimpact.model.structure import section_properties, structure_from_dict


def test_sections_are_the_textbook_areas_and_second_moments():
    A, I = section_properties("50 mm x 10 mm")
    assert A == pytest.approx(5e-4, rel=1e-15)
    assert I == pytest.approx(0.05 * 0.01**3 / 12, rel=1e-15)  # 4166.7 mm⁴
    assert section_properties("50 mm × 10 mm") == (A, I)
    A, I = section_properties("round 20 mm")
    assert A == pytest.approx(math.pi * 0.02**2 / 4, rel=1e-15)
    assert I == pytest.approx(math.pi * 0.02**4 / 64, rel=1e-15)


def test_a_beam_by_material_and_section_is_the_same_beam_by_numbers():
    """1 m of aluminium alloy (6061-T6: E 68.9 GPa, ρ 2700 kg/m³), 50 × 10 mm: 8.160 Hz."""
    named = structure_from_dict({
        "beam": {"type": "cantilever", "material": "aluminium", "section": "50 mm x 10 mm",
                 "L": "1 m", "zeta": 0.01},
        "points": {"tip": "1 m"}})  # fmt: skip
    numbers = structure_from_dict({
        "beam": {"type": "cantilever", "E": "68.9 GPa", "rho": "2700 kg/m^3", "A": 5e-4,
                 "I": 0.05 * 0.01**3 / 12, "L": "1 m", "zeta": 0.01},
        "points": {"tip": "1 m"}})  # fmt: skip
    assert [m.omega for m in named.modes] == [m.omega for m in numbers.modes]
    bl = brentq(lambda b: math.cos(b) * math.cosh(b) + 1.0, 1.0, 3.0)
    f1 = bl**2 / (2 * math.pi) * math.sqrt(68.9e9 * (0.05 * 0.01**3 / 12) / (2700.0 * 5e-4))
    assert named.modes[0].frequency == pytest.approx(f1, rel=1e-9)
    assert named.modes[0].frequency == pytest.approx(8.160, abs=5e-4)


BASE = {"type": "cantilever", "L": "1 m"}


@pytest.mark.parametrize(
    ("beam", "match"),
    [
        (
            {"material": "aluminium", "E": "70 GPa", "A": 5e-4, "I": 4e-9},
            "beam.E: the material gives it",
        ),
        (
            {"section": "50 mm x 10 mm", "I": 1e-9, "material": "steel"},
            "beam.I: the section gives it",
        ),
        (
            {"section": "50 mm by 10 mm", "material": "steel"},
            "beam.section: must be 'width x thickness'",
        ),
        ({"section": "50 kg x 10 mm", "material": "steel"}, "beam.section"),
        ({"material": "aluminium"}, "beam.I: is missing .or give its section."),
    ],
)
def test_a_contradiction_or_a_bad_section_is_refused_in_one_line(beam, match):
    with pytest.raises(ParameterError, match=match):
        structure_from_dict({"beam": BASE | beam, "points": {"tip": "1 m"}})
