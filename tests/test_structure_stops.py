"""Stops on a structure of several modes (issue 36): walls fixed to the ground with a linear
contact law, in the engine of several modes (:mod:`symimpact.forced.engine._modal`), against a
brute-force integration of the physical equations (DOP853 restarted at every contact onset and
exit) written here from the finite-element matrices."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import damper
from symimpact.model.stops import stop
from symimpact.model.structure import modal_structure, structure_from_dict
from symimpact.model.structure_model import model_from_dict

# the issue's two-DOF chain: masses [1, 1], springs [0, 1, 1], modal damping 1.5 %
FE = {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015}
F0 = 0.1


def _chain():
    return structure_from_dict({"fe": FE})


def _brute_force(structure, walls, gap, k1, c1, omega, periods):
    """The chain's physical equations M ẍ + C ẋ + K x = f + contact, C = MΦ diag(2ζᵢωᵢ/Mᵢ) ΦᵀM
    (the modal damping the structure states), integrated by DOP853 at rtol 1e-13 and restarted
    at every located onset and exit of the contact at DOF 0: (final state, onset times)."""
    M, K = np.array(FE["M"], float), np.array(FE["K"], float)
    Phi = structure.shapes()
    C = np.zeros((2, 2))
    for i, mode in enumerate(structure.modes):
        Mphi = M @ Phi[:, i]
        C += 2.0 * mode.zeta * mode.omega / mode.mass * np.outer(Mphi, Mphi)

    def rhs(t, y, w):
        x, v = y[:2], y[2:]
        f = np.array([0.0, F0 * math.cos(omega * t)]) - K @ x - C @ v
        if w != 0:
            f[0] -= k1 * (x[0] - w * gap) + c1 * v[0]
        return np.concatenate([v, np.linalg.solve(M, f)])

    def crossing(level, direction):
        def event(t, y, w):
            return y[0] - level

        event.terminal, event.direction = True, direction
        return event

    t, y, w, onsets = 0.0, np.zeros(4), 0, []
    t_end = periods * 2.0 * math.pi / omega
    while t < t_end:
        if w == 1:
            events = [crossing(gap, -1)]
        elif w == -1:
            events = [crossing(-gap, 1)]
        else:
            events = [crossing(gap, 1), crossing(-gap, -1)]
            events = [events[0]] if walls == 1 else [events[1]] if walls == -1 else events
        sol = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=1e-13, atol=1e-15,
                        events=events, args=(w,))  # fmt: skip
        t, y = sol.t[-1], sol.y[:, -1]
        if sol.status == 1:
            j = next(j for j, te in enumerate(sol.t_events) if len(te))
            t, y = sol.t_events[j][0], sol.y_events[j][0]
            if w == 0:
                onsets.append(t)
                w = int(np.sign(y[0]))
            else:
                w = 0
    return y, np.array(onsets)


@pytest.mark.parametrize(("side", "gap"), [("+", 1.0), ("-", 1.0), ("both", 0.8)])
def test_the_chain_with_a_stop_against_a_brute_force_integration(side, gap):
    structure = _chain()
    s = stop(structure, "s", 0, gap, side, "linear", 100.0, 0.5)
    omega, periods = 0.62, 30
    res = simulate_structure(structure, [], "1", F0, omega, periods=periods, stops=[s])
    y, onsets = _brute_force(structure, s.walls, gap, 100.0, 0.5, omega, periods)
    Phi = structure.shapes()
    N = len(structure.modes)
    x = Phi @ res.final_state[1 : 1 + N]
    xd = Phi @ res.final_state[1 + N : 1 + 2 * N]
    mine = res.contacts("s")
    assert len(mine) == len(onsets) > 10
    # DOP853 at rtol 1e-13 through ~25 contacts holds ~1e-12 (measured 2.8e-12 s on the onsets,
    # 1.2e-12 of the state); the issue's criterion is 1e-8 relative
    assert np.max(np.abs(mine - onsets)) < 1e-8 * res.t_end
    assert np.max(np.abs(np.concatenate([x, xd]) - y)) < 1e-8 * np.max(np.abs(y))
    # the ledger closes with the stop's spring energy and its dashpot's dissipation (roundoff
    # of the Gauss–Legendre sums: measured 2e-14)
    assert res.energy["dissipated_stops"] > 0.0
    assert res.energy["relative_residual"] < 1e-11


def test_a_stop_out_of_reach_leaves_the_run_of_the_dampers_alone():
    structure = _chain()
    d = damper(structure, "d", 1, 0.1, 0.5, 0.6)
    far = stop(structure, "far", 0, 1e3, "both", "linear", 100.0, 0.0)
    alone = simulate_structure(structure, [d], "1", F0, 0.62, periods=40)
    beside = simulate_structure(structure, [d], "1", F0, 0.62, periods=40, stops=[far])
    assert len(alone.events) > 20
    assert np.array_equal(alone.events, beside.events)
    assert np.array_equal(alone.period_max, beside.period_max)
    assert len(beside.contacts("far")) == 0


def test_a_damper_and_a_stop_together_close_the_energy_ledger():
    structure = _chain()
    d = damper(structure, "d", 1, 0.1, 0.5, 0.6)
    s = stop(structure, "s", 0, 0.6, "both", "linear", 50.0, 0.3)
    res = simulate_structure(structure, [d], "1", F0, 0.62, periods=60, stops=[s])
    assert len(res.impacts("d")) > 10 and len(res.contacts("s")) > 10
    # impacts and contacts alternate; the ledger's terms are Gauss–Legendre sums (1e-14 each)
    assert res.energy["relative_residual"] < 1e-11


def test_the_issue_s_file_runs_on_the_command_line(tmp_path, capsys):
    data = {"fe": FE, "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+",
                                 "contact": "linear", "k1": 100, "c1": 0}],
            "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip
    path = tmp_path / "chain.json"
    path.write_text(json.dumps(data))
    assert main(["simulate", "--structure", str(path), "--omega", "0.62", "--periods", "40",
                 "--json"]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    model = model_from_dict(data)
    res = simulate_structure(model.structure, model.dampers, model.force_at, model.F0, 0.62,
                             periods=40, stops=model.stops)  # fmt: skip
    assert out["impacts"] == {"s": len(res.contacts("s"))} and out["impacts"]["s"] > 5
    steady = {p: float(res.period_max[30:, j].max()) for j, p in enumerate(res.points)}
    assert out["amplitudes"] == steady
    assert main(["simulate", "--structure", str(path), "--omega", "0.62", "--periods", "40"]) == 0
    assert "stop 's' at '0':" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("change", "parameter"),
    [
        ({"side": "up"}, "stops.s.side"),
        ({"k1": -5}, "stops.s.k1"),
        ({"k1": None}, "stops.s.k1"),
        ({"c1": -1}, "stops.s.c1"),
        ({"gap": 0}, "stops.s.gap"),
        ({"at": 7}, "stops.s.at"),
        ({"contact": "hertz"}, "stops.s.contact"),
        ({"wall": 1}, "stops[0]"),
    ],
)
def test_a_bad_stop_is_refused_naming_its_field(change, parameter):
    entry = {"name": "s", "at": 0, "gap": 1, "side": "+", "contact": "linear", "k1": 100}
    entry.update(change)
    entry = {k: v for k, v in entry.items() if v is not None}
    with pytest.raises(ParameterError) as err:
        model_from_dict({"fe": FE, "stops": [entry], "force": {"at": 1, "amplitude": 0.1}})
    assert err.value.parameter == parameter


def test_a_stop_named_as_a_damper_is_refused():
    data = {"fe": FE, "dampers": [{"name": "s", "at": 1, "m": 0.1, "gap": 0.5, "e": 0.6}],
            "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+", "k1": 100}],
            "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip
    with pytest.raises(ParameterError) as err:
        model_from_dict(data)
    assert err.value.parameter == "stops.s"


# --- rigid stops: Newton's law at the point, chatter to its accumulation, the point held ---


def _chain_matrices(structure):
    M, K = np.array(FE["M"], float), np.array(FE["K"], float)
    Phi = structure.shapes()
    C = np.zeros((2, 2))
    for i, mode in enumerate(structure.modes):
        Mphi = M @ Phi[:, i]
        C += 2.0 * mode.zeta * mode.omega / mode.mass * np.outer(Mphi, Mphi)
    return M, K, C


def _rigid_brute_force(structure, gap, e, F, omega, periods):
    """The chain's physical equations with a rigid wall at x₀ = +gap: DOP853 at rtol 1e-13
    between impacts (each located as x₀ reaching the wall from below, after the rebound's apex
    so the search never starts on the wall), Newton's law at DOF 0 (M = I: only ẋ₀ changes);
    once the rebound is below 1e-9 the point is held (x₀ = gap, ẋ₀ = 0, DOF 1 alone) until the
    spring and damper forces on DOF 0 turn away from the wall.  (final state, [(t, kind)])."""
    M, K, C = _chain_matrices(structure)

    def forces(t, x, v):
        return np.array([0.0, F * math.cos(omega * t)]) - K @ x - C @ v

    def free(t, y):
        return np.concatenate([y[2:], np.linalg.solve(M, forces(t, y[:2], y[2:]))])

    def held(t, y):
        return np.array([y[1], forces(t, np.array([gap, y[0]]), np.array([0.0, y[1]]))[1]])

    def event(fn, direction):
        fn.terminal, fn.direction = True, direction
        return fn

    hit = event(lambda t, y: y[0] - gap, 1)
    apex = event(lambda t, y: y[2], 1)
    pull = event(lambda t, y: forces(t, np.array([gap, y[0]]), np.array([0.0, y[1]]))[0], -1)
    t, y, t_end, log = 0.0, np.zeros(4), periods * 2 * math.pi / omega, []
    opts = {"method": "DOP853", "rtol": 1e-13, "atol": 1e-15}
    while t < t_end:
        if log and log[-1][1] == 0:
            sol = solve_ivp(free, (t, t_end), y, events=apex, **opts)
            t, y = (
                (sol.t_events[0][0], sol.y_events[0][0])
                if sol.status == 1
                else (sol.t[-1], sol.y[:, -1])
            )
        sol = solve_ivp(free, (t, t_end), y, events=hit, **opts)
        t, y = sol.t[-1], sol.y[:, -1].copy()
        if sol.status != 1:
            break
        t, y = sol.t_events[0][0], sol.y_events[0][0].copy()
        vn = y[2]
        y[0], y[2] = gap, -e * vn
        log.append((t, 0))
        if e * vn < 1e-9:
            log.append((t, 1))
            sol = solve_ivp(held, (t, t_end), y[[1, 3]], events=pull, **opts)
            t, w = sol.t[-1], sol.y[:, -1]
            if sol.status == 1:
                t, w = sol.t_events[0][0], sol.y_events[0][0]
                log.append((t, 2))
            y = np.array([gap, w[0], 0.0, w[1]])
    return y, np.array(log)


@pytest.mark.parametrize(("e", "omega", "gap"), [(0.8, 0.62, 0.8), (0.5, 0.7, 0.5)])
def test_a_rigid_stop_s_impacts_against_a_brute_force_integration(e, omega, gap):
    structure = _chain()
    s = stop(structure, "s", 0, gap, "+", "rigid", e=e)
    res = simulate_structure(structure, [], "1", F0, omega, periods=30, stops=[s])
    y, log = _rigid_brute_force(structure, gap, e, F0, omega, 30)
    assert set(res.events[:, 7].astype(int).tolist()) == {0}  # impacts only: no chatter here
    Phi = structure.shapes()
    state = np.concatenate([Phi @ res.final_state[1:3], Phi @ res.final_state[3:5]])
    mine = res.contacts("s")
    assert len(mine) == len(log) > 10
    # DOP853 at rtol 1e-13 between ~25 impacts: measured 5e-13 s and 2.5e-13 of the state
    assert np.max(np.abs(mine - log[:, 0])) < 1e-9 * res.t_end
    assert np.max(np.abs(state - y)) < 1e-9 * np.max(np.abs(y))
    assert res.energy["dissipated_impacts"] > 0 and res.energy["relative_residual"] < 1e-11


def _two_walls_brute_force(structure, gap, e, F, omega, periods):
    """The chain's physical equations between two rigid walls at x₀ = ±gap: DOP853 at rtol 1e-13,
    each meeting of either wall a terminal event (x₀ − gap rising, x₀ + gap falling) where
    Newton's law reverses ẋ₀ with e (M = I: only ẋ₀ changes) and the point is set four units in
    the last place inside its wall.  Returns (final state, impact times)."""
    M, K, C = _chain_matrices(structure)

    def free(t, y):
        f = np.array([0.0, F * math.cos(omega * t)]) - K @ y[:2] - C @ y[2:]
        return np.concatenate([y[2:], np.linalg.solve(M, f)])

    def upper(t, y):
        return y[0] - gap

    def lower(t, y):
        return y[0] + gap

    upper.terminal, upper.direction = True, 1.0
    lower.terminal, lower.direction = True, -1.0
    t, y, t_end, hits = 0.0, np.zeros(4), periods * 2 * math.pi / omega, []
    while t < t_end:
        sol = solve_ivp(free, (t, t_end), y, events=(upper, lower), method="DOP853", rtol=1e-13,
                        atol=1e-15)  # fmt: skip
        t, y = sol.t[-1], sol.y[:, -1].copy()
        if sol.status != 1:
            break
        w = 1.0 if len(sol.t_events[0]) else -1.0
        y[0], y[2] = w * gap * (1.0 - 4e-16), -e * y[2]
        hits.append(t)
    return y, np.array(hits)


def test_a_two_sided_rigid_stop_watches_its_far_wall_while_the_near_one_is_held_off():
    """A rigid stop with both walls (gap 0.2, e 0.6) at the chain's first DOF, 0.2 at the second
    at Ω 0.55 for six periods.  After an impact on one wall the search does not look for that
    wall again until the point could come back (2|ẋ|/A), but the point crosses to the other wall
    sooner: before the fix the second impact was found at 5.4954 s instead of 5.2856 s, 0.048
    beyond the wall, and the ledger missed 0.4 %.  Impact times and the final state against
    DOP853 with both walls as terminal events (1e-9 of the run, 1e-9 of the state, as the
    one-sided test above; measured 9.1e-13 s over 16 impacts and 5.6e-13) and the ledger
    (1e-11)."""
    structure = _chain()
    s = stop(structure, "s", 0, 0.2, "both", "rigid", e=0.6)
    res = simulate_structure(structure, [], "1", 0.2, 0.55, periods=6, stops=[s])
    y, hits = _two_walls_brute_force(structure, 0.2, 0.6, 0.2, 0.55, 6)
    assert set(res.events[:, 7].astype(int).tolist()) == {0}  # impacts only: no chatter here
    Phi = structure.shapes()
    state = np.concatenate([Phi @ res.final_state[1:3], Phi @ res.final_state[3:5]])
    mine = res.contacts("s")
    assert len(set(np.sign(res.events[:, 4]))) == 2  # both walls met
    assert len(mine) == len(hits) > 10
    assert np.max(np.abs(mine - hits)) < 1e-9 * res.t_end
    assert np.max(np.abs(state - y)) < 1e-9 * np.max(np.abs(y))
    assert res.energy["relative_residual"] < 1e-11


def test_a_rigid_stop_s_chatter_holds_the_point_until_the_wall_would_pull():
    structure = _chain()
    s = stop(structure, "s", 0, 0.2, "+", "rigid", e=0.3)
    res = simulate_structure(structure, [], "1", 0.3, 0.5, periods=12, stops=[s])
    y, log = _rigid_brute_force(structure, 0.2, 0.3, 0.3, 0.5, 12)
    kinds = res.events[:, 7]
    mine = {k: res.events[kinds == k, 0] for k in (1, 2)}
    theirs = {k: log[log[:, 1] == k, 0] for k in (1, 2)}
    assert len(mine[1]) == len(theirs[1]) == len(mine[2]) == len(theirs[2]) >= 5
    # the release: the wall's force turning, located to 4e-16 of the time by both (measured
    # 1.9e-13 s); the hold's start: the brute force stops resolving rebounds below 1e-9, the
    # engine jumps the last 1e-7 periods of the sequence (measured 1.9e-6 s apart)
    assert np.max(np.abs(mine[2] - theirs[2])) < 1e-9
    assert np.max(np.abs(mine[1] - theirs[1])) < 1e-5
    Phi = structure.shapes()
    state = np.concatenate([Phi @ res.final_state[1:3], Phi @ res.final_state[3:5]])
    assert np.max(np.abs(state - y)) < 1e-9 * np.max(np.abs(y))
    # while held the point sits on its wall: each release starts there
    released = res.events[kinds == 2]
    assert np.max(np.abs(released[:, 1] - 0.2)) < 1e-12
    assert res.energy["relative_residual"] < 1e-11


@pytest.mark.parametrize(
    ("entry", "parameter"),
    [
        ({"contact": "rigid", "e": 0.5, "k1": 100}, "stops.s.k1"),
        ({"contact": "rigid"}, "stops.s.e"),
        ({"contact": "rigid", "e": 1.5}, "stops.s.e"),
        ({"contact": "linear", "k1": 100, "e": 0.5}, "stops.s.e"),
    ],
)
def test_a_stop_s_law_takes_its_own_fields(entry, parameter):
    base = {"name": "s", "at": 0, "gap": 1, "side": "+"}
    with pytest.raises(ParameterError) as err:
        model_from_dict({"fe": FE, "stops": [base | entry], "force": {"at": 1, "amplitude": 0.1}})
    assert err.value.parameter == parameter


def test_two_rigid_stops_with_one_wall_are_refused_and_walls_apart_are_kept(tmp_path, capsys):
    """Two rigid stops with a wall at one place (one point, side, gap) are one constraint written
    twice (and a linear stop at a rigid wall never presses: refused too; two linear walls at one
    place are springs side by side, kept): held on both, the point was passed from one to the other at rounding-level speeds,
    ten million times in three periods of a cantilever, before the run gave up.  They are
    refused in one line naming the second stop, from a structure file (exit 2) and from Python,
    and so are two points' walls that coincide in the modes kept (one mode: gaps in the ratio of
    the shapes), while gaps 10 % off that ratio run;
    a "+" and a "-" stop at one point are two walls, kept, and give the events of one two-sided
    stop there (equal to the bit on the machine this was written on: the same walls, searched
    alike; the test asks 1e-12, for other compilers' rounding)."""
    walls = [{"name": "a", "at": 0, "gap": 0.2, "side": "both", "contact": "rigid", "e": 0.0},
             {"name": "b", "at": 0, "gap": 0.2, "side": "+", "contact": "rigid", "e": 0.5}]  # fmt: skip
    path = tmp_path / "chain.json"
    path.write_text(json.dumps({"fe": FE, "stops": walls, "force": {"at": 1, "amplitude": F0}}))
    assert main(["simulate", "--structure", str(path), "--omega", "0.62", "--periods", "3"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "stops.b" in err and "'a'" in err
    structure = _chain()
    a, b = (stop(structure, w["name"], 0, 0.2, w["side"], "rigid", e=w["e"]) for w in walls)
    with pytest.raises(ParameterError) as exc:
        simulate_structure(structure, [], "1", F0, 0.62, periods=3, stops=[a, b])
    assert exc.value.parameter == "stops.b"
    soft = stop(structure, "soft", 0, 0.2, "+", "linear", 100.0, 0.0)
    with pytest.raises(ParameterError) as exc:  # never pressed but for rounding (ledger 3e-9)
        simulate_structure(structure, [], "1", F0, 0.62, periods=3, stops=[a, soft])
    assert exc.value.parameter == "stops.soft" and "never presses" in exc.value.reason
    twin = stop(structure, "twin", 0, 0.2, "both", "linear", 50.0, 0.0)  # springs side by side
    assert simulate_structure(structure, [], "1", F0, 0.62, periods=3, stops=[soft, twin]).t_end > 0
    plus, minus = (stop(structure, n, 0, 0.2, side, "rigid", e=0.0)
                   for n, side in (("p", "+"), ("m", "-")))  # fmt: skip
    pair = simulate_structure(structure, [], "1", F0, 0.62, periods=6, stops=[plus, minus])
    one = simulate_structure(structure, [], "1", F0, 0.62, periods=6, stops=[a])
    assert len(one.events) > 10 and pair.events.shape == one.events.shape
    assert np.allclose(pair.events[:, :10], one.events[:, :10], rtol=1e-12, atol=1e-15)
    # one mode: the walls of two points whose gaps are in the ratio of their shapes coincide
    one_mode = modal_structure([{"f": 1.0, "mass": 1.0, "zeta": 0.01,
                                 "shape": {"tip": 1.0, "mid": 0.25}}])  # fmt: skip
    tip = stop(one_mode, "tip", "tip", 0.004, "+", "rigid", e=0.0)
    for gap, refused in ((0.001, True), (0.0011, False)):
        mid = stop(one_mode, "mid", "mid", gap, "+", "rigid", e=0.0)
        try:
            simulate_structure(one_mode, [], "tip", 1.0, 2 * math.pi, periods=2, stops=[tip, mid])
        except ParameterError as exc:
            assert refused and exc.parameter == "stops.mid" and "'tip'" in exc.reason
        else:
            assert not refused


def test_a_start_beyond_a_rigid_wall_is_refused():
    structure = _chain()
    s = stop(structure, "s", 0, 0.2, "+", "rigid", e=0.5)
    q = np.linalg.solve(structure.shapes(), [0.5, 0.0])  # x₀ = 0.5, past the wall at 0.2
    with pytest.raises(ParameterError) as err:
        simulate_structure(structure, [], "1", F0, 0.5, periods=2, stops=[s],
                           state=np.concatenate([q, [0.0, 0.0]]))  # fmt: skip
    assert err.value.parameter == "state"
