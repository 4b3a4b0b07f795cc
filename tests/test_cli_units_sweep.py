"""Units at the boundary, the command line's JSON contracts and errors, sweeps and gap classes."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
from symimpact.generated import closed_forms, contact_fits, ritz

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.free.simulation import simulate
from symimpact.maps import gap_class, parse_range, sweep
from symimpact.model.system import ImpactSystem, table2_system
from symimpact.model.units import si


@pytest.mark.parametrize(
    ("name", "text", "value"),
    [
        ("K", "100 N/cm", 10000.0),
        ("v0", "7.5 cm/s", 0.075),
        ("gap", "9 mm", 0.009),
        ("k_hz", "1000 N/m^1.5", 1000.0),
        ("c1", "5 N s/cm", 500.0),
        ("a", "0.1553 N/cm^3", 155300.0),
        ("gap", "0.009", 0.009),
        ("M", "500 g", 0.5),
    ],
)
def test_quantities_become_the_si_float_typed_by_hand(name, text, value):
    assert si(name, text) == value  # exact: "9 mm" and 0.009 give identical input


@pytest.mark.parametrize(
    ("name", "text", "reason"),
    [
        ("gap", "5 kg", "dimension"),
        ("gap", "5 furlongz", "cannot read"),
        ("gap", "nan", "finite"),
        ("gap", "", "cannot read"),
        ("gap", "inf mm", "finite"),
    ],
)
def test_bad_quantities_name_the_parameter(name, text, reason):
    with pytest.raises(ParameterError, match=reason) as err:
        si(name, text)
    assert err.value.parameter == name


def test_units_do_not_change_results():
    a = simulate(table2_system("9 mm", C=0.5, c1="5 N s/m"), xdot0="0.5 m/s", t_end=0.5)
    b = simulate(table2_system(0.009, C=0.5, c1=5.0), xdot0=0.5, t_end=0.5)
    assert a.as_dict() == b.as_dict()


def test_system_validation():
    for kwargs, name in (
        ({"M": 0}, "M"),
        ({"K": -1}, "K"),
        ({"gap": "0 mm"}, "gap"),
        ({"C": -1}, "C"),
        ({"zeta": 1.5}, "zeta"),
        ({"contact": "rigid"}, "contact"),
        ({"c1": "-1 N s/m"}, "c1"),
    ):
        base = {"M": 1, "K": 1e4, "m": 0.25, "gap": "9 mm", "k_hz": 1000}
        base.update(kwargs)
        with pytest.raises(ParameterError) as err:
            ImpactSystem(**base)
        assert err.value.parameter == name


def test_from_beam_uses_ritz_constants():
    s = ImpactSystem.from_beam(
        E="70 GPa", I=1e-10, rho=2700, A=1e-4, L=0.5, m=0.01, gap="5 mm", zeta=0.01, k_hz=1000
    )
    assert s.K == pytest.approx(3.0905908420815 * 70e9 * 1e-10 / 0.5**3, rel=1e-12)
    assert s.M == pytest.approx(0.25 * 2700 * 1e-4 * 0.5, rel=1e-12)
    assert s.C == pytest.approx(2 * 0.01 * math.sqrt(s.K * s.M), rel=1e-12)
    with pytest.raises(ParameterError) as err:
        ImpactSystem.from_beam(E=1, I=1, rho=1, A=1, L=1, m=1, gap=1, position=2, k_hz=1)
    assert err.value.parameter == "position"


def _json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def test_cli_ritz_and_fit_contracts(capsys):
    out = _json(capsys, "ritz", "--json")
    assert set(out) == {"beta_L", "stiffness_coefficient", "mass_coefficient"}
    assert out["beta_L"] == ritz.BETA_L[0] and out["mass_coefficient"] == pytest.approx(0.25)
    out = _json(
        capsys,
        "ritz",
        "--E",
        "70 GPa",
        "--I",
        "1e-10",
        "--rho",
        "2700",
        "--A",
        "1e-4",
        "--L",
        "0.5",
        "--json",
    )
    assert {"K", "M"} <= set(out)
    out = _json(capsys, "fit", "--k-hz", "1000", "--delta-max", "2 cm", "--json")
    assert out == {
        "a": float(contact_fits.cubic_fit_a(1000, 0.02)),
        "b": float(contact_fits.cubic_fit_b(1000, 0.02)),
        "k1": float(contact_fits.linear_fit_k1(1000, 0.02)),
    }
    assert round(out["a"] * 1e-6, 4) == 0.1553 and round(out["k1"], 1) == 122.7


def test_cli_contact_duration_contract(capsys):
    out = _json(
        capsys,
        "contact-duration",
        "--m",
        "0.15",
        "--M",
        "1",
        "--K",
        "1000",
        "--v0",
        "7.5 cm/s",
        "--method",
        "all",
        "--json",
    )
    assert {"perturbation", "hertz", "linear", "numerical"} <= set(out)
    assert out["hertz"] == pytest.approx(
        float(closed_forms.hertz_contact_duration(0.15, 1, 1000, 0.075))
    )
    assert all(
        isinstance(out[k], float) and out[k] > 0 for k in ("perturbation", "linear", "numerical")
    )


def test_cli_simulate_and_sweep_contracts(capsys, tmp_path):
    common = ["--C", "0.5", "--c1", "5 N s/m", "--xdot0", "0.5 m/s", "--t-end", "0.5"]
    png, csvf = tmp_path / "s.png", tmp_path / "s.csv"
    out = _json(capsys, "simulate", *common, "--json", "--plot", str(png), "--csv", str(csvf))
    assert {
        "n_impacts",
        "n_effective",
        "effectiveness",
        "damping_inclination",
        "impacts",
        "energy_residual",
    } <= set(out)
    assert out["n_impacts"] == len(out["impacts"]) > 0
    assert {"t", "x", "xdot", "y", "ydot", "effective", "duration"} <= set(out["impacts"][0])
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and csvf.stat().st_size > 0
    rows = _json(capsys, "sweep", *common, "--gap", "6 mm:9 mm:1 mm", "--json", "--workers", "1")
    assert [r["gap"] for r in rows] == [0.006, 0.007, 0.008, 0.009]
    assert {"n_impacts", "n_effective", "effectiveness", "damping_inclination", "class"} <= set(
        rows[0]
    )


@pytest.mark.parametrize(
    "argv",
    [
        ["simulate", "--gap", "5 kg"],
        ["simulate", "--gap", "-1 mm"],
        ["simulate", "--zeta", "2"],
        ["simulate", "--t-end", "0"],
        ["sweep", "--gap", "6 mm:12 mm:0 mm"],
        ["fit", "--k-hz", "abc"],
        ["simulate", "--plot", "/nonexistent-folder/x.png", "--t-end", "0.01"],
        ["contact-duration", "--ba", "0.5", "--method", "perturbation"],
        ["contact-duration", "--method", "euler"],
    ],
)
def test_cli_bad_input_exits_2_with_one_line(argv):
    proc = subprocess.run(
        [sys.executable, "-m", "symimpact.cli", *argv], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr


def test_parse_range_and_classes():
    assert list(parse_range("gap", "6 mm:9 mm:1 mm")) == [0.006, 0.007, 0.008, 0.009]
    assert list(parse_range("gap", "7 mm,9 mm")) == [0.007, 0.009]
    with pytest.raises(ParameterError):
        parse_range("gap", "9 mm:6 mm:1 mm")
    # Table 3 as printed: the criterion gives the printed class of all nine rows
    table3 = [
        (6, 41, 14, "out"),
        (7, 24, 13, "in"),
        (9, 19, 11, "in"),
        (15, 12, 7, "in"),
        (20, 19, 10, "in"),
        (25, 9, 6, "in"),
        (32, 12, 6, "in"),
        (34, 10, 6, "in"),
        (35, 12, 5, "out"),
    ]
    for _, n_tot, n_eff, cls in table3:
        expected = "in range" if cls == "in" else "out of range"
        assert gap_class(n_tot, n_eff) == expected


def test_sweep_parallel_equals_serial():
    s = table2_system("9 mm", C=0.5, c1="5 N s/m")
    gaps = np.linspace(0.006, 0.010, 6)
    kw = {"xdot0": 0.5, "t_end": 0.4, "progress": False}
    assert sweep(s, gaps, workers=2, **kw) == sweep(s, gaps, workers=1, **kw)
    rows = sweep(s, [0.02], "m", **kw)
    assert rows[0]["m"] == 0.02


def test_interrupted_sweep_leaves_no_output(tmp_path, monkeypatch, capsys):
    """Ctrl-C in the middle of a sweep: exit 130, and neither --csv, --plot nor --out leaves a
    file (complete or partial) under its name, nor a temporary file beside it."""
    import symimpact.maps.executors as executors

    calls = {"n": 0}
    real = executors._run_chunk

    def interrupt_on_third(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 3:
            raise KeyboardInterrupt
        return real(*args, **kwargs)

    monkeypatch.setattr(executors, "_run_chunk", interrupt_on_third)  # the third chunk
    argv = ["sweep", "--vary", "gap=4 mm:12 mm:2 mm", "--executor", "serial", "--quiet"]
    argv += ["--chunk-size", "1"]
    outputs = ["--csv", str(tmp_path / "t.csv"), "--plot", str(tmp_path / "t.png")]
    assert main([*argv, *outputs]) == 130
    assert "interrupted" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_atomic_write_interrupted_mid_file_leaves_nothing(tmp_path):
    from symimpact.io import atomic_write

    def half_then_fail(f):
        f.write("gap,n_impacts\n0.004,")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        atomic_write(tmp_path / "t.csv", half_then_fail, "csv")
    assert list(tmp_path.iterdir()) == []
    (tmp_path / "t.csv").write_text("old\n")
    with pytest.raises(KeyboardInterrupt):
        atomic_write(tmp_path / "t.csv", half_then_fail, "csv")
    assert (tmp_path / "t.csv").read_text() == "old\n"  # the previous file is untouched
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]


def test_one_option_name_for_the_contact_law(capsys):
    """Issue 17, item 1: contact-duration named it --law, simulate --contact."""
    from symimpact.cli import main

    args = ["contact-duration", "--method", "numerical", "--json"]
    assert main([*args, "--contact", "hertz"]) == 0
    new = json.loads(capsys.readouterr().out)
    assert main([*args, "--law", "hertz"]) == 0  # the former name still works, unlisted
    assert json.loads(capsys.readouterr().out) == new
    assert main([*args, "--contact", "cubic"]) == 0
    assert json.loads(capsys.readouterr().out) != new
    with pytest.raises(SystemExit):
        main(["contact-duration", "--help"])
    help_text = capsys.readouterr().out
    assert "--contact" in help_text and "--law" not in help_text


def test_a_missing_value_reads_as_a_dash_in_text(capsys):
    from symimpact.cli import main

    assert main(["simulate", "--t-end", "0.01"]) == 0  # too short for four maxima: no DI
    out = capsys.readouterr().out
    assert "DI — µm" in out and "None" not in out and "n/a" not in out


def test_the_command_line_is_a_package_of_subcommands():
    """Issue 17, item 6: one module per subcommand, each registered by one line in SUBCOMMANDS,
    with its parser (add_parser) and what runs it (COMMANDS); the parser offers exactly the
    registered names."""
    import argparse
    import pkgutil

    import symimpact.cli as cli

    modules = {m.name for m in pkgutil.iter_modules(cli.__path__)} - {"common", "__main__"}
    assert modules == {m.__name__.rsplit(".", 1)[1] for m in cli.SUBCOMMANDS}
    for module in cli.SUBCOMMANDS:
        assert callable(module.add_parser) and module.COMMANDS
    parser = cli.build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    assert set(sub.choices) == set(cli.COMMANDS)
