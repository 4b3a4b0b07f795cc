"""Loads from a designer's data: a recorded time history read from CSV with its units, and the
Kanai–Tajimi ground motion — checked against the same load built directly and against the
transfer function the Kanai–Tajimi PSD stands for; and the SRS of the primary's motion against
a state-space simulation of primary and oscillator in series (scipy.signal.lsim)."""

import numpy as np
import pytest
from scipy import signal

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced.loads.random_response import random_statistics
from symimpact.forced.loads.records import kanai_tajimi, read_record, shock_record
from symimpact.forced.loads.shock_response import shock_response
from symimpact.maps.ensemble import random_ensemble
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.01, contact="linear", k1=1e6)
G = 9.80665


def test_the_kanai_tajimi_psd_is_its_filters_transfer_function():
    """|H|² of the ground layer's absolute acceleration under white base acceleration,
    H = (ω_g² + 2iζω_gω)/(ω_g² − ω² + 2iζω_gω), times the level."""
    kt = kanai_tajimi(0.3, 2.5, 0.6)
    f = np.geomspace(0.01, 100, 200)
    w, wg = 2 * np.pi * f, 2 * np.pi * 2.5
    h = (wg**2 + 2j * 0.6 * wg * w) / (wg**2 - w**2 + 2j * 0.6 * wg * w)
    assert np.allclose(kt(f), 0.3 * np.abs(h) ** 2, rtol=1e-13, atol=0)
    with pytest.raises(ParameterError, match="zeta_g"):
        kanai_tajimi(0.3, 2.5, 0.0)


def test_a_kanai_tajimi_ensemble_runs_on_processes_as_in_process():
    kt = kanai_tajimi(0.5, 4.0, 0.6)
    args = (SYSTEM, kt, (0.2, 30.0), 10.0, 0.002)
    kw = {"e": 0.6, "realisations": 4, "seed": 1, "settle": 2.0, "kind": "base-acceleration"}
    direct = random_statistics(*args, **kw)
    mapped, _ = random_ensemble(*args, executor="processes", workers=2, **kw)
    assert np.array_equal(mapped.per_realisation["displacement"],
                          direct.per_realisation["displacement"])  # fmt: skip


def test_a_record_read_from_csv_is_the_record_it_was_written_from(tmp_path):
    """A half-sine written in ms and g reads back as the same samples in s and m/s² (to the
    17 digits written), as a base acceleration (told by its unit)."""
    record = shock_record("half-sine", 20 * G, 0.011, 0.2, 1e-4, "base-acceleration")
    path = tmp_path / "shock.csv"
    lines = ["time [ms],acceleration [g]"]
    lines += [
        f"{float(t) * 1e3!r},{float(a) / G!r}"
        for t, a in zip(record.times, record.values, strict=True)
    ]
    path.write_text("\n".join(lines) + "\n")
    back = read_record(path)
    assert back.kind == "base-acceleration"
    assert back.dt == pytest.approx(1e-4, rel=1e-12)
    assert np.allclose(back.values, record.values, rtol=1e-14, atol=1e-12)
    force = tmp_path / "force.csv"
    force.write_text("time [s],force [kN]\n0,0\n0.001,1\n0.002,0\n")
    f = read_record(force)
    assert f.kind == "force" and list(f.values) == [0.0, 1000.0, 0.0]


@pytest.mark.parametrize(
    "text, why",
    [
        ("time,acceleration\n0,1\n1,2\n2,3\n", "unit in brackets"),
        ("time [s],acceleration [g]\n0,1\n2,2\n1,3\n", "increase"),
        ("time [s],acceleration [g]\n0,1\n1,2\n2.5,3\n", "equally spaced"),
        ("time [s],acceleration [g]\n1,1\n2,2\n3,3\n", "start at t = 0"),
        ("time [s],mass [kg]\n0,1\n1,2\n2,3\n", "dimension"),
        ("time [s],acceleration [g]\n0,1\n1,x\n2,3\n", "not a number"),
    ],
)
def test_a_bad_record_is_refused_naming_it(tmp_path, text, why):
    path = tmp_path / "r.csv"
    path.write_text(text)
    with pytest.raises(ParameterError, match="record") as err:
        read_record(path)
    assert why in str(err.value)


