"""Responses besides the displacement (relative displacement, acceleration, force into the base,
transmissibility): the primary alone against the textbook transmissibility, and along orbits
against a direct numerical integration of the primary between the run's own impacts."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symimpact.errors import MethodNotApplicable, ParameterError
from symimpact.forced import CompliantContact, Forcing, periodic_orbits, simulate_forced
from symimpact.forced.responses import linear_response, orbit_response
from symimpact.forced.simulation import EVENT_COLUMNS
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


def _textbook(zeta, r):
    """√((1 + (2ζr)²)/((1 − r²)² + (2ζr)²)): force and motion transmissibility of a damped
    single-degree-of-freedom system."""
    return np.sqrt((1 + (2 * zeta * r) ** 2) / ((1 - r * r) ** 2 + (2 * zeta * r) ** 2))


@pytest.mark.parametrize("forcing", [Forcing(F0=2.0, omega=30.0), Forcing(X_b=1e-3, omega=30.0),
                                     Forcing(A_b=4.9, omega=30.0)], ids=["force", "base", "acc"])  # fmt: skip
def test_the_primary_alone_has_the_textbook_transmissibility(forcing):
    w = np.linspace(5.0, 80.0, 151)
    r = w / SYSTEM.omega_n
    got = linear_response("transmissibility", SYSTEM, forcing, w)
    # 1e-12: a few roundings of the steady coefficients (condition ~1/(2ζ) = 32 at resonance)
    np.testing.assert_allclose(got, _textbook(SYSTEM.zeta, r), rtol=1e-12)


def test_the_primary_alone_base_motion_responses_by_hand():
    """Under base motion X_b cos θ the relative motion obeys M q̈ + C q̇ + K q = M Ω² X_b cos θ
    (textbook): its amplitude MΩ²X_b/√((K − MΩ²)² + (CΩ)²)); the absolute acceleration is Ω² times
    the absolute amplitude, and the force K q + C q̇ has amplitude √(K² + (CΩ)²)·|q|."""
    f = Forcing(X_b=1e-3, omega=30.0)
    w = np.array([10.0, 31.0, 50.0])
    M, K, C = SYSTEM.M, SYSTEM.K, SYSTEM.C
    q = M * w**2 * 1e-3 / np.hypot(K - M * w**2, C * w)
    np.testing.assert_allclose(linear_response("relative-displacement", SYSTEM, f, w), q,
                               rtol=1e-12)  # fmt: skip
    np.testing.assert_allclose(linear_response("force", SYSTEM, f, w), np.hypot(K, C * w) * q,
                               rtol=1e-12)  # fmt: skip
    np.testing.assert_allclose(linear_response("acceleration", SYSTEM, f, w),
                               w**2 * linear_response("displacement", SYSTEM, f, w), rtol=1e-15)  # fmt: skip


def _integrated(name, forcing, res):
    """``name``'s largest absolute value over the run's first period by solve_ivp (DOP853, rtol
    1e-12) of the primary between the run's own impacts, restarted at each impact from the
    velocity after it (its events), 20 001 samples a period: independent of the closed-form
    flight."""
    M, K, C = SYSTEM.M, SYSTEM.K, SYSTEM.C
    W, phase, X_b = forcing.omega, forcing.phase, float(forcing.base_amplitude(forcing.omega))

    def base(t):
        th = W * t + phase
        return X_b * np.cos(th), -W * X_b * np.sin(th)

    def rhs(t, s):
        xb, vb = base(t)
        return [
            s[1],
            (forcing.F0 * math.cos(W * t + phase) - K * (s[0] - xb) - C * (s[1] - vb)) / M,
        ]

    T = forcing.period
    ev = res.events
    # the orbit's own impact at t = T is found within the search's 4e-16 of the time, on either
    # side of T: one within 1e-12 T of the end closes the period, it does not cut it
    cuts = [0.0, *[float(t) for t in ev[:, 0] if 0 < t < T * (1.0 - 1e-12)], T]
    x, v = res.initial_state[0], res.initial_state[1]
    best = 0.0
    for k, (a, b) in enumerate(itertools.pairwise(cuts)):
        if k > 0:
            row = ev[ev[:, 0] == a][0]
            x, v = row[EVENT_COLUMNS.index("x")], row[EVENT_COLUMNS.index("xdot_after")]
        t = np.linspace(a, b, max(int(20001 * (b - a) / T), 3))
        sol = solve_ivp(rhs, (a, b), [x, v], method="DOP853", rtol=1e-12, atol=1e-15, t_eval=t)
        xb, vb = base(sol.t)
        xs, vs = sol.y
        force = K * (xs - xb) + C * (vs - vb)
        value = {"displacement": xs, "relative-displacement": xs - xb, "force": force,
                 "acceleration": (forcing.F0 * np.cos(W * sol.t + phase) - force) / M}[name]  # fmt: skip
        best = max(best, float(np.max(np.abs(value))))
        x, v = xs[-1], vs[-1]
    return best


@pytest.mark.parametrize("name", ["displacement", "relative-displacement", "force", "acceleration"])
@pytest.mark.parametrize("base", [False, True], ids=["force", "base"])
def test_an_orbits_responses_equal_a_direct_integration(name, base):
    forcing = Forcing(X_b=2e-3, omega=36.0) if base else Forcing(F0=2.0, omega=36.0)
    orbit = max(
        (o for o in periodic_orbits(SYSTEM, forcing, E) if o.stable), key=lambda o: o.amplitude
    )
    f = forcing.at(forcing.omega, orbit.impact_phase)  # t = 0 at the impact on the wall +d/2
    state = (orbit.X, orbit.V, SYSTEM.gap / 2.0, orbit.U)
    got = orbit_response(name, SYSTEM, f, E, state)
    x, v, z, u = state
    res = simulate_forced(SYSTEM, f, contact="rigid", e=E, periods=1, x0=x, xdot0=v, y0=x + z,
                          ydot0=u)  # fmt: skip
    # 1e-7: the integration's samples are 1/20001 of a period apart, so its maximum is low by
    # up to (π·h/20001)²/2 ≈ 1e-8·h² for the h-th harmonic; Brent locates ours to 1e-12 T
    assert got == pytest.approx(_integrated(name, f, res), rel=1e-7)
    if name == "displacement":
        assert got == pytest.approx(orbit.amplitude, rel=1e-12)


def test_the_orbit_without_impacts_has_the_closed_form_responses():
    """A clearance too wide to reach: the motion is the primary alone's steady state."""
    wide = SYSTEM.with_(gap=10.0)
    f = Forcing(F0=2.0, omega=25.0)
    A = float(linear_response("displacement", wide, f, 25.0))
    # the steady state at t = 0: x = A cos φ + B sin φ with φ = 0, from Step 8's coefficients
    from symimpact.generated import forced_flight as ff

    a = float(ff.steady_cosine(wide.M, wide.K, wide.C, 2.0, 0.0, 25.0))
    b = float(ff.steady_sine(wide.M, wide.K, wide.C, 2.0, 0.0, 25.0))
    state = (a, 25.0 * b, 0.0, 25.0 * b)
    for name in ("displacement", "force", "acceleration", "transmissibility"):
        got = orbit_response(name, wide, f, E, state)
        assert got == pytest.approx(float(linear_response(name, wide, f, 25.0)), rel=1e-10), name
    assert orbit_response("displacement", wide, f, E, state) == pytest.approx(A, rel=1e-10)


