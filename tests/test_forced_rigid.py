"""The forced simulation with rigid impacts (Eq. F1, F2) and the closed-form symmetric orbits
(Eq. F3), each against something independent of it.

- A stable closed-form orbit is reached by a long simulation started off it (amplitude to 1e-8
  relative: the simulation's own error is rounding, ~1e-12, and the perturbation decays by the
  largest multiplier to the power 500); an unstable one is left by a simulation started on it.
- Without reachable walls the steady amplitude is the linear frequency response.
- The energy ledger closes: E(end) − E(0) = work of the forcing − dissipation (quadrature and
  impacts), to 1e-11 of the energies exchanged (8-point Gauss–Legendre on 1/16 periods is exact
  to rounding; ~1e3 events each add a few ULPs).
- A chatter sequence jumps to the limit the explicit impact sequence converges to.
"""

from __future__ import annotations

import numpy as np
import pytest
from symimpact.generated import forced_flight as ff

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, periodic_orbits, simulate_forced
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


def _start_on(orbit, omega, scale=1.0):
    forcing = Forcing(F0=2, omega=omega, phase=orbit.impact_phase)
    h = SYSTEM.gap / 2
    return forcing, dict(x0=orbit.X * scale, xdot0=orbit.V, y0=orbit.X * scale + h, ydot0=orbit.U)


def test_a_stable_closed_form_orbit_is_reached():
    (orbit,) = [o for o in periodic_orbits(SYSTEM, Forcing(F0=2, omega=38), E) if o.stable]
    assert orbit.admissible and orbit.multipliers[0] < 1
    forcing, start = _start_on(orbit, 38, scale=1 + 1e-4)
    res = simulate_forced(SYSTEM, forcing, e=E, periods=600, discard=500, **start)
    assert res.steady.amplitude == pytest.approx(orbit.amplitude, rel=1e-8)
    assert res.steady.impacts_per_period == 2
    assert res.steady.periodic and res.steady.period_multiple == 1
    # the impacts of the last period: the closed form's speed and alternating walls
    last = res.events[-2:]
    assert list(last[:, 4]) in ([1.0, -1.0], [-1.0, 1.0])
    np.testing.assert_allclose(last[:, 5], orbit.impact_speed, rtol=1e-8)


@pytest.mark.parametrize("omega", [25.0, 34.0])
def test_an_unstable_closed_form_orbit_is_left(omega):
    orbit = next(o for o in periodic_orbits(SYSTEM, Forcing(F0=2, omega=omega), E) if o.admissible)
    assert not orbit.stable and orbit.multipliers[0] > 1
    forcing, start = _start_on(orbit, omega)
    res = simulate_forced(SYSTEM, forcing, e=E, periods=600, discard=500, **start)
    assert abs(res.steady.amplitude - orbit.amplitude) > 1e-6 * orbit.amplitude


@pytest.mark.parametrize("omega", [20.0, 31.0, 45.0])
def test_without_reachable_walls_the_response_is_linear(omega):
    system = ImpactSystem(M=1, K=1000, C=5.0, m=0.05, gap=2.0, contact="linear", k1=1e6)
    forcing = Forcing(F0=2, X_b="1 mm", omega=omega)
    res = simulate_forced(system, forcing, e=E, periods=300, discard=200)
    expected = float(ff.linear_amplitude(1, 1000, 5.0, 2, 1e-3, omega))
    assert len(res.impacts) == 0
    assert res.steady.amplitude == pytest.approx(expected, rel=1e-9)
    assert res.steady.periodic and res.steady.period_multiple == 1


@pytest.mark.parametrize("e", [0.0, 0.3, 0.9])
def test_the_energy_ledger_closes_with_forcing_chatter_and_sticking(e):
    forcing = Forcing(F0=2, X_b=0.003, omega=30)
    res = simulate_forced(SYSTEM, forcing, e=e, periods=40)
    assert len(res.impacts) > 10
    assert res.energy["relative_residual"] < 1e-11, res.energy


def test_chatter_jumps_to_the_limit_of_the_impact_sequence():
    forcing = Forcing(F0=2, X_b=0.003, omega=30)
    e = 0.3
    res = simulate_forced(SYSTEM, forcing, e=e, periods=3)
    i = int(np.nonzero(res.events[:, 7] == 1)[0][0])  # the first accumulation
    t_jump, t_from = res.events[i, 0], res.events[i - 1, 0]
    explicit = simulate_forced(SYSTEM, forcing, e=e, periods=3, chatter=0.0).events[:, 0]
    seq = explicit[(explicit > t_from - 1e-3) & (explicit < t_jump + 1e-3)]
    flights = np.diff(seq)
    # the flights shrink by e while they are resolved; extrapolate the geometric tail from the
    # last resolved one (ratio within 1 % of e)
    ok = np.nonzero(np.abs(flights[1:] / flights[:-1] - e) < 0.01 * e)[0]
    k = ok[-1] + 1
    limit = seq[k + 1] + flights[k] * e / (1 - e)
    # the jump assumes a constant relative acceleration over Δ = t_jump − t_from: its error is
    # second order in Δ, and 1e-3·Δ is far above it.  Both sequences end in bounces at relative
    # speeds w of order 1e-8 m/s, where the wall's distance is known only to its last place:
    # each such bounce is timed to about ulp(d/2)/w, which a dozen of them add up to
    w_from = e * res.events[i - 1, 5]  # the separation speed of the last resolved bounce
    rounding = 12 * np.spacing(SYSTEM.gap / 2) / w_from
    assert abs(limit - t_jump) < 1e-3 * (t_jump - t_from) + rounding


