"""The modal mass at the damper from modal data (issue 35, item 1; the tutorial's worked example):
a mode normalised to unit modal mass, φᵀMφ = 1, gives M = 1/φ(x_d)² at the damper's point and
K = M(2πf_n)², the ``--fn``/``--M`` inputs.  Checked for a cantilever against the Ritz reduction
(Eq. 1–6, ``beam_constants`` and ``mass_coefficient``) and the textbook fact that a clamped–free
beam's modal mass at its tip is a quarter of its mass, for every mode (∫φ² = L/4·φ(L)²)."""

from __future__ import annotations

import argparse
import math

import pytest
from scipy.integrate import quad
from symimpact.generated import ritz

from symimpact.cli.common import apply_engineer_inputs
from symimpact.model.system import beam_constants

E, I, RHO, A, L = 70e9, 3.125e-10, 2700.0, 1.5e-4, 0.5
M_BEAM = RHO * A * L


def _unit_modal_mass_shape(mode: int):
    bL = ritz.BETA_L[mode]
    norm = quad(lambda u: ritz.mode_shape(bL, u) ** 2, 0, 1, epsabs=0, epsrel=1e-13)[0]
    return lambda xi: ritz.mode_shape(bL, xi) / math.sqrt(M_BEAM * norm)


@pytest.mark.parametrize("mode", [0, 1, 2])
def test_a_cantilever_s_modal_mass_at_its_tip_is_a_quarter_of_its_mass(mode):
    phi = _unit_modal_mass_shape(mode)
    assert 1 / phi(1.0) ** 2 == pytest.approx(M_BEAM / 4, rel=1e-11)  # quadrature to 1e-13


def test_the_unit_modal_mass_route_gives_the_ritz_mass_and_stiffness_at_any_point():
    phi = _unit_modal_mass_shape(0)
    K, M = beam_constants(E=E, I=I, rho=RHO, A=A, L=L)
    f_n = math.sqrt(K / M) / (2 * math.pi)
    for xi in (1.0, 0.5, 0.3):
        M_d = 1 / phi(xi) ** 2
        assert M_d == pytest.approx(ritz.mass_coefficient(ritz.BETA_L[0], xi) * M_BEAM, rel=1e-11)
    assert 1 / phi(1.0) ** 2 == pytest.approx(M, rel=1e-11)
    # --fn with --M (the modal mass at the damper) gives the Ritz K: K = M(2πf_n)²
    ns = argparse.Namespace(command="simulate", fn=f"{f_n!r} Hz", M=repr(M), K=None)
    apply_engineer_inputs(ns, {"fn", "M"})
    assert ns.K == pytest.approx(K, rel=1e-12)
