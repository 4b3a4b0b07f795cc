"""A primary of several modes (issue 36's model): its receptances, effective masses and base
response against direct solutions of the full matrix equations, a beam's Ritz modes against a
finite-element beam written here, the structure file, and bad input."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.linalg import eigh

from symimpact.errors import ParameterError
from symimpact.model.beams import SUPPORTS
from symimpact.model.structure import (
    beam_structure,
    fe_structure,
    modal_structure,
    read_structure,
    structure_from_dict,
)
from tests.helpers import RHO, A, E, I, L, hermite_beam, hermite_beam_whole

# a three-DOF chain with a full (consistent-like) mass matrix: nothing diagonal to hide behind
M3 = np.array([[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]])
K3 = np.array([[3000.0, -1200.0, 0.0], [-1200.0, 2200.0, -1000.0], [0.0, -1000.0, 1000.0]])
ALPHA, BETA = 0.8, 2e-4  # Rayleigh damping C = αM + βK
C3 = ALPHA * M3 + BETA * K3
POINTS3 = {"base": 0, "middle": 1, "top": 2}


def test_receptance_with_all_modes_is_the_direct_solution():
    """Σ φᵢ(p)φᵢ(q)/(Mᵢ(ωᵢ² − Ω² + 2iζᵢωᵢΩ)) over all modes equals (K − Ω²M + iΩC)⁻¹, solved
    directly, at every pair of points: 1e-12 of the largest entry (a 3×3 solve and a sum of
    three terms, each to a few units of rounding; near resonance the condition number, ≤ 1e3
    here, multiplies them)."""
    s = fe_structure(M3, K3, POINTS3, C=C3)
    for W in (5.0, 20.0, 31.0, 45.0, 80.0):
        direct = np.linalg.inv(K3 - W * W * M3 + 1j * W * C3)
        for p, i in POINTS3.items():
            for q, j in POINTS3.items():
                assert abs(s.receptance(p, q, W) - direct[i, j]) <= 1e-12 * np.abs(direct).max()


def test_rayleigh_damping_gives_its_modal_ratios():
    """ζᵢ = α/(2ωᵢ) + βωᵢ/2 for C = αM + βK (Step 15, item 2)."""
    s = fe_structure(M3, K3, POINTS3, C=C3)
    for m in s.modes:
        assert m.zeta == pytest.approx(ALPHA / (2 * m.omega) + BETA * m.omega / 2, rel=1e-12)


def test_effective_mass_with_all_modes_is_the_inverse_of_the_flexibility_of_mass():
    """Σ φᵢ(p)²/Mᵢ over all modes of unit modal mass is (ΦΦᵀ)ₚₚ = (M⁻¹)ₚₚ: the mass a rigid
    impact at p meets is 1/(M⁻¹)ₚₚ (Step 15, item 4)."""
    s = fe_structure(M3, K3, POINTS3, zeta=0.02)
    inverse = np.linalg.inv(M3)
    for p, i in POINTS3.items():
        assert s.effective_mass(p) == pytest.approx(1.0 / inverse[i, i], rel=1e-13)


def test_all_modes_hold_the_whole_static_flexibility():
    """Σ φᵢ(p)²/(Mᵢωᵢ²) over all modes is (K⁻¹)ₚₚ: the share is 1 (1e-12, a 3×3 solve)."""
    s = fe_structure(M3, K3, POINTS3, zeta=0.02)
    inverse = np.linalg.inv(K3)
    for p, i in POINTS3.items():
        assert s.flexibility[p] == pytest.approx(inverse[i, i], rel=1e-13)
        assert s.flexibility_share(p) == pytest.approx(1.0, rel=1e-12)
    assert math.isnan(modal_structure([{"f": 1.0, "shape": {"a": 1.0}}]).flexibility_share("a"))


def test_a_cantilevers_first_mode_holds_12_over_beta4_of_its_tip_flexibility():
    """At the tip φ(L)² = 4∫φ²dξ for every mode and the flexibility is L³/(3EI): mode i holds
    12/βᵢ⁴ of it (closed form; 97.07 % for the first), and the shares of more modes sum to
    Σ 12/βᵢ⁴ (1e-12: the kernels' roots)."""
    s = beam_structure("cantilever", E, I, RHO, A, L, {"tip": L}, modes=4)
    assert s.flexibility["tip"] == pytest.approx(L**3 / (3 * E * I), rel=1e-12)
    betas = [float(SUPPORTS["cantilever"].roots[i]) for i in range(4)]
    assert s.flexibility_share("tip") == pytest.approx(sum(12 / b**4 for b in betas), rel=1e-12)
    one = beam_structure("cantilever", E, I, RHO, A, L, {"tip": L}, modes=1)
    assert one.flexibility_share("tip") == pytest.approx(12 / betas[0] ** 4, rel=1e-12)
    assert 0.9706 < one.flexibility_share("tip") < 0.9708


def test_one_mode_meets_its_own_mass():
    """One mode with φ = 1 at the point: m_eff = M (Step 9's impact)."""
    s = modal_structure([{"f": 12.0, "mass": 40.0, "zeta": 0.01, "shape": {"tip": 1.0}}])
    assert s.effective_mass("tip") == 40.0
    assert s.modes[0].omega == pytest.approx(2 * math.pi * 12.0, rel=1e-15)


def test_base_response_with_all_modes_is_the_direct_solution():
    """The absolute displacement per unit support motion: r + (K − Ω²M + iΩC)⁻¹Ω²Mr, solved
    directly (the relative coordinates' inertia load), equals the modal sum (1e-12, as above)."""
    s = fe_structure(M3, K3, POINTS3, C=C3)
    r = np.ones(3)
    for W in (5.0, 31.0, 80.0):
        direct = r + np.linalg.solve(K3 - W * W * M3 + 1j * W * C3, W * W * (M3 @ r))
        for p, i in POINTS3.items():
            assert abs(s.base_transmissibility(p, W) - direct[i]) <= 1e-12 * np.abs(direct).max()


# --- a beam's Ritz modes against a finite-element beam ------------------------------------------
#: the strip of tests/helpers.py in 50 elements (the issue's check)
N50 = 50
BEAM = {"E": E, "I": I, "rho": RHO, "A": A, "L": L}


@pytest.mark.parametrize("support", ["cantilever", "clamped-clamped", "simply-supported"])
def test_ritz_modes_match_a_finite_element_beam(support):
    """The first five modes: each frequency within 1.2 times the finite-element beam's own error,
    (βᵢh)⁴/1440 relative for cubic Hermite elements of length h (the eigenvalue's (βh)⁴/720,
    halved for ω); measured 1.4e-9 for the cantilever's first mode (the asymptote 1.37e-9) to
    9.9e-6 for the clamped–clamped fifth.  The physical shape product φᵢ(p)φᵢ(q)/Mᵢ at nodes of
    the mesh, 0.2 L, 0.5 L, 0.8 L and the cantilever's tip, within 1e-4 of its largest value (the
    shapes converge one order slower than the frequencies)."""
    where = {"a": 0.2 * L, "mid": 0.5 * L, "b": 0.8 * L}
    if support == "cantilever":
        where["tip"] = L
    s = beam_structure(support, **BEAM, points=where, modes=5)
    K, M, free = hermite_beam(support, N50)
    # the inertia load of a unit support translation, M r with r = 1 on every displacement DOF
    # (the supports' own DOFs included: the elements next to them carry mass coupled to them)
    load = (hermite_beam_whole(N50)[1] @ np.tile([1.0, 0.0], N50 + 1))[free]
    nodes = {p: free.index(2 * round(x / L * N50)) for p, x in where.items()}
    fe = fe_structure(M, K, nodes, modes=5, zeta=0.0)
    errors = []
    for ritz, ref in zip(s.modes, fe.modes, strict=True):
        h_beta = float(SUPPORTS[support].roots[ritz.number - 1]) / N50  # βᵢh
        errors.append(abs(ritz.omega / ref.omega - 1) / (h_beta**4 / 1440))
        scale = max(ref.shape[p] ** 2 for p in where) / ref.mass
        for p in where:
            for q in where:
                a = ritz.shape[p] * ritz.shape[q] / ritz.mass
                b = ref.shape[p] * ref.shape[q] / ref.mass
                assert abs(a - b) <= 1e-4 * scale, (ritz.number, p, q)
    # the support motion: φᵢ(p)Γᵢ, Γᵢ = φᵢᵀMr of unit-modal-mass φᵢ, the same physical product
    # (Eq. F7), 1e-4 of the largest (the shapes' convergence)
    _, vec = eigh(K, M, subset_by_index=[0, 4])
    vec = vec / np.sqrt(np.einsum("ij,ij->j", vec, M @ vec))
    for ritz in s.modes:
        i = ritz.number - 1
        gamma = float(vec[:, i] @ load)
        for p, d in nodes.items():
            assert abs(ritz.shape[p] * ritz.participation - vec[d, i] * gamma) <= 1e-4 * 1.6
    assert max(errors) < 1.2, errors


# --- the structure file ---------------------------------------------------------------------------
def test_structure_file_json_and_toml_give_the_same_model(tmp_path):
    data = {"beam": {"type": "cantilever", "E": "210 GPa", "I": I, "rho": 7850,
                     "A": "500 mm^2", "L": "1000 mm", "modes": 3, "zeta": 0.01},
            "points": {"tip": "1000 mm", "middle": 0.5}}  # fmt: skip
    j = tmp_path / "beam.json"
    j.write_text(json.dumps(data))
    t = tmp_path / "beam.toml"
    t.write_text(
        f'[beam]\ntype = "cantilever"\nE = "210 GPa"\nI = {I!r}\nrho = 7850\n'
        'A = "500 mm^2"\nL = "1000 mm"\nmodes = 3\nzeta = 0.01\n[points]\ntip = "1000 mm"\n'
        "middle = 0.5\n"
    )
    a, b = read_structure(j), read_structure(t)
    direct = beam_structure("cantilever", **BEAM, points={"tip": 1.0, "middle": 0.5}, modes=3,
                            zeta=0.01)  # fmt: skip
    for x in (a, b):
        assert x.points == ("tip", "middle")
        for m, d in zip(x.modes, direct.modes, strict=True):
            assert m.omega == pytest.approx(d.omega, rel=1e-14)
            assert m.shape == pytest.approx(d.shape, rel=1e-14)


def test_fe_structure_from_files(tmp_path):
    np.save(tmp_path / "M.npy", M3)
    np.savez(tmp_path / "K.npz", K=K3)
    data = {"fe": {"M": "M.npy", "K": "K.npz", "zeta": [0.01, 0.02, 0.03]}, "points": POINTS3}
    (tmp_path / "s.json").write_text(json.dumps(data))
    s = read_structure(tmp_path / "s.json")
    inline = fe_structure(M3, K3, POINTS3, zeta=[0.01, 0.02, 0.03])
    assert [m.omega for m in s.modes] == pytest.approx([m.omega for m in inline.modes], rel=1e-14)
    assert [m.zeta for m in s.modes] == [0.01, 0.02, 0.03]


def test_an_inline_model_names_its_dofs_by_number():
    """The issue's two-DOF chain, given without points: each DOF is a point named by its number;
    ω² are the roots of λ² − 3λ + 1 = 0, (3 ∓ √5)/2 (closed form)."""
    s = structure_from_dict({"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]],
                                    "zeta": 0.015}})  # fmt: skip
    assert s.points == ("0", "1")
    assert [m.omega**2 for m in s.modes] == pytest.approx([(3 - 5**0.5) / 2, (3 + 5**0.5) / 2],
                                                          rel=1e-14)  # fmt: skip


