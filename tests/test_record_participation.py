"""A base record drives the primary through its participation Γ (the one-mode reduction of a
structure, Eq. F7 referred to the damper's point a: M·ẍ + C·ẋ + K·x = −Γφ(a)·M·ẍ_b, while the impact
mass feels −m·ẍ_b): checked against a brute-force integration with impacts, against the first
mode of a cantilever integrated on its own, and by the energy ledger (which carries Γ in the
load's work, through sticking too).  Γ = 1 is the primary on its base, bit for bit as before."""

import math

import numpy as np
import pytest
from helpers import flights_with_impacts
from scipy.integrate import solve_ivp

from symimpact.errors import ParameterError
from symimpact.forced.loads.record_flight import primary_response
from symimpact.forced.loads.record_response import damper_response
from symimpact.forced.loads.records import random_record, shock_record
from symimpact.model.structure import beam_structure
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)


def brute_force(system, record, e, gamma):
    """x, ẋ, y, ẏ (relative to the base) at every sample and the impact times: DOP853 with impact
    events (:func:`helpers.flights_with_impacts`) interval by interval of the record; the
    primary's load −Γ·M·a_b, the impact mass's −m·a_b; and x's absolute acceleration at the
    samples, from the equations (the last interval's value at its end)."""
    M, m, K, C, h = system.M, system.m, system.K, system.C, system.gap / 2
    q, dt = record.values, record.dt
    s = np.zeros(4)
    out, hits, acc = [s.copy()], [], [-(gamma - 1.0) * q[0]]
    for i in range(len(q) - 1):
        ta, tb = i * dt, (i + 1) * dt
        slope = (q[i + 1] - q[i]) / dt

        def rhs(t, w, q0=q[i], ta=ta, slope=slope):
            a_b = q0 + slope * (t - ta)
            return [w[1], -gamma * a_b - (C * w[1] + K * w[0]) / M, w[3], -a_b]

        s, more, _ = flights_with_impacts(rhs, s, ta, tb, h, e, M, m)
        hits += more
        out.append(s.copy())
        acc.append(rhs(tb, s)[1] + q[i + 1])
    return np.array(out), np.array(hits), np.array(acc)


@pytest.mark.parametrize("gamma", [1.566, -0.434])
def test_a_base_shock_with_impacts_and_a_participation_agrees_with_a_brute_force(gamma):
    """Γ = 1.566 (a cantilever's first mode at its tip) and −0.434 (a second mode, the supports
    pushing it the other way): impact times and states at every sample as the brute force's to
    1e-8 of the motion (the bound of the Γ = 1 test beside it: DOP853's 1e-12 a step carried
    through the impacts), the absolute acceleration likewise, and the ledger closed to 1e-10."""
    record = shock_record("half-sine", 30.0, 0.05, 1.5, 1e-3, kind="base-acceleration")
    ours = damper_response(SYSTEM, record, e=0.6, participation=gamma)
    states, hits, acc = brute_force(SYSTEM, record, 0.6, gamma)
    assert 8 <= len(hits) == len(ours.impact_times)
    assert np.allclose(ours.impact_times, hits, rtol=0, atol=1e-9)
    scale = np.max(np.abs(states[:, 0]))
    assert np.max(np.abs(ours.displacement - states[:, 0])) < 1e-8 * scale
    assert np.max(np.abs(ours.damper_displacement - states[:, 2])) < 1e-8 * scale
    # the acceleration scale ω_n²·x (and the record's 30 m/s²): the same relative bound
    a_scale = np.max(np.abs(acc))
    assert np.max(np.abs(ours.acceleration - acc)) < 1e-7 * a_scale
    assert ours.ledger["residual"] < 1e-10
    alone = primary_response(SYSTEM, record, participation=gamma)
    # before the first impact both are the primary alone
    first = int(hits[0] / record.dt)
    assert np.allclose(ours.displacement[:first], alone.displacement[:first], rtol=0,
                       atol=1e-12 * scale)  # fmt: skip


