"""Harmonic balance on a structure of several modes with a compliant damper (issue 83, item 1:
"one mode and structures"): :func:`symimpact.forced.orbits.hb_structure.hb_structure_orbit`.

- One mode of shape 1 is the one-mode balance (:func:`hb_orbit`, the paper's primary): the same
  coefficients' amplitude and multipliers to 1e-12 (one scheme written twice over the
  coordinates: rounding only).
- A two-mode steel cantilever with a Hunt–Crossley damper at its tip, 2 N at 8 Hz: the balance's
  tip and midspan amplitudes against the exact periodic orbit of the event-driven engine
  (:func:`shoot_structure`, which shares no code with the balance), within 5e-4 (measured
  1.3e-4 at H = 40 and 0.9e-4 at H = 80: a contact's harmonics fall algebraically, Step 17's
  F12), and the same stability.
"""

from __future__ import annotations

import math

import pytest

from symimpact.errors import ParameterError
from symimpact.forced import Forcing
from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.orbits.harmonic_balance import hb_orbit
from symimpact.forced.orbits.hb_structure import hb_structure_orbit
from symimpact.forced.orbits.structure_orbits import shoot_structure
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import dampers
from symimpact.model.structure import beam_structure, structure_from_dict
from symimpact.model.system import ImpactSystem

M, K, C, m, GAP = 1.0, 1000.0, 0.5, 0.05, 0.02
ONE_MODE = {"modes": [{"f": math.sqrt(K / M) / (2 * math.pi), "mass": M,
                       "zeta": C / (2 * math.sqrt(K * M)), "shape": {"p": 1.0}}]}  # fmt: skip
#: A steel cantilever, 1 m of 40 mm × 10 mm (8.36 and 52.4 Hz), ζ 0.01.
BEAM = {"support": "cantilever", "E": 210e9, "I": 0.04 * 0.01**3 / 12, "rho": 7850.0, "A": 4e-4,
        "L": 1.0}  # fmt: skip


def test_one_mode_of_shape_one_is_the_one_mode_balance():
    structure = structure_from_dict(ONE_MODE)
    ds = dampers(structure, [{"name": "d", "at": "p", "m": m, "gap": GAP, "contact": "hertz",
                              "k_hz": 1e5, "c1": 0.5}])  # fmt: skip
    got = hb_structure_orbit(structure, ds, "p", 2.0, 34.0, harmonics=10, time_samples=40)
    system = ImpactSystem(M=M, K=K, C=C, m=m, gap=GAP, k_hz=1e5, c1=0.5, contact="hertz")
    want = hb_orbit(system, Forcing(F0=2.0, omega=34.0), CompliantContact("hertz"),
                    harmonics=10, time_samples=40)  # fmt: skip
    assert got.amplitudes["p"] == pytest.approx(want.amplitude, rel=1e-12)
    assert got.multipliers[:4] == pytest.approx(want.multipliers[:4], rel=1e-9)
    assert got.stable == want.stable


@pytest.fixture(scope="module")
def cantilever():
    structure = beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=2, zeta=0.01)
    ds = dampers(structure, [{"name": "d", "at": "tip", "m": 0.05, "gap": "10 mm",
                              "contact": "hunt-crossley", "k_hz": 1e6, "chi": 2.0}])  # fmt: skip
    return structure, ds, 2 * math.pi * 8.0


def test_a_cantilever_s_balance_lies_on_its_exact_orbit(cantilever):
    structure, ds, omega = cantilever
    run = simulate_structure(structure, ds, "tip", 2.0, omega, periods=300)
    exact = shoot_structure(structure, ds, "tip", 2.0, omega, run.final_state[1:7])
    assert len(exact.run.impacts("d")) > 0 and exact.stable
    for H in (40, 80):
        hb = hb_structure_orbit(structure, ds, "tip", 2.0, omega, harmonics=H)
        for point in ("tip", "mid"):
            assert hb.amplitudes[point] == pytest.approx(exact.amplitudes[point], rel=5e-4)
        assert hb.stable == exact.stable


def test_a_rigid_damper_is_refused_in_one_line(cantilever):
    structure, _, omega = cantilever
    rigid = dampers(structure, [{"name": "r", "at": "tip", "m": 0.05, "gap": "10 mm", "e": 0.6}])
    with pytest.raises(ParameterError, match=r"dampers\.r: harmonic balance needs a compliant"):
        hb_structure_orbit(structure, rigid, "tip", 2.0, omega)
    with pytest.raises(ParameterError, match="force_at"):
        hb_structure_orbit(structure, dampers(structure, [{"name": "d", "at": "tip", "m": 0.05,
                           "gap": 0.01, "contact": "linear", "k1": 1e5}]), "root", 2.0, omega)  # fmt: skip


CANTILEVER_FILE = {
    "beam": {"type": "cantilever", "E": "210 GPa", "I": BEAM["I"], "rho": "7850 kg/m^3",
             "A": 4e-4, "L": "1 m", "modes": 2, "zeta": 0.01},
    "points": {"tip": "1 m", "mid": "0.5 m"},
    "dampers": [{"name": "tip damper", "at": "tip", "m": "50 g", "gap": "10 mm",
                 "contact": "hunt-crossley", "k_hz": 1e6, "chi": 2.0}],
    "force": {"at": "tip", "amplitude": "2 N"},
}  # fmt: skip


def test_the_command_gives_the_structure_s_balance_beside_its_exact_orbit(tmp_path, capsys):
    """``periodic --structure FILE --method hb``: the balance's amplitudes and their error
    against shooting's exact orbit at every point, the API's numbers (JSON in SI)."""
    import json

    from symimpact.cli import main

    path = tmp_path / "cantilever.json"
    path.write_text(json.dumps(CANTILEVER_FILE))
    argv = ["periodic", "--structure", str(path), "--freq", "8 Hz", "--method", "hb",
            "--harmonics", "40"]  # fmt: skip
    assert main([*argv, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["harmonics"] == 40 and out["time_samples"] == 160
    for point in ("tip", "mid"):
        error = out["amplitudes"][point] / out["exact"]["amplitudes"][point] - 1
        assert out["hb_error"][point] == pytest.approx(error, rel=1e-12) and abs(error) < 5e-4
    assert out["stable"] is True and out["exact"]["stable"] is True
    # refusals, each in one line before anything runs
    for extra, name in ((["--multiple", "2"], "multiple"), (["--time-samples", "60"],
                                                             "time-samples")):  # fmt: skip
        assert main([*argv, *extra]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and f"error: {name}:" in err[0], err
    rigid = CANTILEVER_FILE | {"dampers": [{"name": "ball", "at": "tip", "m": "50 g",
                                            "gap": "10 mm", "e": 0.6}]}  # fmt: skip
    path.write_text(json.dumps(rigid))
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "damper 'ball' has rigid impacts" in err[0], err
