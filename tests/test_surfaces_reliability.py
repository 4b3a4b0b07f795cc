"""The new surfaces (loads, structure files, contact data) give no silently wrong number and lose
no file: each case here was a wrong number, a hang, a lost file or an internal error before it was
fixed (the surfaces' reliability issue).

- A PSD's unit is read by what its frequency counts, wherever the frequency stands: per rad/s is
  2π times per Hz (one rad/s is 1/2π of a cycle a second), per rpm 60 times, per deg/s 360
  times; a unit that names no angle (N² s) is refused, not read as per Hz.  The references are
  the definitions (1 rev = 2π rad, 1 Hz = one cycle a second), and the RMS of a linear primary
  under the PSD against ∫|H|²S df by quadrature.
- Two outputs of one command given one path are refused before the run (the PNG had replaced
  the CSV); an output may not replace an input.
- A structure file is read only if it is a regular file of UTF-8 text, within a size, with each
  key given once; its mass matrix must be positive definite.
- A stiff Hunt–Crossley curve, whose monodromies overflow, is drawn (it had ended in
  LinAlgError).
- The intervals of a random ensemble stay in their quantity's domain.
"""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced.orbits.continuation import _det
from symimpact.forced.orbits.shooting import condition
from symimpact.io import IN_PROGRESS, remove_in_progress, staged_folder
from symimpact.model.materials import material
from symimpact.model.structure import read_structure
from symimpact.model.units import ACCELERATION_PSD, si_float

SYS = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm"]
G = 9.80665
#: Reading a PSD multiplies the shortest decimals of the number and of the unit's factor (each
#: a double, rounded once), and the spelling's number was itself rounded once from the per-Hz
#: value: three roundings of half an ulp (1.1e-16) each, and 2π's own rounding in the factor.
ROUNDING = 1e-15


def _spellings(v: float, unit: str) -> dict[str, float]:
    """One PSD of ``v`` unit²/Hz written per each frequency unit, by the unit's definition."""
    return {
        f"{v!r} {unit}/Hz": v,
        f"{v / (2 * math.pi)!r} {unit}/(rad/s)": v,
        f"{v / (2 * math.pi)!r} {unit} s/rad": v,
        f"{v / (2 * math.pi)!r} {unit} (rad/s)^-1": v,
        f"{v / 60!r} {unit}/rpm": v,  # 1 Hz = 60 rpm: a PSD per rpm is 1/60 of it per Hz
        f"{v / 360!r} {unit}/(deg/s)": v,  # 1 Hz = 360°/s
        f"{v * 1000!r} {unit}/kHz": v,
        f"{v!r} {unit}/(cycle/s)": v,
    }


@given(st.floats(1e-6, 1e3))
def test_a_force_psd_is_the_same_in_every_spelling_of_its_frequency(v):
    for text, expected in _spellings(v, "N^2").items():
        assert si_float("force-psd", text, "N^2/Hz") == pytest.approx(expected, rel=ROUNDING), text


@given(st.floats(1e-6, 10.0))
def test_an_acceleration_psd_is_the_same_in_every_spelling_of_its_frequency(v):
    for text, expected in _spellings(v, "g^2").items():
        got = si_float("base-psd", text, ACCELERATION_PSD)
        assert got == pytest.approx(expected * G**2, rel=ROUNDING), text
    for text, expected in _spellings(v, "(m/s^2)^2").items():
        got = si_float("base-psd", text, ACCELERATION_PSD)
        assert got == pytest.approx(expected, rel=ROUNDING), text


@pytest.mark.parametrize("text", ["0.02 N^2 s", "0.02 N^2/(1/s)", "0.02 N^2 min"])
def test_a_psd_whose_unit_names_no_frequency_is_refused(text):
    with pytest.raises(ParameterError, match="per hertz and per rad/s differ by 2π"):
        si_float("force-psd", text, "N^2/Hz")


def test_a_frequency_still_refuses_a_rate_without_an_angle():
    with pytest.raises(ParameterError, match="names no angle"):
        si_float("omega", "3 min^-1", "rad/s")


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def _linear_rms(s0: float, band: tuple[float, float]) -> float:
    """√∫|H(2πf)|²S df of M = 1, K = 1000, C = 0.5 under a flat force PSD s0 [N²/Hz]."""
    from scipy import integrate

    def h2(f):
        w = 2 * np.pi * f
        return 1.0 / ((1000.0 - w * w) ** 2 + (0.5 * w) ** 2)

    fn = np.sqrt(1000.0) / (2 * np.pi)
    return math.sqrt(
        integrate.quad(lambda f: s0 * h2(f), *band, points=[fn], limit=400, epsrel=1e-10)[0]
    )


