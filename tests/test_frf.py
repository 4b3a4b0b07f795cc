"""``symimpact frf`` (issue 21, item 3): the JSON contract, the curve without reachable walls
(the textbook linear response, typed here), and bad bands refused in one line."""

from __future__ import annotations

import json
import math

import pytest

from symimpact.cli import main

SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N"]
RIGID = ["--contact", "rigid", "--e", "0.6"]


def _run(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_frf_json_contract_and_the_stable_symmetric_branch(capsys, tmp_path):
    """34.6–38 rad/s: the stable symmetric two-impact branch is found (its points are the closed
    form's: tests/test_continuation.py) with the contract's keys; CSV and plot are written."""
    csv, png = tmp_path / "frf.csv", tmp_path / "frf.png"
    out = _run(capsys, ["frf", *SYSTEM, "--gap", "20 mm", *RIGID, "--omega-range",
                        "34.6:38:0.2", "--json", "--csv", str(csv), "--plot", str(png)])  # fmt: skip
    assert set(out) >= {"points", "bifurcations"}
    for p in out["points"]:
        assert set(p) >= {"omega", "amplitude", "stable", "impacts_per_period",
                          "period_multiple", "branch"}  # fmt: skip
        assert isinstance(p["stable"], bool) and isinstance(p["branch"], int)
    for b in out["bifurcations"]:
        assert b["kind"] in ("fold", "branch-point", "period-doubling", "neimark-sacker",
                             "grazing")  # fmt: skip
    stable = [p for p in out["points"] if p["stable"] and 35.5 < p["omega"] < 37.5]
    assert stable and all(p["impacts_per_period"] == 2 for p in stable)
    assert csv.read_text().splitlines()[0].startswith("omega [rad/s],amplitude [m]")
    assert png.stat().st_size > 10_000


def test_without_reachable_walls_the_curve_is_the_linear_response(capsys):
    """d = 2 m: no branch of impacting orbits, and the baseline and both sweeps are the
    textbook amplitude F0/√((K − MΩ²)² + (CΩ)²) (typed here, not from the kernels); each sweep
    point runs until its transient is 1e-6 of its start, and a neighbour is at most ~12 times
    the amplitude here, so 1e-4 bounds what is left."""
    out = _run(capsys, ["frf", *SYSTEM, "--gap", "2 m", *RIGID, "--freq-range", "4:6:0.5",
                        "--json"])  # fmt: skip
    assert out["points"] == [] and out["bifurcations"] == []
    for row in out["baseline"]:
        w = row["omega"]
        assert row["amplitude"] == pytest.approx(2 / math.hypot(1000 - w * w, 0.5 * w), rel=1e-12)
    for sweep in ("sweep_up", "sweep_down"):
        for row, base in zip(out[sweep], out["baseline"], strict=True):
            assert row["amplitude"] == pytest.approx(base["amplitude"], rel=1e-4)


@pytest.mark.parametrize(
    ("extra", "parameter"),
    [
        (["--omega-range", "40:30:0.1"], "omega-range:"),
        (["--omega-range", "30:40:-0.1"], "omega-range:"),
        (["--omega-range", "30:30:0.1"], "omega-range:"),
        (["--omega-range", "30:40:0.1", "--freq-range", "5:6:0.1"], "omega-range:"),
        (["--omega-range", "0:40:0.1"], "omega-range:"),
        (["--freq-range", "1:2:1e-6"], "freq-range:"),
    ],
)
def test_bad_bands_are_one_line(capsys, extra, parameter):
    assert main(["frf", *SYSTEM, "--gap", "20 mm", *RIGID, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and parameter in err


def test_a_compliant_frf_is_refused_in_one_line(capsys):
    argv = ["frf", *SYSTEM, "--gap", "20 mm", "--contact", "hertz", "--omega-range", "30:40:1"]
    assert main(argv) == 2
    assert "follows rigid impacts" in capsys.readouterr().err
