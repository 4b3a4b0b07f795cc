"""Step 16 (Eq. F8) at run time: sampled loads and the primary's exact flight over them, checked
against what does not use Eq. F8 — SciPy's adaptive integration of the same equation, Parseval's
theorem for the random record, the closed-form linear response to its cosines, and the textbook
asymptotes of a half-sine's shock-response spectrum."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from symimpact.generated import sampled_load as sl

from symimpact.errors import ParameterError
from symimpact.forced.loads.record_flight import primary_response, srs
from symimpact.forced.loads.records import (
    random_record,
    shock_record,
    sweep_frequency,
    sweep_record,
)
from symimpact.model.system import ImpactSystem

#: A 5 Hz primary, ζ = 0.02: M 1 kg, K = (2π·5)² N/m.
WN = 2 * math.pi * 5.0
SYSTEM = ImpactSystem(M=1.0, K=WN**2, C=2 * 0.02 * WN, m=0.05, gap=0.02, contact="linear", k1=1e6)


def _integrated(system, times, load, x0=0.0, v0=0.0, base=False):
    """x, ẋ at ``times`` by SciPy's DOP853 at rtol 1e-12 on the load linearly interpolated
    between its samples (np.interp), stepping sample to sample so the kinks are not smoothed."""
    M, K, C = system.M, system.K, system.C
    p = -M * load if base else load
    out = [(x0, v0)]
    y = np.array([x0, v0])
    for i in range(len(times) - 1):
        ta, tb, pa, pb = times[i], times[i + 1], p[i], p[i + 1]

        def rhs(t, s, ta=ta, tb=tb, pa=pa, pb=pb):
            load_t = pa + (pb - pa) * (t - ta) / (tb - ta)
            return [s[1], (load_t - C * s[1] - K * s[0]) / M]

        y = solve_ivp(rhs, (ta, tb), y, method="DOP853", rtol=1e-12, atol=1e-15).y[:, -1]
        out.append(tuple(y))
    return np.array(out)


def test_the_ramp_flight_is_what_an_integrator_gives():
    """One interval, random states and loads: Eq. F8's x, ẋ against DOP853 (rtol 1e-12; the
    comparison holds to 1e-9 of the motion's scale, the integrator's accumulated error)."""
    rng = np.random.default_rng(7)
    for _ in range(20):
        t = rng.uniform(0.0, 0.3)
        p0, pd = rng.uniform(-5, 5), rng.uniform(-100, 100)
        x0, v0 = rng.uniform(-0.01, 0.01), rng.uniform(-0.3, 0.3)
        got = sl.ramp_state_scalar(t, SYSTEM.M, SYSTEM.K, SYSTEM.C, p0, pd, x0, v0)
        ref = _integrated(SYSTEM, np.array([0.0, t]), np.array([p0, p0 + pd * t]), x0, v0)[-1]
        scale = abs(x0) + abs(v0) / WN + (abs(p0) + abs(pd) * t) / SYSTEM.K
        assert abs(got[0] - ref[0]) < 1e-9 * scale
        assert abs(got[1] - ref[1]) < 1e-9 * scale * WN


@pytest.mark.parametrize("kind", ["force", "base-acceleration"])
def test_a_record_response_is_what_an_integrator_gives(kind):
    """A random record of 2 s, every sample of the recurrence against DOP853 run sample to
    sample (1e-8 of the largest displacement: 400 intervals of the integrator's 1e-12)."""
    rec = random_record(1e-2, (1.0, 20.0), 2.0, 0.005, seed=3, kind=kind)
    got = primary_response(SYSTEM, rec, 1e-3, -0.02)
    ref = _integrated(SYSTEM, rec.times, rec.values, 1e-3, -0.02, base=kind != "force")
    scale = np.max(np.abs(ref[:, 0]))
    assert np.max(np.abs(got.displacement - ref[:, 0])) < 1e-8 * scale
    assert np.max(np.abs(got.velocity - ref[:, 1])) < 1e-8 * scale * WN


def test_the_random_record_has_its_psd_and_is_reproducible():
    """Parseval: the record's mean square over its period is the PSD's integral over the band
    as a sum of width 1/T, S₀·Σ 1/T, each line raised by the loss of the straight lines between
    samples, 1/sinc²(fₖ·dt) (to rounding); Welch's
    estimate is S₀ inside the band (within its scatter, 1/√(segments averaged) ≈ 6 %: 25 %) and
    below 1e-3 of it outside (the Hann window's leakage 2 Hz from the band's edges); the same seed gives the same record, another seed another one."""
    S0, T, dt = 0.04, 64.0, 1 / 512
    rec = random_record(S0, (5.0, 40.0), T, dt, seed=11)
    fk = np.arange(5 * T, 40 * T + 1) / T
    # each line raised by the straight lines' loss between samples, 1/sinc²(f·dt) (≤ 1.0078 here)
    gain = (np.sin(np.pi * fk * dt) / (np.pi * fk * dt)) ** 2
    assert np.mean(rec.values[:-1] ** 2) == pytest.approx(S0 * np.sum(gain**-2) / T, rel=1e-12)
    from scipy.signal import welch

    f, P = welch(rec.values[:-1], fs=1 / dt, nperseg=1024)
    inside = (f > 7) & (f < 38)
    outside = (f > 45) | ((f >= 1) & (f <= 3))  # (the lowest bins hold each segment's mean)
    assert np.all(np.abs(P[inside] / S0 - 1) < 0.25)
    assert np.max(P[outside]) < 1e-3 * S0
    again = random_record(S0, ("5 Hz", "2400 rpm"), T, dt, seed=11)  # the same band
    assert np.array_equal(again.values, rec.values)
    other = random_record(S0, (5.0, 40.0), T, dt, seed=12)
    assert not np.allclose(other.values, rec.values)


def test_the_random_response_rms_is_the_linear_theory():
    """The record is a sum of cosines, periodic over T: after the transient (10 T ≫ 1/(ζωₙ))
    the response over one period has the mean square Σ |H(fₖ)|²Aₖ²/2 (H = 1/(K − Mω² + iCω)):
    the samples carry the lines raised by the straight lines' loss between them, which was
    (πf·dt)²/3 ≤ 1e-3 at the band's top at dt = 1/512 s (the tolerance had been 2e-3); what is
    left is the lines' images at 1/dt ± fₖ (their load below 2e-4 of the line's, their response
    below 1e-8 of it behind |H|²) and rounding: 1e-6.  And that sum is ∫S₀|H|²df over the band to 1 % (Δf = 1/T
    resolves the resonance's half-power width 2ζfₙ = 0.2 Hz with 6 frequencies)."""
    S0, T, dt = 1.0, 32.0, 1 / 512
    one = random_record(S0, (2.0, 12.0), T, dt, seed=5)
    periods = 12
    values = np.concatenate([one.values[:-1]] * periods + [one.values[:1]])
    rec = type(one)(values, dt, "force")
    res = primary_response(SYSTEM, rec)
    last = res.displacement[-len(one.values) : -1]
    k = np.arange(2 * T, 12 * T + 1)
    w = 2 * np.pi * k / T
    H2 = 1 / ((SYSTEM.K - SYSTEM.M * w**2) ** 2 + (SYSTEM.C * w) ** 2)
    expected = math.sqrt(np.sum(H2 * (2 * S0 / T) / 2))
    assert math.sqrt(np.mean(last**2)) == pytest.approx(expected, rel=1e-6)
    from scipy.integrate import quad

    def H2f(f):
        om = 2 * np.pi * f
        return S0 / ((SYSTEM.K - SYSTEM.M * om**2) ** 2 + (SYSTEM.C * om) ** 2)

    integral = quad(H2f, 2.0, 12.0, points=[5.0], limit=200)[0]
    assert expected**2 == pytest.approx(integral, rel=1e-2)


def test_a_half_sine_srs_has_its_textbook_asymptotes():
    """A half-sine of peak A and duration τ: far above 1/τ the oscillator follows the base (SRS
    → A, within 2 % at 20/τ with ζ 5 %); far below it the pulse is an impulse of velocity change
    ΔV = 2Aτ/π and the peak is ωₙ·ΔV (undamped, within 2 % at 0.02/τ)."""
    A, tau = 100.0, 0.01
    rec = shock_record("half-sine", A, tau, 60.0, 2e-5, kind="base-acceleration")
    hi = srs(rec, [20 / tau], zeta=0.05)[0]
    assert hi == pytest.approx(A, rel=0.02)
    f_lo = 0.02 / tau
    lo = srs(rec, [f_lo], zeta=0.0)[0]
    assert lo == pytest.approx(2 * math.pi * f_lo * 2 * A * tau / math.pi, rel=0.02)


def test_the_sweep_passes_through_its_frequencies():
    """A linear sweep's zero crossings: between consecutive upward crossings one period of the
    instantaneous frequency there (to 1 %); the log sweep ends at its end frequency."""
    rec = sweep_record(1.0, 2.0, 10.0, 1.0, 1e-3)
    v = rec.values
    up = np.nonzero((v[:-1] < 0) & (v[1:] >= 0))[0]
    t = rec.times[up]
    mids = 0.5 * (t[1:] + t[:-1])
    f = sweep_frequency(mids, 2.0, 10.0, 1.0)
    assert np.allclose(np.diff(t) * f, 1.0, rtol=1e-2)
    log = sweep_record(1.0, 1.0, 16.0, 60.0, 1e-3, law="log")  # 4 octaves at 1 octave/s
    assert log.duration == pytest.approx(4.0, abs=1e-3)
    assert sweep_frequency(np.array([4.0]), 1.0, 16.0, 60.0, "log")[0] == pytest.approx(16.0)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: random_record(1.0, (5.0, 40.0), 10.0, 0.01, 1), "dt"),
        (lambda: random_record(1.0, (40.0, 5.0), 10.0, 0.001, 1), "band"),
        (lambda: random_record(1.0, (-1.0, 5.0), 10.0, 0.001, 1), "band"),
        (lambda: random_record(1.0, "5:40", 10.0, 0.001, 1), "band"),
        (lambda: random_record(-1.0, (5.0, 40.0), 10.0, 0.001, 1), "psd"),
        (lambda: random_record(1.0, (5.0, 40.0), 10.0, 0.001, 1.5), "seed"),
        (lambda: random_record(1.0, (5.0, 40.0), 10.0, 0.001, 1, kind="torque"), "kind"),
        (lambda: shock_record("square", 1.0, 0.01, 1.0, 1e-4), "shape"),
        (lambda: shock_record("half-sine", 1.0, 0.01, 1.0, 1e-3), "dt"),
        (lambda: shock_record("half-sine", 1.0, 0.01, 0.001, 1e-5), "duration"),
        (lambda: sweep_record(1.0, 5.0, 5.0, 1.0, 1e-3), "f_end"),
        (lambda: srs(shock_record("half-sine", 1.0, 0.01, 1.0, 1e-4), [10.0]), "record"),
        (
            lambda: srs(shock_record("half-sine", 1, 0.01, 1, 1e-4, "base-acceleration"), [1e3]),
            "frequencies",
        ),
    ],
)
def test_bad_loads_are_refused_naming_the_parameter(call, name):
    with pytest.raises(ParameterError) as err:
        call()
    assert err.value.parameter == name