def test_modal_data_are_sorted_by_frequency():
    s = modal_structure([
        {"f": 30.0, "mass": 2.0, "zeta": 0.02, "shape": {"a": 1.0, "b": -0.5}},
        {"omega": 20.0, "mass": 3.0, "zeta": 0.01, "shape": {"a": 0.4, "b": 1.0}},
    ])  # fmt: skip
    assert [m.number for m in s.modes] == [1, 2]
    assert s.modes[0].omega == 20.0 and s.modes[1].shape == {"a": 1.0, "b": -0.5}


BAD = [
    (
        {
            "modes": [
                {"f": 10, "mass": 1, "shape": {"a": 1}},
                {"f": 20, "mass": 1, "shape": {"b": 1}},
            ]
        },
        "modes[1].shape",
    ),
    ({"modes": [{"f": 10, "omega": 3, "shape": {"a": 1}}]}, "modes[0]"),
    ({"modes": [{"f": 10, "zeta": 1.2, "shape": {"a": 1}}]}, "zeta"),
    ({"modes": [{"f": -1, "shape": {"a": 1}}]}, "modes[0].f"),
    (
        {"fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-1, 2]], "zeta": 0.01}, "points": {"a": 2}},
        "points.a",
    ),
    (
        {
            "fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-0.5, 2]], "zeta": 0.01},
            "points": {"a": 0},
        },
        "K",
    ),
    (
        {"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 1]], "zeta": 0.01}, "points": {"a": 0}},
        "K",
    ),
    (
        {
            "fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-1, 2]], "C": [[1, 0], [0, 0]]},
            "points": {"a": 0},
        },
        "C",
    ),
    ({"fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-1, 2]]}, "points": {"a": 0}}, "zeta"),
    (
        {
            "beam": {"type": "cantilever", "E": 1, "I": 1, "rho": 1, "A": 1, "L": 1},
            "points": {"a": 2},
        },
        "points.a",
    ),
    (
        {"beam": {"type": "cantilever", "E": 1, "I": 1, "rho": 1, "A": 1}, "points": {"a": 1}},
        "beam.L",
    ),
    (
        {
            "beam": {"type": "cantilever", "E": 1, "I": 1, "rho": 1, "A": 1, "L": 1, "n": 3},
            "points": {"a": 1},
        },
        "beam.n",
    ),
    (
        {
            "beam": {"type": "free-free", "E": 1, "I": 1, "rho": 1, "A": 1, "L": 1},
            "points": {"a": 1},
        },
        "support",
    ),
    ({"beam": {}, "modes": []}, "structure"),
    (
        {
            "fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015},
            "stops": [{"name": "s", "at": 0, "gap": 1}],
        },
        "stops",
    ),
    ({"modes": [{"f": 10, "shape": {"a": 1}}], "point": {"a": 1}}, "point"),
    ({"modes": [{"f": 10, "shape": {"a": 1}}], "points": {"a": 1}}, "points"),
    (
        {
            "fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-1, 2]], "zeta": 0.01, "modes": 3},
            "points": {"a": 0},
        },
        "modes",
    ),
]


@pytest.mark.parametrize(("data", "name"), BAD, ids=[b[1] for b in BAD])
def test_bad_structures_are_refused_naming_the_parameter(data, name):
    with pytest.raises(ParameterError) as info:
        structure_from_dict(data)
    assert info.value.parameter == name


def test_unreadable_files_are_refused(tmp_path):
    (tmp_path / "x.json").write_text("{not json")
    with pytest.raises(ParameterError, match="not valid JSON"):
        read_structure(tmp_path / "x.json")
    with pytest.raises(ParameterError, match="cannot read"):
        read_structure(tmp_path / "missing.json")


def test_modes_command_lists_a_structure_and_its_effective_masses(tmp_path, capsys):
    """``symimpact modes --structure``: a cantilever's every mode has φ(L)² = 4∫φ²dξ, so the
    mass an impact at the tip meets over N modes is ρAL/(4N) (closed form)."""
    from symimpact.cli import main

    data = {"beam": {"type": "cantilever", "E": E, "I": I, "rho": RHO, "A": A, "L": L,
                     "modes": 4, "zeta": 0.02}, "points": {"tip": L, "middle": L / 2}}  # fmt: skip
    path = tmp_path / "beam.json"
    path.write_text(json.dumps(data))
    assert main(["modes", "--structure", str(path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["effective_mass"]["tip"] == pytest.approx(RHO * A * L / 16, rel=1e-12)
    assert [m["zeta"] for m in out["modes"]] == [0.02] * 4
    assert main(["modes", "--structure", str(path)]) == 0
    text = capsys.readouterr().out
    assert "mass an impact meets" in text and "tip" in text
    assert main(["modes", "--structure", str(tmp_path / "none.json")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "structure: cannot read" in err[0], err


def test_a_structure_mode_is_the_primary_on_the_command_line(tmp_path, capsys):
    """``--structure FILE --at P --mode I``: the primary is the mode referred to P, M = Mᵢ/φᵢ(P)²
    and K = ωᵢ²M, against the cantilever's closed form with mpmath (its roots of
    1 + cos β cosh β = 0 and φ = cosh βξ − cos βξ − σ(sinh βξ − sin βξ), ∫φ²dξ = 1):
    at the tip M = ρAL/4 for every mode.  1e-12: the kernels' roots and shapes in double
    precision.  Bad combinations are refused in one line naming the option."""
    import mpmath as mp

    from symimpact.cli import main

    data = {"beam": {"type": "cantilever", "E": E, "I": I, "rho": RHO, "A": A, "L": L,
                     "modes": 3, "zeta": 0.01}, "points": {"tip": L, "middle": L / 2}}  # fmt: skip
    path = tmp_path / "beam.json"
    path.write_text(json.dumps(data))
    mass = RHO * A * L
    for at, xi, mode in (("tip", 1, 1), ("middle", 0.5, 2), ("tip", 1, 3)):
        beta = mp.findroot(lambda b: 1 + mp.cos(b) * mp.cosh(b), [1.875, 4.694, 7.855][mode - 1])
        sigma = (mp.cosh(beta) + mp.cos(beta)) / (mp.sinh(beta) + mp.sin(beta))
        phi = (mp.cosh(beta * xi) - mp.cos(beta * xi)
               - sigma * (mp.sinh(beta * xi) - mp.sin(beta * xi)))  # fmt: skip
        M = mass / float(phi) ** 2
        K = float(beta) ** 4 * E * I / L**3 * M / mass
        argv = ["simulate", "--structure", str(path), "--at", at, "--mode", str(mode), "--m",
                "0.05", "--gap", "5 mm", "--json"]  # fmt: skip
        assert main(argv) == 0
        out = capsys.readouterr()
        system = json.loads(out.out)["system"]
        assert system["M"] == pytest.approx(M, rel=1e-12)
        assert system["K"] == pytest.approx(K, rel=1e-12)
        assert system["zeta"] == pytest.approx(0.01, rel=1e-14)  # ζ back from C = 2ζ√(KM)
        assert f"the primary is mode {mode}" in out.err
    for argv, name in (
        (["--structure", str(path), "--m", "0.05"], "at"),
        (["--structure", str(path), "--at", "base", "--m", "0.05"], "at"),
        (["--structure", str(path), "--at", "tip", "--mode", "4", "--m", "0.05"], "mode"),
        (["--structure", str(path), "--at", "tip", "--K", "100", "--m", "0.05"], "K"),
        (["--at", "tip", "--m", "0.05"], "at"),
    ):
        assert main(["simulate", *argv]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and f"error: {name}:" in err[0], err


def test_a_node_at_the_point_is_refused(tmp_path, capsys):
    """A clamped–clamped beam's second mode has a node at midspan: it cannot be the primary of
    a damper there."""
    from symimpact.cli import main

    path = tmp_path / "cc.toml"
    path.write_text(
        f'[beam]\ntype = "clamped-clamped"\nE = {E!r}\nI = {I!r}\nrho = {RHO!r}\nA = {A!r}\n'
        f"L = {L!r}\nmodes = 2\n[points]\nmid = {L / 2!r}\n"
    )
    assert main(["simulate", "--structure", str(path), "--mode", "2", "--m", "0.05"]) == 2
    assert "node" in capsys.readouterr().err
    assert main(["simulate", "--structure", str(path), "--mode", "1", "--m", "0.05"]) == 0
