"""Compliant impact dampers on a structure of several modes (issue 36: "K impact dampers, each
with ... rigid with e, or any compliant law"): the contact phases integrated over the whole
state (:mod:`symimpact.forced.engine._structure_contact`) against what does not share that code — the
one-mode engine's compliant contact (:func:`simulate_forced`, its own Dormand–Prince steps on the
paper's two equations), SciPy's DOP853 on the modal equations with event location, one damper of
twice the mass and twice the law — and against the energy ledger."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.structure_orbits import shoot_structure
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import dampers
from symimpact.model.structure import beam_structure, structure_from_dict
from symimpact.model.system import ImpactSystem

M, K, C, m, GAP = 1.0, 1000.0, 0.5, 0.05, 0.02
ONE_MODE = {"modes": [{"f": math.sqrt(K / M) / (2 * math.pi), "mass": M,
                       "zeta": C / (2 * math.sqrt(K * M)), "shape": {"p": 1.0}}]}  # fmt: skip
LAWS = [("hertz", {"k_hz": 1e6, "c1": 2.0}), ("linear", {"k1": 1e5, "c1": 3.0}),
        ("hunt-crossley", {"k_hz": 1e6, "chi": 0.5})]  # fmt: skip
#: A steel cantilever, 1 m of 40 mm × 10 mm (8.36, 52.4 and 146.7 Hz), ζ 0.01.
BEAM = {"support": "cantilever", "E": 210e9, "I": 0.04 * 0.01**3 / 12, "rho": 7850.0, "A": 4e-4,
        "L": 1.0}  # fmt: skip


@pytest.mark.parametrize(("law", "params"), LAWS, ids=[law for law, _ in LAWS])
def test_one_mode_is_the_one_mode_engines_compliant_contact(law, params):
    """The paper's primary (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg in 20 mm, 2 N at 36 rad/s)
    as one mode of shape 1: the first eight contact onsets from rest against the one-mode
    engine's (1e-9 s: both integrate at rtol 1e-13 with their own steps; measured 1.9e-13 to
    1.6e-11 s; later the transient's sensitivity — about threefold per contact — amplifies the two
    integrators' differences), and the energy ledger closes (1e-10; measured ≤ 5.9e-12)."""
    system_law = "hertz" if law == "hunt-crossley" else law
    elastic = {k: v for k, v in params.items() if k != "chi"}
    system = ImpactSystem(M=M, K=K, C=C, m=m, gap=GAP, contact=system_law, **elastic)
    extra = {"chi": params["chi"]} if "chi" in params else {}
    one = simulate_forced(system, Forcing(F0=2, omega=36.0), contact=law, periods=8, **extra)
    structure = structure_from_dict(ONE_MODE)
    ds = dampers(structure, [{"name": "d", "at": "p", "m": m, "gap": GAP, "contact": law,
                              **params}])  # fmt: skip
    r = simulate_structure(structure, ds, "p", 2.0, 36.0, periods=8)
    assert len(one.impacts) >= 8 and len(r.impacts("d")) >= 8
    np.testing.assert_allclose(r.impacts("d")[:8], one.impacts[:8], rtol=0, atol=1e-9)
    assert r.energy["relative_residual"] < 1e-10


def _cantilever_reference(structure, ds, F0, omega, t_end):
    """DOP853 on the modal equations with the Hertz contact's force, contact onsets and exits
    located as events (rtol 1e-13)."""
    modes = structure.modes
    N = len(modes)
    Mi = np.array([md.mass for md in modes])
    Ki = np.array([md.omega**2 * md.mass for md in modes])
    Ci = np.array([2 * md.zeta * md.omega * md.mass for md in modes])
    d = ds[0]
    phi = np.array([md.shape[d.at] for md in modes])
    fi = F0 * np.array([md.shape["tip"] for md in modes])
    h = d.gap / 2

    def rhs(t, s):
        q, v, y, u = s[:N], s[N : 2 * N], s[2 * N], s[2 * N + 1]
        x, xd = phi @ q, phi @ v
        side = 1.0 if y > x else -1.0
        delta = side * (y - x) - h
        F = d.k_hz * delta**1.5 + d.c1 * side * (u - xd) if delta > 0 else 0.0
        a = (fi * math.cos(omega * t) - Ci * v - Ki * q + phi * side * F) / Mi
        return np.concatenate([v, a, [u, -side * F / d.m]])

    def wall(t, s):
        return abs(s[2 * N] - phi @ s[:N]) - h

    sol = solve_ivp(rhs, (0, t_end), np.zeros(2 * N + 2), method="DOP853", rtol=1e-13,
                    atol=1e-16, events=wall, max_step=2e-4)  # fmt: skip
    return sol.t_events[0]