def test_random_reads_a_psd_per_rad_s_as_2_pi_times_per_hz(capsys, tmp_path):
    """The same load per Hz, per rad/s and in a table per rad/s: the same RMS, and out of the
    damper's reach that RMS is ∫|H|²S df with S per Hz = 2π·S per rad/s (the reading as per Hz
    was √(2π) = 2.5 times too small: far outside the realisations' spread)."""
    per_rad = 0.01
    common = [*SYS[:8], "--gap", "1 km", "--e", "0.6", "--band", "0.2 Hz:50 Hz",
              "--duration", "100 s", "--realisations", "8", "--seed", "3", "--json"]  # fmt: skip
    a = _json(capsys, ["random", *common, "--force-psd", f"{per_rad} N^2/(rad/s)"])
    b = _json(capsys, ["random", *common, "--force-psd", f"{2 * math.pi * per_rad!r} N^2/Hz"])
    table = tmp_path / "psd.csv"
    table.write_text(f"frequency [Hz],psd [N^2/(rad/s)]\n0.1,{per_rad}\n60,{per_rad}\n")
    c = _json(capsys, ["random", *common, "--psd-file", str(table)])
    for key in ("displacement", "velocity"):
        assert a["rms"][key] == pytest.approx(b["rms"][key], rel=1e-12)
        assert a["rms"][key] == pytest.approx(c["rms"][key], rel=1e-12)
    expected = _linear_rms(2 * math.pi * per_rad, (0.2, 50.0))
    spread = 3.5 * a["rms_spread"]["displacement"] if "rms_spread" in a else 0.15 * expected
    assert abs(a["rms"]["displacement"] - expected) < spread


