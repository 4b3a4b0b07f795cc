"""``symimpact random``, ``shock`` and ``sweep-sine``: the JSON is the API's result for the same
load (units converted at the boundary: g²/Hz, g, ms), the CSV has its units in the headers, and
bad input is refused in one line naming the parameter (exit 2)."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.loads.random_response import random_statistics
from symimpact.forced.loads.records import shock_record
from symimpact.forced.loads.shock_response import shock_response
from symimpact.model.system import ImpactSystem

SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm", "--e", "0.6"]
API = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
G = 9.80665


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_random_json_is_the_api_with_g2_per_hz_converted(capsys, tmp_path):
    """0.002 g²/Hz is 0.002·9.80665² (m/s²)²/Hz; the JSON's keys are the issue's contract."""
    argv = ["random", *SYSTEM, "--base-psd", "0.002 g^2/Hz", "--band", "1 Hz:40 Hz",
            "--duration", "20 s", "--realisations", "3", "--seed", "9", "--settle", "5 s",
            "--json", "--csv", str(tmp_path / "psd.csv")]  # fmt: skip
    out = _json(capsys, argv)
    api = random_statistics(API, 0.002 * G**2, (1, 40), 20.0, 1 / 800, e=0.6, realisations=3,
                            seed=9, settle=5.0, kind="base-acceleration")  # fmt: skip
    assert set(out) >= {"rms", "rms_ci95", "baseline_rms", "reduction", "realisations", "seed"}
    for key in ("displacement", "velocity", "acceleration", "base_force"):
        assert out["rms"][key] == api.rms[key]
        assert out["baseline_rms"][key] == api.baseline_rms[key]
        assert out["rms_ci95"][key] == list(api.rms_ci95[key])
    assert out["realisations"] == 3 and out["seed"] == 9
    with open(tmp_path / "psd.csv") as f:
        header = next(csv.reader(f))
    assert header == ["frequency [Hz]", "displacement_psd [m^2/Hz]",
                      "baseline_displacement_psd [m^2/Hz]"]  # fmt: skip


def test_an_rms_over_the_band_is_the_flat_psd_a_test_engineer_computes(capsys):
    """--base-acc-rms "0.5 g" over 5–100 Hz is the flat PSD grms²/Δf = 0.25/95 g²/Hz =
    0.00263158 g²/Hz (the specification's arithmetic, issue 80); --force-rms "5 N" over 1–26 Hz
    is 1 N²/Hz.  Far from the walls (no impacts: the run is linear in the PSD's square root) the
    statistics equal --base-psd's at that level to 1e-9 (the decimal level's last digits)."""
    far = ["--M", "40", "--fn", "12 Hz", "--zeta", "0.01", "--m", "2", "--gap", "1 m", "--e",
           "0.6", "--duration", "10 s", "--realisations", "2", "--settle", "2 s", "--json"]  # fmt: skip
    a = _json(capsys, ["random", *far, "--base-acc-rms", "0.5 g", "--band", "5:100"])
    assert a["load"]["psd"] == pytest.approx(0.25 / 95 * G**2, rel=1e-15)
    assert a["load"]["psd"] / G**2 == pytest.approx(0.00263158, abs=5e-9)
    assert a["load"]["rms"] == pytest.approx(0.5 * G, rel=1e-15)
    assert a["load"]["kind"] == "base-acceleration" and a["load"]["band"] == [5.0, 100.0]
    b = _json(capsys, ["random", *far, "--base-psd", "0.0026315789473684 g^2/Hz", "--band",
                       "5:100"])  # fmt: skip
    for key in ("displacement", "acceleration", "base_force"):
        assert a["rms"][key] == pytest.approx(b["rms"][key], rel=1e-9)
        assert a["baseline_rms"][key] == pytest.approx(b["baseline_rms"][key], rel=1e-9)
    f = _json(capsys, ["random", *far, "--force-rms", "5 N", "--band", "1:26"])
    assert f["load"]["psd"] == pytest.approx(1.0, rel=1e-15) and f["load"]["kind"] == "force"
    assert main(["random", *far[:-1], "--base-acc-rms", "0.5 g", "--band", "5:100"]) == 0
    assert capsys.readouterr().out.startswith(
        "load: base acceleration PSD 0.00263158 g²/Hz flat over 5–100 Hz, 0.5 g rms\n"
    )


@pytest.mark.parametrize("extra, parameter", [
    (["--base-acc-rms", "0.5 g", "--base-psd", "0.01 g^2/Hz"], "base-psd"),
    (["--force-rms", "2 N", "--base-acc-rms", "0.5 g"], "force-rms"),
    (["--base-acc-rms", "0.5 N"], "base-acc-rms"),
    (["--force-rms", "-1 N"], "force-rms"),
    (["--base-acc-rms", "0.5 g", "--kanai-tajimi", "2.5:0.6"], "kanai-tajimi"),
    ([], "force-psd"),
])  # fmt: skip
def test_an_rms_load_given_twice_or_wrongly_is_refused_in_one_line(extra, parameter, capsys):
    argv = ["random", *SYSTEM, "--band", "5:100", *extra]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and f"error: {parameter}:" in err, err


def test_a_psd_table_is_read_with_its_units(capsys, tmp_path):
    """A flat table in g²/Hz gives the flat PSD's statistics (linear interpolation of a constant
    is the constant)."""
    table = tmp_path / "spec.csv"
    table.write_text("frequency [Hz],psd [g^2/Hz]\n0.5,0.002\n50,0.002\n")
    common = [*SYSTEM, "--band", "1:40", "--duration", "10", "--realisations", "2", "--settle",
              "2", "--json"]  # fmt: skip
    a = _json(capsys, ["random", *common, "--psd-file", str(table)])
    b = _json(capsys, ["random", *common, "--base-psd", "0.002 g^2/Hz"])
    assert a["rms"] == pytest.approx(b["rms"], rel=1e-12)


def test_shock_json_is_the_api_with_g_and_ms(capsys):
    argv = ["shock", *SYSTEM, "--base-peak", "20 g", "--pulse", "11 ms", "--duration", "1 s",
            "--srs-range", "1:50", "--srs-points", "5", "--json"]  # fmt: skip
    out = _json(capsys, argv)
    dt = 1.0 / np.ceil(1.0 / (0.011 / 200))  # 200 samples in the pulse, dividing the 1 s run
    record = shock_record("half-sine", 20 * G, 0.011, 1.0, dt, "base-acceleration")
    api = shock_response(API, record, e=0.6, frequencies=np.geomspace(1, 50, 5))
    # pint's "20 g" and 20·9.80665 may differ in the last bit, which the run carries along
    close = {"rel": 1e-12, "abs": 0}
    assert out["peak"] == pytest.approx(api.peak, **close)
    assert out["baseline_peak"] == pytest.approx(api.baseline_peak, **close)
    assert [r["frequency"] for r in out["srs"]] == list(api.frequency)
    assert [r["response"] for r in out["srs"]] == pytest.approx(list(api.srs), **close)
    assert [r["baseline"] for r in out["srs"]] == pytest.approx(list(api.baseline_srs), **close)


@pytest.mark.parametrize(
    ("contact", "law"),
    [(["--contact", "linear", "--k1", "1e5", "--c1", "2"], CompliantContact("linear")),
     (["--contact", "hunt-crossley", "--k-hz", "1e6", "--chi", "0.5"],
      CompliantContact("hunt-crossley", 0.5))],
)  # fmt: skip
def test_shock_with_a_compliant_contact_is_the_api(capsys, contact, law):
    system = [*SYSTEM[:-2], *contact]  # (--e left out: the law sets its own restitution)
    argv = ["shock", *system, "--force-peak", "60 N", "--pulse", "20 ms", "--duration", "1 s",
            "--srs-range", "1:50", "--srs-points", "5", "--json"]  # fmt: skip
    out = _json(capsys, argv)
    api_system = ImpactSystem(M=1, K=1000, C=0.5, m=0.05, gap=0.02,
                              **({"contact": "linear", "k1": 1e5, "c1": 2.0}
                                 if law.law == "linear" else {"contact": "hertz", "k_hz": 1e6}))  # fmt: skip
    dt = 1.0 / np.ceil(1.0 / (0.02 / 200))
    record = shock_record("half-sine", 60.0, 0.02, 1.0, dt, "force")
    api = shock_response(api_system, record, e=law, frequencies=np.geomspace(1, 50, 5))
    assert out["impacts"] == api.impacts > 0
    assert out["peak"] == pytest.approx(api.peak, rel=1e-15)
    assert [r["response"] for r in out["srs"]] == pytest.approx(list(api.srs), rel=1e-15)


def test_sweep_sine_runs_up_and_down(capsys, tmp_path):
    plot = tmp_path / "sweep.png"
    out = _json(capsys, ["sweep-sine", *SYSTEM, "--force-amplitude", "2 N", "--band", "4:6",
                         "--rate", "0.2", "--json", "--plot", str(plot)])  # fmt: skip
    for name in ("up", "down"):
        env = out[name]["envelope"]
        assert len(env) > 20
        assert out[name]["peak"] == max(r["envelope"] for r in env)
    # the steady curve of frf beside it: its located peak is no sample's
    steady = out["steady"]
    assert steady["stable"] and steady["peak"] >= max(r["amplitude"] for r in steady["stable"])
    assert plot.stat().st_size > 10_000


@pytest.mark.parametrize(
    "argv, name",
    [
        (["random", "--band", "1:40", "--force-psd", "-1 N^2/Hz"], "force-psd"),
        (["random", "--band", "1:40", "--force-psd", "1 N^2/Hz", "--base-psd", "1 g^2/Hz"],
         "force-psd"),
        (["random", "--band", "40:1", "--force-psd", "1"], "band"),
        (["random", "--band", "1:40", "--force-psd", "1", "--realisations", "two"],
         "realisations"),
        (["random", "--band", "1:40", "--base-psd", "1 N^2/Hz"], "base-psd"),
        (["shock", "--force-peak", "20 kg", "--pulse", "11 ms"], "force-peak"),
        (["shock", "--force-peak", "20", "--pulse", "1 s", "--duration", "0.5 s"], "duration"),
        (["sweep-sine", "--force-amplitude", "2", "--band", "4:6", "--rate", "0"], "rate"),
    ],
)  # fmt: skip
def test_bad_input_is_one_line_naming_the_parameter(capsys, argv, name):
    assert main([argv[0], *SYSTEM, *argv[1:]]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{name}:" in err[0]


def test_a_bad_psd_table_is_refused(capsys, tmp_path):
    for text, why in (("frequency,psd\n1,2\n3,4\n", "unit"),
                      ("frequency [Hz],psd [g^2/Hz]\n5,1\n1,1\n", "increase"),
                      ("frequency [Hz],psd [g^2/Hz]\n1,-1\n5,1\n", "≥ 0")):  # fmt: skip
        table = tmp_path / "t.csv"
        table.write_text(text)
        argv = ["random", *SYSTEM, "--band", "1:40", "--psd-file", str(table)]
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert "psd-file:" in err and why in err


def test_random_as_a_map_is_the_in_process_ensemble(capsys, tmp_path):
    """--executor/--out run the realisations as map runs: the same RMS values (the seed fixes
    each record), one row per realisation in the file, and no PSD (--plot refused)."""
    common = [*SYSTEM, "--force-psd", "0.02 N^2/Hz", "--band", "0.2:50", "--duration", "20",
              "--realisations", "4", "--settle", "5", "--json"]  # fmt: skip
    direct = _json(capsys, ["random", *common])
    out = tmp_path / "ensemble.csv"
    mapped = _json(capsys, ["random", *common, "--executor", "serial", "--out", str(out)])
    assert mapped["rms"] == direct["rms"] and mapped["rms_ci95"] == direct["rms_ci95"]
    assert len(out.read_text().splitlines()) == 1 + 4
    assert main(["random", *common, "--executor", "serial", "--plot", str(tmp_path / "p.png")]) == 2
    assert "plot:" in capsys.readouterr().err
