"""A branch of a structure's orbits continued at a fixed Ω in a damper's clearance or the force
amplitude (issue 36's ``branch`` of a structure): its bifurcations located and checked against
brute-force runs on either side, every orbit a fixed point of a brute-force period, and the
period doubling of a branch in F0 lying on the one the branch in Ω locates."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from symimpact.errors import ParameterError
from symimpact.forced.orbits.structure_branch import (
    NEIMARK_SACKER,
    PERIOD_DOUBLING,
    parameter_branch,
    structure_branch,
)
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import damper
from symimpact.model.structure import structure_from_dict
from symimpact.model.structure_model import model_from_dict

# the two-DOF chain (masses [1, 1], springs [0, 1, 1], modal damping 1.5 %), driven at
# its second DOF with 0.1
FE = {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015}
OMEGA = 1.6  # just below the chain's second mode (ω₂ = 1.618 rad/s): the damper rattles


@pytest.fixture(scope="module")
def rattling():
    """The chain with a 1 kg damper (e 0.6) at its second DOF, its clearance continued from 0.5
    to 2 at Ω 1.6."""
    structure = structure_from_dict({"fe": FE})
    dampers = (damper(structure, "d", 1, 0.1, 0.5, 0.6),)
    start = simulate_structure(structure, dampers, "1", 0.1, OMEGA, periods=300)
    branch = parameter_branch(structure, dampers, "1", 0.1, OMEGA, "gap", 0.5, 2.0,
                              start.final_state[1:7])  # fmt: skip
    return structure, dampers, branch


def _comes_back(structure, dampers, gap, state, periods=800):
    """How far the state ``periods`` periods from ``state`` comes back after 1, 2 and 4 periods
    (relative to its size), with the damper's clearance ``gap``."""
    ds = (replace(dampers[0], gap=gap),)
    x = simulate_structure(structure, ds, "1", 0.1, OMEGA, periods=periods, state=state)
    x = x.final_state[1:7]
    back = [simulate_structure(structure, ds, "1", 0.1, OMEGA, periods=k, state=x)
            .final_state[1:7] for k in (1, 2, 4)]  # fmt: skip
    return [float(np.max(np.abs(b - x)) / np.max(np.abs(x))) for b in back]


def test_the_clearance_s_bifurcations_are_where_brute_force_runs_change(rattling):
    structure, dampers, branch = rattling
    kinds = [b.kind for b in branch.bifurcations]
    assert kinds == [PERIOD_DOUBLING, NEIMARK_SACKER]
    pd, ns = branch.bifurcations
    for b in (pd, ns):
        assert b.parameter == "gap" and b.omega == OMEGA
        assert b.tolerance < 1e-8 * b.value
        assert abs(abs(b.multiplier) - 1.0) < 1e-5  # the bracket's end: 1e-10 measured
    assert pd.multiplier.real == pytest.approx(-1.0, abs=1e-5)
    assert 0.1 < abs(np.angle(ns.multiplier)) < 3.0
    assert pd.value < ns.value

    # brute force, 0.003 either side, from the nearest traced orbit perturbed by 1e-4: a settled
    # orbit comes back to roundoff (7e-12 measured), a period-2 motion after 2 periods only
    # (6.5e-2 after one), a motion on a torus after none (5e-2, 0.1, 0.18)
    def nearest(gap):
        return branch.orbits[int(np.argmin(np.abs(branch.values - gap)))].state * (1.0 + 1e-4)

    below_pd = _comes_back(structure, dampers, pd.value - 0.003, nearest(pd.value - 0.003))
    assert below_pd[0] > 1e-2 and below_pd[1] < 1e-9
    above_pd = _comes_back(structure, dampers, pd.value + 0.003, nearest(pd.value + 0.003))
    assert above_pd[0] < 1e-9
    below_ns = _comes_back(structure, dampers, ns.value - 0.003, nearest(ns.value - 0.003))
    assert below_ns[0] < 1e-9
    above_ns = _comes_back(structure, dampers, ns.value + 0.003, nearest(ns.value + 0.003))
    assert min(above_ns) > 1e-2


def test_every_orbit_of_a_clearance_branch_is_a_fixed_point_of_a_brute_force_period(rattling):
    structure, dampers, branch = rattling
    assert len(branch.orbits) >= 10
    assert branch.values[0] == 0.5 and np.all(np.diff(branch.values) > 0)
    for gap, o in zip(branch.values, branch.orbits, strict=True):
        ds = (replace(dampers[0], gap=gap),)
        again = simulate_structure(structure, ds, "1", 0.1, OMEGA, periods=1, state=o.state)
        # Newton stops at a residual of 1e-12 of the state (well conditioned here: the orbits
        # near the branch's end, where a multiplier grows to 1.22, measured 2e-13)
        assert np.max(np.abs(again.final_state[1:7] - o.state)) < 1e-10 * np.max(np.abs(o.state))
    point = branch.as_dict()["points"][0]
    assert point["value"] == 0.5 and branch.as_dict()["parameter"] == "gap"


