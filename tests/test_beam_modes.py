"""Beams of several modes (Step 14, Eq. F6; issue 36, the primary as a beam): the cantilever, the
clamped–clamped and the simply supported beam, checked against textbook roots (Blevins, *Formulas
for Natural Frequency and Mode Shape*, Table 8-1), textbook static flexibilities and an
independent finite-element model (Hermite cubic beam elements, consistent mass, scipy's
generalised eigensolver), which shares no formula with the derivation."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.linalg import eigh, solve

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.model.beams import beam_constants, beam_modes, static_flexibility
from tests.helpers import N_EL, RHO, A, E, I, L
from tests.helpers import hermite_beam as _fe

#: Blevins, Table 8-1, to the digits printed there
BLEVINS = {
    "cantilever": (1.87510407, 4.69409113, 7.85475744, 10.99554073),
    "clamped-clamped": (4.73004074, 7.85320462, 10.9956078, 14.1371655),
    "simply-supported": (math.pi, 2 * math.pi, 3 * math.pi, 4 * math.pi),
}


@pytest.mark.parametrize("support", list(BLEVINS))
def test_the_roots_are_blevins_table(support):
    modes = beam_modes(support, E, I, RHO, A, L, n=4)
    for mode, printed in zip(modes, BLEVINS[support], strict=True):
        assert mode.beta_L == pytest.approx(printed, abs=6e-8)  # Blevins prints 8–9 digits


@pytest.mark.parametrize("support", list(BLEVINS))
@pytest.mark.parametrize("xi", [0.3, 0.5, 1.0])
def test_frequencies_and_modal_masses_agree_with_a_finite_element_model(support, xi):
    """The first five natural frequencies, and each mode's mass at the point (1/v_j² of the
    mass-normalised eigenvector's displacement there), against 200 Hermite elements.  The
    elements converge as (βh)⁴ (mode 5 of the clamped–clamped beam, βh = 0.086: measured 3.9e-8
    in ω, 1.5e-7 in M, i.e. 7e-4 and 2.7e-3 times (βh)⁴), down to the solver's 6e-10 for mode 1:
    bound max(1e-8, 1e-2·(βh)⁴); a node of the mode at the point (both infinite) is checked as a
    node."""
    if support != "cantilever" and xi == 1.0:
        return  # a support: every mode has a node there
    K, M, kept = _fe(support)
    # the flexibility form M v = μ K v, μ = 1/ω²: the solver's error is eps·μ_max, so the lowest
    # modes (the largest μ) keep their relative accuracy (K v = λ M v would lose eps·λ_max/λ₁,
    # 1e-5 here)
    n = len(kept)
    mu, vec = eigh(M, K, subset_by_index=[n - 5, n - 1])
    mu, vec = mu[::-1], vec[:, ::-1]
    vec = vec / np.sqrt(np.einsum("ij,ik,kj->j", vec, M, vec))  # mass-normalised
    j = kept.index(2 * round(xi * N_EL))  # the point's displacement DOF
    modes = beam_modes(support, E, I, RHO, A, L, position=xi * L, n=5)
    for mode, mu_i, v in zip(modes, mu, vec.T, strict=True):
        bound = max(1e-8, 1e-2 * (mode.beta_L / N_EL) ** 4)
        assert mode.omega == pytest.approx(1.0 / math.sqrt(mu_i), rel=bound)
        if mode.node:
            assert abs(v[j]) < 1e-7 * np.max(np.abs(v[::2]))
        else:
            assert mode.M == pytest.approx(1.0 / v[j] ** 2, rel=bound)
            assert mode.K == pytest.approx(mode.omega**2 * mode.M, rel=1e-12)


@pytest.mark.parametrize("support", list(BLEVINS))
@pytest.mark.parametrize("xi", [0.3, 0.5, 0.8])
def test_the_static_flexibility_is_the_finite_element_one(support, xi):
    """Hermite elements hold the static deflection under point loads exactly at the nodes, so
    the derived flexibility (Eq. F6's two cubics) and the elements agree to the solve's
    rounding (condition ~1e9: bound 1e-9)."""
    K, _, kept = _fe(support)
    j = kept.index(2 * round(xi * N_EL))
    load = np.zeros(len(kept))
    load[j] = 1.0
    fe = solve(K, load, assume_a="pos")[j]
    assert static_flexibility(support, E, I, L, xi * L) == pytest.approx(fe, rel=1e-9)


def test_textbook_static_flexibilities():
    """PL³/(3EI) at the cantilever's tip, PL³/(48EI) and PL³/(192EI) at the midspans."""
    c = L**3 / (E * I)
    assert static_flexibility("cantilever", E, I, L) == pytest.approx(c / 3, rel=1e-15)
    assert static_flexibility("simply-supported", E, I, L) == pytest.approx(c / 48, rel=1e-15)
    assert static_flexibility("clamped-clamped", E, I, L) == pytest.approx(c / 192, rel=1e-15)


def test_the_cantilever_is_step_1s():
    """The cantilever's first mode is the paper's Ritz primary (Eq. 6: M = ρAL/4 and K = 3.0906
    EI/L³ at the tip)."""
    K, M = beam_constants(E, I, RHO, A, L)
    assert M == pytest.approx(RHO * A * L / 4, rel=1e-13)
    assert K == pytest.approx(1.875104068711961**4 / 4 * E * I / L**3, rel=1e-13)


def test_a_mode_with_a_node_at_the_damper_is_refused_as_its_primary():
    with pytest.raises(
        ParameterError, match="position: mode 2 of the simply-supported beam has a node"
    ):
        beam_constants(E, I, RHO, A, L, support="simply-supported", mode=2)
    with pytest.raises(ParameterError, match="support"):
        beam_modes("free-free", E, I, RHO, A, L)
    with pytest.raises(ParameterError, match="modes"):
        beam_modes("cantilever", E, I, RHO, A, L, n=9)


def test_ritz_lists_the_modes_at_the_point(capsys):
    argv = ["ritz", "--support", "simply-supported", "--E", "210 GPa", "--I", repr(I), "--rho",
            "7850", "--A", repr(A), "--L", "1 m", "--modes", "4", "--json"]  # fmt: skip
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["support"] == "simply-supported"
    assert [m["node"] for m in out["modes"]] == [False, True, False, True]  # midspan
    assert out["modes"][1]["M"] is None
    assert out["modes"][0]["M"] == pytest.approx(RHO * A * L / 2, rel=1e-13)
    # the sum over the two moving modes (1 and 3) falls short of PL³/(48EI) by Σ_{odd i ≥ 5}
    exact = L**3 / (48 * E * I)
    assert out["static_flexibility"] == pytest.approx(exact, rel=1e-15)
    tail = sum(2 / (i * math.pi) ** 4 for i in range(5, 20001, 2)) * L**3 / (E * I)
    assert out["static_flexibility_of_the_modes"] == pytest.approx(exact - tail, rel=1e-9)
    assert main([*argv[:-1]]) == 0
    text = capsys.readouterr().out
    assert "node" in text and "mm/N" in text


@pytest.mark.parametrize(
    ("extra", "name"),
    [(["--modes", "9"], "modes"), (["--mode", "2"], "position"), (["--modes", "0"], "modes")],
)
def test_ritz_refuses_in_one_line(capsys, extra, name):
    argv = ["ritz", "--support", "simply-supported", "--E", "210 GPa", "--I", repr(I), "--rho",
            "7850", "--A", repr(A), "--L", "1 m", *extra]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"error: {name}" in err[0], err


def test_a_system_from_a_clamped_beam_is_its_mode_at_the_point():
    """ImpactSystem.from_beam with a support and a mode: K and M of that mode at the damper, so
    that the primary's ω_n is the mode's (ω₃ of the clamped–clamped beam at 0.3 L)."""
    from symimpact.model.system import ImpactSystem

    s = ImpactSystem.from_beam(E, I, RHO, A, L, m=0.05, gap=0.002, position=0.3 * L,
                               support="clamped-clamped", mode=3, contact="hertz", k_hz=1e9)  # fmt: skip
    (third,) = beam_modes("clamped-clamped", E, I, RHO, A, L, position=0.3 * L, n=3)[2:]
    assert (s.K, s.M) == (third.K, third.M)
    assert s.omega_n == pytest.approx(10.9956078**2 * math.sqrt(E * I / (RHO * A * L**4)),
                                      rel=1e-8)  # Blevins' β₃L, 9 digits  # fmt: skip


@pytest.mark.parametrize("c1", [0.0, 3.0])
def test_the_point_impulse_is_a_short_contact_integrated(c1):
    """An impact mass m against the point of a three-mode structure (modal masses 1, 3 and 0.5 kg
    referred to the point), through a linear contact spring k₁ 1e6 N/m with damping c₁, integrated
    by scipy (DOP853, rtol 1e-12) with the modal springs left out (the contact lasts about a
    millisecond): each modal velocity jumps by P/Mᵢ with Step 14's impulse (kernel
    ``point_impulse``) at the restitution of Step 6's linear contact for m against the effective
    mass (kernel ``linear_restitution``; 1 without damping).  Bound 1e-9 of P: the integrator's
    tolerance."""
    from scipy.integrate import solve_ivp
    from symimpact.generated import beam_modes as bm
    from symimpact.generated import closed_forms as cf

    m, Ms, k1 = 0.2, np.array([1.0, 3.0, 0.5]), 1e6
    m_eff = 1.0 / np.sum(1.0 / Ms)
    q0, u0 = np.array([0.1, -0.05, 0.02]), -0.5  # the point moves at 0.07 m/s, the mass at −0.5

    def rhs(_t, s):
        z, q, u = s[0] - np.sum(s[1:4]), s[4:7], s[7]  # s: y, q₁…q₃, q̇₁…q̇₃, ẏ (z = y − x)
        zdot = u - np.sum(q)
        force = -(k1 * z + c1 * zdot) if z < 0 else 0.0  # the mass presses on the point from above
        return [u, *q, *(-force / Ms), force / m]

    def leaves(_t, s):
        return s[0] - np.sum(s[1:4])

    leaves.terminal, leaves.direction = True, 1
    start = [0.0, 0.0, 0.0, 0.0, *q0, u0]
    run = solve_ivp(rhs, (0.0, 1.0), start, method="DOP853", rtol=1e-12, atol=1e-15,
                    events=leaves, first_step=1e-7)  # fmt: skip
    end = run.y_events[0][0]
    zdot0 = np.sum(q0) - u0  # approach speed of the point towards the mass
    e = 1.0 if c1 == 0 else float(cf.linear_restitution(m, m_eff, k1, c1))
    P = float(bm.point_impulse(m, m_eff, e, zdot0))
    assert np.max(np.abs(end[4:7] - (q0 - P / Ms))) < 1e-9 * P / Ms.min()
    assert end[7] == pytest.approx(u0 + P / m, rel=1e-9)
