"""Fuzzing the new surfaces' readers: random JSON trees as structure files and random unit texts
as load options either read or are refused with :class:`ParameterError` — never another
exception (a RecursionError, a UnicodeDecodeError, a TypeError from a stray type), never a
non-finite number.  Slow (the README's test command leaves it out; CI runs it with the slow set).
"""

from __future__ import annotations

import json
import math
import string
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from symimpact.errors import ParameterError
from symimpact.model.structure import read_structure
from symimpact.model.units import ACCELERATION_PSD, si_float

pytestmark = pytest.mark.slow

#: The fields a structure file may hold, and values of the kinds they take: drawn among random
#: keys so that the trees reach the readers' deeper checks, not only the first refusal.
KEYS = ["beam", "modes", "fe", "points", "type", "E", "I", "rho", "A", "L", "zeta", "f", "mass",
        "shape", "M", "K", "C", "influence", "tip", "dampers", "x"]  # fmt: skip
SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-(10**20), 10**20),
    st.floats(allow_nan=False, allow_infinity=False),
    st.sampled_from(
        ["cantilever", "10 Hz", "1 kg", "200 GPa", "5 mm", "0.02", "-1", "nan", "", "1e400", "tip"]
    ),
    st.text(max_size=12),
)
TREES = st.recursive(
    SCALARS,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(st.one_of(st.sampled_from(KEYS), st.text(max_size=6)), inner, max_size=5),
    ),
    max_leaves=30,
)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(TREES)
@example({"beam": None, "\n": None})  # a key with a line break had made a two-line refusal
def test_a_random_structure_file_is_read_or_refused_in_one_line(tree):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "s.json"
        path.write_text(json.dumps(tree), encoding="utf-8")
        try:
            s = read_structure(path)
        except ParameterError as exc:
            assert "\n" not in str(exc)
            return
    assert all(math.isfinite(m.omega) and m.omega > 0 for m in s.modes)


UNIT_WORDS = ["N", "N^2", "g", "g^2", "m/s^2", "(m/s^2)^2", "Hz", "kHz", "rad/s", "rpm", "deg/s",
              "s", "rad", "min", "cycle/s", "turn", "kg", "m", "mm", "1/s", "(rad/s)^2", "%"]  # fmt: skip
UNIT_TEXTS = st.lists(
    st.one_of(
        st.sampled_from(UNIT_WORDS),
        st.sampled_from(["/", " ", "^", "*", "(", ")", "-1"]),
        st.text(alphabet=string.printable, max_size=3),
    ),
    min_size=1,
    max_size=6,
).map("".join)


@settings(max_examples=600, deadline=None)
@given(
    st.floats(-1e6, 1e6, allow_nan=False),
    UNIT_TEXTS,
    st.sampled_from(["N^2/Hz", ACCELERATION_PSD, "Hz", "rad/s", "m/s^2"]),
)
def test_a_random_unit_text_is_read_or_refused_in_one_line(number, unit, target):
    try:
        v = si_float("force-psd", f"{number!r} {unit}", target)
    except ParameterError as exc:
        assert "\n" not in str(exc)
        return
    assert math.isfinite(v)
