"""A finite-element model's modes at the damper's DOF (symimpact.model.modal, ``symimpact modes``;
issue 36, a primary given by its finite-element model): the Hermite beam model of
tests/helpers.py, written to .npz, Matrix Market and CSV files, reduced and compared with Step
14's derived modes of the same beam, which share no code with the reduction."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy import io, sparse

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.model.beams import beam_modes
from symimpact.model.beams import static_flexibility as beam_flexibility
from symimpact.model.modal import fe_modes, read_matrices, static_flexibility
from tests.helpers import N_EL, RHO, A, E, I, L
from tests.helpers import hermite_beam as _fe


def _files(tmp_path, K, M):
    np.savez(tmp_path / "beam.npz", K=K, M=M)
    io.mmwrite(str(tmp_path / "K.mtx"), sparse.coo_matrix(K))
    io.mmwrite(str(tmp_path / "M.mtx"), sparse.coo_matrix(M))
    np.savetxt(tmp_path / "K.csv", K, delimiter=",")
    np.savetxt(tmp_path / "M.csv", M, delimiter=",")
    return tmp_path


@pytest.mark.parametrize("support", ["cantilever", "clamped-clamped", "simply-supported"])
def test_the_reduction_gives_the_derived_modes_at_the_dof(support, tmp_path):
    """Frequencies and modal masses at 0.3 L within the elements' (βh)⁴ error (as in
    tests/test_beam_modes.py: bound max(1e-8, 1e-2·(βh)⁴)), nodes as nodes, and the DOF's static
    flexibility equal to the beam's (Hermite elements are exact there: 1e-9)."""
    K, M, kept = _fe(support)
    j = kept.index(2 * round(0.3 * N_EL))
    _files(tmp_path, K, M)
    derived = beam_modes(support, E, I, RHO, A, L, position=0.3 * L, n=4)
    for source in ({"fe": tmp_path / "beam.npz"},
                   {"K": tmp_path / "K.mtx", "M": tmp_path / "M.mtx"},
                   {"K": tmp_path / "K.csv", "M": tmp_path / "M.csv"}):  # fmt: skip
        Kf, Mf = read_matrices(**{k: str(v) for k, v in source.items()})
        for got, want in zip(fe_modes(Kf, Mf, j, 4), derived, strict=True):
            bound = max(1e-8, 1e-2 * (want.beta_L / N_EL) ** 4)
            assert got.omega == pytest.approx(want.omega, rel=bound)
            assert got.node == want.node
            if not want.node:
                assert got.M == pytest.approx(want.M, rel=bound)
                assert got.K == pytest.approx(got.omega**2 * got.M, rel=1e-12)
        flex = static_flexibility(Kf, j)
        assert flex == pytest.approx(beam_flexibility(support, E, I, L, 0.3 * L), rel=1e-9)


def test_a_large_sparse_model_is_solved_by_shift_invert(monkeypatch):
    """Above DENSE DOFs a sparse model goes to ARPACK (shift-invert about 0); with the threshold
    lowered, the 200-element model takes that path and gives the derived modes within the same
    bound as the dense solver (measured 2e-9 against the dense 4e-10 for mode 1: both are the
    model's conditioning, cond(K) growing as the elements' number to the fourth)."""
    from symimpact.model import modal

    monkeypatch.setattr(modal, "DENSE", 100)
    K, M, kept = _fe("simply-supported")
    j = kept.index(2 * round(0.3 * N_EL))
    got = fe_modes(sparse.csc_matrix(K), sparse.csc_matrix(M), j, 3)
    derived = beam_modes("simply-supported", E, I, RHO, A, L, position=0.3 * L, n=3)
    for g, w in zip(got, derived, strict=True):
        bound = max(1e-8, 1e-2 * (w.beta_L / N_EL) ** 4)
        assert g.omega == pytest.approx(w.omega, rel=bound)
        assert g.M == pytest.approx(w.M, rel=bound)


def test_refusals_name_the_parameter(tmp_path):
    K, M, _ = _fe("cantilever")
    with pytest.raises(ParameterError, match="dof"):
        fe_modes(K, M, len(K), 2)
    with pytest.raises(ParameterError, match="modes"):
        fe_modes(K, M, 0, 0)
    with pytest.raises(ParameterError, match=r"^M: is 3×3"):
        fe_modes(K, M[:3, :3], 0, 1)
    free = np.array([[1.0, -1.0], [-1.0, 1.0]])  # a free spring: a rigid-body mode
    with pytest.raises(ParameterError, match=r"^K: the model is not positive definite"):
        fe_modes(free, np.eye(2), 0, 1)
    with pytest.raises(ParameterError, match=r"^K: is not symmetric"):
        fe_modes(np.array([[2.0, 1.0], [0.0, 2.0]]), np.eye(2), 0, 1)
    with pytest.raises(ParameterError, match=r"^fe: cannot read .*(no such file)"):
        read_matrices(fe=str(tmp_path / "missing.npz"))


def test_modes_command(tmp_path, capsys):
    K, M, kept = _fe("cantilever")
    _files(tmp_path, K, M)
    tip = kept.index(2 * N_EL)
    assert main(["modes", "--fe", str(tmp_path / "beam.npz"), "--dof", str(tip), "--modes", "3",
                 "--json"]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    assert out["modes"][0]["M"] == pytest.approx(RHO * A * L / 4, rel=1e-8)  # ρAL/4 at the tip
    assert out["static_flexibility"] == pytest.approx(L**3 / (3 * E * I), rel=1e-9)
    assert main(["modes", "--stiffness", str(tmp_path / "K.mtx"), "--mass",
                 str(tmp_path / "M.mtx"), "--dof", str(tip)]) == 0  # fmt: skip
    assert "% short" in capsys.readouterr().out
    assert main(["modes", "--fe", str(tmp_path / "beam.npz"), "--dof", "100000"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "error: dof" in err[0], err
