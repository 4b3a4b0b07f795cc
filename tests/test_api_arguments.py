"""The public functions of the forced response check their arguments like the command line: each
argument in turn is given each odd value below (wrong types, NaN, infinities, fractions where a
count is due, None, strings, arrays), the others valid, and the call either computes a result
with finite numbers or refuses with the package's ``SymimpactError`` in one line — never
Python's TypeError, AttributeError or ValueError, never a hang (the reliability issue, item 4).

Every call is enumerated (no random draw): 13 functions, their arguments, 14 odd values each.
The valid values are a small system and a narrow band, so the whole set takes seconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.errors import SymimpactError
from symimpact.forced import (
    CompliantContact,
    Forcing,
    backbone,
    best_clearance,
    continue_orbit,
    monodromy,
    periodic_orbits,
    rigid_limit,
    shoot,
    shoot_from_rest,
    simulate_forced,
    slow_flow_responses,
    steady_state,
    trace_branch,
)
from symimpact.forced.orbits.frf import frequency_response
from symimpact.maps.design import design_map, design_row
from symimpact.model.system import ImpactSystem

ODD = [0, -1, 1.5, math.nan, math.inf, -math.inf, 1e308, True, None, "abc", [1.0, 2.0],
       {"a": 1}, complex(1, 1), np.array([1.0, 2.0])]  # fmt: skip

SYSTEM = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, k_hz=1000, k1=1e6, c1=70)
FORCING = Forcing(F0=2, omega=36)
E = 0.6
#: the stable symmetric orbit at 36 rad/s (shooting from rest finds it)
ORBIT = shoot_from_rest(SYSTEM, FORCING, E, warmup=100)
STATE = ORBIT.state
RESULT = simulate_forced(SYSTEM, FORCING, contact="rigid", e=E, periods=8)
BAND = [35.95, 36.0]

#: function → (its valid keyword arguments, the names to spoil)
CASES = {
    simulate_forced: (
        {"system": SYSTEM, "forcing": FORCING, "contact": "rigid", "e": E, "periods": 4,
         "discard": 2, "x0": 0.0, "xdot0": 0.0, "y0": 0.0, "ydot0": 0.0, "chatter": 0.5,
         "samples_per_period": 16},
        None,
    ),
    steady_state: ({"result": RESULT, "discard": 4}, None),
    periodic_orbits: ({"system": SYSTEM, "forcing": FORCING, "e": E}, None),
    monodromy: ({"system": SYSTEM, "forcing": FORCING, "e": E, "state": STATE, "periods": 1},
                None),
    shoot: ({"system": SYSTEM, "forcing": FORCING, "e": E, "start": STATE, "periods": 1,
             "tol": 1e-10, "max_iter": 20}, None),
    shoot_from_rest: ({"system": SYSTEM, "forcing": FORCING, "e": E, "warmup": 20,
                       "periods": 1, "start": (0.0, 0.0, 0.0, 0.0)}, None),
    continue_orbit: ({"system": SYSTEM, "forcing": FORCING, "e": E, "state": STATE,
                      "bounds": (35.9, 36.1), "parameter": "omega", "periods": 1,
                      "direction": 1, "step": 0.02, "max_points": 50}, None),
    trace_branch: ({"system": SYSTEM, "forcing": FORCING, "e": E, "state": STATE,
                    "bounds": (35.9, 36.1), "parameter": "omega", "periods": 1,
                    "step": 0.02}, None),
    frequency_response: ({"system": SYSTEM, "forcing": FORCING, "e": E, "omegas": BAND,
                          "starts": 1, "sweeps": False}, None),
    rigid_limit: ({"system": SYSTEM, "forcing": FORCING, "e": E, "contact": "linear",
                   "stiffnesses": [1e6], "periods": 20, "discard": 10}, None),
    slow_flow_responses: ({"system": SYSTEM, "forcing": FORCING, "e": E}, None),
    best_clearance: ({"system": SYSTEM, "forcing": FORCING, "e": E}, None),
    design_map: ({"system": SYSTEM, "forcing": FORCING, "e": E, "omegas": BAND,
                  "grid": {"gap": [2.0]}, "executor": "serial", "multistart": 0}, None),
}  # fmt: skip


def _finite(obj, where):
    if obj is None or isinstance(obj, (str, bool)):
        return
    if isinstance(obj, (int, float, np.floating, np.integer)):
        assert math.isfinite(float(obj)), where
    elif isinstance(obj, np.ndarray) and obj.dtype.kind == "f":
        assert not np.any(np.isinf(obj)), where  # NaN marks "none" in a few log columns


def _cases():
    for fn, (kwargs, names) in CASES.items():
        for name in names or kwargs:
            for k, odd in enumerate(ODD):
                yield pytest.param(fn, kwargs, name, odd, id=f"{fn.__name__}-{name}-{k}")


@pytest.mark.parametrize(("fn", "kwargs", "name", "odd"), list(_cases()))
def test_an_odd_argument_is_computed_or_refused_naming_it(fn, kwargs, name, odd):
    try:
        out = fn(**{**kwargs, name: odd})
    except SymimpactError as exc:
        text = str(exc)
        assert text.strip() and "\n" not in text, text
        return
    _finite(out, (fn.__name__, name, odd))


def test_the_valid_calls_compute():
    for fn, (kwargs, _) in CASES.items():
        fn(**kwargs)  # every spoiled call above starts from a call that works


def test_backbone_and_a_compliant_contact_check_theirs():
    with pytest.raises(SymimpactError, match="xi"):
        backbone(SYSTEM, FORCING, E, xi="abc")
    with pytest.raises(SymimpactError, match="chi"):
        CompliantContact("hunt-crossley", chi="abc")
    assert design_row(SYSTEM, FORCING, E, BAND)["peak_amplitude"] > 0
