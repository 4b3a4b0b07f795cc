"""``design --response NAME``: the design map's peaks measured in another response than the
displacement (issue 35, item 2) — checked against the textbook force transmitted by a damped
oscillator, and through the command line's JSON, CSV and refusals."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from symimpact.cli import main
from symimpact.forced import Forcing
from symimpact.maps.design import design_row
from symimpact.model.system import ImpactSystem

M, K, C, F0 = 1.0, 1000.0, 0.5, 2.0


def _transmitted(omega: float) -> float:
    """The force a damped oscillator under F0·cos Ωt passes to the ground, F0·√(K² + (CΩ)²)/
    √((K − MΩ²)² + (CΩ)²) (any vibration textbook: force transmissibility)."""
    return F0 * math.hypot(K, C * omega) / math.hypot(K - M * omega**2, C * omega)


def test_without_impacts_the_force_peak_is_the_textbook_transmitted_force():
    """A clearance no motion of the band closes (1 km): the design's force peak is the primary
    alone's, located at the maximum of the textbook formula (Brent's method on it here, 1e-9:
    both locate one smooth maximum to their xatol, whose error enters the value squared)."""
    system = ImpactSystem(M=M, K=K, C=C, m=0.05, gap=1000.0, contact="linear", k1=1e6)
    w = np.linspace(28.0, 36.0, 9)
    row = design_row(system, Forcing(F0=F0, omega=30.0), 0.6, w, multistart=0,
                     response="force")  # fmt: skip
    best = minimize_scalar(lambda x: -_transmitted(x), bounds=(28.0, 36.0), method="bounded",
                           options={"xatol": 1e-10})  # fmt: skip
    assert row["baseline_peak"] == pytest.approx(-best.fun, rel=1e-9)
    assert row["peak_amplitude"] == pytest.approx(-best.fun, rel=1e-9)
    assert row["peak_ratio"] == pytest.approx(1.0, rel=1e-9)
    assert row["peak_motion"] == "no impact"


def test_cli_names_the_response_in_json_and_csv(tmp_path, capsys):
    """The JSON names its response and unit and keys its peaks by it; the CSV's headers carry
    the unit (N); the text says "peak force"."""
    out = tmp_path / "d.csv"
    argv = ["design", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N",
            "--contact", "rigid", "--e", "0.6", "--omega-range", "30:33:1", "--gaps", "1 km",
            "--executor", "serial", "--quiet", "--response", "force", "--multistart", "0",
            "--csv", str(out)]  # fmt: skip
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert "peak force" in text and " N at Ω" in text
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["response"] == {"name": "force", "unit": "N"}
    (row,) = data["designs"]
    assert {"peak_force", "baseline_force"} <= set(row) and "peak_amplitude" not in row
    assert row["peak_force"] == pytest.approx(row["baseline_force"], rel=1e-12)
    with open(out, newline="", encoding="utf-8") as f:
        header = next(csv.reader(f))
    assert "peak_force [N]" in header and "baseline_force [N]" in header


@pytest.mark.parametrize(
    "extra, word",
    [(["--response", "stress"], "response"),
     (["--response", "acceleration", "--contact", "linear", "--k1", "1e5"], "response"),
     (["--response", "transmissibility", "--base", "1 mm"], "transmissibility")],
)  # fmt: skip
def test_cli_refuses_a_response_it_cannot_give_in_one_line(extra, word, capsys):
    """An unknown response, the acceleration of a compliant contact (not resolved inside a
    contact) and a transmissibility under both a force and base motion: exit 2, one line, before
    any design is run."""
    contact = [] if "--contact" in extra else ["--contact", "rigid", "--e", "0.6"]
    argv = ["design", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N",
            *contact, "--omega-range", "30:33:1", "--gaps", "20 mm", "--executor", "serial",
            "--quiet", *extra]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and word in err[0], err


def test_robust_design_in_a_response(tmp_path, capsys):
    """The design robust to e in the force: its JSON keys and text name the force, and its
    figure is drawn in newtons (it was drawn as a displacement in mm before)."""
    plot = tmp_path / "robust.png"
    argv = ["design", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N",
            "--contact", "rigid", "--e", "0.4:0.8", "--e-samples", "3", "--omega-range",
            "30:33:1", "--gaps", "1 km", "--executor", "serial", "--quiet", "--multistart", "0",
            "--response", "force", "--plot", str(plot), "--json"]  # fmt: skip
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["response"] == {"name": "force", "unit": "N"}
    (row,) = data["rows"]
    # no impacts: every e gives the primary alone's force
    assert row["worst_force"] == pytest.approx(row["baseline_force"], rel=1e-9)
    assert plot.stat().st_size > 0
