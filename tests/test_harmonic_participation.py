"""A harmonic base motion drives a one-mode reduction through its participation Γφ (Eq. F7 at the
damper's point: M·ẍ_r + C·ẋ_r + K·x_r = −Γφ·M·ẍ_b relative to the supports), carried by the
forcing's ``inertia`` (Γφ − 1)·M: in the absolute x = x_r + x_b of Eq. F1 a force
(Γφ − 1)·M·Ω²·X_b in phase with the base's displacement.  Checked against the mode's closed form,
against DOP853 with impacts on the relative equations, and on orbits of the frequency-response
curve (each returns to its state under DOP853 over its period)."""

import math

import numpy as np
import pytest
from helpers import flights_with_impacts

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.frf import frequency_response
from symimpact.forced.orbits.slow_flow import backbone, best_clearance
from symimpact.forced.responses import linear_response
from symimpact.forced.simulation import state_at
from symimpact.model.system import ImpactSystem

#: the first mode of a 0.5 m aluminium cantilever at its tip (tests/test_reduction_participation)
GP, M, WN, ZETA = 1.566, 0.050625, 2 * math.pi * 16.45, 0.01
SYSTEM = ImpactSystem(
    M=M, K=WN**2 * M, C=2 * ZETA * WN * M, m=0.005, gap=0.01, contact="linear", k1=1e6
)  # (the contact law unused: rigid impacts)
INERTIA = (GP - 1.0) * M


def relative_brute_force(system, X_b, W, e, gp, t_end, times):
    """(x_r, ẋ_r, y_r, ẏ_r) at ``times`` and the impact times: DOP853 with impact events
    (:func:`helpers.flights_with_impacts`) on the equations relative to the supports,
    ẍ_r = −Γφ·ẍ_b − (C·ẋ_r + K·x_r)/M, ÿ_r = −ẍ_b, with ẍ_b = −Ω²X_b·cos Ωt; from rest relative
    to the supports."""
    _, hits, states = flights_with_impacts(_relative(system, X_b, W, 0.0, gp), np.zeros(4), 0.0,
                                           t_end, system.gap / 2, e, system.M, system.m,
                                           times)  # fmt: skip
    return states, np.array(hits)


def _relative(system, X_b, W, phase, gp):
    """The right side of the equations relative to the supports (:func:`relative_brute_force`)."""

    def rhs(t, w):
        acc_b = -W * W * X_b * math.cos(W * t + phase)
        return [w[1], -gp * acc_b - (system.C * w[1] + system.K * w[0]) / system.M, w[3], -acc_b]

    return rhs


def test_out_of_reach_the_reduction_is_the_modes_closed_form():
    """The bare mode's absolute tip amplitude X_b·|1 + Γφ·Ω²/(ωₙ² − Ω² + 2iζωₙΩ)| (Eq. F7,
    written here), at 200 frequencies across the resonance: the linear response to 1e-12 (the
    same complex arithmetic, rearranged), and a long run's steady amplitude at 16 Hz to 1e-6 (its
    transient decayed to e^(−ζωₙt) ≈ 1e-9 of it)."""
    w = np.linspace(0.5, 1.5, 200) * WN
    X_b = 1e-3
    exact = X_b * np.abs(1 + GP * w**2 / (WN**2 - w**2 + 2j * ZETA * WN * w))
    f = Forcing(X_b=X_b, omega=w[0], inertia=INERTIA)
    assert np.allclose(linear_response("displacement", SYSTEM, f, w), exact, rtol=1e-12)
    far = SYSTEM.with_(gap=10.0)
    W = 2 * math.pi * 16.0
    run = simulate_forced(far, Forcing(X_b=X_b, omega=W, inertia=INERTIA), e=0.6, periods=2000,
                          discard=1900)  # fmt: skip
    one = X_b * abs(1 + GP * W**2 / (WN**2 - W**2 + 2j * ZETA * WN * W))
    assert run.steady.amplitude == pytest.approx(one, rel=1e-6)
    # Γφ = 1 would have given a third less
    assert abs(1 + W**2 / (WN**2 - W**2 + 2j * ZETA * WN * W)) * X_b < 0.7 * one