@pytest.mark.parametrize(
    "kw, parameter",
    [
        (dict(e=1.5), "e"),
        (dict(e=-0.1), "e"),
        (dict(e=None), "e"),
        (dict(e=0.5, periods=0), "periods"),
        (dict(e=0.5, periods=10, discard=10), "discard"),
        (dict(e=0.5, y0=0.5), "y0"),
    ],
)
def test_bad_input_names_the_parameter(kw, parameter):
    with pytest.raises(ParameterError) as info:
        simulate_forced(SYSTEM, Forcing(F0=2, omega=30), **kw)
    assert info.value.parameter == parameter


def test_forcing_reads_hz_as_cycles_and_refuses_two_frequencies():
    # Hz given for Ω counts cycles (tests/test_reliability.py has every unit)
    assert Forcing(F0=1, omega="5 Hz").omega == pytest.approx(2 * np.pi * 5, rel=1e-15)
    with pytest.raises(ParameterError, match="omega"):
        Forcing(F0=1, omega=3, freq=1)
    assert Forcing(F0=1, freq="5 Hz").omega == pytest.approx(2 * np.pi * 5)


@pytest.mark.parametrize("omega", [34.0, 36.0, 38.0, 40.0])
def test_closed_form_multipliers_are_those_of_the_simulated_stroboscopic_map(omega):
    """The closed form's multipliers (the linearised impact-to-impact map, next impact time
    included) against the eigenvalues of the stroboscopic map P — one forcing period of the
    event-driven simulation from a section a quarter period after an impact — differentiated by
    central differences (step 1e-6 of each component's scale: truncation ~1e-12, rounding
    ~1e-16/1e-6 = 1e-10 of the map).  Measured: 1e-9 of the largest modulus; eigenvalues move by
    the matrix's error times its norm, so the bound is 1e-6 of the largest modulus."""
    from symimpact.forced.simulation import state_at

    h = SYSTEM.gap / 2
    orbits = [o for o in periodic_orbits(SYSTEM, Forcing(F0=2, omega=omega), E) if o.admissible]
    assert orbits
    for o in orbits:
        T = 2 * np.pi / omega
        f = Forcing(F0=2, omega=omega, phase=o.impact_phase)
        on = simulate_forced(SYSTEM, f, e=E, periods=1, x0=o.X, xdot0=o.V, y0=o.X + h,
                             ydot0=o.U)  # fmt: skip
        s0 = state_at(on, np.array([T / 4]))[0]  # x, ẋ, z = y − x, ẏ
        g = Forcing(F0=2, omega=omega, phase=o.impact_phase + np.pi / 2)

        def P(s, g=g):
            r = simulate_forced(SYSTEM, g, e=E, periods=1, x0=s[0], xdot0=s[1], y0=s[0] + s[2],
                                ydot0=s[3])  # fmt: skip
            x, v, y, u = r.final_state
            return np.array([x, v, y - x, u])

        np.testing.assert_allclose(P(s0), s0, atol=1e-13)  # a fixed point of P
        scale = np.array([o.amplitude, o.amplitude * omega, h, o.amplitude * omega]) * 1e-6
        J = np.column_stack(
            [(P(s0 + d) - P(s0 - d)) / (2 * d[j]) for j, d in enumerate(np.diag(scale))]
        )
        moduli = np.sort(np.abs(np.linalg.eigvals(J)))[::-1]
        assert np.all(np.abs(moduli - o.multipliers) <= 1e-6 * o.multipliers[0])
        assert o.stable == (moduli[0] < 1.0)


UNDAMPED = ImpactSystem(M=1, K=1000, C=0, m=0.05, gap=0.1, contact="linear", k1=1e6)


