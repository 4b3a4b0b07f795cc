"""Periodic orbits of a structure through chatter and sticking (issue 36: "shooting and
continuation through sticking or chatter"; issue 33, item 3): Newton on the stroboscopic map with
the monodromy the engine of several modes carries through the accumulation point, the plastic
closure, the sticking phase and the release, against what does not share it — the one-mode
engine's own chain through the same events from its event log (:func:`symimpact.forced.monodromy`),
the map's central differences (:func:`symimpact.forced.orbits.structure_orbits.differenced_monodromy`)
and long simulations from rest."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced import Forcing, monodromy, shoot_from_rest
from symimpact.forced.orbits import structure_orbits
from symimpact.forced.orbits.structure_branch import structure_branch
from symimpact.forced.orbits.structure_orbits import (
    differenced_monodromy,
    shoot_structure,
    stroboscopic_map,
)
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import damper, dampers
from symimpact.model.structure import beam_structure, structure_from_dict
from symimpact.model.system import ImpactSystem

#: The paper's primary of tests/test_shooting.py (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg in
#: 20 mm, 2 N) as one mode of shape 1.
SYSTEM = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
ONE_MODE = {"modes": [{"f": math.sqrt(1000) / (2 * math.pi), "mass": 1.0,
                       "zeta": 0.5 / (2 * math.sqrt(1000)), "shape": {"p": 1.0}}]}  # fmt: skip
#: A steel cantilever, 1 m of 40 mm × 10 mm (8.36 and 52.4 Hz), ζ 0.02, a plastic damper of
#: 50 g in 10 mm at its tip, 2 N at the tip: every impact sticks, the tip carrying the mass.
BEAM = {"support": "cantilever", "E": 210e9, "I": 0.04 * 0.01**3 / 12, "rho": 7850.0, "A": 4e-4,
        "L": 1.0}  # fmt: skip


def _settled(structure, ds, omega, periods, F0=2.0, at="p"):
    res = simulate_structure(structure, ds, at, F0, omega, periods=periods)
    return res.final_state[1 : 1 + 2 * len(structure.modes) + 2 * len(ds)]


@pytest.mark.parametrize(("e", "omega"), [(0.05, 28.0), (0.16, 30.0), (0.6, 30.8)])
def test_one_mode_through_chatter_and_sticking_is_the_one_mode_engines_orbit(e, omega):
    """The orbits of tests/test_shooting.py whose mass chatters to an accumulation point and
    sticks each half period, shot on the structure of one mode from where its run from rest is
    after 300 periods: the orbit against the one-mode engine's (1e-9 of the scales: both
    Newtons stop near 1e-11), and the monodromy the engine carried against the one-mode
    engine's chain in the coordinates (x, ẋ, y, ẏ): the same closed forms in two orderings of
    the arithmetic, whose rounding the chatter's dozens of impacts amplify (measured 1.2e-12 to
    8.2e-11 of the scales; 1e-9), so the multipliers agree (1e-9)."""
    structure = structure_from_dict(ONE_MODE)
    ds = dampers(structure, [{"name": "d", "at": "p", "m": 0.05, "gap": 0.02, "e": e}])
    orbit = shoot_structure(structure, ds, "p", 2.0, omega, _settled(structure, ds, omega, 300))
    f = Forcing(F0=2, omega=omega)
    one = shoot_from_rest(SYSTEM, f, e, warmup=400)
    x, v, z, u = one.state
    want = np.array([x, v, x + z, u])
    a = one.amplitude
    scale = np.array([a, a * omega, 0.01, a * omega])
    kinds = set(orbit.run.events[:, 7].astype(int).tolist())
    assert orbit.jacobian == "carried" and orbit.stable and {1, 2} <= kinds
    assert np.max(np.abs(orbit.state - want) / scale) < 1e-9
    _, J, _ = monodromy(SYSTEM, f, e, np.array(one.state))
    T = np.eye(4)
    T[2, 0] = 1.0  # (x, ẋ, y, ẏ) = T·(x, ẋ, z, ẏ)
    carried = T @ J @ np.linalg.inv(T)
    assert np.max(np.abs((orbit.monodromy - carried) * scale[None, :] / scale[:, None])) < 1e-9
    moduli = np.sort(np.abs(orbit.multipliers))[::-1]
    assert np.max(np.abs(moduli - np.array(one.multipliers))) < 1e-9


def test_the_differenced_jacobian_equals_the_carried_one_on_two_modes():
    """Where the chain is carried (the two-mode cantilever's damper, e 0.6, at 7.6 Hz: impacts
    only), the differenced Jacobian equals it (1e-7 of the matrix's scale, the differences'
    truncation and rounding at steps of 1e-5, as above)."""
    s = beam_structure(**BEAM, points={"p": 1.0}, modes=2, zeta=0.02)
    ds = dampers(s, [{"name": "d", "at": "p", "m": 0.05, "gap": "10 mm", "e": 0.6}])
    omega = 2 * math.pi * 7.6
    orbit = shoot_structure(s, ds, "p", 2.0, omega, _settled(s, ds, omega, 300))
    assert orbit.jacobian == "carried" and sum(orbit.impacts.values()) >= 2
    G = differenced_monodromy(s, ds, "p", 2.0, omega, orbit.state)
    assert np.max(np.abs(G - orbit.monodromy)) < 1e-7 * np.max(np.abs(orbit.monodromy))


@pytest.mark.parametrize("f_hz", [7.5, 8.0, 8.5])
def test_a_sticking_orbit_of_two_modes_is_the_brute_force_steady_state(f_hz):
    """The plastic damper at the cantilever's tip: shot from 50 periods from rest, the orbit
    equals where a 400-period run from rest settles (its largest multiplier is at most 0.87:
    0.87^400 is far below rounding; 1e-9 of the scales, measured ~1e-13), a 300-period run
    from the orbit comes back to it (1e-9), and the monodromy carried through its plastic
    closures, sticking phases and releases is the map's central differences (1e-7 of the
    matrix's scale at the differences' step of 1e-5, as above; measured 3e-10 to 1.8e-9) where
    the section does not fall on the mass resting on its wall."""
    s = beam_structure(**BEAM, points={"p": 1.0}, modes=2, zeta=0.02)
    ds = dampers(s, [{"name": "d", "at": "p", "m": 0.05, "gap": "10 mm", "e": 0.0}])
    omega = 2 * math.pi * f_hz
    orbit = shoot_structure(s, ds, "p", 2.0, omega, _settled(s, ds, omega, 50))
    kinds = set(orbit.run.events[:, 7].astype(int).tolist())
    # at 8.5 Hz the section falls in a sticking phase (the mass on its wall): there the map's
    # sides differ and the Jacobian is differenced (one-sided into the clearance)
    phi = s.shapes(["p"]).ravel()
    on_wall = abs(orbit.state[4] - phi @ orbit.state[:2]) >= 0.005 * (1 - 1e-9)
    assert on_wall == (f_hz == 8.5)
    assert {1, 2} <= kinds and orbit.jacobian == ("differenced" if on_wall else "carried")
    assert orbit.stable and orbit.impact_events["d"] >= 2
    settled = _settled(s, ds, omega, 400)
    scale = np.abs(settled).max()
    assert np.max(np.abs(orbit.state - settled)) < 1e-9 * scale
    back = _settled_from(s, ds, omega, orbit.state, 300)
    assert np.max(np.abs(back - orbit.state)) < 1e-9 * scale
    if not on_wall:
        G = differenced_monodromy(s, ds, "p", 2.0, omega, orbit.state)
        assert np.max(np.abs(G - orbit.monodromy)) < 1e-7 * np.max(np.abs(G))


def _settled_from(s, ds, omega, state, periods):
    res = simulate_structure(s, ds, "p", 2.0, omega, periods=periods, state=state)
    return res.final_state[1 : 1 + 2 * len(s.modes) + 2 * len(ds)]


def test_a_branch_is_continued_through_sticking():
    """The plastic damper's branch from 7.5 to 7.75 Hz: every orbit sticks (carried), the
    branch reaches the band's end, and at its middle orbit the amplitude is the one a run from
    rest settles on (1e-8: the orbit's residual and the 400-period transient are far below)."""
    s = beam_structure(**BEAM, points={"p": 1.0}, modes=2, zeta=0.02)
    ds = dampers(s, [{"name": "d", "at": "p", "m": 0.05, "gap": "10 mm", "e": 0.0}])
    w0, w1 = 2 * math.pi * 7.5, 2 * math.pi * 7.75
    b = structure_branch(s, ds, "p", 2.0, w0, w1, _settled(s, ds, w0, 300), step=0.1)
    assert not b.ended and b.omegas[-1] == pytest.approx(w1, rel=1e-12)
    assert all(o.jacobian == "carried" for o in b.orbits)
    o = b.orbits[len(b.orbits) // 2]
    run = simulate_structure(s, ds, "p", 2.0, o.run.omega, periods=400)
    assert o.amplitudes["p"] == pytest.approx(float(run.period_max[-1, 0]), rel=1e-8)


def test_a_plastic_damper_on_the_chain_is_shot():
    """The issue's two-DOF chain with a plastic damper (0.1 kg, 0.5 clearance) at its second
    DOF, driven there with 0.1 at Ω 0.55: the mass sticks at once, and the shot orbit is where a
    600-period run settles (1e-9 of the state)."""
    structure = structure_from_dict({"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]],
                                            "zeta": 0.015}})  # fmt: skip
    d = damper(structure, "d", 1, 0.1, 0.5, 0.0)
    start = _settled(structure, [d], 0.55, 20, F0=0.1, at="1")
    orbit = shoot_structure(structure, [d], "1", 0.1, 0.55, start)
    settled = _settled(structure, [d], 0.55, 600, F0=0.1, at="1")
    assert orbit.jacobian == "carried" and orbit.stable
    assert np.max(np.abs(orbit.state - settled)) < 1e-9 * np.max(np.abs(settled))


def _on_the_attractor(s, ds, omega, base):
    """The state where runs of 200 periods from rest, each from the last one's end, first end
    on a motion that repeats after one to four periods (the tip's period maxima to 1e-9; at
    most 2000 periods): at 8 Hz the chattering dampers' transient is chaotic, and how long it
    lasts depends on the rounding of the run (measured: from under 200 to some 550 periods)."""
    state = None
    for _ in range(10):
        res = simulate_structure(s, ds, "tip", 2.0, omega, periods=200, base=base, state=state)
        state = res.final_state[1:11]
        top = res.period_max[:, 0]
        if any(abs(top[-1] - top[-1 - k]) <= 1e-9 * top[-1] for k in (1, 2, 3, 4)):
            break
    return state


@pytest.mark.parametrize(("f_hz", "e_tip", "e_mid", "base"),
                         [(8.0, 0.16, 0.6, 0.0), (7.8, 0.16, 0.16, 0.0), (8.0, 0.0, 0.6, 0.0),
                          (8.0, 0.16, 0.6, 0.002)],
                         ids=["chatter-impacts", "two-chatter", "plastic-impacts", "base"])  # fmt: skip
def test_the_monodromy_carried_through_sticking_is_the_limit_of_the_map_s_differences(
    f_hz, e_tip, e_mid, base, monkeypatch
):
    """Three cantilever modes (8.4, 52 and 147 Hz) with a damper at the tip that chatters to its
    accumulation point and sticks (or closes plastically) and one at mid-span, 2 N at the tip (with
    ``base``, 2 mm of the supports' motion as well), one period from a state on the motion the runs
    from rest settle on (:func:`_on_the_attractor`): the monodromy carried through the
    accumulations, the sticking phases — with the other damper's impacts while the mass rides
    (where the log has them) — and the releases, against the map's central differences at steps h
    of 1e-5, 3e-6 and 1e-6 of each block's scale. Their error is truncation, falling as h², plus
    rounding growing as 1/h, which the chatter's impacts amplify (measured at the three steps:
    2.4e-8, 2.1e-9, 8.3e-10; two chattering dampers 1.9e-8, 4.8e-9, 1.0e-8; e 0 at the tip
    7.3e-9, 6.8e-10, 7.6e-10; on the moving supports 7.4e-9, 8.1e-9, 4.0e-8). The best of the
    three steps is within 2e-8 of the carried monodromy (measured 6.8e-10 to 7.4e-9)."""
    s = beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=3, zeta=0.02)
    ds = dampers(s, [{"name": "tip", "at": "tip", "m": 0.05, "gap": "10 mm", "e": e_tip},
                     {"name": "mid", "at": "mid", "m": 0.03, "gap": "3 mm", "e": e_mid}])  # fmt: skip
    omega = 2 * math.pi * f_hz
    start = _on_the_attractor(s, ds, omega, base)
    _, G, res = stroboscopic_map(s, ds, "tip", 2.0, omega, start, 1, base=base)
    kinds = set(res.events[:, 7].astype(int).tolist())
    assert {1, 2} <= kinds and np.all(np.isfinite(G))  # accumulations (or closures), releases
    errors = []
    for h in (1e-5, 3e-6, 1e-6):
        monkeypatch.setattr(structure_orbits, "DIFFERENCE_STEP", h)
        FD = differenced_monodromy(s, ds, "tip", 2.0, omega, start, 1, base=base)
        errors.append(np.max(np.abs(G - FD)) / np.max(np.abs(FD)))
    assert min(errors) < 2e-8
