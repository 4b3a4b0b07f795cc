"""Participation factors and effective modal masses (Step 15, Eq. F7; issue 36, the primary as a
structure under base motion): the beams' closed forms against an independent Hermite-element
model, the finite-element reduction against a two-mass chain's closed form and against the full
model's complex frequency response, and the sum rule over all modes."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.linalg import eigh
from symimpact.generated import forced_flight as ff

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.model.beams import beam_modes
from symimpact.model.modal import fe_modes, influence_vector
from tests.helpers import RHO, A, E, I, L
from tests.helpers import hermite_beam as _fe

#: Elements of the Hermite model here: the h⁴ error of the fourth mode's share is 7.3e-8 at 100
#: (measured, the same with one BLAS thread or two), while rounding stays below 1e-8 (the
#: spread between the two); at 200 the stiffness matrix's conditioning (~N⁴) lets rounding
#: reach 2e-7, which moved with the BLAS's thread count.
N_FE = 100


@pytest.mark.parametrize("support", ["cantilever", "clamped-clamped", "simply-supported"])
def test_beam_participation_and_mass_share_match_hermite_elements(support):
    """Γ at the point and the mass share of the derived beam modes (kernels of Eq. F7) against
    N_FE Hermite elements with consistent mass (scipy's eigensolver).  The supports move every
    deflection DOF by one, the constrained ones included, so the load on the free DOFs is
    (M·r) over the whole model, the coupling of consistent mass to the supports with it; the
    total is ρAL.  The elements converge as h⁴ in the frequencies and the shares: at 100 they
    leave up to 7.3e-8 on the first four modes (the fourth's), 2e-7 its bound with rounding."""
    K, M, kept = _fe(support, N_FE)
    _, Mf, _ = _fe("free", N_FE)
    xi = 1.0 if support == "cantilever" else 0.3  # off-centre: no mode has a node there
    dof = kept.index(2 * round(xi * N_FE))
    r = np.array([1.0 if d % 2 == 0 else 0.0 for d in range(Mf.shape[0])])
    load = (Mf @ r)[kept]
    _, vec = eigh(K, M, subset_by_index=[0, 3])
    vec = vec / np.sqrt(np.einsum("ij,ij->j", vec, M @ vec))
    assert r @ Mf @ r == pytest.approx(RHO * A * L, rel=1e-12)
    derived = beam_modes(support, E, I, RHO, A, L, position=xi * L, n=4)
    for i, mode in enumerate(derived):
        share = float(vec[:, i] @ load) ** 2 / (RHO * A * L)
        gamma = float(vec[dof, i] * (vec[:, i] @ load))
        assert mode.mass_share == pytest.approx(share, rel=2e-7, abs=1e-12)
        assert mode.participation == pytest.approx(gamma, rel=2e-7, abs=2e-7)  # Γ₁ ~ 1
    # textbook: the cantilever's tip Γ₁ = 1.566 and its first mode moves 61.3 % of the mass
    if support == "cantilever":
        assert derived[0].participation == pytest.approx(1.566, abs=5e-4)
        assert derived[0].mass_share == pytest.approx(0.613, abs=5e-4)


def test_two_mass_chain_shares_are_the_golden_ratio_closed_form():
    """Two equal masses on two equal springs, the first to the base: the modes are (1, φ) and
    (1, −1/φ), φ the golden ratio, so mode 1 moves (1 + φ)²/(2(1 + φ²)) of the mass; the two
    shares sum to one (to rounding)."""
    m, k = 2.0, 5000.0
    K = np.array([[2 * k, -k], [-k, k]])
    M = np.diag([m, m])
    modes = fe_modes(K, M, 1, 2, influence="1")
    phi = (1 + math.sqrt(5)) / 2
    assert modes[0].mass_share == pytest.approx((1 + phi) ** 2 / (2 * (1 + phi**2)), rel=1e-13)
    assert modes[0].mass_share + modes[1].mass_share == pytest.approx(1.0, rel=1e-14)
    assert modes[0].omega == pytest.approx(math.sqrt(k / m * (3 - math.sqrt(5)) / 2), rel=1e-13)


def test_all_modes_of_a_model_share_all_of_its_mass():
    """Σ (φᵢᵀMr)²/rᵀMr over every mode = 1 (Φ diag(1/Mᵢ) Φᵀ = M⁻¹): a random chain of eight
    masses, its shares summed to 1e-12 (eight terms of order one, each to a few ULPs of the
    eigensolver's residual)."""
    rng = np.random.default_rng(7)
    n = 8
    ks = rng.uniform(500.0, 5000.0, n)
    K = np.zeros((n, n))
    for i, k in enumerate(ks):
        K[i, i] += k
        if i:
            K[i - 1, i - 1] += k
            K[i - 1, i] -= k
            K[i, i - 1] -= k
    M = np.diag(rng.uniform(0.5, 3.0, n))
    modes = fe_modes(K, M, n - 1, n, influence=np.ones(n))
    assert sum(m.mass_share for m in modes) == pytest.approx(1.0, abs=1e-12)


def test_base_motion_drives_each_mode_through_its_participation_factor():
    """The steady amplitude at the top of a base-excited chain of three masses (proportional
    damping C = αM + βK, the base moving as X_b cos Ωt, absolute coordinates): the full model's
    complex frequency response, solved directly, against the sum of the modes referred to the
    top DOF, each Step 8's steady solution (Eq. F1's steady_cosine and steady_sine kernels) with
    its own M, K, C and the base amplitude Γ·X_b.  Both are exact up to rounding in a
    well-conditioned 3×3 solve: 1e-12."""
    ms, ks = np.array([1.0, 1.5, 0.7]), np.array([2000.0, 1500.0, 900.0])
    K = np.array([[ks[0] + ks[1], -ks[1], 0], [-ks[1], ks[1] + ks[2], -ks[2]], [0, -ks[2], ks[2]]])
    M = np.diag(ms)
    alpha, beta = 0.8, 2e-4
    C = alpha * M + beta * K
    Xb, W = 0.002, 31.0
    r = np.ones(3)
    full = np.linalg.solve(K - W**2 * M + 1j * W * C, (K + 1j * W * C) @ r * Xb)[2]
    total = 0.0 + 0.0j
    for mode in fe_modes(K, M, 2, 3, influence=r):
        zeta = (alpha / mode.omega + beta * mode.omega) / 2
        Ci = 2 * zeta * mode.omega * mode.M
        a = float(ff.steady_cosine(mode.M, mode.K, Ci, 0.0, mode.participation * Xb, W))
        b = float(ff.steady_sine(mode.M, mode.K, Ci, 0.0, mode.participation * Xb, W))
        total += a - 1j * b  # A cos Ωt + B sin Ωt = Re((A − iB) e^{iΩt})
    assert abs(total - full) <= 1e-12 * abs(full)


def test_influence_refusals_name_the_parameter():
    with pytest.raises(ParameterError, match="influence"):
        influence_vector("1,0,1", 4)
    with pytest.raises(ParameterError, match="influence"):
        influence_vector("0", 4)
    with pytest.raises(ParameterError, match="influence"):
        influence_vector("one", 4)
    assert list(influence_vector("1,0", 4)) == [1.0, 0.0, 1.0, 0.0]


def test_modes_command_lists_participation(tmp_path, capsys):
    """``symimpact modes --influence``: the JSON holds each mode's Γ and share, the text the
    share the listed modes move."""
    m, k = 2.0, 5000.0
    np.savez(tmp_path / "chain.npz", K=np.array([[2 * k, -k], [-k, k]]), M=np.diag([m, m]))
    assert main(["modes", "--fe", str(tmp_path / "chain.npz"), "--dof", "1", "--modes", "2",
                 "--influence", "1", "--json"]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    assert sum(x["mass_share"] for x in out["modes"]) == pytest.approx(1.0, rel=1e-14)
    assert main(["modes", "--fe", str(tmp_path / "chain.npz"), "--dof", "1", "--modes", "1",
                 "--influence", "1"]) == 0  # fmt: skip
    assert "these 1 modes move 94.72 % of the mass" in capsys.readouterr().out
    assert main(["modes", "--fe", str(tmp_path / "chain.npz"), "--dof", "1", "--modes", "2",
                 "--influence", "1,0,0"]) == 2  # fmt: skip
    assert "influence" in capsys.readouterr().err