@pytest.mark.parametrize("ratio", [1.0, 1 + 1e-6, 1 - 1e-6, 1 + 1e-4])
def test_an_undamped_primary_at_and_next_to_resonance_has_its_orbit(ratio):
    """Masri and Caughey's setting: C = 0 with Ω at or next to ωₙ, where the steady solution of
    the primary alone does not exist.  The closed form (Γ written with sinc, Eq. F3) gives the
    stable orbit; a simulation started 1e-4 off it settles on it (1e-8: the perturbation decays
    by the largest multiplier, 0.79, to the power 500, and each period's events add rounding)."""
    omega = np.sqrt(1000.0) * ratio
    (orbit,) = [o for o in periodic_orbits(UNDAMPED, Forcing(F0=2, omega=omega), E) if o.stable]
    assert orbit.admissible and 0.7 < orbit.multipliers[0] < 0.9
    forcing = Forcing(F0=2, omega=omega, phase=orbit.impact_phase)
    h = UNDAMPED.gap / 2
    x0 = orbit.X * (1 + 1e-4)
    start = dict(x0=x0, xdot0=orbit.V, y0=x0 + h, ydot0=orbit.U)
    res = simulate_forced(UNDAMPED, forcing, e=E, periods=600, discard=500, **start)
    assert res.steady.amplitude == pytest.approx(orbit.amplitude, rel=1e-8)
    assert res.steady.impacts_per_period == 2


def test_the_closed_form_is_smooth_through_the_undamped_resonance():
    """X at Ω = ωₙ(1 − δ), ωₙ, ωₙ(1 + δ) (δ = 1e-10) lies on a line: the second difference is
    within 1e-12·d/2 (measured 2e-15 m; X moves by 5e-10 m, its slope times the offset).  Before
    the Γ form the steady solution's coefficients lost digits like 1/(Ω − ωₙ) (X 46.3 mm instead
    of 39.3 mm at 1 + 1e-8) and Ω = ωₙ was refused."""
    wn = np.sqrt(1000.0)

    def xs(ratio):
        return np.sort([o.X for o in periodic_orbits(UNDAMPED, Forcing(F0=2, omega=wn * ratio), E)])

    below, at, above = xs(1 - 1e-10), xs(1.0), xs(1 + 1e-10)
    assert len(at) == 2
    assert np.all(np.abs(below + above - 2 * at) <= 1e-12 * UNDAMPED.gap / 2)
    assert np.all(np.abs(above - at) > 1e-12)  # X does move: the test sees the offset


def test_the_closed_form_has_no_pole_where_three_conditions_degenerate():
    """At Ω = 0.98433714339907 ωₙ (C = 0.5) the determinant of the first three conditions
    vanishes: Cramer's rule on them divided by zero there (an internal error, and 1e-5 wrong
    1e-6 rad/s away).  The four conditions together give the orbits; each satisfies the four
    conditions with the flight of Step 8 (forced_displacement, forced_velocity) over the half
    period, to 1e-12 of the scale of each (rounding of the kernels; measured 6e-16)."""
    omega = 0.9843371433990715 * np.sqrt(1000.0)
    orbits = periodic_orbits(SYSTEM, Forcing(F0=2, omega=omega), E)
    assert len(orbits) == 2
    S, h, tau = SYSTEM, SYSTEM.gap / 2, np.pi / omega
    for o in orbits:
        args = (tau, S.M, S.K, S.C, 2.0, 0.0, omega, o.impact_phase, o.X, o.V)
        x, v = float(ff.forced_displacement(*args)), float(ff.forced_velocity(*args))
        speed = abs(o.V) + abs(o.U) + abs(v)
        residuals = [
            (x + o.X) / o.amplitude,
            (2 * o.X + 2 * h + o.U * tau) / o.amplitude,
            (S.M * v + S.m * o.U + S.M * o.V + S.m * o.U) / ((S.M + S.m) * speed),
            (o.V - o.U + E * (o.U - v)) / speed,
        ]
        np.testing.assert_allclose(residuals, 0.0, atol=1e-12)


def test_impact_events_count_a_chatter_sequence_once_whatever_the_chatter_threshold():
    """e = 0.05 at Ω 28 rad/s: one chatter sequence on each wall a period.  How many of its
    impacts the run resolves before jumping to their limit depends on the chatter threshold
    (a fraction of the period: 6 impacts a period at 1e-2, 12 at 1e-5); the impact events do
    not (2), and the amplitude agrees to 1e-8 once the threshold resolves it (≤ 1e-4)."""
    counts = {}
    for chatter in (1e-2, 1e-3, 1e-4, 1e-5):
        r = simulate_forced(SYSTEM, Forcing(F0=2, omega=28), e=0.05, periods=300, discard=200,
                            chatter=chatter)  # fmt: skip
        assert r.steady.periodic and r.steady.period_multiple == 1
        counts[chatter] = (r.steady.impacts_per_period, r.steady.impact_events_per_period)
        if chatter <= 1e-4:
            assert r.steady.amplitude == pytest.approx(0.01017114912, rel=1e-8)
    assert {events for _, events in counts.values()} == {2.0}
    assert len({impacts for impacts, _ in counts.values()}) > 1  # the resolved count does move