@settings(max_examples=60, deadline=None)
@given(
    M=st.floats(0.1, 20.0),
    fn=st.floats(0.5, 50.0),
    zeta=st.floats(0.0, 0.2),
    p0=st.floats(-10.0, 10.0),
    pd=st.floats(-200.0, 200.0),
    x0=st.floats(-0.01, 0.01),
    v0=st.floats(-0.5, 0.5),
    t1=st.floats(0.0, 0.05),
    t2=st.floats(0.0, 0.05),
)
def test_two_flights_make_one_and_the_flight_is_linear(M, fn, zeta, p0, pd, x0, v0, t1, t2):
    """The flight is a flow: τ₁ then τ₂ (the load carried on, p₀ + ṗτ₁) is τ₁ + τ₂ at once;
    and it is linear in (p₀, ṗ, x₀, ẋ₀) jointly: the flight of a sum is the sum of the flights.
    Both to 1e-12 of the motion's scale: a few roundings of terms of that size (the closed form
    adds the line and a decay that cancel no more than that)."""
    w = 2 * math.pi * fn
    K, C = M * w * w, 2 * zeta * M * w
    state = sl.ramp_state_scalar
    mid = state(t1, M, K, C, p0, pd, x0, v0)
    two = state(t2, M, K, C, p0 + pd * t1, pd, *mid)
    one = state(t1 + t2, M, K, C, p0, pd, x0, v0)
    T = t1 + t2
    scale = abs(x0) + abs(v0) / w + (abs(p0) + abs(pd) * T + C * abs(pd) / K) / K
    assert abs(two[0] - one[0]) <= 1e-12 * scale
    assert abs(two[1] - one[1]) <= 1e-12 * scale * w
    a = state(T, M, K, C, p0, 0.0, x0, 0.0)
    b = state(T, M, K, C, 0.0, pd, 0.0, v0)
    assert abs(a[0] + b[0] - one[0]) <= 1e-12 * scale
    assert abs(a[1] + b[1] - one[1]) <= 1e-12 * scale * w
