"""Periodic orbits embedded in a chaotic motion (issue 33, items 4 and 5): the close returns of
its Poincaré section are starts for shooting (:func:`symimpact.forced.orbits.coverage.close_returns`),
and the branch through such an unstable orbit leads to a stable window that the multi-start's
frequencies step over.  Checked against closed forms (the logistic map's orbits) and against
the simulation alone (a long run at a frequency inside the window settles on the orbit the
branch holds there)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.errors import SymimpactError
from symimpact.forced import Forcing, shoot
from symimpact.forced.orbits.continuation import orbits_at
from symimpact.forced.orbits.coverage import (
    attractor,
    close_returns,
    initial_states,
    least_period,
    section_states,
)
from symimpact.forced.orbits.frf import _trace, frequency_response
from symimpact.model.system import ImpactSystem


def logistic_orbit(n: int, x0: float = 0.1234) -> np.ndarray:
    """The fully chaotic logistic map x → 4x(1 − x), as an (n + 1, 1) section."""
    xs = [x0]
    for _ in range(n):
        xs.append(4.0 * xs[-1] * (1.0 - xs[-1]))
    return np.array(xs)[:, None]


def logistic_points(k: int) -> list[float]:
    """Every solution of f^k(x) = x for f(x) = 4x(1 − x), in closed form: with x = sin²(πθ) the
    map doubles θ (mod 1), so θ = j/(2^k − 1) or j/(2^k + 1)."""
    return [math.sin(math.pi * j / q) ** 2 for q in (2**k - 1, 2**k + 1) for j in range(q)]


@pytest.mark.parametrize("k", [1, 2, 3])
def test_close_returns_of_the_logistic_map_lie_near_its_orbits(k):
    # the two best returns of a long chaotic run shadow points of period k: each lies near a
    # solution of f^k(x) = x, to 1e-3 (a return is a start for Newton, not a solution; the
    # distances measured over 20 000 iterations from 0.1234: 1e-8 to 5e-5.  The map has only
    # two fixed points, so a third distinct return of period 1 is a poor one: 0.018 away)
    section = logistic_orbit(20_000)
    points = logistic_points(k)
    for best in close_returns(section, k, count=2):
        assert min(abs(float(best[0]) - p) for p in points) < 1e-3


def test_close_returns_are_distinct_and_best_first():
    section = logistic_orbit(5000)
    picks = close_returns(section, 3, count=6)
    spread = float(np.std(section))
    assert len(picks) == 6
    for i, a in enumerate(picks):
        for b in picks[:i]:
            assert abs(float(a[0] - b[0])) > 0.05 * spread
    index = [int(np.flatnonzero(section[:, 0] == p[0])[0]) for p in picks]
    gap = [abs(section[i + 3, 0] - section[i, 0]) for i in index]
    assert gap == sorted(gap)
    assert close_returns(section[:3], 3) == []


# The README's system, its rigid impacts (e 0.6): a period-3 window between a fold at 28.125 and
# a period doubling at 28.199 rad/s, which the curve's multi-start (every 1.25 rad/s over
# 25–45 rad/s) steps over; the motion at 28.75 rad/s is chaotic.
SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
CHAOTIC, WINDOW = 28.75, 28.18407960199005


@pytest.fixture(scope="module")
def embedded_orbits():
    """The period-3 orbits shot from the close returns of the chaotic motions the multi-start's
    initial states land on at 28.75 rad/s (every landing: which of the embedded orbits the best
    returns of 1000 periods catch depends on the stretch searched, and so on the rounding of
    the run; some ten distinct ones over the four landings), each phase point once."""
    f = Forcing(F0=2.0, omega=CHAOTIC)
    orbits = []
    for start in initial_states(SYSTEM, f):
        a = attractor(SYSTEM, f, E, start)
        assert a.kind == "chaotic" and a.lyapunov > 0
        for s in close_returns(section_states(SYSTEM, f, E, a.state), 3):
            try:
                o = shoot(SYSTEM, f, E, s, periods=3)
            except SymimpactError:  # a return Newton does not converge from (a guess)
                continue
            if any(np.allclose(o.state, p.state, rtol=1e-9, atol=1e-12) for p in orbits):
                continue
            # the period-1 orbit is among the returns too (it repeats every third period)
            if least_period(SYSTEM, f, E, o.state, 3, o.amplitude) == 3:
                orbits.append(o)
    return f, orbits


def test_the_chaotic_motion_holds_unstable_orbits_of_period_3(embedded_orbits):
    _, orbits = embedded_orbits
    assert len(orbits) >= 3
    assert not any(o.stable for o in orbits)


def test_a_branch_from_them_holds_the_window_a_long_run_settles_on(embedded_orbits):
    f, orbits = embedded_orbits
    # independent of the branches: the runs from the multi-start's initial states at a
    # frequency inside the window settle on a stable period-3 motion
    inside = Forcing(F0=2.0, omega=WINDOW)
    landed = [attractor(SYSTEM, inside, E, s, exponent=False)
              for s in initial_states(SYSTEM, inside)]  # fmt: skip
    stable3 = {round(a.amplitude, 12) for a in landed
               if a.kind == "periodic" and a.period_multiple == 3 and a.stable}  # fmt: skip
    assert stable3
    for o in orbits:  # the branch of each embedded orbit until one holds it
        b = _trace(SYSTEM, f, E, o.state, (25.0, 45.0), 3, 0.05)
        held = [p.amplitude for p in orbits_at(b, SYSTEM, inside, E, WINDOW)]
        # both shot: their amplitudes agree to Newton's tolerance
        if all(any(abs(h - a) <= 1e-7 * a for h in held) for a in stable3):
            return
    pytest.fail(f"no branch of the {len(orbits)} embedded orbits holds the window")


def test_embedded_orbits_are_refused_for_a_structure(tmp_path, capsys):
    path = tmp_path / "model.json"
    path.write_text(json.dumps({"modes": [{"f": 5, "mass": 1, "zeta": 0.01, "shape": {"tip": 1}}],
                                "dampers": [{"name": "d", "at": "tip", "m": 0.05, "gap": 0.02,
                                             "contact": "rigid", "e": 0.6}],
                                "force": {"at": "tip", "amplitude": 2}}))  # fmt: skip
    code = main(["frf", "--structure", str(path), "--freq-range", "4:6:1", "--embedded"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "error: embedded:" in err


def test_the_curve_with_embedded_orbits_traces_them_and_holds_the_window():
    # the curve from one multi-start frequency, 28.75 rad/s (chaotic): with embedded orbits it
    # traces branches from that motion's unstable orbits, without them none; both hold the
    # stable period-3 motion the runs at 28.184 rad/s settle on, which over this narrow band the
    # multi-start's halving of the interval from the band's end reaches (every 1.5/128 rad/s at
    # most, against the window's 0.074; over benchmark 6's 25–45 rad/s only the embedded orbits
    # reach it: 127 of 128 against 125)
    inside = Forcing(F0=2.0, omega=WINDOW)
    landed = {round(a.amplitude, 12) for a in
              (attractor(SYSTEM, inside, E, s, exponent=False)
               for s in initial_states(SYSTEM, inside))
              if a.kind == "periodic" and a.period_multiple == 3 and a.stable}  # fmt: skip
    assert landed
    for embedded in (False, True):
        curve = frequency_response(SYSTEM, inside, E, [28.0, 29.5], starts=0, sweeps=False,
                                   multistart=1, jumps=0, embedded=embedded)  # fmt: skip
        held = [o.amplitude for b in curve.branches if b.period_multiple == 3
                for o in orbits_at(b, SYSTEM, inside.at(WINDOW, b.phase), E, WINDOW)]  # fmt: skip
        assert all(any(abs(h - a) <= 1e-7 * a for h in held) for a in landed), (embedded, held)
        from_chaos = [b for b in curve.branches
                      if b.origin.startswith("period-3 orbit in the chaotic motion at Ω = 28.75")]  # fmt: skip
        assert bool(from_chaos) == embedded


@pytest.mark.parametrize("flag", ["folds", "embedded"])
def test_folds_and_embedded_orbits_are_refused_for_a_compliant_contact(flag, capsys):
    # both search what rigid impacts have: a grazing no orbit continues beyond (a compliant
    # contact's orbits change smoothly there), motions classified chaotic by their exponent
    code = main(["frf", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap",
                 "20 mm", "--force", "2 N", "--omega-range", "25:26:0.5", "--contact",
                 "linear", "--k1", "1e6", "--c1", "1", f"--{flag}"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and f"error: {flag}:" in err