def test_a_hertz_damper_at_a_cantilevers_tip_against_dop853():
    """Three cantilever modes, a 50 g mass in 10 mm at the tip on a Hertz contact (k_hz 1e8
    N/m^1.5, c1 5 N s/m), 2 N at the tip at 8 Hz for four periods: every contact onset and exit
    against DOP853 with event location (1e-8 s: the reference's rtol 1e-13 with its step capped
    at 0.2 ms; measured 7.1e-10 s over 14 onsets and exits), and the ledger closes (2e-12)."""
    s = beam_structure(**BEAM, points={"tip": 1.0}, modes=3, zeta=0.01)
    ds = dampers(s, [{"name": "d", "at": "tip", "m": 0.05, "gap": "10 mm", "contact": "hertz",
                      "k_hz": 1e8, "c1": 5.0}])  # fmt: skip
    omega = 2 * math.pi * 8.0
    r = simulate_structure(s, ds, "tip", 2.0, omega, periods=4)
    kinds = r.events[:, 7]
    got = np.sort(r.events[(kinds == 3) | (kinds == 4), 0])
    want = _cantilever_reference(s, ds, 2.0, omega, r.t_end)
    assert len(got) == len(want) >= 6
    assert np.max(np.abs(got - want)) < 1e-8
    assert r.energy["relative_residual"] < 1e-10


def test_two_identical_compliant_dampers_are_one_of_twice_the_mass_and_law():
    """The issue's check: two identical Hertz dampers at the tip, started identically, move
    together and equal one damper of twice the mass with twice the contact law (k_hz and c1
    doubled), over three periods of the three-mode cantilever: contact onsets to 1e-10 s (the
    issue's bound), the final modal state to 1e-9 of each block's scale (the two runs take their
    own steps, each to rtol 1e-13, over some hundred steps a contact: measured 5.5e-10), and the
    masses' displacement to 1e-9 of the tip's largest (measured 8.3e-10).  The pair stays alike
    to the bit: the same operations on the same numbers."""
    s = beam_structure(**BEAM, points={"tip": 1.0}, modes=3, zeta=0.01)
    one = {"at": "tip", "m": 0.05, "gap": "10 mm", "contact": "hertz", "k_hz": 1e8, "c1": 5.0}
    pair = dampers(s, [{"name": "a", **one}, {"name": "b", **one}])
    double = dampers(s, [{"name": "ab", **(one | {"m": 0.1, "k_hz": 2e8, "c1": 10.0})}])
    omega = 2 * math.pi * 8.0
    r2 = simulate_structure(s, pair, "tip", 2.0, omega, periods=3)
    r1 = simulate_structure(s, double, "tip", 2.0, omega, periods=3)
    assert len(r1.impacts("ab")) >= 3
    np.testing.assert_array_equal(r2.impacts("a"), r2.impacts("b"))
    np.testing.assert_allclose(r2.impacts("a"), r1.impacts("ab"), rtol=0, atol=1e-10)
    f2, f1 = r2.final_state, r1.final_state
    N = 3
    for block in (slice(1, 1 + N), slice(1 + N, 1 + 2 * N)):
        scale = np.max(np.abs(f1[block]))
        assert np.max(np.abs(f2[block] - f1[block])) < 1e-9 * scale
    y = 1 + 2 * N
    assert f2[y] == f2[y + 1] and f2[y + 2] == f2[y + 3]  # alike to the bit
    # of the scale the mass moves over: the tip's largest displacement, as the blocks' own
    assert abs(f2[y] - f1[y]) < 1e-9 * r1.amplitudes(0.0)["tip"]
    assert abs(f2[y + 2] - f1[y + 1]) < 1e-9 * abs(f1[y + 1])
    assert r2.energy["relative_residual"] < 1e-10


@pytest.mark.parametrize(("law", "params"), [("hunt-crossley", {"k_hz": 1e6, "chi": 2.0}),
                                             ("linear", {"k1": 1e5, "c1": 40.0})])  # fmt: skip
def test_a_compliant_orbit_is_shot_and_is_where_a_long_run_settles(law, params):
    """The one-mode primary at 35 rad/s with a well damped contact (two contacts a period): the
    orbit shot (differenced Jacobian) from 40 periods from rest is where 400 periods from rest
    settle (1e-9 of the state: the integrator's rtol 1e-13 over a contact's steps; the transient
    long gone: the settled state comes back after a period to 2e-12), and its impacts counted
    with chatter sequences once are its two contacts (not their onsets and exits)."""
    structure = structure_from_dict(ONE_MODE)
    ds = dampers(structure, [{"name": "d", "at": "p", "m": m, "gap": GAP, "contact": law,
                              **params}])  # fmt: skip
    start = simulate_structure(structure, ds, "p", 2.0, 35.0, periods=40).final_state[1:5]
    orbit = shoot_structure(structure, ds, "p", 2.0, 35.0, start)
    settled = simulate_structure(structure, ds, "p", 2.0, 35.0, periods=400).final_state[1:5]
    assert orbit.jacobian == "differenced" and orbit.stable and orbit.impacts == {"d": 2}
    assert orbit.impact_events == {"d": 2}  # its contacts, an exit not counted as an impact
    assert np.max(np.abs(orbit.state - settled)) < 1e-9 * np.max(np.abs(settled))


def test_compliant_dampers_bad_input_is_one_line():
    s = beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=2, zeta=0.01)
    base = {"name": "d", "at": "tip", "m": 0.05, "gap": "10 mm"}
    with pytest.raises(ParameterError, match=r"dampers\.d\.k_hz: missing"):
        dampers(s, [base | {"contact": "hertz"}])
    with pytest.raises(ParameterError, match="does not take e"):
        dampers(s, [base | {"contact": "linear", "k1": 1e5, "e": 0.5}])
    with pytest.raises(ParameterError, match=r"dampers\.d\.contact"):
        dampers(s, [base | {"contact": "steel"}])
