"""The forced-response command line: ``simulate`` with forcing and rigid impacts or a compliant
contact, and ``periodic`` — the JSON contracts, --freq as Ω/2π, and bad input refused in one line
naming the parameter."""

from __future__ import annotations

import json
import math

import pytest

from symimpact.cli import main
from symimpact.forced import Forcing, periodic_orbits, simulate_forced
from symimpact.model.system import ImpactSystem

SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm"]


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_periodic_json_is_the_closed_form_contract(capsys):
    argv = ["periodic", "--method", "closed-form", "--contact", "rigid", "--e", "0.6"]
    out = _json(capsys, [*argv, "--omega", "34 rad/s", *SYSTEM, "--force", "2 N", "--json"])
    system = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
    api = periodic_orbits(system, Forcing(F0=2.0, omega=34.0), 0.6)
    assert len(out) == len(api) == 2
    for row, orbit in zip(out, api, strict=True):
        for key in ("impact_phase", "amplitude", "impact_speed"):
            assert isinstance(row[key], float) and row[key] == getattr(orbit, key)
        assert isinstance(row["admissible"], bool) and isinstance(row["stable"], bool)
        assert row["multipliers"] == sorted(row["multipliers"], reverse=True)
    # Ω 34 rad/s: one admissible unstable orbit (the simulation leaves it: test_forced_rigid)
    assert [r["admissible"] for r in out] == [True, False] and not any(r["stable"] for r in out)


def test_freq_in_hz_is_omega_over_two_pi(capsys):
    base = ["periodic", "--contact", "rigid", "--e", "0.6", *SYSTEM, "--force", "2", "--json"]
    by_omega = _json(capsys, [*base, "--omega", "38"])
    by_freq = _json(capsys, [*base, "--freq", f"{38 / (2 * math.pi)!r} Hz"])
    for a, b in zip(by_omega, by_freq, strict=True):
        # Ω = 2π·(38/2π) rounds to 38 within one ULP; the orbit is well conditioned there
        assert b["amplitude"] == pytest.approx(a["amplitude"], rel=1e-13)


def test_simulate_forced_json_adds_the_steady_state(capsys):
    argv = ["simulate", *SYSTEM[:-2], "--gap", "2 m", "--force", "2 N", "--omega", "31 rad/s"]
    argv += ["--contact", "rigid", "--e", "0.6", "--periods", "1200", "--discard", "1100"]
    out = _json(capsys, [*argv, "--json"])
    steady = out["steady"]
    assert set(steady) >= {"amplitude", "impacts_per_period", "periodic", "period_multiple"}
    # no wall within reach: the linear frequency response |F0|/√((K − MΩ²)² + (CΩ)²), typed
    # here from the textbook rather than from the generated kernels; after 1100 periods the
    # free transient has decayed by exp(−ζωn·t) ≈ 1e-24, so rounding is all that is left
    linear = 2.0 / math.hypot(1000.0 - 31.0**2, 0.5 * 31.0)
    assert steady["amplitude"] == pytest.approx(linear, rel=1e-9)
    assert steady["impacts_per_period"] == 0 and steady["periodic"]
    assert steady["period_multiple"] == 1 and out["n_impacts"] == 0


def test_simulate_forced_writes_csv_and_plot(tmp_path, capsys):
    csv, png = tmp_path / "f.csv", tmp_path / "f.png"
    argv = ["simulate", *SYSTEM, "--force", "2 N", "--omega", "34 rad/s", "--contact", "rigid"]
    argv += ["--e", "0.6", "--periods", "40", "--csv", str(csv), "--plot", str(png)]
    assert main(argv) == 0
    assert "impacts per period" in capsys.readouterr().out
    header = csv.read_text().splitlines()[0]
    assert header == "t [s],x [m],xdot [m/s],z [m],ydot [m/s]"
    assert len(csv.read_text().splitlines()) == 40 * 64 + 2 and png.stat().st_size > 10_000


@pytest.mark.parametrize(
    ("law", "extra", "kw"),
    [
        ("hertz", ["--k-hz", "1e9", "--c1", "20"], {"k_hz": 1e9, "c1": 20.0}),
        ("hunt-crossley", ["--k-hz", "1e9 N/m^1.5", "--chi", "0.4 s/m"], {"k_hz": 1e9}),
        ("linear", ["--k1", "1e7 N/m", "--c1", "200 N*s/m"], {"k1": 1e7, "c1": 200.0}),
    ],
)
def test_simulate_forced_with_a_compliant_contact_is_the_api_run(capsys, law, extra, kw):
    """The command line's compliant forced run is simulate_forced's, to the last bit (the same
    parameters reach the same code), and its JSON names the law (and χ)."""
    argv = ["simulate", *SYSTEM, "--force", "2 N", "--omega", "36 rad/s", "--contact", law]
    out = _json(capsys, [*argv, *extra, "--periods", "12", "--discard", "8", "--json"])
    system = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact=law.replace(
        "hunt-crossley", "hertz"), **kw)  # fmt: skip
    chi = {"chi": 0.4} if law == "hunt-crossley" else {}
    api = simulate_forced(system, Forcing(F0=2.0, omega=36.0), contact=law, periods=12, discard=8,
                          **chi)  # fmt: skip
    assert out["contact"] == law and out.get("chi") == chi.get("chi")
    assert out["steady"]["amplitude"] == api.steady.amplitude > 0.0
    assert out["n_impacts"] == len(api.impacts) > 0
    assert out["energy"]["relative_residual"] < 1e-8  # the ledger with the forcing's work


