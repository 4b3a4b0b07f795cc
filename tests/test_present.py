"""The board presentation (derive/present.py) changes how a result looks, never what it is: for
every line of every derivation step, the written form with its "where" definitions substituted
back equals the board's value at random points (to the rounding of the displayed numbers), and a
step's own board form (``shown``) equals its value."""

from __future__ import annotations

import random

import pytest
import sympy as sp

import derive
from derive.present import board_form, readable_numbers, tex, width_em

#: Relative agreement of a written form with the value.  Exact forms agree to the working
#: precision (30 digits); a form with numbers rounded to 7 significant digits (≈ on the board)
#: carries a relative error up to 5e-7 per number, amplified by the cancellation of a few terms.
EXACT, ROUNDED = 1e-20, 1e-4


def _sample(expr: sp.Basic, rng: random.Random) -> dict:
    return {s: sp.Float(rng.uniform(0.3, 1.7), 30) for s in expr.free_symbols}


def _agree(a: sp.Basic, b: sp.Basic, tol: float, rng: random.Random) -> None:
    for _ in range(3):
        point = _sample(a - b, rng)
        va, vb = sp.N(a.subs(point), 30), sp.N(b.subs(point), 30)
        if not (va.is_finite and vb.is_finite):
            continue
        assert abs(va - vb) <= tol * (1 + abs(vb)), (va, vb, point)


def _lines(boards):
    for step in derive.STEPS:
        for line in boards[step].lines:
            if isinstance(line.value, sp.Expr):
                yield step, line


def test_written_form_equals_the_value(boards):
    rng = random.Random(20261122)
    checked = 0
    for _step, line in _lines(boards):
        shown = board_form(line.value)
        assert shown is not None
        written = _written(line.value, shown)
        if written is None:
            continue
        _agree(written, readable_numbers(line.value)[0], ROUNDED if shown.approx else EXACT, rng)
        checked += 1
    assert checked > 40


def _written(value: sp.Expr, shown) -> sp.Expr | None:
    """The value rebuilt from the presentation's substitutions (names → their expressions)."""
    from derive.present import _prepare

    form, _ = _prepare(value, {})
    for _ in range(len(shown.definitions) + 1):
        form = form.xreplace(shown.definitions)
    return form if not (form.free_symbols & set(shown.definitions)) else None


def test_own_board_forms_equal_the_values(boards):
    rng = random.Random(7)
    n = 0
    for step in derive.STEPS:
        for line in boards[step].lines:
            if line.shown is None:
                continue
            form = line.shown
            for _ in range(4):
                form = form.xreplace(line.names or {})
            _agree(form, line.value, EXACT, rng)
            n += 1
    assert n >= 4


@pytest.mark.parametrize(
    ("number", "text"),
    [(sp.Rational(12362361, 1000000), "12.362361"), (sp.Rational(12362361, 4000000), "3.09059025"), (sp.Rational(3679, 1250), "2.9432"),
     (sp.Rational(3, 8), r"\frac{3}{8}")],
)  # fmt: skip
def test_numbers_read_as_the_paper_prints_them(number, text):
    shown, rounded = readable_numbers(number)
    assert tex(shown) == text and not rounded


def test_exact_constants_stay_exact_and_long_roots_are_rounded():
    """3/(4π²) (Eq. 29's cubic term over π²) is written as it is, not as 0.07599089; a long
    algebraic number and a logarithm's value are still rounded (and the line says ≈)."""
    T = sp.Symbol("T")
    shown, rounded = readable_numbers(3 * T**2 / (4 * sp.pi**2))
    assert not rounded and r"\pi^{2}" in tex(shown)
    shown, rounded = readable_numbers(sp.sqrt(2) / 2 + sp.Rational(1, 3) * sp.pi)
    assert not rounded
    for long in (sp.sqrt(3 + sp.sqrt(5 + sp.sqrt(7 + sp.sqrt(11)))) * sp.pi, sp.log(3) ** 3):
        _, rounded = readable_numbers(long * T)
        assert rounded


def test_amplitude_ratio_reads_b_over_b_minus_a():
    ba = sp.Symbol("ba")
    shown = board_form(ba / (ba - 1))
    assert shown is not None and shown.lines == [r"\frac{B}{B - A}"]


def test_long_results_are_broken_to_the_board_width(boards):
    widths = []
    for _step, line in _lines(boards):
        shown = board_form(line.value)
        for text in shown.lines + [t for _, d in shown.where for t in d]:
            widths.append(width_em(text))
    assert max(widths) <= 34.0 + 1e-9
