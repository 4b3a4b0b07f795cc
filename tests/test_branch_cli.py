"""``symimpact branch``: a branch continued in the clearance (or F0, X_b, e) at a fixed forcing
frequency, against the closed-form symmetric two-impact orbits (Eq. F3) at every point; its CSV
and plot; bad input refused in one line."""

from __future__ import annotations

import itertools
import json

import pytest

from symimpact.cli import main
from symimpact.forced import Forcing, periodic_orbits
from symimpact.model.system import ImpactSystem

ARGS = ["branch", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
        "--force", "2 N", "--omega", "36"]  # fmt: skip
RIGID = ["--contact", "rigid", "--e", "0.6"]


def test_a_branch_in_the_clearance_is_the_closed_form_orbit(capsys, tmp_path):
    """At 36 rad/s the run from rest settles on the symmetric two-impact orbit; continued in d
    over 5–40 mm, every point's amplitude and stability are the closed form's at its d (Eq. F3,
    typed nowhere here but in the kernels the closed form evaluates: an independent path from
    shooting), to 1e-8; its one branch point, the symmetry-breaking pitchfork, lies where the
    stability changes (14.637 mm)."""
    csv, png = tmp_path / "b.csv", tmp_path / "b.png"
    assert main([*ARGS, *RIGID, "--parameter", "gap", "--range", "5 mm:40 mm", "--json",
                 "--csv", str(csv), "--plot", str(png)]) == 0  # fmt: skip
    out = json.loads(capsys.readouterr().out)
    assert out["parameter"] == "gap" and out["unit"] == "m"
    points = out["points"]
    assert len(points) > 50
    base = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
    for p in points[::10]:
        orbits = periodic_orbits(base.with_(gap=p["value"]), Forcing(F0=2.0, omega=36.0), 0.6)
        closest = min(orbits, key=lambda o: abs(o.amplitude - p["amplitude"]))
        assert p["amplitude"] == pytest.approx(closest.amplitude, rel=1e-8)
        assert p["stable"] == closest.stable and p["impacts_per_period"] == 2
    (bp,) = [b for b in out["bifurcations"] if b["kind"] == "branch-point"]
    assert bp["value"] == pytest.approx(0.014637, abs=1e-6)
    flips = [(p, q) for p, q in itertools.pairwise(points) if p["stable"] != q["stable"]]
    assert len(flips) == 1
    lo, hi = sorted((flips[0][0]["value"], flips[0][1]["value"]))
    assert lo <= bp["value"] <= hi
    assert csv.read_text().splitlines()[0].startswith("gap [m],amplitude [m],stable")
    assert png.stat().st_size > 10_000


@pytest.mark.parametrize(
    ("extra", "name"),
    [
        ([*RIGID, "--parameter", "gap", "--range", "40 mm:5 mm"], "range:"),
        ([*RIGID, "--parameter", "gap", "--range", "30 mm:40 mm"], "range:"),
        ([*RIGID, "--parameter", "gap", "--range", "5 mm"], "range:"),
        ([*RIGID, "--parameter", "F0", "--range", "1 mm:3 mm"], "F0:"),
        (["--contact", "hertz", "--parameter", "e", "--range", "0.1:0.9"], "parameter:"),
        (["--contact", "rigid", "--parameter", "gap", "--range", "5 mm:40 mm"], "e:"),
    ],
)
def test_bad_branch_input_is_one_line(capsys, extra, name):
    assert main([*ARGS, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and name in err
