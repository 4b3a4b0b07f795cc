"""Issue 82, item 3: the identified parameters' uncertainty carried into the curve's peak.

Against closed forms: with the clearance out of reach the peak is the primary alone's resonance,
F0/(K·2ζ√(1 − ζ²)), a function of ζ only, so each draw's peak is that formula at its ζ and the
peaks' median is the formula at the draws' median (it falls as ζ grows).  The draws themselves:
their mean and covariance are the file's (a normal sample, so to its standard error), and none
leaves the physics' bounds."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.identify.propagation import parameter_draws


def _resonance(zeta: float, F0: float = 0.2, K: float = 1000.0) -> float:
    return F0 / K / (2 * zeta * math.sqrt(1 - zeta**2))


def test_the_draws_have_the_files_mean_and_covariance():
    """20 000 draws: the mean to 4 standard errors of a mean (σ/√n), the covariance to 5 % (its
    relative standard error is √(2/n) ≈ 1 %); truncation at the bounds takes no draw here, all
    being well inside them."""
    mean = np.array([0.6, 0.01, 0.01])
    sd = np.array([0.01, 1e-4, 1e-5])
    rho = np.array([[1, 0.5, -0.3], [0.5, 1, 0.2], [-0.3, 0.2, 1]])
    cov = rho * np.outer(sd, sd)
    d = parameter_draws(["e", "zeta", "gap"], mean, cov, 20_000, seed=3)
    assert np.all(np.abs(d.mean(axis=0) - mean) < 4 * sd / math.sqrt(d.shape[0]))
    assert np.allclose(np.cov(d.T), cov, rtol=0.05, atol=0.05 * np.outer(sd, sd).max())


def test_draws_stay_inside_the_bounds():
    """e near 1 with a wide spread: every kept draw has e < 1 and ζ > 0."""
    d = parameter_draws(["e", "zeta"], [0.98, 0.002], np.diag([0.02**2, 0.002**2]), 500, seed=1)
    assert d.shape == (500, 2) and np.all(d[:, 0] < 1) and np.all(d[:, 1] > 0)


def test_the_peak_over_draws_of_zeta_is_the_resonance_at_each(tmp_path, capsys):
    """A clearance of 1 m: no impact, each draw's peak the closed-form resonance at its ζ (the
    located peak to 1e-9: its Brent tolerance), the median the formula at the median ζ."""
    rig = tmp_path / "rig.toml"
    rig.write_text('M = 1.0\nK = 1000.0\nm = 0.05\nzeta = 0.01\ngap = 1.0\ne = 0.6\n\n'
                   '[uncertainty]\nnames = ["zeta"]\nvalues = [0.01]\n'
                   'covariance = [[1e-6]]\n')  # fmt: skip
    code = main(["frf", "--system", str(rig), "--force", "0.2 N", "--contact", "rigid",
                 "--omega-range", "29:34:0.5", "--no-sweeps", "--multistart", "0",
                 "--propagate", "7", "--json"])  # fmt: skip
    out = json.loads(capsys.readouterr().out)["propagated"]
    assert code == 0 and out["parameters"] == ["zeta"] and out["samples"] == 7
    zetas = np.array(out["draws"])[:, 0]
    for z, peak in zip(zetas, out["peaks"], strict=True):
        assert peak == pytest.approx(_resonance(z), rel=1e-9)
    assert out["median"] == pytest.approx(_resonance(float(np.median(zetas))), rel=1e-9)


@pytest.mark.parametrize("table, words", [
    ("", "propagate: needs --system FILE with the fit's [uncertainty]"),
    ('\n[uncertainty]\nnames = ["zeta"]\nvalues = [0.01]\ncovariance = [[1e-6, 0]]\n',
     "[uncertainty] must name system parameters"),
])  # fmt: skip
def test_propagation_without_an_uncertainty_is_refused_in_one_line(tmp_path, capsys, table,
                                                                    words):  # fmt: skip
    rig = tmp_path / "rig.toml"
    rig.write_text("M = 1.0\nK = 1000.0\nm = 0.05\nzeta = 0.01\ngap = 1.0\ne = 0.6\n" + table)
    code = main(["frf", "--system", str(rig), "--force", "0.2 N", "--contact", "rigid",
                 "--omega-range", "29:34:0.5", "--propagate", "3"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1
