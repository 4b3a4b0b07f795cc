"""The located peak of a frequency-response curve (issue 33, item 6), against what does not
locate it: the textbook resonance of the primary alone, long simulations of the peak's orbit,
a dense scan of the traced branches by shooting, and the same system written in other units or
sampled with another frequency step."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.continuation import orbits_at
from symimpact.forced.orbits.frf import frequency_response
from symimpact.forced.orbits.peak import baseline_peak, linear_amplitude, stable_peak
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
BAND = np.linspace(23.7, 42.7, 191)


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, Forcing(F0=2.0, omega=30.0), E, BAND, sweeps=False)


def _stable(curve):
    """The located peak of the stable orbits (the curve's own peak may also be a motion the
    multi-start samples off every branch)."""
    p = stable_peak(curve.branches, SYSTEM, Forcing(F0=2.0, omega=30.0), E, (BAND[0], BAND[-1]))
    assert curve.peak.amplitude >= p.amplitude
    return p


def test_the_resonance_peak_is_located_on_its_chattering_orbit(curve):
    """Near resonance the impact mass chatters to an accumulation point and sticks on each wall
    (68 impacts a period): the curve, without sweeps, traces that orbit and locates the peak
    between its points (before: a multi-start sample, 102 mm at 30.825 rad/s).  A 600-period
    simulation from rest at the located frequency settles on the same amplitude (independent
    brute force; to 1e-9, measured 1e-12)."""
    p = curve.peak
    assert (p.motion, p.where, p.period_multiple) == ("periodic", "maximum", 1)
    assert p.impacts_per_period > 10
    brute = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=p.omega), contact="rigid", e=E,
                            periods=600)  # fmt: skip
    assert p.amplitude == pytest.approx(np.max(brute.period_max[-100:]), rel=1e-9)


@pytest.mark.parametrize("zeta", [0.002, 0.0079, 0.05, 0.3])
def test_the_baseline_peak_is_the_textbook_resonance(zeta):
    # a force on a damped oscillator peaks at Ω = ω_n √(1 − 2ζ²) with F0 / (2Kζ √(1 − ζ²));
    # Brent's method stops at 1e-9 of Ω, where the curve is flat to second order: 1e-12 on the
    # amplitude, 1e-8 on Ω (the bracket, not the rounding, bounds it)
    K, M = 1000.0, 1.0
    s = ImpactSystem(M=M, K=K, zeta=zeta, m=0.05, gap=0.02, contact="linear", k1=1e6)
    wn = math.sqrt(K / M)
    p = baseline_peak(s, Forcing(F0=2.0, omega=wn), (0.5 * wn, 1.5 * wn))
    assert p.where == "resonance"
    assert p.omega == pytest.approx(wn * math.sqrt(1 - 2 * zeta**2), rel=1e-8)
    assert p.amplitude == pytest.approx(2.0 / (2 * K * zeta * math.sqrt(1 - zeta**2)), rel=1e-12)


def test_the_baseline_peak_off_the_band_is_its_nearer_edge():
    p = baseline_peak(SYSTEM, Forcing(F0=2.0, omega=20.0), (20.0, 30.0))
    assert p.where == "band edge" and p.omega == 30.0
    assert p.amplitude == pytest.approx(float(linear_amplitude(SYSTEM, Forcing(F0=2.0,
                                        omega=30.0), 30.0)), rel=1e-15)  # fmt: skip


def test_the_issue_baseline_is_located_not_sampled():
    # the issue: a 1 rad/s grid over 30–36 rad/s put the primary alone at 69.3 mm (32 rad/s);
    # its resonance is 126.5 mm at 31.6 rad/s
    c = frequency_response(SYSTEM, Forcing(F0=2.0, omega=30.0), E, np.arange(30.0, 36.5, 1.0),
                           sweeps=False, starts=0)  # fmt: skip
    assert c.baseline_peak.amplitude == pytest.approx(0.12649505943910974, rel=1e-12)
    wn, zeta = math.sqrt(1000.0), 0.5 / (2 * math.sqrt(1000.0))
    assert c.baseline_peak.omega == pytest.approx(wn * math.sqrt(1 - 2 * zeta**2), rel=1e-8)


def test_no_stable_orbit_of_a_dense_scan_exceeds_the_peak(curve):
    # every traced branch shot at every 0.02 rad/s (Newton from its interpolated state): no
    # stable amplitude found exceeds the located peak (1e-9: the shooting's tolerance); within
    # 0.01 rad/s of the peak at 1e-4 rad/s, the stable orbits come within 1e-3 of it (the
    # steepest branch there rises 40 mm per rad/s: 4 µm a step, 1.4e-4 of the peak)
    p = _stable(curve)

    def best(ws):
        top = 0.0
        for w in ws:
            f = Forcing(F0=2.0, omega=float(w))
            for b in curve.branches:
                for o in orbits_at(b, SYSTEM, f, E, float(w)):
                    if o.stable:
                        top = max(top, o.amplitude)
        return top

    assert best(np.arange(BAND[0], BAND[-1], 0.02)) <= p.amplitude * (1 + 1e-9)
    near = best(p.omega + np.arange(-0.01, 0.01, 1e-4))
    assert p.amplitude * (1 - 1e-3) <= near <= p.amplitude * (1 + 1e-9)


def test_a_stable_peak_orbit_is_a_long_run_steady_state(curve):
    # the stable orbit nearest the located peak (1e-4 rad/s inside its stable side), run 800
    # periods from its state: the simulation keeps it (1e-6), and its amplitude is within the
    # branch's slope times 1e-4 rad/s of the peak
    p = _stable(curve)
    b = curve.branches[p.branch]
    for dw in (-1e-4, 1e-4):
        w = p.omega + dw
        f = Forcing(F0=2.0, omega=w)
        for o in orbits_at(b, SYSTEM, f, E, w):
            if not o.stable or abs(o.amplitude - p.amplitude) > 1e-3 * p.amplitude:
                continue
            x, v, z, u = o.state
            fs = Forcing(F0=2.0, omega=w, phase=next(q.phase for q in b.points))
            near = min(b.points, key=lambda q: abs(q.omega - w))
            fs = Forcing(F0=2.0, omega=w, phase=near.phase)
            res = simulate_forced(SYSTEM, fs, e=E, periods=800, discard=780, x0=x, xdot0=v,
                                  y0=x + z, ydot0=u)  # fmt: skip
            assert res.steady.amplitude == pytest.approx(o.amplitude, rel=1e-6)
            return
    pytest.fail(f"no stable orbit beside the peak {p}")


@pytest.mark.slow  # three more curves (~18 s): in the slow set
def test_the_peak_does_not_depend_on_the_frequency_step_or_the_units(curve):
    finer = frequency_response(SYSTEM, Forcing(F0=2.0, omega=30.0), E,
                               np.linspace(23.7, 42.7, 381), sweeps=False)  # fmt: skip
    assert finer.peak.amplitude == pytest.approx(curve.peak.amplitude, rel=1e-9)
    assert finer.peak.omega == pytest.approx(curve.peak.omega, rel=1e-9)
    # lengths and forces ×1000 (mm and mN written as m and N): amplitudes ×1000, Ω unchanged
    big = SYSTEM.with_(gap=SYSTEM.gap * 1000)
    scaled = frequency_response(big, Forcing(F0=2000.0, omega=30.0), E, BAND, sweeps=False)
    assert scaled.peak.amplitude == pytest.approx(1000 * curve.peak.amplitude, rel=1e-6)
    assert scaled.peak.omega == pytest.approx(curve.peak.omega, rel=1e-6)
    assert scaled.baseline_peak.amplitude == pytest.approx(
        1000 * curve.baseline_peak.amplitude, rel=1e-12)  # fmt: skip


def test_undriven_there_is_nothing_to_reduce():
    # F0 = 0: the primary alone rests (baseline 0 m) and the reduction is not a number (JSON
    # null), not a division by zero (tests/test_limits.py's "no forcing" frf found it)
    c = frequency_response(SYSTEM, Forcing(F0=0.0, omega=34.0), E, np.linspace(34, 38, 5),
                           sweeps=False, multistart=0)  # fmt: skip
    assert c.baseline_peak.amplitude == 0.0
    assert math.isnan(c.reduction) and c.as_dict()["reduction"] is None


def test_plastic_impacts_give_a_whole_curve_and_its_peak():
    """Plastic impacts (e = 0, the regime of bean-bag and granular dampers): before the
    reliability issue the curve held 2 points in all.  Every periodic attractor the multi-start
    finds lies on a traced stable branch (coverage 1), and the located peak, an orbit whose impact
    mass sticks on each wall after a plastic impact, is the steady state of a 600-period
    simulation from rest at its frequency (independent brute force; to 1e-9, measured 1.8e-12)."""
    f = Forcing(F0=2.0, omega=30.0)
    c = frequency_response(SYSTEM, f, 0.0, np.linspace(25.0, 40.0, 61), sweeps=False)
    assert c.coverage.share == 1.0 and len(c.coverage.periodic) > 5
    assert sum(len(b.points) for b in c.branches) > 100
    p = c.peak
    assert (p.motion, p.period_multiple) == ("periodic", 1) and p.impacts_per_period >= 2
    brute = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=p.omega), contact="rigid", e=0.0,
                            periods=600)  # fmt: skip
    assert p.amplitude == pytest.approx(np.max(brute.period_max[-100:]), rel=1e-9)


@pytest.mark.parametrize("step", [1.0, 0.5, 0.25, 0.125])
def test_the_motion_without_impacts_ends_where_x_reaches_the_gap_whatever_the_step(step):
    """d = 160 mm on the README system: X(Ω) passes d/2 only between 31.3 and 31.9 rad/s, inside
    one step of 1 rad/s (at 31 and 32 rad/s the primary stays inside the clearance).  The
    intervals of the motion without impacts end where X = d/2 for every step: there
    (K − MΩ²)² + (CΩ)² = (F0/(d/2))², a quadratic in Ω² solved in closed form (to 1e-9 rad/s:
    Brent's method stops at 1e-12).  Before, a 1 rad/s step read the whole band as without
    impacts and its peak as the resonance's 126.5 mm, beyond the clearance."""
    from symimpact.forced.orbits.frf import _no_impact
    from symimpact.forced.orbits.peak import no_impact_peak

    M, K, C, F0, d = 1.0, 1000.0, 0.5, 2.0, 0.16
    s = ImpactSystem(M=M, K=K, C=C, m=0.05, gap=d, contact="linear", k1=1e6)
    f = Forcing(F0=F0, omega=30.0)
    w = np.arange(28.0, 36.0 + step / 2, step)
    intervals, grazings = _no_impact(s, f, w, baseline_peak(s, f, (w[0], w[-1])).omega)
    # M²u² + (C² − 2KM)u + K² − (2F0/d)² = 0, u = Ω²
    a, b, c = M**2, C**2 - 2 * K * M, K**2 - (2 * F0 / d) ** 2
    u = np.sort(np.roots([a, b, c]).real)
    assert grazings == pytest.approx(np.sqrt(u), abs=1e-9)
    ends = [(28.0, math.sqrt(u[0])), (math.sqrt(u[1]), 36.0)]
    assert np.array(intervals) == pytest.approx(np.array(ends), abs=1e-9)
    peak = no_impact_peak(s, f, intervals)
    assert peak.amplitude == pytest.approx(d / 2, rel=1e-9) and peak.where == "grazing"