def test_random_refuses_a_psd_per_second(capsys):
    argv = ["random", *SYS, "--e", "0.6", "--band", "1:40", "--force-psd", "0.02 N^2 s"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "force-psd" in err and "2π" in err


SIM = [*SYS, "--force", "2 N", "--omega", "34", "--contact", "rigid", "--e", "0.6",
       "--periods", "3"]  # fmt: skip


def test_two_outputs_to_one_path_are_refused_before_the_run(capsys, tmp_path):
    out = tmp_path / "out.csv"
    out.write_text("kept\n")
    assert main(["simulate", *SIM, "--csv", str(out), "--plot", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "give each output its own path" in err
    assert out.read_text() == "kept\n"
    link = tmp_path / "link.csv"
    link.symlink_to(out)
    assert main(["simulate", *SIM, "--csv", str(link), "--plot", str(out)]) == 2
    assert out.read_text() == "kept\n"


def test_an_output_may_not_replace_an_input(capsys, tmp_path):
    table = tmp_path / "psd.csv"
    table.write_text("frequency [Hz],psd [N^2/Hz]\n0.1,0.02\n60,0.02\n")
    argv = ["random", *SYS, "--e", "0.6", "--band", "1:40", "--psd-file", str(table),
            "--csv", str(table)]  # fmt: skip
    assert main(argv) == 2
    assert "replace the input" in capsys.readouterr().err
    assert table.read_text().startswith("frequency [Hz]")


def _refused(capsys, path, *words):
    t0 = time.monotonic()
    assert main(["modes", "--structure", str(path)]) == 2
    assert time.monotonic() - t0 < 1.0  # refused before reading, not after a timeout
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    for w in words:
        assert w in err, err


def test_a_structure_file_that_is_no_text_file_is_refused_within_a_second(capsys, tmp_path):
    binary = tmp_path / "bin.json"
    binary.write_bytes(bytes(range(256)) * 8)
    _refused(capsys, binary, "structure", "not UTF-8 text")
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    _refused(capsys, fifo, "structure", "not a regular file")
    zero = tmp_path / "zero.json"
    zero.symlink_to("/dev/zero")
    _refused(capsys, zero, "structure", "not a regular file")
    _refused(capsys, tmp_path, "structure", "folder")
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000)
    _refused(capsys, deep, "structure", "too deeply")


def test_a_key_given_twice_is_refused_naming_it_and_its_line(capsys, tmp_path):
    twice = tmp_path / "twice.json"
    twice.write_text(
        '{"modes": [{"f": "10 Hz", "mass": "1 kg", "zeta": 0.01,\n'
        '            "shape": {"tip": 1}, "zeta": 0.02}]}\n'
    )
    _refused(capsys, twice, "'zeta' twice", "line 2")
    toml = tmp_path / "twice.toml"
    toml.write_text('[[modes]]\nf = "10 Hz"\nmass = "1 kg"\nf = "12 Hz"\n')
    _refused(capsys, toml, "structure", "line 4")


def test_a_singular_mass_matrix_is_refused_with_its_condition(capsys, tmp_path):
    singular = tmp_path / "singular.json"
    singular.write_text('{"fe": {"M": [[1, 0], [0, 0]], "K": [[2, -1], [-1, 1]], "zeta": 0.01}}')
    _refused(capsys, singular, "M:", "not positive definite", "condition infinite")
    ill = tmp_path / "ill.json"
    ill.write_text('{"fe": {"M": [[1, 0], [0, 1e-15]], "K": [[2, -1], [-1, 1]], "zeta": 0.01}}')
    _refused(capsys, ill, "M:", "condition 1e+15")
    ok = tmp_path / "ok.json"
    ok.write_text('{"fe": {"M": [[1, 0], [0, 1]], "K": [[2, -1], [-1, 1]], "zeta": 0.01}}')
    s = read_structure(ok)
    # ω² of [[2, −1], [−1, 1]] with M = I: (3 ∓ √5)/2
    assert [m.omega**2 for m in s.modes] == pytest.approx([(3 - 5**0.5) / 2, (3 + 5**0.5) / 2])


@pytest.mark.parametrize("value", [None, 123, b"x.json", 1.5])
def test_read_structure_refuses_what_is_no_path(value):
    with pytest.raises(ParameterError, match="structure: expected a file path"):
        read_structure(value)


def test_a_material_property_given_twice_is_refused():
    with pytest.raises(ParameterError, match="material E: given twice"):
        material("E 200 GPa, nu 0.3, rho 7800 kg/m^3, E 100 GPa")


def test_an_overflowed_jacobian_reads_as_no_accuracy_not_an_error():
    """A stiff contact's Jacobian (k_hz 1e9 N/m^1.5) can hold NaN where its differences
    overflowed: NumPy's condition number raised "SVD did not converge" into the curve; its
    determinant overflowed with a warning.  Both now read as infinite, with their sign."""
    assert condition(np.array([[np.nan, 1.0], [1.0, 1.0]])) == math.inf
    assert condition(np.array([[1e300, 0.0], [0.0, 1e-300]])) == math.inf
    assert condition(np.diag([4.0, 2.0])) == pytest.approx(2.0, rel=1e-15)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no overflow warning reaches the user
        assert _det(np.diag([1e200, 1e200, -1.0, 1.0])) == -math.inf
        assert _det(np.diag([1e200, 1e200, 1.0, 1.0])) == math.inf
    assert _det(np.diag([2.0, 3.0, -1.0, 1.0])) == pytest.approx(-6.0, rel=1e-15)


@pytest.mark.slow
def test_a_stiff_hunt_crossley_curve_is_drawn(capsys, monkeypatch):
    """k_hz 1e9 N/m^1.5 over 26–40 rad/s, the case as reported: drawn, not an internal error,
    through monodromies whose determinant overflows (counted here: the test fails if the curve
    no longer reaches one).  Every 2 rad/s, without the multi-start, in this process: 29 s of
    one core, 59 stable points, 4 overflowed determinants (the reported 0.5 rad/s step took
    300 s of CI's slow set for the same paths; it adds the 110 mm branch near 31 rad/s, which
    a 2 rad/s step does not resolve)."""
    from symimpact.forced.orbits import continuation

    overflowed = []

    def det(A):
        d = _det(A)
        overflowed.extend([d] if math.isinf(d) else [])
        return d

    monkeypatch.setattr(continuation, "_det", det)
    out = _json(capsys, ["frf", *SYS, "--force", "2 N", "--contact", "hunt-crossley",
                         "--k-hz", "1e9", "--chi", "0.5", "--omega-range", "26:40:2",
                         "--multistart", "0", "--workers", "1", "--json"])  # fmt: skip
    stable = [p for p in out["points"] if p["stable"]]
    assert len(stable) > 20
    assert all(math.isfinite(p["amplitude"]) for p in out["points"])
    assert out["peak"]["amplitude"] > 0.02  # the impacting orbits reach beyond the gap's 10 mm
    assert overflowed, "no monodromy's determinant overflowed: the case no longer reaches it"


def test_a_signal_handler_removes_what_is_half_written(tmp_path):
    """``os._exit`` runs no ``finally``: the handler removes the staged folder itself."""
    with staged_folder(tmp_path / "report") as tmp:
        (tmp / "index.html").write_text("half")
        assert str(tmp) in IN_PROGRESS
        remove_in_progress()
        assert not tmp.exists()
        tmp.mkdir()  # for the context's own ending
    assert not IN_PROGRESS


@pytest.mark.slow
def test_reproduce_ended_by_sigterm_leaves_no_partial_folder(tmp_path):
    code = "import sys; from symimpact.cli import main; sys.exit(main())"
    p = subprocess.Popen([sys.executable, "-c", code, "reproduce", "report", "--quick"],
                         cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True)  # fmt: skip
    deadline = time.monotonic() + 300
    while not list(tmp_path.glob(".report.partial-*")) and p.poll() is None:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    assert p.poll() is None, "the report was done before its folder could be seen"
    time.sleep(0.5)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=30)
    assert p.returncode == 143 and err.strip().endswith("ended by signal 15")
    assert not [q.name for q in Path(tmp_path).iterdir()]


#: The SI unit each option of the documentation's table is read in.
_DOC_UNITS = {"--omega": "rad/s", "--freq": "Hz", "--force-psd": "N^2/Hz",
              "--base-psd": ACCELERATION_PSD, "--base-acc": "m/s^2", "--gap": "m",
              "--k-hz": "N/m^1.5", "--a": "N/m^3"}  # fmt: skip


def test_the_documented_spellings_are_what_the_package_reads():
    """docs/units.md's table: each spelling, read by the package, gives the SI value printed."""
    text = (Path(__file__).parents[1] / "docs" / "units.md").read_text(encoding="utf-8")
    rows = [line.split("|")[1:4] for line in text.splitlines() if line.startswith("| `--")]
    assert len(rows) >= 15
    for option, spelling, value in rows:
        option, spelling = option.strip(" `"), spelling.strip(" `")
        printed = float(value.split()[0])
        got = si_float(option.lstrip("-"), spelling, _DOC_UNITS[option])
        assert got == pytest.approx(printed, rel=ROUNDING), (option, spelling)


def test_random_intervals_stay_in_their_domain():
    """Two realisations: Student's t with one degree of freedom is 12.7 standard errors, and the
    ordinary interval of the RMS reached below zero; the interval by logarithms stays positive,
    holds the mean, and a warning names the few realisations.  With many it is the ordinary
    interval to first order in its relative half-width h: the bounds differ at second order
    (e^(±h) against 1 ± h, the logarithms' spread against the coefficient of variation), so
    within 3h² (h is 10–17 % here under seeds 1–5, and the
    measured differences 0.05–1.4 h²)."""
    from symimpact.forced.loads.random_response import random_statistics
    from symimpact.model.system import ImpactSystem

    system = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
    with pytest.warns(UserWarning, match="2 realisations"):
        few = random_statistics(system, 0.02, (0.2, 50.0), 5.0, 0.002, e=0.6, realisations=2,
                                seed=1, kind="force")  # fmt: skip
    for key, (lo, hi) in few.rms_ci95.items():
        assert 0.0 < lo <= few.rms[key] <= hi, key
    for key, (lo, hi) in few.reduction_ci95.items():
        assert lo <= few.reduction[key] <= hi < 1.0, key
    many = random_statistics(system, 0.02, (0.2, 50.0), 100.0, 0.002, e=0.6, realisations=12,
                             seed=1, kind="force")  # fmt: skip
    values = many.per_realisation["displacement"]
    from scipy import stats

    half = stats.t.ppf(0.975, 11) * np.std(values, ddof=1) / math.sqrt(12)
    lo, hi = many.rms_ci95["displacement"]
    h = half / np.mean(values)
    assert lo == pytest.approx(np.mean(values) - half, rel=3 * h * h)
    assert hi == pytest.approx(np.mean(values) + half, rel=3 * h * h)


def _srs_reference(fp, zp, peak, td, f, z):
    """The SRS at f [Hz] (damping z) of a primary of natural frequency fp [Hz], damping zp, under
    a half-sine base acceleration of ``peak`` [m/s²] lasting td [s], by DOP853 on the primary and
    the oscillator together (relative coordinates x and r = W − y), run until both have decayed
    (to e^-25), the absolute acceleration −ω²r − 2ζωr' read from the dense output on a grid of
    400 points a period of the faster one (a peak missed by (2π/400)²/8 = 3e-5 of its height)."""
    from scipy.integrate import solve_ivp

    wp, w = 2 * np.pi * fp, 2 * np.pi * f

    def a_b(t):
        return peak * np.sin(np.pi * t / td) if t < td else 0.0

    def rhs(t, s):
        x, v, r, rd = s
        acc_rel = -2 * zp * wp * v - wp * wp * x - a_b(t)
        return [v, acc_rel, rd, -2 * z * w * rd - w * w * r - (acc_rel + a_b(t))]

    T = td + 25 / min(zp * wp, z * w)
    best, start = 0.0, np.zeros(4)
    for t0, t1 in ((0.0, td), (td, T)):  # the kink at td: two pieces
        sol = solve_ivp(rhs, (t0, t1), start, method="DOP853", rtol=1e-12, atol=1e-15,
                        dense_output=True)  # fmt: skip
        start = sol.y[:, -1]
        t = np.arange(t0, t1, 1 / (400 * max(f, fp)))
        r, rd = sol.sol(t)[2:]
        best = max(best, float(np.max(np.abs(w * w * r + 2 * z * w * rd))))
    return best


def test_the_srs_holds_the_residual_response_of_a_shock():
    """A stiff primary (50 Hz, ζ 2 %) under a 20 g, 11 ms half-sine, the damper out of reach: the
    SRS (ζ 5 %) at 5–500 Hz against DOP853 on the primary and the oscillator, run until both
    decay.  With the residual in closed form, a record of the pulse alone gives the same SRS as
    the pulse followed by 1 s of rest (at 5 Hz the maximax over the pulse alone had been 71 %
    low).  Bound 2e-4: the peaks read at the samples (dt = td/2000: (2πf·dt)²/8 ≤ 4e-5 at
    500 Hz), the residual's grid (7.5e-5) and the reference's (3e-5)."""
    from symimpact.forced.loads.records import followed_by_rest, shock_record
    from symimpact.forced.loads.shock_response import shock_response
    from symimpact.model.system import ImpactSystem

    fp, zp, td, peak = 50.0, 0.02, 0.011, 20 * G
    K = (2 * np.pi * fp) ** 2
    system = ImpactSystem(M=1.0, K=K, C=2 * zp * np.sqrt(K), m=0.05, gap=1e3, contact="linear",
                          k1=1e6)  # fmt: skip
    freqs = [5.0, 12.6, 50.0, 200.0, 500.0]
    pulse = shock_record("half-sine", peak, td, td, td / 2000, "base-acceleration")
    short = shock_response(system, pulse, e=0.6, frequencies=freqs)
    long = shock_response(system, followed_by_rest(pulse, 0.2), e=0.6, frequencies=freqs)
    for f, a, b in zip(freqs, short.baseline_srs, long.baseline_srs, strict=True):
        want = _srs_reference(fp, zp, peak, td, f, 0.05)
        assert a == pytest.approx(want, rel=2e-4), f
        assert b == pytest.approx(want, rel=2e-4), f
    assert short.baseline_srs == pytest.approx(short.srs, rel=1e-12)  # out of reach


def test_a_recorded_shock_is_followed_by_its_free_vibration(capsys, tmp_path):
    """The same 20 g, 11 ms half-sine as a pulse and as a record sampled over 50 ms: the record
    is followed by rest as the pulse is, so both give one peak (to the difference of their
    samplings, 1e-4 s against td/200)."""
    t = np.arange(0, 0.05 + 1e-12, 1e-4)
    a = np.where(t <= 0.011 + 1e-12, 20 * np.sin(np.pi * np.clip(t / 0.011, 0, 1)), 0.0)
    record = tmp_path / "shock.csv"
    record.write_text("time [s],acceleration [g]\n"
                      + "".join(f"{x:.6f},{float(y)!r}\n" for x, y in zip(t, a, strict=True)))  # fmt: skip
    common = [*SYS, "--contact", "rigid", "--e", "0.6", "--json"]
    rec = _json(capsys, ["shock", *common, "--record-file", str(record)])
    pul = _json(capsys, ["shock", *common, "--base-peak", "20 g", "--pulse", "11 ms"])
    assert rec["baseline_peak"] == pytest.approx(pul["baseline_peak"], rel=1e-3)
    longer = _json(capsys, ["shock", *common, "--record-file", str(record), "--duration", "3 s"])
    assert longer["baseline_peak"] == pytest.approx(rec["baseline_peak"], rel=1e-12)
    assert main(["shock", *common, "--record-file", str(record), "--duration", "10 ms"]) == 2
    assert main(["shock", *common, "--base-peak", "20 g", "--pulse", "11 ms",
                 "--srs-range", "0:100"]) == 2  # fmt: skip


def test_a_sweep_at_the_default_sampling_has_the_exact_chirps_peak():
    """A force sweep 4 → 6.5 Hz at 0.02 Hz/s through the 5.03 Hz primary (ζ 0.8 %), sampled 20
    times a period at the band's top (the command's default): the envelope's peak against DOP853
    on the exact chirp F0 sin(2π(f₀t + rt²/2)), no sampling (rtol 1e-11, the peak read on 400
    points a period: 3e-5).  The straight lines between samples had lost (πf·dt)²/3 = 0.5 % at
    the resonance and the samples alone missed up to 0.7 % of a period's peak; now 1e-4."""
    from scipy.integrate import solve_ivp

    from symimpact.forced.loads.sweep_response import sweep_response
    from symimpact.model.system import ImpactSystem

    system = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=1e3, contact="linear", k1=1e6)
    f0, f1, rate, F0 = 4.0, 6.5, 0.02, 2.0
    dt = 1.0 / (20 * f1)
    got = sweep_response(system, F0, f0, f1, rate, dt, e=0.6)
    peak = float(np.max(got.up["baseline"]))

    def rhs(t, s):
        force = F0 * np.sin(2 * np.pi * (f0 * t + 0.5 * rate * t * t))
        return [s[1], (force - 0.5 * s[1] - 1000.0 * s[0])]

    T = (f1 - f0) / rate
    sol = solve_ivp(rhs, (0, T), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14,
                    dense_output=True)  # fmt: skip
    t = np.arange(0, T, 1 / (400 * f1))
    want = float(np.max(np.abs(sol.sol(t)[0])))
    assert peak == pytest.approx(want, rel=1e-4)


