"""The primary with its impact damper under a sampled load (symimpact.forced.loads.record_response):
checked against a brute-force integration of the same record, against the harmonic engine on a
finely sampled sine, against the primary alone when the damper is out of reach, and by its energy
ledger."""

import numpy as np
import pytest
from helpers import flights_with_impacts

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.loads.record_flight import primary_response
from symimpact.forced.loads.record_response import damper_response
from symimpact.forced.loads.records import Record, random_record, shock_record
from symimpact.forced.simulation import state_at
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)


def brute_force(system, record, e, t_end):
    """x, ẋ, y, ẏ at the record's samples up to t_end, and the impact times: the equations of
    motion integrated by DOP853 (rtol 1e-12) interval by interval of the record (the load a
    straight line on each), each impact located as a terminal event and Eq. F2 applied there
    (:func:`helpers.flights_with_impacts`).  Under a base acceleration a_b both masses feel −a_b
    in the base's frame."""
    M, m, K, C, h = system.M, system.m, system.K, system.C, system.gap / 2
    base = record.kind == "base-acceleration"
    q, dt = record.values, record.dt
    s = np.zeros(4)
    out, hits = [s.copy()], []
    for i in range(round(t_end / dt)):
        ta, tb = i * dt, (i + 1) * dt
        slope = (q[i + 1] - q[i]) / dt

        def rhs(t, w, q0=q[i], ta=ta, slope=slope):
            load = q0 + slope * (t - ta)
            if base:
                return [w[1], -load - (C * w[1] + K * w[0]) / M, w[3], -load]
            return [w[1], (load - C * w[1] - K * w[0]) / M, w[3], 0.0]

        s, more, _ = flights_with_impacts(rhs, s, ta, tb, h, e, M, m)
        hits += more
        out.append(s.copy())
    return np.array(out), np.array(hits)


@pytest.mark.parametrize("kind", ["force", "base-acceleration"])
def test_a_shock_with_impacts_agrees_with_a_brute_force_integration(kind):
    """A half-sine shock that throws the impact mass from wall to wall (27 impacts under the
    force, 22 under the base acceleration): impact times and the state at every sample agree
    with DOP853 on the same record (measured 3e-12 and 6e-11 of the motion); the bound 1e-8 leaves
    room for DOP853's tolerance of 1e-12 a step carried through the impacts, whose times it
    locates by its own interpolant."""
    peak = 30.0
    record = shock_record("half-sine", peak, 0.05, 1.5, 1e-3, kind=kind)
    ours = damper_response(SYSTEM, record, e=0.6)
    states, hits = brute_force(SYSTEM, record, 0.6, record.duration)
    assert 8 <= len(hits) == len(ours.impact_times)
    assert np.allclose(ours.impact_times, hits, rtol=0, atol=1e-9)
    scale = np.max(np.abs(states[:, 0]))
    assert np.max(np.abs(ours.displacement - states[:, 0])) < 1e-8 * scale
    assert np.max(np.abs(ours.damper_displacement - states[:, 2])) < 1e-8 * scale
    assert ours.ledger["residual"] < 1e-10


def test_a_finely_sampled_sine_converges_to_the_harmonic_engine_with_chatter_and_sticking():
    """F0·cos Ωt sampled at N points a period against the harmonic engine's closed form (Eq. F1),
    on a motion that chatters and sticks (e = 0.2, Ω = 32 rad/s): the same impacts, and the
    difference shrinks as N⁻² (linear interpolation's error, (ΩΔt)²/8 of the load)."""
    omega, periods = 32.0, 10
    period = 2 * np.pi / omega
    harmonic = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=omega), contact="rigid", e=0.2,
                               periods=periods)  # fmt: skip
    errors = []
    for n in (1000, 4000):
        dt = period / n
        t = dt * np.arange(n * periods + 1)
        ours = damper_response(SYSTEM, Record(2.0 * np.cos(omega * t), dt), e=0.2)
        reference = state_at(harmonic, t[:: n // 50])[:, 0]
        errors.append(np.max(np.abs(ours.displacement[:: n // 50] - reference)))
        n_impacts = int(np.sum(harmonic.events[:, 7] == 0))  # kind 0: an impact
        assert len(ours.impact_times) == n_impacts
        assert 0.05 < ours.stuck.mean() < 0.5  # it sticks part of each period
        assert ours.ledger["residual"] < 1e-10
    scale = np.max(np.abs(state_at(harmonic, t[:: n // 50])[:, 0]))
    assert errors[1] < 1e-5 * scale
    assert 16 / 3 < errors[0] / errors[1] < 16 * 3  # N⁻²: 16 for 4× the samples


@pytest.mark.parametrize("kind", ["force", "base-acceleration"])
def test_out_of_reach_the_damper_leaves_the_primary_alone(kind):
    """d = 1 km: no impact, and the primary's response is the record flight's (Eq. F8 alone,
    without the impact search) to rounding."""
    psd = 0.5 if kind == "force" else 2.0
    record = random_record(psd, (1, 20), 20.0, 0.005, seed=3, kind=kind)
    far = SYSTEM.with_(gap=1e3)
    ours = damper_response(far, record, e=0.6)
    alone = primary_response(far, record)
    assert len(ours.impact_times) == 0
    scale = np.max(np.abs(alone.displacement))
    assert np.max(np.abs(ours.displacement - alone.displacement)) < 1e-12 * scale
    assert np.allclose(ours.acceleration, alone.acceleration, rtol=0, atol=1e-10 * scale * 1e3)


@pytest.mark.parametrize("kind", ["force", "base-acceleration"])
def test_the_energy_ledger_closes_under_random_loads(kind):
    """Work of the load = change of energy + C's dissipation + the impacts' loss, to 1e-10 (the
    quadrature's error is far smaller; what remains is rounding over a few thousand pieces)."""
    psd = 0.5 if kind == "force" else 5.0
    record = random_record(psd, (1, 20), 30.0, 0.005, seed=11, kind=kind)
    for e in (0.0, 0.3, 0.9):
        ours = damper_response(SYSTEM, record, e=e)
        assert len(ours.impact_times) > 20
        assert ours.ledger["residual"] < 1e-10


def test_bad_input_is_refused_in_one_line():
    record = shock_record("half-sine", 30.0, 0.05, 0.5, 1e-3)
    with pytest.raises(ParameterError, match="e"):
        damper_response(SYSTEM, record, e=1.5)
    with pytest.raises(ParameterError, match="y0"):
        damper_response(SYSTEM, record, e=0.5, y0=0.5)
    with pytest.raises(ParameterError, match="record"):
        damper_response(SYSTEM, np.zeros(4), e=0.5)


def test_a_release_at_a_tangency_does_not_loop():
    """The report's system (e = 0.16) under base noise: in one record the stuck pair's s·ẍ_abs
    touches zero at 19.77 s and a release by rounding alone was undone at once by an impact at
    zero speed, 20 million times without time moving on.  The release now needs the wall to pull
    by more than 1e-12 of the pair's acceleration scale; the record runs through, its ledger
    closed."""
    from symimpact.forced.loads.random_response import default_settle, realisation_seed

    system = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, contact="linear", k1=122.7)
    n = int(np.ceil(default_settle(system) / 0.005 - 1e-9)) + 20000
    record = random_record(0.01, (0.1, 10.0), n * 0.005, 0.005, realisation_seed(2026, 4),
                           "base-acceleration")  # fmt: skip
    ours = damper_response(system, record, e=0.1594, max_events=200_000)
    assert 100 < len(ours.impact_times) < 20_000
    assert ours.stuck.any()
    assert ours.ledger["residual"] < 1e-10
