"""Periodic orbits of a structure of several modes by shooting (issue 36): the monodromy carried
through flights, impacts and a stop's contacts against central differences of the stroboscopic
map, and the shot orbit against the state a long run settles on."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced.orbits.structure_orbits import shoot_structure, stroboscopic_map
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import damper
from symimpact.model.stops import stop
from symimpact.model.structure import structure_from_dict

# the issue's two-DOF chain (masses [1, 1], springs [0, 1, 1], modal damping 1.5 %), driven at
# its second DOF with 0.1
FE = {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015}
F0 = 0.1


def _settled(structure, dampers, stops, omega, periods):
    res = simulate_structure(structure, dampers, "1", F0, omega, periods=periods, stops=stops)
    return res.final_state[1 : 1 + 2 * len(structure.modes) + 2 * len(dampers)]


@pytest.mark.parametrize(
    ("with_damper", "omega", "periods"),
    [(False, 0.62, 2), (True, 0.62, 1), (True, 0.62, 2), (True, 0.55, 1)],
    ids=["stop-2T", "damper-stop-1T", "damper-stop-2T", "damper-1T"],
)
def test_the_carried_monodromy_is_the_map_s_central_difference(with_damper, omega, periods):
    structure = structure_from_dict({"fe": FE})
    dampers = [damper(structure, "d", 1, 0.1, 0.5, 0.6)] if with_damper else []
    stops = [stop(structure, "s", 0, 0.6, "both", "linear", 50.0, 0.3)] if omega == 0.62 else []
    X = _settled(structure, dampers, stops, omega, 200)
    _, G, res = stroboscopic_map(structure, dampers, "1", F0, omega, X, periods, stops)
    kinds = set(res.events[:, 7].astype(int).tolist())
    assert kinds <= {0, 3, 4} and len(res.events) >= 4  # impacts and contacts, no sticking
    FD = np.zeros_like(G)
    for j in range(len(X)):
        dx = np.zeros(len(X))
        dx[j] = 1e-7 * max(1.0, abs(X[j]))
        a, _, _ = stroboscopic_map(structure, dampers, "1", F0, omega, X + dx, periods, stops)
        b, _, _ = stroboscopic_map(structure, dampers, "1", F0, omega, X - dx, periods, stops)
        FD[:, j] = (a - b) / (2.0 * dx[j])
    # central differences at h = 1e-7: roundoff ε·abs(P)/h ≈ 1e-9 and a truncation h²·P''' that
    # an impact near the period's end makes large (measured 6e-9 over these runs; 6.5e-7 at
    # h = 1e-6, falling as h²): 1e-6 of the matrix's scale is what the differences can resolve
    assert np.max(np.abs(G - FD)) < 1e-6 * np.max(np.abs(G))


def test_the_shot_orbit_is_where_a_long_run_settles():
    structure = structure_from_dict({"fe": FE})
    d = damper(structure, "d", 1, 0.1, 0.5, 0.6)
    start = _settled(structure, [d], [], 0.55, 20)
    orbit = shoot_structure(structure, [d], "1", F0, 0.55, start)
    settled = _settled(structure, [d], [], 0.55, 600)
    assert orbit.iterations > 2 and orbit.residual < 1e-11
    # the transient decays as the largest multiplier (0.889) to the 600th power, far below
    # rounding: what is left is the runs' roundoff (measured 3e-12 of the state)
    assert np.max(np.abs(orbit.state - settled)) < 1e-9 * np.max(np.abs(settled))
    assert orbit.stable and abs(orbit.multipliers[0]) < 1.0
    assert orbit.impacts == {"d": 4}
    again = simulate_structure(structure, [d], "1", F0, 0.55, periods=1, state=orbit.state)
    assert np.max(np.abs(again.final_state[1:7] - orbit.state)) < 1e-10


def test_the_chain_s_orbit_against_its_stop():
    structure = structure_from_dict({"fe": FE})
    s = stop(structure, "s", 0, 0.6, "both", "linear", 50.0, 0.3)
    start = _settled(structure, [], [s], 0.62, 60)
    orbit = shoot_structure(structure, [], "1", F0, 0.62, start, stops=[s])
    settled = _settled(structure, [], [s], 0.62, 400)
    assert orbit.impacts == {"s": 2} and orbit.stable
    assert np.max(np.abs(orbit.state - settled)) < 1e-9 * np.max(np.abs(settled))


def test_a_damper_that_meets_no_wall_adds_two_multipliers_at_one():
    structure = structure_from_dict({"fe": FE})
    d = damper(structure, "d", 1, 0.1, 5.0, 0.6)  # a clearance the motion never spans
    orbit = shoot_structure(structure, [d], "1", F0, 0.75, np.zeros(6))
    G = orbit.run.monodromy
    T = 2 * np.pi / 0.75
    assert G[4, 4] == 1.0 and G[5, 5] == 1.0 and G[4, 5] == pytest.approx(T, rel=1e-15)
    assert orbit.impacts == {"d": 0} and orbit.stable
    assert sorted(np.abs(orbit.multipliers))[-2:] == pytest.approx([1.0, 1.0], abs=1e-12)


CHAIN_FILE = {"fe": FE, "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+",
                                   "contact": "linear", "k1": 100, "c1": 0}],
              "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip


def _periodic(tmp_path, capsys, *args):
    import json

    from symimpact.cli import main

    path = tmp_path / "chain.json"
    path.write_text(json.dumps(CHAIN_FILE))
    code = main(["periodic", "--structure", str(path), *args])
    return code, capsys.readouterr()


def test_periodic_shoots_the_issue_s_chain_on_the_command_line(tmp_path, capsys):
    import json

    from symimpact.model.structure_model import model_from_dict

    code, out = _periodic(tmp_path, capsys, "--omega", "0.65", "--json")
    assert code == 0, out.err
    got = json.loads(out.out)
    assert got["periods"] == 1 and got["stable"] and got["impacts"] == {"s": 1}
    model = model_from_dict(CHAIN_FILE)
    start = simulate_structure(model.structure, [], "1", F0, 0.65, periods=300,
                               stops=model.stops).final_state[1:5]  # fmt: skip
    orbit = shoot_structure(model.structure, [], "1", F0, 0.65, start, stops=model.stops)
    assert got["state"] == [float(x) for x in orbit.state]


def test_a_period_four_motion_is_named_and_then_shot(tmp_path, capsys):
    """At Ω 0.62 the chain's stop has doubled the period twice: one period's shooting is refused
    naming --multiple with the period the settled run returns after, which then shoots."""
    import json

    code, out = _periodic(tmp_path, capsys, "--omega", "0.62")
    assert code == 2 and out.err.count("\n") == 1
    assert "error: multiple:" in out.err and "try --multiple 4" in out.err
    code, out = _periodic(tmp_path, capsys, "--omega", "0.62", "--multiple", "4", "--json")
    assert code == 0, out.err
    got = json.loads(out.out)
    assert got["stable"] and got["periods"] == 4
    # brute force: the orbit's state comes back after 4 periods, not after 1 or 2
    from symimpact.model.structure_model import model_from_dict

    model = model_from_dict(CHAIN_FILE)
    state = np.array(got["state"])
    back = {k: simulate_structure(model.structure, [], "1", F0, 0.62, periods=k, state=state,
                                  stops=model.stops).final_state[1:5] for k in (1, 2, 4)}  # fmt: skip
    scale = np.max(np.abs(state))
    assert np.max(np.abs(back[4] - state)) < 1e-10 * scale
    assert min(np.max(np.abs(back[k] - state)) for k in (1, 2)) > 1e-2 * scale


@pytest.mark.parametrize(("e", "omega", "gap"), [(0.5, 0.7, 0.5), (0.5, 0.62, 0.8)])
def test_the_monodromy_through_a_rigid_stop_is_the_map_s_central_difference(e, omega, gap):
    structure = structure_from_dict({"fe": FE})
    stops = [stop(structure, "s", 0, gap, "+", "rigid", e=e)]
    X = _settled(structure, [], stops, omega, 300)
    _, G, res = stroboscopic_map(structure, [], "1", F0, omega, X, 1, stops)
    assert set(res.events[:, 7].astype(int).tolist()) == {0}
    FD = np.zeros_like(G)
    for j in range(len(X)):
        dx = np.zeros(len(X))
        dx[j] = 1e-7 * max(1.0, abs(X[j]))
        a, _, _ = stroboscopic_map(structure, [], "1", F0, omega, X + dx, 1, stops)
        b, _, _ = stroboscopic_map(structure, [], "1", F0, omega, X - dx, 1, stops)
        FD[:, j] = (a - b) / (2.0 * dx[j])
    # as for the dampers (above): measured 1.4e-9 and 2.9e-8 of the matrix's scale
    assert np.max(np.abs(G - FD)) < 1e-6 * np.max(np.abs(G))
    orbit = shoot_structure(structure, [], "1", F0, omega, X, stops=stops)
    assert orbit.stable and orbit.impacts == {"s": 1}