def test_hertz_far_outside_its_validity_is_warned_of_and_absurd_speeds_refused(capsys):
    """A 20 mm steel ball on a steel flat: at 1 m/s √(Rδ)/R is 0.049 and the speed 34 times first
    yield (0.0295 m/s), within both
    bounds; at 500 m/s the contact radius is 0.59 of R and the speed 1.7e4 times first yield:
    two warnings; at 3e8 m/s Hertz's penetration (144 m) exceeds the radius: refused."""
    common = ["contact", "--impactor", "steel sphere 20 mm", "--cavity", "steel flat"]
    assert main([*common, "--v0", "1 m/s"]) == 0
    out = capsys.readouterr()
    assert "warning" not in out.err
    assert "AISI 1045" in out.out and "yield strength 530 MPa" in out.out
    assert "'bearing steel' (52100)" in out.out  # what a designer of hardened balls should say
    assert main([*common, "--v0", "500 m/s"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 2 and "0.59 of R" in err[0] and "1.7e+04 times" in err[1]
    assert main([*common, "--v0", "3e8 m/s"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "v0:" in err and "beyond the 10 mm radius" in err


@pytest.mark.parametrize(
    ("name", "grade"),
    [("52100", "AISI 52100"), ("440C", "AISI 440C"), ("mild steel", "AISI 1018"),
     ("carbide", "WC–6 % Co"), ("nylon", "PA 66"), ("steel", "AISI 1045")],
)  # fmt: skip
def test_the_grades_a_designer_buys_are_named(name, grade):
    assert grade in material(name).grade


@pytest.mark.parametrize(
    ("rate", "why"),
    [("1e6", "a sweep needs at least 4"), ("1e-9", "more than 50,000,000")],
)
def test_a_sweep_too_fast_or_too_slow_is_refused_before_it_allocates(capsys, rate, why):
    """1e6 Hz/s had met an empty envelope (internal error); 1e-9 Hz/s had asked for 2.4 TiB."""
    t0 = time.monotonic()
    argv = ["sweep-sine", *SYS, "--e", "0.6", "--force-amplitude", "2 N", "--band", "4:6.5",
            "--rate", rate]  # fmt: skip
    assert main(argv) == 2
    assert time.monotonic() - t0 < 1.0
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "rate:" in err and why in err


def test_coverage_claims_the_lower_of_its_two_samples():
    """The share a curve prints is the lower of the grid's and the random check's: a check that
    finds one periodic attractor in two off the branches makes the share 0.5, whatever the
    grid's; the JSON states the frequencies, the starts and the check's seed."""
    from symimpact.forced.orbits.coverage import CHECK_SEED, Attractor, Coverage, check_frequencies

    def periodic(w):
        return Attractor(w, 0.01, "periodic", 1, 2.0, (0.0, 0.0, 0.0, 0.0), True)

    grid = Coverage([periodic(30.0), periodic(31.0)], [True, True], (30.0, 31.0))
    assert grid.share == 1.0
    grid.check, grid.seed = Coverage([periodic(30.4), periodic(30.7)], [True, False],
                                     (30.4, 30.7)), CHECK_SEED  # fmt: skip
    assert grid.share == 0.5 and grid.grid_share == 1.0
    out = grid.as_dict()
    assert out["share"] == 0.5 and out["grid_share"] == 1.0 and out["starts"] == 4
    assert out["check"]["seed"] == CHECK_SEED and out["check"]["frequencies"] == [30.4, 30.7]
    assert [a["omega"] for a in out["check"]["missed"]] == [30.7]
    ws = check_frequencies((25.0, 40.0))
    assert np.all((ws > 25.0) & (ws < 40.0)) and np.all(np.diff(ws) > 0)
    assert np.array_equal(ws, check_frequencies((25.0, 40.0)))  # seeded: the same each time


def test_an_srs_of_no_frequency_is_refused():
    from symimpact.forced.loads.record_flight import srs
    from symimpact.forced.loads.records import shock_record

    record = shock_record("half-sine", 1.0, 0.01, 0.1, 1e-4, "base-acceleration")
    with pytest.raises(ParameterError, match="frequencies: give at least one"):
        srs(record, [])


def test_the_residual_of_an_undamped_primary_ends():
    """C = 0: the primary's free vibration never decays, and the residual's reading had no end
    (shock --C 0 hung); it reads RESIDUAL_PERIODS of the slowest term, and the SRS holds at
    least the run's own maximax."""
    from symimpact.forced.loads.records import shock_record
    from symimpact.forced.loads.shock_response import shock_response
    from symimpact.model.system import ImpactSystem

    system = ImpactSystem(M=1.0, K=1000.0, C=0.0, m=0.05, gap=1e3, contact="linear", k1=1e6)
    pulse = shock_record("half-sine", 20 * G, 0.011, 0.011, 0.011 / 200, "base-acceleration")
    t0 = time.monotonic()
    out = shock_response(system, pulse, e=0.6, frequencies=[2.0, 5.0, 50.0])
    assert time.monotonic() - t0 < 30.0
    assert np.all(np.isfinite(out.baseline_srs)) and np.all(out.baseline_srs > 0)


def test_a_line_break_in_a_files_key_stays_in_the_refusals_one_line(tmp_path, capsys):
    """Found by the structure-file fuzz (tests/test_surfaces_fuzz.py): an unknown key "\\n" was
    named as it is, and the refusal took two lines.  Line breaks are written as escapes."""
    from symimpact.model.structure import read_structure

    path = tmp_path / "s.json"
    path.write_text(json.dumps({"beam": None, "\n": None, "a\u2028b": 1}))
    with pytest.raises(ParameterError) as caught:
        read_structure(path)
    assert str(caught.value).splitlines() == [str(caught.value)]
    assert str(caught.value).startswith("\\n: is not a field of a structure file")
