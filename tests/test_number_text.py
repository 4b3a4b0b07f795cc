"""Numbers mean what was typed (issue 16, item 1).

The rule, as a property: any text the package accepts has the value a person reading it would
say (a Unicode minus or dash is a minus; a prefix scales by its power of ten), and every other
text (a decimal comma, numbers side by side, digit groups, operators, overlong text) is refused
with a ParameterError naming the parameter.  The same reader serves options, ``--vary`` lists,
``--sets`` cells and the Python API (all go through ``units.si``).
"""

from __future__ import annotations

import json
import subprocess
import sys
from decimal import Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symimpact.errors import ParameterError
from symimpact.model.units import MAX_TEXT, MINUS_SIGNS, si

UNITS = {"": "1", "m": "1", "mm": "0.001", "cm": "0.01", "km": "1000", "µm": "0.000001"}


@st.composite
def written_numbers(draw):
    """(text, the value a reader says) for a length in metres."""
    sign = draw(st.sampled_from(["", "+", *MINUS_SIGNS]))
    whole = draw(st.integers(0, 999_999))
    frac = draw(st.one_of(st.just(""), st.from_regex(r"\.[0-9]{1,6}", fullmatch=True)))
    exp = draw(st.one_of(st.just(""), st.tuples(st.sampled_from(["", "+", *MINUS_SIGNS]),
                                                 st.integers(0, 12))))  # fmt: skip
    unit = draw(st.sampled_from(sorted(UNITS)))
    space = draw(st.sampled_from(["", " ", "  "])) if unit else ""
    text = f"{sign}{whole}{frac}"
    ascii_number = f"{whole}{frac}"
    if exp:
        esign, e = exp
        text += f"e{esign}{e}"
        ascii_number += f"e{'-' if esign and esign in MINUS_SIGNS else ''}{e}"
    text += space + unit
    negative = bool(sign) and sign in MINUS_SIGNS  # ("" is in every string)
    value = float(Decimal(repr(float(ascii_number))) * Decimal(UNITS[unit]))
    return text, -value if negative else value


@settings(max_examples=400, deadline=None)
@given(written_numbers())
def test_accepted_text_has_the_value_a_reader_says(case):
    text, value = case
    assert si("x0", text) == value, text


def _bad_texts():
    digits = st.integers(0, 999).map(str)
    return st.one_of(
        st.tuples(digits, st.integers(0, 99)).map(lambda t: f"{t[0]},{t[1]:02d}"),  # 0,05
        st.tuples(digits, st.integers(0, 99)).map(lambda t: f"{t[0]},{t[1]} mm"),
        st.tuples(digits, digits).map(lambda t: f"{t[0]} {t[1]}"),  # side by side
        st.tuples(digits, st.integers(0, 999)).map(lambda t: f"{t[0]} {t[1]:03d} mm"),  # groups
        st.tuples(digits, st.sampled_from(["**", "+", "*", "/", "^", "_"]), digits).map(
            lambda t: f"{t[0]}{t[1]}{t[2]} mm"
        ),
        st.integers(MAX_TEXT + 1, 3 * MAX_TEXT).map(lambda n: "1" * n),
        st.sampled_from(["nan", "−inf mm", "", "mm", "2**1024 kg", "10**10**10 kg", "0x10",
                         "1e99999", "1.2.3", "--1", "−−1 mm"]),
    )  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(_bad_texts())
def test_every_other_text_is_refused_naming_the_parameter(text):
    with pytest.raises(ParameterError) as err:
        si("x0", text)
    assert err.value.parameter == "x0"
    assert "\n" not in str(err.value)


def test_a_decimal_comma_asks_for_a_point():
    with pytest.raises(ParameterError, match="use a decimal point"):
        si("zeta", "0,05")


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "symimpact.cli", *args], capture_output=True, text=True
    )


def test_cli_reads_a_unicode_minus_as_a_minus_and_refuses_a_comma():
    out = _run("simulate", "--x0", "−2 mm", "--t-end", "0.1", "--json")
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout)["initial_state"]["x0"] == -0.002
    bad = _run("simulate", "--xdot0", "0,5 m/s")
    assert bad.returncode == 2
    assert bad.stderr.count("\n") == 1 and "xdot0" in bad.stderr and "decimal point" in bad.stderr


def test_sets_cells_and_vary_lists_use_the_same_reader(tmp_path):
    from symimpact.maps import parse_range, read_sets

    assert list(parse_range("x0", "−2 mm,2 mm")) == [-0.002, 0.002]
    csv = tmp_path / "sets.csv"
    csv.write_text("\ufeffgap [mm],x0\n9,−1 mm\n", encoding="utf-8")  # with Excel's BOM
    pts = read_sets(csv)
    assert pts.names == ("gap", "x0") and pts.values.tolist() == [[0.009, -0.001]]
    bad = tmp_path / "bad.csv"
    bad.write_text('gap [mm]\n"9,5"\n', encoding="utf-8")
    with pytest.raises(ParameterError, match="decimal point"):
        read_sets(bad)


def test_a_range_whose_step_has_no_unit_is_refused(capsys):
    """Issue 17, item 3: "gap=6 mm:12 mm:2" took the step as 2 m and ran one gap."""
    from symimpact.cli import main

    assert main(["map", "--vary", "gap=6 mm:12 mm:2", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "gap" in err and "units" in err


def _outcome(fn, name, value):
    from symimpact.errors import ParameterError

    try:
        return ("value", fn(name, value))
    except ParameterError as exc:
        return ("refused", str(exc).split(",")[0])


@given(
    st.one_of(
        st.floats(allow_nan=True, allow_infinity=True),
        st.integers(min_value=-(10**32), max_value=10**32),
        st.sampled_from([0.0, -0.0, 1e-31, 1e-30, 1e30, 1.0000001e30, 5e-324]),
    ),
    st.sampled_from(["gap", "x0", "c1"]),
)
@settings(max_examples=300)
def test_a_plain_number_reads_as_through_the_array_path(value, name):
    """si/positive/nonnegative read a Python float or int without NumPy (a map validates
    every point): the value, or the refusal, is the one the array path gives for the same
    number as a 0-d array."""
    import numpy as np

    from symimpact.model.units import nonnegative_float, positive_float, si_float

    for fn in (si_float, positive_float, nonnegative_float):
        fast = _outcome(fn, name, value)
        try:
            slow = _outcome(fn, name, np.asarray(float(value)))
        except OverflowError:
            continue
        assert fast[0] == slow[0], (fn.__name__, value, fast, slow)
        if fast[0] == "value":
            assert fast[1] == slow[1] and type(fast[1]) is float