def test_the_ledger_closes_with_a_participation_through_chatter_and_sticking():
    """e = 0 and 0.3 under base noise with Γ = 1.566: the masses chatter, stick and ride (the
    pair's load −(Γ·M + m)·a_b), and the work −∫a_b·(Γ·M·ẋ + m·ẏ) dt balances the energy, C's
    dissipation and the impacts' loss to 1e-10, as for Γ = 1 (test_record_response)."""
    record = random_record(5.0, (1, 20), 30.0, 0.005, seed=11, kind="base-acceleration")
    for e in (0.0, 0.3):
        ours = damper_response(SYSTEM, record, e=e, participation=1.566)
        assert len(ours.impact_times) > 20
        if e == 0.0:
            assert ours.stuck.any()
        assert ours.ledger["residual"] < 1e-10


def test_the_one_mode_reduction_is_the_structures_first_mode():
    """A 0.5 m aluminium cantilever's first mode (Ritz kernels, Step 14) reduced to its tip:
    M = M₁/φ₁(L)², K = ω₁²M, Γ = Γ₁φ₁(L).  Its response to a band-limited base record equals
    φ₁(L)·q₁ of mode 1's own equation M₁q̈ + C₁q̇ + K₁q = −Γ₁M₁·a_b integrated by DOP853
    (rtol 1e-11), to 1e-8 of the motion (the integrator's tolerance, carried over 10⁴ steps of the
    record); the damper far out of reach changes nothing.  Γ = 1 would be 36 % low."""
    beam = beam_structure("cantilever", 70e9, 3.125e-10, 2700.0, 1.5e-4, 0.5, {"tip": 0.5},
                          modes=3, zeta=0.01)  # fmt: skip
    mode = beam.modes[0]
    phi = mode.shape["tip"]
    gp = mode.participation * phi
    assert gp == pytest.approx(1.566, abs=5e-4)  # the textbook figure
    M = mode.mass / phi**2
    reduced = ImpactSystem(M=M, K=mode.omega**2 * M, C=2 * mode.zeta * mode.omega * M, m=0.005,
                           gap=1e3, contact="linear", k1=1e6)  # fmt: skip
    record = random_record(20.0, (5, 100), 2.0, 2e-4, seed=5, kind="base-acceleration")
    q, dt = record.values, record.dt
    w1, z1 = mode.omega, mode.zeta

    def rhs(t, w):
        i = min(int(t / dt), len(q) - 2)
        a_b = q[i] + (q[i + 1] - q[i]) * (t / dt - i)
        return [w[1], -mode.participation * a_b - 2 * z1 * w1 * w[1] - w1 * w1 * w[0]]

    s, modal = np.zeros(2), [0.0]
    for i in range(len(q) - 1):  # interval by interval: the record has a kink at each sample
        s = solve_ivp(rhs, (i * dt, (i + 1) * dt), s, method="DOP853", rtol=1e-11,
                      atol=1e-16).y[:, -1]  # fmt: skip
        modal.append(s[0])
    tip = phi * np.array(modal)
    alone = primary_response(reduced, record, participation=gp)
    ours = damper_response(reduced, record, e=0.6, participation=gp)
    scale = np.max(np.abs(tip))
    assert np.max(np.abs(alone.displacement - tip)) < 1e-8 * scale
    assert len(ours.impact_times) == 0
    assert np.max(np.abs(ours.displacement - tip)) < 1e-8 * scale
    unit = primary_response(reduced, record)
    ratio = math.sqrt(np.mean(unit.displacement**2) / np.mean(tip**2))
    assert ratio == pytest.approx(1 / gp, rel=1e-12)  # linear: the response scales with Γ


def test_a_participation_needs_a_base_record():
    record = shock_record("half-sine", 30.0, 0.05, 0.5, 1e-3)
    with pytest.raises(ParameterError, match=r"participation: .*not a base acceleration"):
        damper_response(SYSTEM, record, e=0.5, participation=1.5)
    with pytest.raises(ParameterError, match="participation"):
        primary_response(SYSTEM, record, participation=math.nan)