def test_bad_requests_are_one_line_refusals():
    with pytest.raises(ParameterError, match="response: must be one of"):
        linear_response("stress", SYSTEM, Forcing(F0=1.0, omega=30.0), 30.0)
    with pytest.raises(ParameterError, match="not both"):
        linear_response("transmissibility", SYSTEM, Forcing(F0=1.0, X_b=1e-3, omega=30.0), 30.0)
    hc = CompliantContact("linear")
    with pytest.raises(MethodNotApplicable, match="compliant contact"):
        orbit_response("acceleration", SYSTEM, Forcing(F0=2.0, omega=36.0), hc, (0, 0, 0, 0))


# --- the curve in another response (frf --response) ------------------------------------------
@pytest.fixture(scope="module")
def force_curve():
    from symimpact.forced.orbits.frf import frequency_response
    from symimpact.forced.orbits.response_curve import response_curve

    f = Forcing(F0=2.0, omega=33.0)
    w = np.arange(33.0, 36.0001, 0.1)
    frf = frequency_response(SYSTEM, f, E, w, sweeps=False)
    return frf, response_curve(frf, "force", SYSTEM, f, E), f


def test_the_force_curve_carries_each_orbits_force(force_curve):
    frf, curve, f = force_curve
    assert curve.response == "force" and frf.response == "displacement"
    b0, b1 = frf.branches[0], curve.branches[0]
    for p, q in list(zip(b0.points, b1.points, strict=True))[::10]:
        assert q.omega == p.omega and q.stable == p.stable
        direct = orbit_response("force", SYSTEM, f.at(p.omega, p.phase), E, p.state,
                                b0.period_multiple)  # fmt: skip
        assert q.amplitude == direct


