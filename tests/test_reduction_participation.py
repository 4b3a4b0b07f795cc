"""A one-mode reduction of a structure (``--structure FILE --at POINT --mode I``) under base motion
is refused in one line that gives the mode's participation Γφ, where it had run with Γφ = 1.

Under base motion the mode's equation at the point a is M·ẍ + C·ẋ + K·x = −M·Γφ(a)·ẍ_b (Eq. F7
referred to a); the one-mode primary takes Γφ = 1.  For a cantilever's first mode at its tip
Γφ = φ(L)·∫φ/∫φ² = 1.566 (the textbook figure; here by quadrature of the closed-form shape
cosh βx − cos βx − σ(sinh βx − sin βx), βL = 1.8751, against the package's Ritz kernels): the
run had been 36 % low in displacement, without a word.  A force on the primary is no base
motion and runs.
"""

from __future__ import annotations

import json
import math
import re

import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from symimpact.cli import main

BEAM = {"beam": {"type": "cantilever", "E": "70 GPa", "I": 3.125e-10, "rho": "2700 kg/m^3",
                 "A": 1.5e-4, "L": "0.5 m", "modes": 3, "zeta": 0.01},
        "points": {"tip": "0.5 m"}}  # fmt: skip
DAMPER = ["--m", "0.005", "--gap", "10 mm"]


def _tip_participation() -> float:
    """φ(L)·∫φ/∫φ² of a cantilever's first mode, by quadrature of its closed form."""
    bl = brentq(lambda b: math.cos(b) * math.cosh(b) + 1.0, 1.0, 3.0)
    sigma = (math.cosh(bl) + math.cos(bl)) / (math.sinh(bl) + math.sin(bl))

    def phi(x: float) -> float:
        return math.cosh(bl * x) - math.cos(bl * x) - sigma * (math.sinh(bl * x) - math.sin(bl * x))

    area = quad(phi, 0.0, 1.0, epsabs=1e-13)[0]
    square = quad(lambda x: phi(x) ** 2, 0.0, 1.0, epsabs=1e-13)[0]
    return phi(1.0) * area / square


@pytest.mark.parametrize(
    "command",
    [
        ["random", "--e", "0.6", "--base-psd", "0.01 g^2/Hz", "--band", "5:100"],
        ["shock", "--e", "0.6", "--base-peak", "20 g", "--pulse", "11 ms"],
        ["sweep-sine", "--e", "0.6", "--base-amplitude", "0.5 g", "--band", "10:20", "--rate", "1"],
        ["simulate", "--contact", "rigid", "--e", "0.6", "--base-acc", "0.5 g", "--freq", "16 Hz"],
        ["frf", "--contact", "rigid", "--e", "0.6", "--base", "1 mm", "--freq-range", "15:18:1"],
    ],
    ids=["random", "shock", "sweep-sine", "simulate", "frf"],
)
def test_base_motion_on_a_one_mode_reduction_is_refused_with_its_participation(
    tmp_path, capsys, command
):
    beam = tmp_path / "beam.json"
    beam.write_text(json.dumps(BEAM))
    argv = [command[0], "--structure", str(beam), "--at", "tip", "--mode", "1", *DAMPER,
            *command[1:]]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2, err  # the reduction's line, then the refusal
    assert "the primary is mode 1" in err[0]
    flag = next(a for a in command if a.startswith("--base"))[2:]
    assert err[1].startswith(f"symimpact {command[0]}: error: {flag}: moves the supports")
    gp = float(re.search(r"Γφ = ([0-9.]+)", err[1])[1])
    # the file's Ritz kernels (Step 14) against the quadrature, to the 4 digits printed
    assert gp == pytest.approx(_tip_participation(), abs=5e-4)
    assert _tip_participation() == pytest.approx(1.566, abs=5e-4)  # the textbook figure


def test_a_force_on_a_one_mode_reduction_runs(tmp_path, capsys):
    beam = tmp_path / "beam.json"
    beam.write_text(json.dumps(BEAM))
    argv = ["random", "--structure", str(beam), "--at", "tip", "--mode", "1", *DAMPER,
            "--e", "0.6", "--force-psd", "0.01 N^2/Hz", "--band", "5:100", "--realisations", "2",
            "--duration", "5 s"]  # fmt: skip
    assert main(argv) == 0
    assert "2 realisations of 5 s" in capsys.readouterr().out