def test_the_modal_closed_form_is_the_textbook_white_noise_response():
    """One mode (f 10 Hz, ζ 0.02, shape 0.8 at the point, Γ 1.9) under white base acceleration G
    [(m/s²)²/Hz] over a band wide enough to hold the resonance's whole area: the relative
    displacement's variance is (φΓ)²·G/(8ζωₙ³) and the velocity's (φΓ)²·G/(8ζωₙ) (the integrals
    ∫₀^∞ dω/|ωₙ² − ω² + 2iζωₙω|² = π/(4ζωₙ³) and ω² times it = π/(4ζωₙ), df = dω/2π).  The band
    0.001–10⁴ Hz leaves out 2.5e-6 of the displacement's area (below 0.001 Hz: 4ζω₁/(πωₙ)) and
    2.5e-5 of the velocity's (above: 4ζωₙ/(πω₂)); the bounds are 1e-4."""
    from symimpact.forced.loads.random_response import modal_random_rms
    from symimpact.model.structure import modal_structure

    s = modal_structure([{"f": 10.0, "mass": 3.0, "zeta": 0.02, "shape": {"a": 0.8},
                          "participation": 1.9}])  # fmt: skip
    G, wn, z, gp = 0.3, 2 * math.pi * 10.0, 0.02, 0.8 * 1.9
    rms = modal_random_rms(s, "a", G, (1e-3, 1e4))
    assert rms["displacement"] ** 2 == pytest.approx(gp**2 * G / (8 * z * wn**3), rel=1e-4)
    assert rms["velocity"] ** 2 == pytest.approx(gp**2 * G / (8 * z * wn), rel=1e-4)
    # the absolute acceleration of a point on the base alone (Γ = 0): the base's own G·band
    s0 = modal_structure([{"f": 10.0, "mass": 3.0, "zeta": 0.02, "shape": {"a": 0.8}}])
    assert modal_random_rms(s0, "a", G, (5, 50))["acceleration"] == pytest.approx(
        math.sqrt(G * 45.0), rel=1e-12
    )
    with pytest.raises(ParameterError, match="band"):
        modal_random_rms(s, "a", G, (0, 50))


def test_the_reductions_base_force_is_the_modes_base_shear():
    """A structure's supports take Σ Γᵢ(Kᵢqᵢ + Cᵢq̇ᵢ) from its modes (the modal base shear,
    Chopra's Vᵢ = Lᵢωᵢ²qᵢ with Lᵢ = ΓᵢMᵢ, and its damping part): the reduction's base force is
    Γφ·(K·x + C·ẋ), x = φ·q, the same number to rounding (here from the modal coordinate of the
    reduction's own run, q = x/φ)."""
    beam = beam_structure("cantilever", 70e9, 3.125e-10, 2700.0, 1.5e-4, 0.5, {"tip": 0.5},
                          modes=3, zeta=0.01)  # fmt: skip
    mode = beam.modes[0]
    phi = mode.shape["tip"]
    M = mode.mass / phi**2
    reduced = ImpactSystem(M=M, K=mode.omega**2 * M, C=2 * mode.zeta * mode.omega * M, m=0.005,
                           gap=1e3, contact="linear", k1=1e6)  # fmt: skip
    record = random_record(20.0, (5, 100), 1.0, 2e-4, seed=5, kind="base-acceleration")
    gp = mode.participation * phi
    alone = primary_response(reduced, record, participation=gp)
    q, qd = alone.displacement / phi, alone.velocity / phi
    Ki, Ci = mode.omega**2 * mode.mass, 2 * mode.zeta * mode.omega * mode.mass
    shear = mode.participation * (Ki * q + Ci * qd)
    assert np.allclose(alone.base_force, shear, rtol=1e-12, atol=1e-12 * np.abs(shear).max())