def test_a_branch_in_the_force_finds_the_period_doubling_the_branch_in_omega_finds():
    """The chain with its one-sided linear stop: the branch in Ω at F0 = 0.1 locates a period
    doubling at Ω*; the branch in F0 at Ω* − 0.001 locates one at F0*; the branch in Ω at F0*
    locates it at Ω* − 0.001 again.  Two continuations in different parameters meet on one
    curve of doublings."""
    chain = {"fe": FE, "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+",
                                  "contact": "linear", "k1": 100, "c1": 0}],
             "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip
    model = model_from_dict(chain)
    args = (model.structure, model.dampers, model.force_at)
    start = simulate_structure(*args, 0.1, 0.66, periods=300, stops=model.stops)
    start = start.final_state[1:5]
    in_omega = structure_branch(*args, 0.1, 0.66, 0.75, start, 1, model.stops)
    (pd,) = [b for b in in_omega.bifurcations if b.kind == PERIOD_DOUBLING]
    w = pd.omega - 0.001
    near = in_omega.orbits[int(np.argmin(np.abs(in_omega.omegas - w)))]
    there = structure_branch(*args, 0.1, near.run.omega, w, near.state, 1, model.stops)
    assert there.orbits[-1].stable
    in_force = parameter_branch(*args, 0.1, w, "F0", 0.1, 0.12, there.orbits[-1].state,
                                stops=model.stops)  # fmt: skip
    (f0,) = in_force.bifurcations
    assert f0.kind == PERIOD_DOUBLING and 0.1 < f0.value < 0.12 and f0.omega == w
    start = simulate_structure(*args, f0.value, 0.66, periods=300, stops=model.stops)
    again = structure_branch(*args, f0.value, 0.66, 0.75, start.final_state[1:5], 1, model.stops)
    (pd2,) = [b for b in again.bifurcations if b.kind == PERIOD_DOUBLING]
    # each point is located to its bracket; the curve's slope dΩ*/dF0 is 0.48 here (0.001 over
    # 0.00207), below 1: 4.8e-11 measured
    assert abs(pd2.omega - w) <= pd2.tolerance + f0.tolerance


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"parameter": "X_b"}, "parameter"),
        ({"parameter": "gap", "damper": "nobody"}, "damper"),
        ({"parameter": "e", "end": 1.5}, "end"),
        ({"parameter": "gap", "end": 0.5}, "end"),
        ({"parameter": "m", "start": -1.0}, "start"),
    ],
)
def test_bad_input_is_refused_in_one_line_naming_the_parameter(rattling, kwargs, name):
    structure, dampers, _ = rattling
    call = {"parameter": "gap", "start": 0.5, "end": 1.0, "damper": None} | kwargs
    with pytest.raises(ParameterError) as info:
        parameter_branch(structure, dampers, "1", 0.1, OMEGA, call["parameter"], call["start"],
                         call["end"], np.zeros(6), damper=call["damper"])  # fmt: skip
    assert info.value.parameter == name and "\n" not in str(info.value)


def test_branch_continues_a_structure_file_on_the_command_line(tmp_path, capsys):
    """``symimpact branch --structure FILE --omega Ω --parameter gap --range a:b`` continues the
    file's damper both ways from its own clearance: the same bifurcations as the API's branch,
    and one line for what it does not take."""
    import json

    from symimpact.cli import main

    model = {"fe": FE, "dampers": [{"name": "d", "at": 1, "m": 0.1, "gap": 0.5,
                                    "contact": "rigid", "e": 0.6}],
             "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip
    path = tmp_path / "chain.json"
    path.write_text(json.dumps(model))
    base = ["branch", "--structure", str(path), "--omega", str(OMEGA), "--parameter", "gap"]
    assert main([*base, "--range", "0.45:0.7", "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    assert got["damper"] == "d" and got["start"]["value"] == 0.5
    down, up = got["branches"]
    assert down["points"][-1]["value"] == pytest.approx(0.45, abs=1e-12)
    kinds = [(b["kind"], b["value"]) for b in up["bifurcations"]]
    structure = structure_from_dict({"fe": FE})
    dampers = (damper(structure, "d", 1, 0.1, 0.5, 0.6),)
    api = parameter_branch(structure, dampers, "1", 0.1, OMEGA, "gap", 0.5, 0.7,
                           np.array(got["start"]["state"]))  # fmt: skip
    assert [k for k, _ in kinds] == [b.kind for b in api.bifurcations]
    for (_, value), b in zip(kinds, api.bifurcations, strict=True):
        assert value == pytest.approx(b.value, abs=2 * b.tolerance)
    # its CSV (the JSON's orbits, row for row, SI) and its figure
    import csv

    out_csv, out_png = tmp_path / "b.csv", tmp_path / "b.png"
    assert main([*base, "--range", "0.45:0.7", "--csv", str(out_csv), "--plot", str(out_png)]) == 0
    capsys.readouterr()
    with open(out_csv) as f:
        rows = list(csv.DictReader(f))
    orbits = [(i, pt) for i, br in enumerate(got["branches"]) for pt in br["points"]]
    assert len(rows) == len(orbits)
    for r, (i, pt) in zip(rows, orbits, strict=True):
        assert (r["kind"], int(r["branch"])) == ("orbit", i)
        assert float(r["gap [m]"]) == pt["value"] and float(r["omega [rad/s]"]) == OMEGA
        assert float(r["amplitude at 1 [m]"]) == pt["amplitudes"]["1"]
        assert r["stable"] == str(pt["stable"])
    assert out_png.stat().st_size > 10_000
    for args, name in ((["--range", "0.6:0.7"], "range"),
                       (["--range", "0.4:0.7", "--damper", "q"], "damper"),
                       (["--range", "0:0.7"], "range")):  # fmt: skip
        assert main([*base, *args]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and f"error: {name}:" in err
