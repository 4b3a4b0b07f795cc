"""Shocks and sine sweeps on the primary with its impact damper (symimpact.forced.loads.shock_response,
symimpact.forced.loads.sweep_response): the SRS of a moving base against the SRS of its acceleration,
and slow sweeps against the steady responses they pass through."""

import numpy as np
import pytest

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.loads.record_flight import srs
from symimpact.forced.loads.records import shock_record
from symimpact.forced.loads.shock_response import base_motion, motion_srs, shock_response
from symimpact.forced.loads.sweep_response import sweep_response
from symimpact.forced.orbits.periodic import periodic_orbits
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)


def test_the_srs_of_a_base_motion_is_the_srs_of_its_acceleration():
    """An 11 ms half-sine base acceleration: oscillators driven through their spring and damper
    by the base's displacement and velocity (what the damper's SRS uses, since impacts make the
    acceleration impulsive) give the SRS of the acceleration itself (record_flight.srs), to the
    O(dt²) of interpolating displacement and velocity by straight lines: 4× closer for half the
    step (measured 5.3e-3 and 1.3e-3)."""
    f = np.geomspace(5, 400, 12)
    errors = []
    for dt in (1e-4, 5e-5):
        record = shock_record("half-sine", 100.0, 0.011, 0.5, dt, kind="base-acceleration")
        xb, vb = base_motion(record)
        ours = motion_srs(xb, vb, dt, f)
        direct = srs(record, f)
        errors.append(np.max(np.abs(ours / direct - 1)))
    assert errors[1] < 2e-3
    assert 3.5 < errors[0] / errors[1] < 4.5


def test_base_motion_integrates_the_acceleration_exactly():
    """A constant acceleration a from rest: ẋ_b = a·t and x_b = a·t²/2 at every sample."""
    record = shock_record("sawtooth", 0.0, 0.02, 0.1, 1e-3, kind="base-acceleration")
    record = type(record)(np.full(101, 3.0), 1e-3, "base-acceleration")
    xb, vb = base_motion(record)
    t = record.times
    assert np.allclose(vb, 3.0 * t, rtol=1e-13, atol=0)
    assert np.allclose(xb, 1.5 * t * t, rtol=1e-12, atol=1e-18)


def test_a_shock_with_the_damper_out_of_reach_has_the_primarys_srs():
    record = shock_record("half-sine", 50.0, 0.011, 1.0, 1e-4, kind="base-acceleration")
    out = shock_response(SYSTEM.with_(gap=1e3), record, e=0.6, frequencies=[2.0, 5.0, 20.0])
    assert out.impacts == 0
    assert np.array_equal(out.srs, out.baseline_srs)
    assert out.peak == out.baseline_peak
    near = shock_response(SYSTEM.with_(gap=0.01), record, e=0.6, frequencies=[2.0, 5.0, 20.0])
    assert near.impacts > 5
    assert not np.array_equal(near.srs, near.baseline_srs)


def test_slow_sweeps_settle_on_the_steady_responses():
    """Through 36 rad/s (5.73 Hz) the up sweep rides the impacting orbit and the down sweep the
    motion without impacts (the two coexist there): as the rate falls the envelopes approach the
    steady amplitudes — the event-driven run's steady state (Eq. F1/F2, harmonic forcing), and
    the linear F0/|K − MΩ² + iCΩ| — and the error shrinks with the rate."""
    omega = 36.0
    steady = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=omega), contact="rigid", e=0.6,
                             periods=400, discard=300).steady.amplitude  # fmt: skip
    linear = 2.0 / abs(1000.0 - omega**2 + 0.5j * omega)
    assert steady < 0.9 * linear
    errors = []
    for rate in (0.05, 0.003):
        out = sweep_response(SYSTEM, 2.0, 5.0, 6.5, rate, 0.002, e=0.6)
        up, down = out.up, out.down
        i = np.argmin(np.abs(up["frequency"] - omega / (2 * np.pi)))
        j = np.argmin(np.abs(down["frequency"] - omega / (2 * np.pi)))
        errors.append((abs(up["envelope"][i] / steady - 1), abs(down["envelope"][j] / linear - 1)))
    assert errors[1][0] < 2e-3 and errors[1][1] < 2e-3
    assert errors[1][1] < errors[0][1]


def test_the_linear_sweep_peak_rises_towards_the_resonance_peak_as_the_rate_falls():
    """The primary alone: a sweep's peak falls short of the steady resonance peak F0/(Cω_n)
    by less and less as the rate falls (measured 0.057, 0.086, 0.111 m against 0.126)."""
    peak = 2.0 / (0.5 * np.sqrt(1000.0))
    shortfalls = []
    for rate in (0.2, 0.05, 0.0125):
        out = sweep_response(SYSTEM.with_(gap=1e3), 2.0, 3.5, 6.5, rate, 0.002, e=0.6)
        shortfalls.append(peak - np.max(out.up["baseline"]))
    assert 0 < shortfalls[2] < shortfalls[1] < shortfalls[0]


def test_bad_shock_and_sweep_input_is_refused():
    record = shock_record("half-sine", 50.0, 0.011, 0.2, 1e-4, kind="base-acceleration")
    with pytest.raises(ParameterError, match="frequencies"):
        shock_response(SYSTEM, record, e=0.6, frequencies=[1e5])
    with pytest.raises(ParameterError, match="rate"):
        sweep_response(SYSTEM, 2.0, 5.0, 6.5, 0.0, 0.002, e=0.6)
    with pytest.raises(ParameterError, match="duration"):
        shock_record("half-sine", 50.0, 0.011, 0.005, 1e-4)


@pytest.mark.slow  # run in CI's second step (the README command stays within ~12 min)
def test_the_steady_curve_beside_a_sweep_holds_the_closed_form_orbits():
    """The steady curve drawn beside a sweep (sweep-sine's JSON "steady"): its stable orbit at
    its highest frequency is the symmetric two-impact orbit of the closed form (Step 10, solved
    there without shooting or continuation); the linear curve under a base acceleration A_b is
    the closed form of x − x_b, M·A_b/abs(K − MΩ² + iCΩ)."""
    out = sweep_response(SYSTEM, 2.0, 5.5, 6.5, 0.2, 0.002, e=0.6, steady=True).as_dict()
    stable = out["steady"]["stable"]
    top = max(r["frequency"] for r in stable)
    here = [r["amplitude"] for r in stable if r["frequency"] == top]
    closed = [o.amplitude for o in periodic_orbits(SYSTEM, Forcing(F0=2.0, freq=top), 0.6)
              if o.admissible and o.stable]  # fmt: skip
    # the branch's orbit is shot to ~1e-12 of the state; the closed form solves for its phase
    assert min(abs(a / c - 1) for a in here for c in closed) < 1e-9
    base = sweep_response(SYSTEM, 0.2 * 9.80665, 4.0, 6.5, 0.2, 0.002, e=0.6,
                          kind="base-acceleration", steady=True).steady  # fmt: skip
    w = 2 * np.pi * base.linear[:, 0]
    linear = 0.2 * 9.80665 / np.abs(1000.0 - w**2 + 0.5j * w)
    # the same complex quotient evaluated two ways: rounding only
    np.testing.assert_allclose(base.linear[:, 1], linear, rtol=1e-12)
    assert base.peak is not None and base.peak < np.max(linear)
