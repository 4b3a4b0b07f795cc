"""Base excitation as a shaker specifies it (issue 35, item 2): an acceleration or a velocity
amplitude held constant over the band, X_b = A_b/Ω² or V_b/Ω at each frequency (Eq. F1)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced import Forcing, periodic_orbits
from symimpact.model.system import ImpactSystem

G = 9.80665  # the standard gravity [m/s²] (CGPM 1901: exact by definition)
SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05"]


def test_half_a_g_is_half_the_standard_gravity_over_omega_squared():
    # "0.5 g" is an acceleration here, not half a gram; the decimal product is exact
    for omega in (10.0, 30.0, 31.6227766016838):
        f = Forcing(A_b="0.5 g", omega=omega)
        assert f.A_b == 0.5 * G and f.X_b == 0.5 * G / omega**2
        assert f.at(2 * omega).X_b == 0.5 * G / (2 * omega) ** 2
    assert Forcing(A_b="4.903325 m/s^2", freq="5 Hz").X_b == Forcing(A_b="0.5 g", freq="5 Hz").X_b
    f = Forcing(V_b="10 mm/s", omega=20.0)
    assert f.X_b == 0.01 / 20.0 and f.at(40.0).X_b == 0.01 / 40.0
    assert Forcing(X_b="1 mm", omega=20.0).at(40.0).X_b == 0.001  # a displacement stays


@pytest.mark.parametrize(
    "kw, name",
    [
        ({"A_b": 1.0, "X_b": 0.001}, "A_b"),
        ({"A_b": 1.0, "V_b": 0.1}, "A_b"),
        ({"A_b": "0.5 kg"}, "A_b"),
    ],
)
def test_the_base_motion_is_given_once_in_its_own_units(kw, name):
    with pytest.raises(ParameterError) as exc:
        Forcing(omega=30.0, **kw)
    assert exc.value.parameter == name


def test_cli_refusals_name_the_option(capsys):
    argv = ["simulate", *SYSTEM, "--gap", "20 mm", "--omega", "30", "--contact", "rigid", "--e",
            "0.6", "--base", "1 mm", "--base-acc", "0.5 g"]  # fmt: skip
    assert main(argv) == 2
    assert "base-acc" in capsys.readouterr().err


def test_a_shaker_sweep_without_impacts_is_the_textbook_transmissibility(capsys):
    """The primary alone under a constant base acceleration: |X| = (A_b/Ω²)·√(K² + (CΩ)²) /
    √((K − MΩ²)² + (CΩ)²) (e.g. Rao, Mechanical Vibrations, §3.6), to 1e-12 (a few roundings
    of the steady solution's coefficients, Step 8)."""
    argv = ["frf", *SYSTEM, "--gap", "2 m", "--base-acc", "0.5 g", "--omega-range", "20:45:0.5",
            "--contact", "rigid", "--e", "0.6", "--no-sweeps", "--json"]  # fmt: skip
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    w = np.array([r["omega"] for r in out["baseline"]])
    X = np.array([r["amplitude"] for r in out["baseline"]])
    K, C, M = 1000.0, 0.5, 1.0
    textbook = 0.5 * G / w**2 * np.hypot(K, C * w) / np.hypot(K - M * w**2, C * w)
    np.testing.assert_allclose(X, textbook, rtol=1e-12)
    # the located peak of the primary alone: where d|X|/dΩ = 0, against a fine grid of the formula
    fine = np.linspace(30.0, 33.0, 300001)
    best = fine[np.argmax(np.hypot(K, C * fine) / fine**2 / np.hypot(K - M * fine**2, C * fine))]
    assert out["baseline_peak"]["omega"] == pytest.approx(best, abs=2e-5)


@pytest.mark.slow  # a whole frf without its multi-start (its branches are the point): 30 s
def test_a_shaker_frf_traces_the_orbits_at_each_frequencys_own_displacement(capsys):
    """With impacts: the symmetric two-impact branch of `frf --base-acc` is the closed-form
    orbit (Eq. F3) for X_b = A_b/Ω² at each point's Ω, to 1e-8 of the amplitude (the
    continuation's corrector; measured 4e-14).  Measured: 18 points match; the same command
    with --base fixed at the band start's X_b (what a continuation that kept it would trace)
    matches none of its 292."""
    argv = ["frf", *SYSTEM, "--gap", "20 mm", "--base-acc", "0.3 g", "--omega-range",
            "26:40:0.5", "--contact", "rigid", "--e", "0.6", "--no-sweeps", "--multistart", "0",
            "--json"]  # fmt: skip
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    system = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
    matched = 0
    # the closed form's orbits (Eq. F3) are symmetric, two impacts a period: only those points
    # are solved for (the others cost 80 s of closed-form solving for no match)
    symmetric = [p for p in out["points"] if p["impacts_per_period"] == 2
                 and p["period_multiple"] == 1 and not p["asymmetric"]]  # fmt: skip
    for p in symmetric:
        f = Forcing(X_b=0.3 * G / p["omega"] ** 2, omega=p["omega"])
        orbits = periodic_orbits(system, f, 0.6)
        matched += any(abs(o.amplitude - p["amplitude"]) <= 1e-8 * p["amplitude"] for o in orbits)
    assert matched >= 10
