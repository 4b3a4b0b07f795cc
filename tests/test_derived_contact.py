"""The contact from materials and geometry (Step 13, Eq. F5), against independent references:
a direct integration of the impact, textbook values (Johnson, *Contact Mechanics*, 1985), a
catalogue mass, and a brute-force integration of Thornton's elastic–plastic force law."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from symimpact.generated import closed_forms
from symimpact.generated import hertz_contact as hz

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.model.derived_contact import (
    cavity_body,
    derived_contact,
    impactor_body,
    sphere_mass,
    yield_pressure,
)
from symimpact.model.materials import MATERIALS, material

STEEL_ON_STEEL = ("steel sphere 20 mm", "steel flat")


def _impact(force_in, force_out, mu, v0, rtol=1e-12):
    """Integrate μδ̈ = −F(δ) from δ = 0, δ̇ = v₀ until δ returns to 0 (loading law while δ̇ > 0,
    unloading law after): (largest δ, duration, peak force, rebound speed)."""

    def rhs(t, y):
        f = force_in(y[0]) if y[1] > 0 else force_out(y[0])
        return [y[1], -f / mu]

    def deepest(t, y):
        return y[1]

    deepest.terminal, deepest.direction = True, -1

    def out(t, y):
        return y[0] - out.floor

    out.terminal, out.direction = True, -1
    a = solve_ivp(rhs, (0, 1e3), [0.0, v0], method="DOP853", events=deepest, rtol=rtol,
                  atol=1e-30, dense_output=True)  # fmt: skip
    t1, (dm, _) = a.t_events[0][0], a.y_events[0][0]
    out.floor = 0.0
    b = solve_ivp(lambda t, y: [y[1], -max(force_out(max(y[0], 0.0)), 0.0) / mu], (t1, t1 + 1e3),
                  [dm, 0.0], method="DOP853", events=out, rtol=rtol, atol=1e-30)  # fmt: skip
    return dm, b.t_events[0][0], force_in(dm), -b.y_events[0][0][1]


def test_sphere_mass_matches_a_bearing_ball_catalogue():
    # a 20 mm ball of AISI 52100 weighs 32.7 g in bearing-ball catalogues (ρ = 7810 kg/m³)
    m = sphere_mass(impactor_body("bearing steel sphere 20 mm"))
    assert m == pytest.approx(0.0327, abs=5e-5)


def test_a_sphere_given_by_its_mass_is_the_sphere_of_that_diameter():
    """'steel sphere 2 kg' (a designer's phrase, issue 80) is the steel sphere whose diameter
    gives 2 kg: 78.654 mm at ρ = 7850 kg/m³ (by hand: (6·2/(π·7850))^(1/3) = 0.0786540 m).
    Its mass read back and every derived contact property equal those of the sphere given by
    that diameter, within 1e-12 (the cube root and the cube: a few ULPs)."""
    by_mass = impactor_body("steel sphere 2 kg")
    assert MATERIALS["steel"].rho == 7850.0
    assert 2 * by_mass.radius == pytest.approx(0.0786540, abs=5e-8)
    assert sphere_mass(by_mass) == pytest.approx(2.0, rel=1e-12)
    by_size = impactor_body(f"steel sphere {2 * by_mass.radius!r} m")
    a, b = derived_contact(by_mass, "steel flat", 1.0), derived_contact(by_size, "steel flat", 1.0)
    for key in ("m", "k_hz", "duration", "peak_force", "yield_speed", "e", "chi", "k1", "c1"):
        assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-12), key
    # other units of mass read as masses; a bearing ball in grams gives its catalogue size back
    ball = impactor_body("bearing steel sphere 32.7 g")
    assert 2 * ball.radius == pytest.approx(0.020, abs=2e-5)
    assert 2 * impactor_body("steel sphere 4.40925 lb").radius == pytest.approx(0.078654, rel=1e-5)


@pytest.mark.parametrize("text", ["steel sphere 2 N", "steel sphere 2 kg/m",
                                  "steel cylinder 40 mm x 60 mm", "steel sphere"])  # fmt: skip
def test_an_impactor_neither_a_diameter_nor_a_mass_is_refused_showing_both_forms(text):
    with pytest.raises(ParameterError) as info:
        impactor_body(text)
    assert info.value.parameter == "impactor"
    assert "'20 mm'" in str(info.value) or "'steel sphere 20 mm'" in str(info.value)
    assert "2 kg" in str(info.value)


def test_hertz_stiffness_of_steel_on_steel_is_seven_orders_above_the_papers():
    c = derived_contact(*STEEL_ON_STEEL, 0.5)
    s = MATERIALS["steel"]
    e_star = s.E / (2 * (1 - s.nu**2))  # two equal bodies: Johnson Eq. 4.22 with E₁ = E₂
    assert c.E_star == pytest.approx(e_star, rel=1e-14)
    assert c.k_hz == pytest.approx(4 / 3 * e_star * math.sqrt(0.01), rel=1e-14)
    assert 1e7 < c.k_hz / 1000.0 < 1e8  # the paper's 1000 N/m^1.5 is a resilient contact


@pytest.mark.parametrize("cavity", ["steel flat", "steel spherical cavity 60 mm",
                                    "brass sphere 30 mm", "polyurethane flat"])  # fmt: skip
def test_elastic_impact_against_a_direct_integration(cavity):
    # 1e-10: DOP853 at rtol 1e-12 on an impact of O(1) steps per event; the event root is found
    # to machine precision, so the integration error dominates
    M = 3.0
    c = derived_contact("steel sphere 20 mm", cavity, 0.3, M=M)
    mu = c.m * M / (c.m + M)

    def hertz(d):
        return c.k_hz * max(d, 0.0) ** 1.5

    dm, duration, peak, rebound = _impact(hertz, hertz, mu, 0.3)
    assert c.max_penetration == pytest.approx(dm, rel=1e-10)
    assert c.duration == pytest.approx(duration, rel=1e-10)
    assert c.peak_force == pytest.approx(peak, rel=1e-10)
    assert rebound == pytest.approx(0.3, rel=1e-10)  # elastic: no loss in Hertz's law
    a = hz.contact_radius_scalar(c.R, dm)
    # the peak pressure is 3/2 of the mean pressure F/(πa²) (Hertz's ellipsoidal distribution)
    assert c.peak_pressure == pytest.approx(1.5 * peak / (math.pi * a**2), rel=1e-10)


def test_duration_matches_johnsons_formula_to_its_digits():
    # Johnson Eq. 11.24: t_c = 2.87 (μ²/(R E*² v))^{1/5}, printed to three digits
    c = derived_contact(*STEEL_ON_STEEL, 0.7)
    johnson = 2.87 * (c.m**2 / (c.R * c.E_star**2 * 0.7)) ** 0.2
    assert c.duration == pytest.approx(johnson, rel=0.005 / 2.87)


def test_yield_onset_matches_johnson():
    # Johnson §4.2: under a Hertz pressure the largest shear τ₁ = 0.31 p₀ (ν = 0.3) at 0.48a, so
    # yield starts at p₀ = Y/0.62 (printed to two digits)
    steel = material("E 200 GPa, nu 0.3, rho 7800 kg/m^3, Y 400 MPa")
    p_y = yield_pressure(steel)
    assert 1 / (2 * p_y / steel.yield_strength) == pytest.approx(0.31, abs=0.005)
    # Johnson Eq. 11.26: a sphere on a massive flat of the same material yields at
    # ρV_Y²/Y = 26 (Y/E*)⁴, with p₀ = 1.6 Y (printed to two digits)
    R, rho, Y = 0.01, steel.rho, steel.yield_strength
    e_star = steel.E / (2 * (1 - steel.nu**2))
    m = rho * 4 / 3 * math.pi * R**3
    v_y = hz.yield_speed_scalar(m, m * 1e17, e_star, R, 1.6 * Y)
    assert rho * v_y**2 / Y / (Y / e_star) ** 4 == pytest.approx(26, abs=0.5)


def _thornton_rebound(E_star, R, mu, p_y, v0):
    """Rebound speed of Thornton's (1997) elastic–perfectly-plastic impact, integrated: Hertz up
    to δ_y, then F = F_y + πRp_y(δ − δ_y); unloading Hertzian about R_p = 4E*a_m³/(3F_m) from the
    deepest point."""
    k = hz.hertz_stiffness_scalar(E_star, R)
    d_y = R * (math.pi * p_y / (2 * E_star)) ** 2
    f_y = k * d_y**1.5

    def load(d):
        d = max(d, 0.0)
        return k * d**1.5 if d <= d_y else f_y + math.pi * R * p_y * (d - d_y)

    dm, *_ = _impact(load, load, mu, v0)  # the deepest point (loading only)
    fm, am = load(dm), math.sqrt(R * dm)
    rp = 4 * E_star * am**3 / (3 * fm)
    d_r = dm - am**2 / rp  # where the unloading Hertz law reaches zero force

    def rhs(t, y):
        return [y[1], -4 / 3 * E_star * math.sqrt(rp) * max(y[0] - d_r, 0.0) ** 1.5 / mu]

    def separation(t, y):
        return y[0] - d_r

    separation.terminal, separation.direction = True, -1
    sol = solve_ivp(rhs, (0, 1e3), [dm, 0.0], method="DOP853", events=separation, rtol=1e-12,
                    atol=1e-30)  # fmt: skip
    return -sol.y_events[0][0][1]


def test_thornton_restitution_against_its_force_law_integrated():
    # the kernel against the integrated force law (1e-9: two integrations at rtol 1e-12 and the
    # event location)
    E_star, R, mu, p_y = 100e9, 0.01, 0.05, 2e9
    v_y = hz.yield_speed_scalar(mu, mu * 1e17, E_star, R, p_y)
    for v0 in (1.5 * v_y, 4 * v_y, 30 * v_y):
        e = _thornton_rebound(E_star, R, mu, p_y, v0) / v0
        assert hz.thornton_restitution_scalar(v_y / v0) == pytest.approx(e, rel=1e-9)


def test_restitution_of_the_derived_contact():
    # below the yield speed the impact is elastic; above it Thornton's e; chi and c1 reproduce it
    from symimpact.model.hunt_crossley import hunt_crossley_restitution

    c = derived_contact(*STEEL_ON_STEEL, 0.5)
    assert c.yield_speed < 0.5 and c.e == pytest.approx(
        hz.thornton_restitution_scalar(c.yield_speed / 0.5), rel=1e-15
    )
    assert float(hunt_crossley_restitution(c.chi, 0.5)) == pytest.approx(c.e, rel=1e-12)
    M = c.m * 1e17
    assert closed_forms.linear_restitution_scalar(c.m, M, c.k1, c.c1) == pytest.approx(c.e, 1e-12)
    slow = derived_contact(*STEEL_ON_STEEL, 0.5 * c.yield_speed)
    assert slow.e == 1.0 and slow.chi == 0.0 and slow.c1 == 0.0
    pu = derived_contact("steel sphere 20 mm", "polyurethane flat", 0.5)
    assert pu.e == pytest.approx(math.sqrt(MATERIALS["polyurethane"].resilience), rel=1e-15)


def test_restitution_falls_with_speed_and_tends_to_the_quarter_power():
    r = np.geomspace(1e-6, 1, 50)
    e = hz.thornton_restitution(r)
    assert np.all(np.diff(e) > 0) and e[-1] == pytest.approx(1.0, rel=1e-15)
    # e·(v₀/v_y)^{1/4} → (6√3/5)^{1/2}·2^{-1/4}(6/5)^{-1/8} as v_y/v₀ → 0
    limit = math.sqrt(6 * math.sqrt(3) / 5) * (2 * math.sqrt(6 / 5)) ** -0.25
    assert e[0] * r[0] ** -0.25 == pytest.approx(limit, rel=1e-5)


@pytest.mark.parametrize(
    ("impactor", "cavity", "parameter"),
    [
        ("unobtainium sphere 20 mm", "steel flat", "material"),
        ("steel cube 20 mm", "steel flat", "impactor"),
        ("steel sphere -20 mm", "steel flat", "impactor diameter"),
        ("steel sphere 20 mm", "steel spherical cavity 10 mm", "cavity"),
        ("steel sphere 20 mm", "E 1 GPa, nu 0.7, rho 1000 kg/m^3 flat", "material: nu"),
        ("steel sphere 20 mm", "E 1 GPa, rho 1000 kg/m^3 flat", "material"),
        ("steel sphere 20 mm", "steel cone", "cavity"),
    ],
)
def test_bad_input_names_the_parameter(impactor, cavity, parameter):
    with pytest.raises(ParameterError) as info:
        derived_contact(impactor, cavity, 0.5)
    assert info.value.parameter == parameter


def test_cli_contact_json_and_errors(capsys):
    argv = ["contact", "--impactor", "steel sphere 20 mm", "--cavity", "steel flat", "--v0",
            "0.5 m/s", "--json"]  # fmt: skip
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    expected = {"m", "k_hz", "e", "chi", "c1", "max_penetration", "duration", "peak_force",
                "yield_speed", "sources"}  # fmt: skip
    assert expected <= set(out) and set(out["sources"]) >= expected - {"sources"}
    assert out["k_hz"] == pytest.approx(derived_contact(*STEEL_ON_STEEL, 0.5).k_hz, rel=1e-15)
    assert main(["contact", "--impactor", "steel sphere 2 cm", "--cavity", "steel flat",
                 "--v0", "-1 m/s"]) == 2  # fmt: skip
    assert "v0" in capsys.readouterr().err


def test_cavity_shapes():
    assert cavity_body("steel flat").radius is None
    assert cavity_body("steel spherical cavity 30 mm").radius == pytest.approx(-0.015)
    assert cavity_body("brass sphere 30 mm").radius == pytest.approx(0.015)
    # a ball in a seat of nearly its own size: the conforming contact has a large R
    # (1/R = 1/R₁ − 1/R₂) and so a stiffer K_Hz ∝ √R
    tight = derived_contact("steel sphere 20 mm", "steel spherical cavity 21 mm", 0.5)
    assert tight.R == pytest.approx(1 / (1 / 0.01 - 1 / 0.0105), rel=1e-14)


def _json_of(argv, capsys):
    assert main([*argv, "--json"]) == 0
    captured = capsys.readouterr()
    return json.loads(captured.out), captured.err


def test_commands_take_the_contact_from_the_materials(capsys):
    # the same run with the numbers the materials give, typed in: the same JSON
    c = derived_contact("steel sphere 30 mm", "brass flat", 0.4, M=1.0)
    system = ["--M", "1", "--K", "1000", "--C", "0.5", "--gap", "20 mm"]
    forcing = ["--force", "2", "--omega", "25.39", "--contact", "rigid"]
    derived, said = _json_of(["periodic", *system, "--impactor", "steel sphere 30 mm", "--cavity",
                              "brass flat", "--impact-speed", "0.4 m/s", *forcing], capsys)  # fmt: skip
    typed, _ = _json_of(["periodic", *system, "--m", repr(c.m), "--e", repr(c.e), *forcing], capsys)
    assert derived == typed
    assert f"e {c.e:.4g} at 0.4 m/s (Thornton)" in said
    # a compliant law: K_Hz from the materials, c1 giving the material's e at the impact speed
    from symimpact.free.contact import restitution
    from symimpact.model.system import ImpactSystem

    argv = ["simulate", *system, "--impactor", "steel sphere 30 mm", "--cavity",
            "polyurethane flat", "--impact-speed", "0.4 m/s", "--contact", "hertz",
            "--t-end", "0.5"]  # fmt: skip
    _, said = _json_of(argv, capsys)
    pu = derived_contact("steel sphere 30 mm", "polyurethane flat", 0.4, M=1.0)
    c1 = float(said.split("c1 ")[1].split(" N s/m")[0])
    sys_ = ImpactSystem(M=1, K=1000, C=0.5, m=pu.m, gap=0.02, contact="hertz", k_hz=pu.k_hz, c1=c1)
    assert float(restitution(sys_, 0.4)) == pytest.approx(pu.e, rel=1e-4)  # c1 printed to 5 digits


@pytest.mark.parametrize(
    ("extra", "parameter"),
    [
        (["--cavity", "steel flat"], "cavity"),
        (["--impactor", "steel sphere 2 cm", "--m", "1"], "m"),
        (["--impactor", "steel sphere 2 cm", "--cavity", "steel flat", "--k-hz", "1e9"], "k-hz"),
        (["--impactor", "steel sphere 2 cm", "--cavity", "steel flat"], "impact-speed"),
        (["--impactor", "steel sphere 2 cm", "--impact-speed", "1"], "impact-speed"),
    ],
)
def test_material_options_refuse_contradictions(extra, parameter, capsys):
    assert main(["simulate", "--t-end", "0.1", *extra]) == 2
    assert f"error: {parameter}:" in capsys.readouterr().err


def test_the_derived_contact_stiffened_gives_the_rigid_orbit():
    # a 23 mm steel ball (50 g) in a brass-walled damper on the primary at 36 rad/s: e
    # from Thornton's law at the rigid orbit's own impact speed (a fixed point, 8 iterations to
    # 1e-9), then the Hunt–Crossley contact with the derived K_Hz (χ giving that e) against the
    # rigid orbit, and at K_Hz/100: the error falls like the contact duration, K^(−2/5)
    from symimpact.forced import Forcing, periodic_orbits, rigid_limit
    from symimpact.model.system import ImpactSystem

    ball, wall, f = "steel sphere 23 mm", "brass flat", Forcing(F0=2, omega=36)
    c = derived_contact(ball, wall, 1.0, M=1.0)
    s = ImpactSystem(M=1, K=1000, C=0.5, m=c.m, gap=0.02, k_hz=c.k_hz)
    e = 0.6
    for _ in range(8):
        (orbit,) = [o for o in periodic_orbits(s, f, e) if o.stable]
        e_next = derived_contact(ball, wall, orbit.impact_speed, M=1.0).e
        e, change = e_next, abs(e_next - e)
    assert change < 1e-8
    _, (soft, derived) = rigid_limit(s, f, e, "hunt-crossley", [c.k_hz / 100, c.k_hz],
                                     periods=120, discard=90)  # fmt: skip
    assert abs(derived.relative_error) < 1e-3  # measured 3.6e-4: 30 µs contacts at 5.7 Hz
    # the ratio carries ~1e-6 of transient over errors of 1e-3–1e-4 (as the convergence table)
    assert soft.relative_error / derived.relative_error == pytest.approx(100**0.4, rel=0.05)


def _boussinesq(p0, a, b, x, y):
    """E*·u at (x, y) under p₀√(1 − x'²/a² − y'²/b²): (1/π)∬p/ρ dA, in polar coordinates about
    the field point (the 1/ρ singularity cancels against ρ dρ), by nested adaptive quadrature."""
    from scipy.integrate import quad

    def along(theta):
        c, s = math.cos(theta), math.sin(theta)
        qa = (c / a) ** 2 + (s / b) ** 2
        qb = 2 * (x * c / a**2 + y * s / b**2)
        qc = (x / a) ** 2 + (y / b) ** 2 - 1
        rho_max = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)

        def p(rho):
            inside = 1 - ((x + rho * c) / a) ** 2 - ((y + rho * s) / b) ** 2
            return p0 * math.sqrt(max(inside, 0.0))

        return quad(p, 0, rho_max, epsabs=0, epsrel=1e-12, limit=200)[0]

    return quad(along, 0, 2 * math.pi, epsabs=0, epsrel=1e-11, limit=200)[0] / math.pi


@pytest.mark.parametrize("cavity", ["steel cylindrical bore 24 mm", "steel cylinder 24 mm",
                                    "steel cylindrical bore 200 mm"])  # fmt: skip
def test_elliptical_contact_against_boussinesq(cavity):
    # the elliptical pressure's displacement, integrated: it closes the gap δ − Ax² − By² inside
    # the ellipse, and the pressure's integral is K_Hz·δ^{3/2} (1e-9: nested quadrature at 1e-11
    # to 1e-12 of a square-root edge)
    from symimpact.model.derived_contact import curvatures, elliptical_hertz

    imp, cav = impactor_body("steel sphere 20 mm"), cavity_body(cavity)
    A, B = curvatures(imp, cav)
    ell = elliptical_hertz(A, B)
    delta, E_star = 1e-5, 1.0  # per unit E*
    a = ell.a_per_root * math.sqrt(delta)
    b, p0 = ell.k * a, ell.p0_per_root * E_star * math.sqrt(delta)
    u0 = _boussinesq(p0, a, b, 0.0, 0.0)
    assert u0 == pytest.approx(delta, rel=1e-9)
    for frac in (0.3, 0.7):
        assert u0 - _boussinesq(p0, a, b, frac * a, 0.0) == pytest.approx(A * (frac * a) ** 2,
                                                                           rel=1e-8)  # fmt: skip
        assert u0 - _boussinesq(p0, a, b, 0.0, frac * b) == pytest.approx(B * (frac * b) ** 2,
                                                                          rel=1e-8)  # fmt: skip
    from scipy.integrate import dblquad

    force = dblquad(lambda yy, xx: p0 * math.sqrt(max(1 - (xx / a) ** 2 - (yy / b) ** 2, 0.0)),
                    -a, a, lambda xx: -b * math.sqrt(1 - (xx / a) ** 2),
                    lambda xx: b * math.sqrt(1 - (xx / a) ** 2), epsabs=0, epsrel=1e-11)[0]  # fmt: skip
    assert force == pytest.approx(ell.k_hz_per_modulus * E_star * delta**1.5, rel=1e-9)


def test_elliptical_contact_tends_to_the_circle():
    # B/A → 1: Hertz's elliptical contact becomes Step 13's circular one (R = 1/(2A)); the
    # difference falls with B/A − 1 (first order)
    from symimpact.model.derived_contact import elliptical_hertz

    A = 50.0
    circle = hz.hertz_stiffness_scalar(1.0, 1 / (2 * A))
    for excess in (1e-2, 1e-4, 1e-6, 1e-10):
        ell = elliptical_hertz(A, A * (1 + excess))
        # K_Hz ∝ √R_e·F(e) with R_e = 1/(2√(AB)): the relative change is O(excess)
        assert ell.k_hz_per_modulus == pytest.approx(circle, rel=excess)
    assert elliptical_hertz(A, A).k_hz_per_modulus == pytest.approx(circle, rel=1e-15)
