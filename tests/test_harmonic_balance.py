"""Multi-harmonic balance with AFT (issue 83, item 1): symimpact.forced.orbits.harmonic_balance,
checked against what does not use it.

- The balance's Jacobians (∂R/∂U, ∂R/∂ω) against central differences of its residual, for a
  force depending on position and speed and for the impact damper's Hertz contact.
- A Duffing oscillator (no gap): the periodic orbit's state at t = 0 against DOP853 shooting at
  rtol 1e-13, falling spectrally with H (below 1e-8 by H = 15), and Hill's Floquet multipliers
  against the exact ones (central differences of the DOP853 period map).
- The impact damper with a Hertz contact: the balance's amplitude against the exact orbit of
  shooting (the compliant engine), its error falling as H grows (algebraically: the contact's
  force has a kink at its onset), and the largest multiplier likewise.
- Bad input: a rigid contact, too few time samples, fewer harmonics than the period multiple.
- A branch by pseudo-arclength continuation (:func:`hb_curve`): points along it against the exact
  orbits shooting finds from the balance's own states, and its fold in Ω where the arc turns.
- ``symimpact periodic --method hb``: its JSON is the API's orbit and shooting's beside it, its
  text says the same numbers, and its bad input is one line with exit code 2.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from symimpact.cli import main
from symimpact.errors import MethodNotApplicable, ParameterError
from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.harmonic_balance import (
    Basis,
    Problem,
    _problem,
    hb_curve,
    hb_orbit,
    newton,
)
from symimpact.forced.orbits.shooting import shoot, shoot_from_rest
from symimpact.model.system import ImpactSystem

#: The Duffing oscillator x'' + 0.1x' + x + βx³ = F cos Ωt, on its resonant (upper) branch.
BETA, F, W, ZETA2 = 0.5, 0.3, 1.2, 0.1
#: The README's primary with a Hertz contact (k_hz 1e5 N/m^1.5, c₁ 0.5 N s/m) at Ω 34 rad/s,
#: where a run from rest settles on a stable orbit with two contacts a period.
HERTZ = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, k_hz=1e5, k1=2e4, c1=0.5)


def _duffing_force(q, qd):
    return -BETA * q**3, (-3.0 * BETA * q**2)[None], np.zeros((1, 1, q.shape[1]))


def _duffing(H: int) -> Problem:
    F_ext = np.zeros((1, 2 * H + 1))
    F_ext[0, 1] = F
    return Problem(np.eye(1), ZETA2 * np.eye(1), np.eye(1), F_ext, _duffing_force,
                   Basis.of(H, 4 * H + 4))  # fmt: skip


@pytest.fixture(scope="module")
def duffing_exact():
    """The orbit's state at t = 0 and its multipliers by DOP853 (rtol 1e-13), the period map's
    Jacobian by central differences (step 1e-6: truncation 1e-12, rounding 1e-13/1e-6)."""

    def rhs(t, s):
        return [s[1], F * math.cos(W * t) - ZETA2 * s[1] - s[0] - BETA * s[0] ** 3]

    T = 2 * math.pi / W

    def period_map(s):
        return solve_ivp(rhs, (0, T), s, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1]

    s = solve_ivp(rhs, (0, 200 * T), [0.0, 0.0], rtol=1e-10, atol=1e-12).y[:, -1]
    s = fsolve(lambda s: period_map(s) - s, s, xtol=1e-13)
    J = np.column_stack([(period_map(s + e) - period_map(s - e)) / 2e-6
                         for e in np.eye(2) * 1e-6])  # fmt: skip
    return s, np.linalg.eigvals(J)


def _padded(U: np.ndarray, n: int, H: int) -> np.ndarray:
    """The coefficients of n coordinates ``U`` carried to H harmonics (zeros above)."""
    old = len(U) // n
    out = np.zeros(n * (2 * H + 1))
    for i in range(n):
        out[i * (2 * H + 1) : i * (2 * H + 1) + old] = U[i * old : (i + 1) * old]
    return out


def test_jacobians_equal_central_differences():
    def force(q, qd):
        return -BETA * q**3 - 0.2 * qd**3, (-3 * BETA * q**2)[None], (-0.6 * qd**2)[None]

    H = 3
    F_ext = np.zeros((1, 2 * H + 1))
    F_ext[0, 1] = F
    pr = Problem(np.eye(1), ZETA2 * np.eye(1), np.eye(1), F_ext, force, Basis.of(H, 16))
    U = np.random.default_rng(1).normal(size=2 * H + 1) * 0.3
    _, J, dR_dw, _ = pr.jacobian(U, W)
    h = 1e-7  # central differences: truncation h²·R''' ~ 1e-14, rounding 1e-16/h ~ 1e-9
    fd = np.column_stack([(pr.residual(U + e, W) - pr.residual(U - e, W)) / (2 * h)
                          for e in np.eye(len(U)) * h])  # fmt: skip
    assert np.max(np.abs(J - fd)) < 1e-7 * np.max(np.abs(J))
    fd_w = (pr.residual(U, W + h) - pr.residual(U, W - h)) / (2 * h)
    assert np.max(np.abs(dR_dw - fd_w)) < 1e-7 * np.max(np.abs(dR_dw))


def test_impact_damper_jacobian_equals_central_differences():
    H = 8
    pr = _problem(HERTZ, Forcing(F0=2.0, omega=34.0), CompliantContact("hertz"), H, 64, 1)
    rng = np.random.default_rng(2)
    U = np.zeros(2 * (2 * H + 1))
    U[1], U[2 * H + 2] = 0.007, 0.012  # x and y in phase, y past the wall part of the period
    U += rng.normal(size=U.size) * 1e-4
    _, J, dR_dw, _ = pr.jacobian(U, 34.0)
    h = 1e-9  # of coefficients of 1e-2: no sample crosses δ = 0 within ±h here (checked below)
    cols = []
    for e in np.eye(U.size) * h:
        cols.append((pr.residual(U + e, 34.0) - pr.residual(U - e, 34.0)) / (2 * h))
    fd = np.column_stack(cols)
    # the Hertz force's second derivative ~ k_hz/√δ: the differences' truncation stays below
    # 1e-6 of the Jacobian's scale unless a sample sits within ~h of a contact's onset
    z = (U[2 * H + 1 :] - U[: 2 * H + 1]) @ pr.basis.E.T
    assert np.min(np.abs(np.abs(z) - HERTZ.gap / 2)) > 1e-6
    assert np.max(np.abs(J - fd)) < 1e-6 * np.max(np.abs(J))
    fd_w = (pr.residual(U, 34.0 + 1e-6) - pr.residual(U, 34.0 - 1e-6)) / 2e-6
    assert np.max(np.abs(dR_dw - fd_w)) < 1e-6 * np.max(np.abs(dR_dw))


def test_duffing_converges_spectrally_to_the_exact_orbit(duffing_exact):
    s, exact_mult = duffing_exact
    errors, U = {}, None
    for H in (1, 3, 5, 7, 9, 11, 15):
        pr = _duffing(H)
        U0 = np.eye(2 * H + 1)[1] if U is None else _padded(U, 1, H)
        U, _, _ = newton(pr, U0, W, 1.0)
        b = pr.basis
        x0, v0 = b.at(U, np.array([0.0]))[0], W * b.at(U, np.array([0.0]), 1)[0]
        errors[H] = max(abs(x0 - s[0]), abs(v0 - s[1]))
        lam = pr.exponents(U, W)
    # spectral: each two harmonics more gain at least a factor 10 until rounding (measured:
    # 8e-2, 1.3e-3, 4.4e-5, 1.9e-6, 1.6e-8, 6.2e-10, 1.7e-13)
    for a, b_ in ((1, 3), (3, 5), (5, 7), (7, 9), (9, 11)):
        assert errors[b_] < 0.1 * errors[a], errors
    assert errors[15] < 1e-8
    # Hill's multipliers at H = 15 against the period map's (its differences: 1e-9)
    mult = np.sort_complex(np.exp(lam * 2 * math.pi / W))
    assert np.max(np.abs(mult - np.sort_complex(exact_mult))) < 1e-8


@pytest.fixture(scope="module")
def hertz_exact():
    return shoot_from_rest(HERTZ, Forcing(F0=2.0, omega=34.0), CompliantContact("hertz"))


def test_hertz_contact_amplitude_converges_to_shooting(hertz_exact):
    forcing, contact = Forcing(F0=2.0, omega=34.0), CompliantContact("hertz")
    err, mult, U = {}, {}, None
    for H in (10, 20, 40, 60):
        start = None if U is None else _padded(U, 2, H)
        o = hb_orbit(HERTZ, forcing, contact, harmonics=H, time_samples=8 * H, start=start)
        U = np.array(o.x + o.y)
        err[H] = abs(o.amplitude - hertz_exact.amplitude) / hertz_exact.amplitude
        mult[H] = abs(o.multipliers[-1] - min(hertz_exact.multipliers))
        assert o.residual < 1e-9
    # algebraic convergence (measured 4.0e-3, 4.0e-4, 1.4e-4, 7.8e-6): the δ^1.5 force and c₁δ̇
    # switch on with a kink and a step at each onset, which the series resolves as a power of H
    assert err[60] < 0.01 * err[10]
    assert err[60] < 1e-4
    # the smallest multiplier modulus (a decaying pair, which the sorting keeps) converges:
    # measured 7.4e-4 at H = 10, 5.1e-5 at H = 60
    assert mult[60] < 0.2 * mult[10]


def test_bad_input_is_refused_in_one_line():
    forcing = Forcing(F0=2.0, omega=34.0)
    with pytest.raises(ParameterError, match="contact: harmonic balance needs a compliant"):
        hb_orbit(HERTZ, forcing, 0.6)
    with pytest.raises(ParameterError, match=r"time_samples: must be at least 2H \+ 1 = 21"):
        hb_orbit(HERTZ, forcing, CompliantContact("hertz"), harmonics=10, time_samples=20)
    with pytest.raises(ParameterError, match="harmonics: must be at least the period multiple 3"):
        hb_orbit(HERTZ, forcing, CompliantContact("hertz"), harmonics=2, subharmonic=3)


HERTZ_ARGS = ["periodic", "--M", "1 kg", "--K", "1000 N/m", "--C", "0.5 N*s/m", "--m", "50 g",
              "--gap", "20 mm", "--force", "2 N", "--omega", "34 rad/s", "--contact", "hertz",
              "--k-hz", "1e5 N/m^1.5", "--c1", "0.5 N*s/m", "--method", "hb"]  # fmt: skip


def test_the_command_gives_the_api_orbit_beside_shooting(capsys, hertz_exact):
    assert main([*HERTZ_ARGS, "--harmonics", "20", "--time-samples", "160", "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    api = hb_orbit(HERTZ, Forcing(F0=2.0, omega=34.0), CompliantContact("hertz"), harmonics=20,
                   time_samples=160)  # fmt: skip
    assert got["x"] == list(api.x) and got["amplitude"] == api.amplitude
    assert got["exact"]["amplitude"] == hertz_exact.amplitude
    assert got["hb_error"] == (api.amplitude - hertz_exact.amplitude) / hertz_exact.amplitude
    assert main([*HERTZ_ARGS, "--harmonics", "20", "--time-samples", "160"]) == 0
    text = capsys.readouterr().out
    assert f"amplitude {api.amplitude * 1e3:.6g} mm" in text
    assert f"error {100 * got['hb_error']:+.3g} %" in text


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--harmonics", "10", "--time-samples", "20"], "time-samples: must be at least 2H + 1"),
        (["--harmonics", "0"], "harmonics: must be a whole number 1 to 400, got 0"),
        (["--multiple", "3", "--harmonics", "2"], "harmonics: must be at least the period"),
        (["--response", "force"], "response: applies to --method closed-form or shooting"),
        # a contact 1000 times stiffer: Eq. 34's 0.767 ms at the settled motion's 0.295 m/s,
        # where 60 samples a period are 3.08 ms apart
        (
            ["--k-hz", "1e8 N/m^1.5", "--harmonics", "15", "--time-samples", "60"],
            "the hertz contact lasts about 0.767 ms (Eq. 34 at the approach speed 0.295 m/s), less "
            "than the spacing of the N = 60 samples (3.08 ms)",
        ),
    ],
)
def test_the_command_refuses_bad_input_in_one_line(capsys, extra, message):
    argv = list(HERTZ_ARGS)
    if "--k-hz" in extra:  # the stiffness given replaces the case's (an option is given once)
        at = argv.index("--k-hz")
        del argv[at : at + 2]
    assert main([*argv, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and "\n" not in err and "Traceback" not in err


def test_the_samples_asked_for_a_stiff_contact_resolve_it():
    """The refusal's count of samples is enough: with it the contact lasts at least one sample
    spacing, and the balance goes on to Newton."""
    stiff = HERTZ.with_(k_hz=1e8)
    forcing, contact = Forcing(F0=2.0, omega=34.0), CompliantContact("hertz")
    with pytest.raises(ParameterError, match="give at least 242 samples"):
        hb_orbit(stiff, forcing, contact, harmonics=15, time_samples=60)
    try:
        hb_orbit(stiff, forcing, contact, harmonics=15, time_samples=242)
    except MethodNotApplicable:
        pass  # Newton may still not converge at H = 15; the sampling is not what it refuses


def test_a_branch_followed_in_omega_lies_on_the_exact_orbits():
    forcing, contact = Forcing(F0=2.0, omega=33.0), CompliantContact("hertz")
    curve = hb_curve(HERTZ, forcing, contact, (33.0, 37.0), harmonics=40, time_samples=320)
    assert len(curve.orbits) >= 10
    omegas = [o.omega for o in curve.orbits]
    # the arc turns back in Ω where it reports a fold (pseudo-arclength passes it): Ω rises to
    # the fold's point and falls after it
    i = int(np.argmax(omegas))
    assert curve.folds == (omegas[i],) and omegas[i - 1] < omegas[i] > omegas[i + 1]
    shot = []
    for o in curve.orbits:
        try:
            shot.append((o, shoot(HERTZ, forcing.at(o.omega), contact, o.state(0.0))))
        except MethodNotApplicable:  # beside the fold, where shooting's Newton is ill-conditioned
            continue
    assert len(shot) >= 0.8 * len(curve.orbits)
    for o, exact in shot:
        # Hill's sorting at H = 40 agrees with the exact multipliers along this branch, through
        # the loss of stability before the fold (measured: every point)
        assert o.stable == exact.stable, o.omega
        # H = 40's truncation: up to 7e-4 of the amplitude on the stable part (1.4e-4 at 34 rad/s
        # in the convergence test), up to 1e-2 beside the fold, where the contacts last longest
        # (measured 9.9e-3)
        bound = 1e-3 if exact.stable else 2e-2
        assert abs(o.amplitude - exact.amplitude) < bound * exact.amplitude, o.omega
