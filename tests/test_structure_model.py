"""A structure file with its dampers and force (symimpact.model.structure_model) and
``symimpact simulate --structure FILE`` on it: the file's quantities mean what they say, the run
is the API's, a damper out of reach leaves the closed-form modal response, and bad files and
options are refused in one line naming the parameter (exit 2)."""

from __future__ import annotations

import json
import math

import pytest

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import damper
from symimpact.model.structure import beam_structure
from symimpact.model.structure_model import model_from_dict, read_model
from tests.helpers import RHO, A, E, I, L

#: A steel cantilever strip (tests.helpers) with two rigid dampers, quantities as texts.
FILE = {
    "beam": {"type": "cantilever", "E": E, "I": I, "rho": RHO, "A": A, "L": f"{L * 1e3} mm",
             "modes": 3, "zeta": 0.01},
    "points": {"tip": L, "mid": L / 2},
    "dampers": [
        {"name": "d1", "at": "tip", "m": "20 g", "gap": "4 mm", "contact": "rigid", "e": 0.6},
        {"name": "d2", "at": "mid", "m": 0.02, "gap": "2 mm", "contact": "rigid", "e": 0.6},
    ],
    "force": {"at": "tip", "amplitude": "2 N"},
}  # fmt: skip


def _run(tmp_path, capsys, data, *args):
    path = tmp_path / "model.json"
    path.write_text(json.dumps(data))
    code = main(["simulate", "--structure", str(path), *args])
    return code, capsys.readouterr()


def test_the_file_is_the_model_the_api_builds(tmp_path, capsys):
    """The file's texts ("20 g", "4 mm", "2 N", a length in mm) are read in SI, and the command's
    JSON is :func:`simulate_structure` on the same model built from SI numbers: the same engine on
    the same inputs, so equal to the last bit; the run has impacts at both dampers."""
    s = beam_structure("cantilever", E, I, RHO, A, L, {"tip": L, "mid": L / 2}, 3, 0.01)
    ds = (damper(s, "d1", "tip", 0.02, 0.004, 0.6), damper(s, "d2", "mid", 0.02, 0.002, 0.6))
    model = model_from_dict(FILE)
    assert model.dampers == ds and model.F0 == 2.0 and model.force_at == "tip"
    omega = 2 * math.pi * 10.0
    code, out = _run(tmp_path, capsys, FILE, "--omega", str(omega), "--periods", "40", "--json")
    assert code == 0, out.err
    got = json.loads(out.out)
    res = simulate_structure(s, ds, "tip", 2.0, omega, 40)
    assert got["impacts"] == {"d1": len(res.impacts("d1")), "d2": len(res.impacts("d2"))}
    assert got["impacts"]["d1"] > 0 and got["impacts"]["d2"] > 0
    assert got["amplitudes"] == res.amplitudes(30 / 40)
    assert got["dampers"][0]["gap"] == 0.004 and got["dampers"][0]["m"] == 0.02


def test_a_damper_out_of_reach_leaves_the_modal_closed_form(tmp_path, capsys):
    """With the clearances too wide to close, every point's steady amplitude is the modal sum
    |Σᵢ φᵢ(p)φᵢ(f)F₀ / (Mᵢ(ωᵢ² − Ω² + 2iζᵢωᵢΩ))|, written here from the modes.  The start from
    rest beats with mode 1 (10.57 Hz) and decays as e^(−ζω₁t): the kept periods 600–800 begin at
    t = 60 s, e^(−40) = 4e-18, times the transient's start (measured: up to 60× the decay
    alone, the beat's phase), far below 1e-9 relative; the period maxima are read at the zeros
    of ẋ, to rounding."""
    data = dict(FILE, dampers=[dict(d, gap="10 m") for d in FILE["dampers"]])
    omega = 2 * math.pi * 10.0
    code, out = _run(tmp_path, capsys, data, "--omega", str(omega), "--periods", "800", "--json")
    assert code == 0, out.err
    got = json.loads(out.out)
    assert got["impacts"] == {"d1": 0, "d2": 0}
    s = read_model_from(tmp_path, data).structure
    for p in ("tip", "mid"):
        h = sum(m.shape[p] * m.shape["tip"] * 2.0
                / (m.mass * (m.omega**2 - omega**2 + 2j * m.zeta * m.omega * omega))
                for m in s.modes)  # fmt: skip
        assert got["amplitudes"][p] == pytest.approx(abs(h), rel=1e-9)


def read_model_from(tmp_path, data):
    path = tmp_path / "again.json"
    path.write_text(json.dumps(data))
    return read_model(path)