def test_simulate_compliant_forced_writes_the_sampled_csv(tmp_path, capsys):
    csv = tmp_path / "h.csv"
    argv = ["simulate", *SYSTEM, "--force", "2 N", "--omega", "36", "--contact", "hertz"]
    assert main([*argv, "--k-hz", "1e9", "--periods", "5", "--csv", str(csv)]) == 0
    assert "contact hertz" in capsys.readouterr().out
    assert len(csv.read_text().splitlines()) == 5 * 64 + 2


@pytest.mark.parametrize(
    ("extra", "parameter"),
    [
        (["--e", "1.5", "--omega", "30"], "e:"),
        (["--e", "-0.1", "--omega", "30"], "e:"),
        (["--e", "0.6", "--omega", "0"], "omega:"),
        (["--e", "0.6", "--omega", "30", "--freq", "5"], "omega:"),
        (["--e", "0.6", "--omega", "30", "--omega", "31"], "--omega"),
        (["--e", "0.6", "--omega", "30 /s"], "omega:"),  # a rate naming no angle
        (["--e", "0.6"], "omega:"),
        (["--omega", "30"], "e:"),
    ],
)
def test_periodic_bad_input_is_one_line_naming_the_parameter(capsys, extra, parameter):
    assert _status(["periodic", "--contact", "rigid", *SYSTEM, "--force", "2 N", *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and parameter in err


def _status(argv) -> int:
    """The exit status of ``symimpact argv`` (argparse's own refusals exit through SystemExit)."""
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


def test_a_closed_form_for_a_compliant_law_is_refused(capsys):
    argv = ["periodic", "--contact", "hertz", "--e", "0.6", *SYSTEM, "--force", "2"]
    assert main([*argv, "--omega", "30"]) == 2
    assert "closed form holds for rigid impacts" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("extra", "parameter"),
    [
        (["--contact", "rigid", "--force", "2", "--omega", "30"], "e:"),
        (["--contact", "rigid", "--e", "0.5"], "force:"),
        (["--contact", "rigid", "--e", "0.5", "--force", "2", "--omega", "30", "--t-end", "3"],
         "t-end:"),
        (["--contact", "rigid", "--e", "0.5", "--force", "2", "--omega", "30", "--periods", "10",
          "--discard", "10"], "discard:"),
        (["--e", "0.5"], "e:"),
        (["--periods", "5"], "periods:"),
        (["--force", "2", "--omega", "30", "--e", "0.5"], "contact:"),
        (["--force", "2", "--omega", "30", "--contact", "hunt-crossley"], "chi:"),
        (["--contact", "hunt-crossley", "--chi", "1"], "force:"),
        (["--force", "2", "--omega", "30", "--contact", "hertz", "--chi", "1"], "chi:"),
        (["--force", "2", "--omega", "30", "--contact", "hertz", "--e", "0.5"], "e:"),
        (["--force", "2", "--omega", "30", "--contact", "perturbation"], "free-vibration"),
        (["--force", "2", "--omega", "30", "--contact", "hunt-crossley", "--chi", "-1"], "chi:"),
        (["--chi", "1"], "chi:"),
    ],
)  # fmt: skip
def test_simulate_bad_forcing_input_is_one_line(capsys, extra, parameter):
    assert _status(["simulate", *SYSTEM, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and parameter in err


def test_periodic_by_shooting_has_the_closed_form_json_keys(capsys):
    """--method shooting at 36 rad/s settles from rest onto the stable symmetric orbit: the same
    keys as the closed form and, to 1e-8, the same amplitude, speed and multipliers."""
    base = ["periodic", "--contact", "rigid", "--e", "0.6", *SYSTEM, "--force", "2", "--json"]
    (shot,) = _json(capsys, [*base, "--omega", "36", "--method", "shooting"])
    closed = [o for o in _json(capsys, [*base, "--omega", "36"]) if o["stable"]]
    contract = {"impact_phase", "amplitude", "impact_speed", "admissible", "stable", "multipliers"}
    assert len(closed) == 1 and contract <= set(closed[0]) and contract <= set(shot)
    assert shot["stable"] and shot["period_multiple"] == 1 and shot["impacts_per_period"] == 2
    for key in ("amplitude", "impact_speed"):
        assert shot[key] == pytest.approx(closed[0][key], rel=1e-8)
    assert shot["multipliers"] == pytest.approx(closed[0]["multipliers"], rel=1e-6)


@pytest.mark.parametrize(
    ("extra", "parameter"),
    [
        (["--warmup", "100"], "warmup:"),
        (["--method", "shooting", "--multiple", "0"], "multiple:"),
        (["--method", "shooting", "--multiple", "1.5"], "multiple:"),
        (["--method", "shooting", "--warmup", "-3"], "warmup:"),
        (["--method", "shooting", "--omega", "38"], "does not impact"),
    ],
)
def test_periodic_shooting_bad_input_is_one_line(capsys, extra, parameter):
    argv = ["periodic", "--contact", "rigid", "--e", "0.6", *SYSTEM, "--force", "2"]
    if "--omega" not in extra:
        argv += ["--omega", "36"]
    assert _status([*argv, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and parameter in err