@pytest.mark.parametrize("gp", [1.566, -0.868])
def test_with_impacts_the_reduction_agrees_with_dop853_on_the_relative_equations(gp):
    """Γφ = 1.566 and −0.868 (a cantilever's second mode at its tip): impact times and the
    relative displacement over 8 periods at 16 Hz, 0.5 g, as DOP853's to 1e-9 s and 1e-8 of the
    motion (measured 3e-11 s and 1e-12 s: its tolerance carried through the impacts).  The
    motion with Γφ = 1.566 does not repeat, and the two drift apart about threefold an impact
    after the tenth (7e-9 s by the 28th, 12 periods): 8 periods keep well inside that."""
    W, A = 2 * math.pi * 16.0, 0.5 * 9.80665
    X_b = A / W**2
    forcing = Forcing(A_b=A, omega=W, inertia=(gp - 1.0) * M)
    run = simulate_forced(SYSTEM, forcing, e=0.6, periods=8, x0=X_b, y0=X_b)
    T = 8 * 2 * math.pi / W
    times = np.linspace(0.0, T, 241)[1:-1]
    states, hits = relative_brute_force(SYSTEM, X_b, W, 0.6, gp, T, times)
    ours_hits = run.impacts
    assert 8 <= len(hits) == len(ours_hits)
    assert np.allclose(ours_hits, hits, rtol=0, atol=1e-9)
    ours = state_at(run, times)
    x_rel = ours[:, 0] - X_b * np.cos(W * times)
    scale = np.max(np.abs(states[:, 0]))
    assert np.max(np.abs(x_rel - states[:, 0])) < 1e-8 * scale
    assert run.energy["relative_residual"] < 1e-10


def test_the_curves_orbits_repeat_under_dop853():
    """The frequency-response curve of the reduction over 15–18 Hz at 0.5 g (continued by
    central differences, the chain's ∂P/∂Ω not holding a force that grows with Ω²): five stable
    points spread over its branches, each integrated for its k periods by DOP853 on the relative
    equations from its state, return to it to 1e-7 of the motion (DOP853's 1e-12 a step, carried
    through the orbit's impacts and the shooting's own 1e-10 tolerance)."""
    A = 0.5 * 9.80665
    w = 2 * math.pi * np.linspace(15.0, 18.0, 25)
    forcing = Forcing(A_b=A, omega=w[0], inertia=INERTIA)
    curve = frequency_response(SYSTEM, forcing, 0.6, w, sweeps=False, multistart=0)
    stable = [(b, p) for b in curve.branches for p in b.points if p.stable]
    assert len(stable) >= 5
    for b, p in stable[:: max(1, len(stable) // 5)][:5]:
        W, k = p.omega, b.period_multiple
        X_b = A / W**2
        xb, vb = X_b * math.cos(p.phase), -W * X_b * math.sin(p.phase)
        x, v, z, u = p.state
        start = np.array([x - xb, v - vb, x + z - xb, u - vb])  # relative to the supports
        end = _relative_period(SYSTEM, X_b, W, p.phase, 0.6, GP, start, k)
        scale = max(abs(start[0]), 1e-6)
        assert np.max(np.abs(end[[0, 2]] - start[[0, 2]])) < 1e-7 * scale, (W, k)


def _relative_period(system, X_b, W, phase, e, gp, s, k):
    """The relative state after k forcing periods from ``s`` at forcing phase ``phase`` (DOP853
    with impact events, as :func:`relative_brute_force`)."""
    rhs = _relative(system, X_b, W, phase, gp)
    end, _, _ = flights_with_impacts(
        rhs, s, 0.0, k * 2 * math.pi / W, system.gap / 2, e, system.M, system.m
    )
    return end


def test_the_slow_flow_backbone_refuses_a_force_that_grows_with_frequency():
    """The backbone and its best clearance (Eq. F5) move along frequencies with one force."""
    f = Forcing(X_b=1e-3, omega=100.0, inertia=INERTIA)
    with pytest.raises(ParameterError, match="inertia: the slow flow"):
        backbone(SYSTEM, f, 0.6, [2.0])
    with pytest.raises(ParameterError, match="inertia: the slow flow"):
        best_clearance(SYSTEM, f, 0.6)
