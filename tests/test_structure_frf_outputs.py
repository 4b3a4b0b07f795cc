"""A structure's curve (``frf --structure``) writes its CSV and draws its figure (issue 79,
item 2: every analysis on every structure, its outputs as the one-mode curve's): the CSV holds
the JSON's numbers, row for row; the figure has one panel a named point with the bare
structure's curve, whose largest value the located bare peak bounds."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.forced.orbits.structure_branch import bare_amplitude
from symimpact.model.structure_model import model_from_dict

#: The issue's two-mode chain with a stop at mass 0 (tests/test_structure_branch.py), over a band
#: short enough for the quick set, across its Neimark–Sacker point at 0.6193 rad/s.
CHAIN = {"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015},
         "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+", "contact": "linear",
                    "k1": 100, "c1": 0}],
         "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("chain")
    path = folder / "chain.json"
    path.write_text(json.dumps(CHAIN))
    argv = ["frf", "--structure", str(path), "--omega-range", "0.6:0.64:0.005", "--json",
            "--csv", str(folder / "c.csv"), "--plot", str(folder / "c.png")]  # fmt: skip
    return argv, folder


def test_the_csv_holds_the_json_row_for_row(outputs, capsys):
    argv, folder = outputs
    assert main(argv) == 0, capsys.readouterr().err
    out = json.loads(capsys.readouterr().out)
    with open(folder / "c.csv") as f:
        rows = list(csv.DictReader(f))
    orbits = [r for r in rows if r["kind"] == "orbit"]
    settled = [r for r in rows if r["kind"] == "from rest"]
    points = [(i, pt) for i, br in enumerate(out["branches"]) for pt in br["points"]]
    assert len(orbits) == len(points) > 0 and len(settled) == len(out["settled"]) > 0
    for r, (i, pt) in zip(orbits, points, strict=True):
        assert int(r["branch"]) == i and float(r["omega [rad/s]"]) == pt["omega"]
        assert r["stable"] == str(pt["stable"])
        for p in ("0", "1"):
            assert float(r[f"amplitude at {p} [m]"]) == pt["amplitudes"][p]  # SI, every digit
    for r, s in zip(settled, out["settled"], strict=True):
        assert float(r["omega [rad/s]"]) == s["omega"] and r["periods"] == r["stable"] == ""
        assert float(r["amplitude at 0 [m]"]) == s["amplitudes"]["0"]
    assert (folder / "c.png").stat().st_size > 10_000
    # the bare curve the figure draws: the located bare peak bounds it (its maximum, refined
    # by Brent's method), and it is the receptance's amplitude times the force
    model = model_from_dict(CHAIN)
    w = np.linspace(0.6, 0.64, 400)
    for p, peak in out["bare_peaks"].items():
        drawn = [bare_amplitude(model.structure, model.force_at, model.F0, p, x) for x in w]
        assert max(drawn) <= peak["amplitude"] * (1 + 1e-12)
        direct = abs(model.structure.receptance(p, "1", 0.62)) * 0.1
        assert bare_amplitude(model.structure, "1", 0.1, p, 0.62) == pytest.approx(direct, 1e-15)


def test_a_structure_run_draws_each_points_period_maxima_and_its_csv_gives_the_json(tmp_path,
                                                                                     capsys):  # fmt: skip
    """``simulate --structure --plot``: one panel a point, its largest |x| each period; the
    CSV's rows after --discard give the JSON's steady amplitudes, to the last digit."""
    path = tmp_path / "chain.json"
    path.write_text(json.dumps(CHAIN))
    argv = ["simulate", "--structure", str(path), "--omega", "0.62", "--periods", "120",
            "--discard", "90", "--csv", str(tmp_path / "r.csv"), "--plot", str(tmp_path / "r.png"),
            "--json"]  # fmt: skip
    assert main(argv) == 0, capsys.readouterr().err
    out = json.loads(capsys.readouterr().out)
    with open(tmp_path / "r.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 120
    for p in ("0", "1"):
        assert max(float(r[f"x_max {p} [m]"]) for r in rows[90:]) == out["amplitudes"][p]
    assert (tmp_path / "r.png").stat().st_size > 10_000


def test_a_structure_design_writes_its_rows_and_draws_its_map(tmp_path, capsys):
    """``design --structure --csv --plot``: a row a clearance with the JSON's peak, the bare
    structure's and the best flagged, to the last digit; the figure written."""
    model = {"fe": CHAIN["fe"],
             "dampers": [{"name": "d", "at": 1, "m": 0.1, "gap": 0.5, "contact": "rigid",
                          "e": 0.6}],
             "force": {"at": 1, "amplitude": 0.1}}  # fmt: skip
    path = tmp_path / "damped.json"
    path.write_text(json.dumps(model))
    argv = ["design", "--structure", str(path), "--omega-range", "1.5:1.7:0.05", "--gaps",
            "0.4,0.6", "--csv", str(tmp_path / "d.csv"), "--plot", str(tmp_path / "d.png"),
            "--json"]  # fmt: skip
    assert main(argv) == 0, capsys.readouterr().err
    out = json.loads(capsys.readouterr().out)
    with open(tmp_path / "d.csv") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["gap [m]"]) for r in rows] == [r["gap"] for r in out["rows"]]
    for r, j in zip(rows, out["rows"], strict=True):
        assert float(r["peak_amplitude [m]"]) == j["peak"]["amplitude"]
        assert float(r["peak_omega [rad/s]"]) == j["peak"]["omega"]
        assert float(r["baseline_peak [m]"]) == out["bare_peak"]["amplitude"]
        assert r["best"] == str(j["gap"] == out["best"]["gap"])
    assert (tmp_path / "d.png").stat().st_size > 10_000