def test_shock_from_a_record_file_is_the_pulse_run(capsys, tmp_path):
    """symimpact shock --record-file with the pulse's samples gives the --base-peak run's JSON."""
    import json

    system = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "10 mm",
              "--e", "0.6", "--srs-range", "1:40", "--srs-points", "4", "--json"]  # fmt: skip
    pulse = ["--base-peak", "20 g", "--pulse", "11 ms", "--duration", "0.5 s", "--dt", "0.1 ms"]
    assert main(["shock", *system, *pulse]) == 0
    a = json.loads(capsys.readouterr().out)
    record = shock_record("half-sine", 20 * G, 0.011, 0.5, 1e-4, "base-acceleration")
    path = tmp_path / "shock.csv"
    rows = [f"{float(t)!r},{float(v)!r}" for t, v in zip(record.times, record.values, strict=True)]
    path.write_text("time [s],acceleration [m/s^2]\n" + "\n".join(rows) + "\n")
    assert main(["shock", *system, "--record-file", str(path)]) == 0
    b = json.loads(capsys.readouterr().out)
    assert b["peak"] == pytest.approx(a["peak"], rel=1e-9)
    assert [r["response"] for r in b["srs"]] == pytest.approx([r["response"] for r in a["srs"]],
                                                              rel=1e-9)  # fmt: skip
    assert main(["shock", *system, "--record-file", str(path), "--pulse", "11 ms"]) == 2
    assert "record-file:" in capsys.readouterr().err


def test_the_srs_out_of_reach_is_the_series_state_space_response():
    """d = 1 km: the SRS of the main mass's motion is the largest absolute acceleration of an
    oscillator riding on the primary, which scipy.signal.lsim gives for the two in series
    (4 states, the record held first-order between samples: exact for it), then the free
    response after the record until it has decayed (the residual response); ours interpolates
    the main mass's displacement and velocity, O(dt²) (dt = 0.1 ms: within 1e-4)."""
    record = shock_record("half-sine", 20 * G, 0.011, 0.6, 1e-4, "base-acceleration")
    freqs = np.array([2.0, 5.0, 12.0, 40.0])
    ours = shock_response(SYSTEM.with_(gap=1e3), record, e=0.6, frequencies=freqs, zeta=0.05)
    M, K, C = SYSTEM.M, SYSTEM.K, SYSTEM.C
    for f, got in zip(freqs, ours.baseline_srs, strict=True):
        w = 2 * np.pi * f
        k, c = w * w, 2 * 0.05 * w
        # states: u = primary relative to the base, u', r = oscillator relative to the primary, r'
        # ü = −a − (K u + C u')/M ; r̈ = −(ü + a) − (k r + c r') ; output r̈ + ü + a = −(k r + c r')
        A = np.array([[0, 1, 0, 0], [-K / M, -C / M, 0, 0], [0, 0, 0, 1],
                      [K / M, C / M, -k, -c]])  # fmt: skip
        B = np.array([[0], [-1], [0], [0]])
        Cm = np.array([[0, 0, -k, -c]])
        _, y, x = signal.lsim((A, B, Cm, np.zeros((1, 1))), record.values, record.times,
                              interp=True)  # fmt: skip
        # and after the record, the free response from its last state until it has decayed
        # (e^-30), by A's eigenvectors, on a grid of 400 points a period of the faster of the two
        # (a peak missed by 3e-5 of its height): the SRS holds the residual response too
        lam, V = np.linalg.eig(A)
        c = (Cm @ V)[0] * np.linalg.solve(V, x[-1])
        h, end = 1 / (400 * max(f, 5.04)), 30 / min(-lam.real)
        rest = 0.0
        for t0 in np.arange(0.0, end, 4096 * h):
            t = t0 + h * np.arange(4096)
            rest = max(rest, float(np.max(np.abs((np.exp(np.outer(t, lam)) @ c).real))))
        assert abs(got / max(np.max(np.abs(y)), rest) - 1) < 1e-4