def test_csv_gives_every_points_period_maxima(tmp_path, capsys):
    csv_path = tmp_path / "maxima.csv"
    code, out = _run(tmp_path, capsys, FILE, "--freq", "10", "--periods", "20", "--csv",
                     str(csv_path))  # fmt: skip
    assert code == 0, out.err
    lines = csv_path.read_text().splitlines()
    assert lines[0] == "period,x_max tip [m],x_max mid [m]"
    assert len(lines) == 1 + 20
    assert "damper 'd1' at 'tip'" in out.out and "amplitude at 'mid'" in out.out


BAD_FILES = [
    (dict(FILE, stops=[{"name": "s", "at": "tip", "gap": 0.001}]), "stops[0]"),
    (
        dict(FILE, stops=[{"name": "s", "at": "root", "gap": 0.001, "side": "+", "k1": 1e4}]),
        "stops.s.at",
    ),
    (dict(FILE, base={"at": "root", "amplitude": 0.001}), "base"),
    ({k: v for k, v in FILE.items() if k != "force"}, "force"),
    (dict(FILE, force={"at": "tip"}), "force"),
    (dict(FILE, force={"at": "root", "amplitude": 1}), "force.at"),
    (dict(FILE, force={"at": "tip", "amplitude": -1}), "force.amplitude"),
    (dict(FILE, dampers=[FILE["dampers"][0], FILE["dampers"][0]]), "dampers.d1"),
    (dict(FILE, dampers=[dict(FILE["dampers"][0], gap=0)]), "dampers.d1.gap"),
    (dict(FILE, dampers=[dict(FILE["dampers"][0], at="root")]), "dampers.d1.at"),
    (dict(FILE, dampers=[dict(FILE["dampers"][0], contact="steel")]), "dampers.d1.contact"),
]


@pytest.mark.parametrize(("data", "name"), BAD_FILES, ids=[b[1] for b in BAD_FILES])
def test_bad_files_are_refused_naming_the_parameter(tmp_path, capsys, data, name):
    with pytest.raises(ParameterError) as info:
        model_from_dict(data)
    assert info.value.parameter == name
    code, out = _run(tmp_path, capsys, data, "--freq", "10")
    assert code == 2 and out.out == ""
    assert out.err.count("\n") == 1 and f"error: {name}:" in out.err


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (["--freq", "10", "--m", "0.1"], "m"),
        (["--freq", "10", "--contact", "rigid"], "contact"),
        (["--freq", "10", "--force", "1"], "force"),
        (["--freq", "10", "--x0", "0.001"], "x0"),
        (["--freq", "10", "--at", "tip"], "at"),
        (["--periods", "10"], "omega"),
        (["--freq", "10", "--periods", "10", "--discard", "10"], "discard"),
        (["--freq", "10", "--response", "force"], "response"),
    ],
)
def test_options_the_file_replaces_are_refused(tmp_path, capsys, args, name):
    code, out = _run(tmp_path, capsys, FILE, *args)
    assert code == 2 and out.err.count("\n") == 1 and f"error: {name}:" in out.err


def test_other_commands_refuse_what_a_file_with_dampers_does_not_take(tmp_path, capsys):
    """``branch`` continues such a file in a damper's gap, e or m or in F0, not in the one-mode
    primary's base motion: one line.  ``periodic`` shoots it, refusing the options the file
    replaces."""
    path = tmp_path / "model.json"
    path.write_text(json.dumps(FILE))
    code = main(["branch", "--structure", str(path), "--freq", "10", "--parameter", "X_b",
                 "--range", "1 mm:3 mm"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "error: parameter:" in err
    code = main(["periodic", "--structure", str(path), "--freq", "10", "--contact", "rigid",
                 "--e", "0.6", "--force", "1"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "error: contact:" in err
    assert main(["modes", "--structure", str(path)]) == 0  # the modes are listed all the same
    assert "φ(tip)" in capsys.readouterr().out


def test_workers_spread_a_curve_s_runs_and_zero_is_refused(tmp_path, capsys):
    """``frf --workers`` spreads a --structure curve's runs from rest, and a one-mode curve's
    multi-start, over processes; zero workers is refused in one line, exit 2, for both."""
    code = main(["frf", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
                 "--contact", "rigid", "--e", "0.6", "--force", "2", "--omega-range",
                 "30:31:0.5", "--workers", "0"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "error: workers:" in err
    path = tmp_path / "model.json"
    path.write_text(json.dumps(FILE))
    code = main(["frf", "--structure", str(path), "--freq-range", "9:11:1", "--workers", "0"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "error: workers:" in err