def test_the_force_peak_is_located_above_every_stable_point(force_curve):
    """The located peak is no lower than any stable point of the curve, and the primary alone's
    peak force equals the closed form's maximum on a fine grid (its own maximum, not a sample)."""
    _, curve, f = force_curve
    stable = [
        p.amplitude
        for b in curve.branches
        for p in b.points
        if p.stable and 33.0 <= p.omega <= 36.0
    ]  # (a branch ends just past the band)
    stable += [v for lo, hi in curve.no_impact
               for v in linear_response("force", SYSTEM, f, np.linspace(lo, hi, 201))]  # fmt: skip
    assert curve.peak.amplitude >= max(stable) * (1 - 1e-12)
    w = np.linspace(33.0, 36.0, 300001)
    fine = linear_response("force", SYSTEM, f, w)
    # the grid's step 1e-5 rad/s leaves its maximum low by ~(1e-5/width)²: 1e-9 relative
    assert curve.baseline_peak.amplitude == pytest.approx(float(fine.max()), rel=1e-9)
    assert curve.baseline_peak.amplitude >= float(fine.max())


def test_frf_response_on_the_command_line(tmp_path, capsys):
    import json

    from symimpact.cli import main

    argv = ["frf", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
            "--force", "2 N", "--contact", "rigid", "--e", "0.6", "--omega-range", "33:36:0.5",
            "--no-sweeps"]  # fmt: skip
    assert main([*argv, "--response", "force", "--csv", str(tmp_path / "f.csv")]) == 0
    text = capsys.readouterr().out
    assert "peak force with the damper:" in text and " N at Ω" in text
    assert (tmp_path / "f.csv").read_text().startswith("omega [rad/s],force [N],")
    assert main([*argv, "--response", "relative-displacement", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["response"] == {"name": "relative-displacement", "unit": "m"}
    assert "relative_displacement" in out["points"][0] and "amplitude" not in out["points"][0]
    assert set(out["peak"]) >= {"relative_displacement", "omega"}
    assert main([*argv, "--response", "stress"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "response" in err[0]
    assert main([*argv, "--base", "1 mm", "--response", "transmissibility"]) == 2
    assert "not both" in capsys.readouterr().err


def test_periodic_response_on_the_command_line(capsys):
    import json

    from symimpact.cli import main

    argv = ["periodic", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
            "--force", "2 N", "--omega", "36", "--contact", "rigid", "--e", "0.6"]  # fmt: skip
    assert main([*argv, "--response", "force", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    f = Forcing(F0=2.0, omega=36.0)
    for row, o in zip(rows, periodic_orbits(SYSTEM, f, E), strict=True):
        state = (o.X, o.V, SYSTEM.gap / 2.0, o.U)
        direct = orbit_response("force", SYSTEM, f.at(36.0, o.impact_phase), E, state)
        assert row["force"] == direct
    assert main([*argv, "--response", "acceleration", "--method", "shooting"]) == 0
    assert "acceleration: " in capsys.readouterr().out
    assert main([*argv, "--response", "nope"]) == 2


def test_steady_response_of_a_run_equals_its_settled_orbits():
    """A run from rest that settles on the stable orbit at 36 rad/s: its steady force over the
    kept periods equals the orbit's own (the run's transient after 300 periods is
    exp(−ζωₙ·300T) ≈ 1e-9 of it; 1e-8 asserted)."""
    from symimpact.forced.responses import steady_response

    f = Forcing(F0=2.0, omega=36.0)
    o = min((o for o in periodic_orbits(SYSTEM, f, E) if o.stable), key=lambda o: o.amplitude)
    res = simulate_forced(SYSTEM, f, contact="rigid", e=E, periods=400, discard=300)
    state = (o.X, o.V, SYSTEM.gap / 2.0, o.U)
    orbit = orbit_response("force", SYSTEM, f.at(36.0, o.impact_phase), E, state)
    assert steady_response("force", res, 300) == pytest.approx(orbit, rel=1e-8)


def test_simulate_response_on_the_command_line(capsys):
    import json

    from symimpact.cli import main

    argv = ["simulate", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
            "--force", "2 N", "--omega", "36"]  # fmt: skip
    assert main([*argv, "--contact", "rigid", "--e", "0.6", "--response", "force", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["response"]["name"] == "force" and out["response"]["unit"] == "N"
    assert out["response"]["value"] == pytest.approx(4.5216, abs=1e-4)
    hc = ["--contact", "hunt-crossley", "--k-hz", "1e9", "--chi", "0.5 s/m"]
    # refused before the run: one line, exit 2
    assert main([*argv, *hc, "--response", "acceleration", "--periods", "100000"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "compliant contact" in err[0]
