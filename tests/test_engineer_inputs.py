"""The primary as an engineer gives it (issue 35, items 1 and 4): --fn with the modal mass or
the stiffness, and no trap in the clearance's wording or in options a command ignores."""

from __future__ import annotations

import json
import math

import pytest

from symimpact.cli import build_parser, main
from symimpact.cli.common import apply_engineer_inputs


def _ns(argv):
    ns = build_parser().parse_args(argv)
    return ns, ns.__dict__.pop("_options_given", set())


def test_fn_with_the_modal_mass_gives_k():
    # K = M(2πf)²: 1 kg at 1 Hz is 4π² N/m; the 40 kg at 12 Hz is 227 396 N/m, given
    # to the unit (so to half a unit)
    for argv, K, rel in ((["--M", "1 kg", "--fn", "1 Hz"], 4 * math.pi**2, 1e-15),
                         (["--M", "40", "--fn", "12"], 227396, 0.5 / 227396)):  # fmt: skip
        ns, given = _ns(["simulate", *argv])
        apply_engineer_inputs(ns, given)
        assert float(ns.K) == pytest.approx(K, rel=rel)


def test_fn_with_the_stiffness_gives_m_and_other_frequency_units():
    ns, given = _ns(["simulate", "--K", "1000", "--fn", f"{math.sqrt(1000):.17g} rad/s"])
    apply_engineer_inputs(ns, given)
    assert float(ns.M) == pytest.approx(1.0, rel=1e-14)
    ns, given = _ns(["simulate", "--M", "2", "--fn", "720 rpm"])  # 12 Hz
    apply_engineer_inputs(ns, given)
    assert float(ns.K) == pytest.approx(2 * (2 * math.pi * 12) ** 2, rel=1e-14)


def test_fn_runs_the_same_as_k(capsys):
    common = ["periodic", "--M", "40", "--zeta", "0.01", "--m", "2", "--gap", "10 mm", "--force",
              "50", "--freq", "12", "--contact", "rigid", "--e", "0.6", "--json"]  # fmt: skip
    assert main([*common, "--fn", "12"]) == 0
    by_fn = json.loads(capsys.readouterr().out)
    K = 40 * (2 * math.pi * 12) ** 2
    assert main([*common, "--K", repr(K)]) == 0
    assert json.loads(capsys.readouterr().out) == by_fn


def test_damping_as_q_or_loss_factor_is_the_damping_ratio_a_textbook_gives():
    """Q = 50 and η = 0.02 are ζ = 0.01 (ζ = 1/(2Q) = η/2), so the same run as --zeta 0.01; and
    Q read back as a test engineer measures it, f_n over the half-power bandwidth of the primary
    alone's |H(f)| = 1/|K − M(2πf)² + iC·2πf| found by bisection, is 50 to O(ζ²) (the
    half-power points of a viscous oscillator are f_n·√(1 − 2ζ² ± 2ζ√(1 − ζ²)): their distance
    is 2ζf_n to within ζ²·f_n)."""
    from scipy.optimize import brentq, minimize_scalar

    base = ["simulate", "--M", "40", "--fn", "12 Hz", "--m", "2"]
    runs = {}
    for damping in (["--zeta", "0.01"], ["--q-factor", "50"], ["--loss-factor", "0.02"]):
        ns, given = _ns([*base, *damping])
        apply_engineer_inputs(ns, given)
        runs[damping[0]] = ns.zeta if damping[0] != "--zeta" else float(ns.zeta)
    assert runs["--q-factor"] == runs["--loss-factor"] == runs["--zeta"] == 0.01
    M, wn, zeta = 40.0, 2 * math.pi * 12.0, runs["--q-factor"]
    K, C = M * wn**2, 2 * zeta * M * wn

    def gain(f):
        w = 2 * math.pi * f
        return 1.0 / abs(complex(K - M * w * w, C * w))

    top = minimize_scalar(lambda f: -gain(f), bounds=(11.0, 13.0), method="bounded",
                          options={"xatol": 1e-12})  # fmt: skip
    level = gain(top.x) / math.sqrt(2.0)
    f1 = brentq(lambda f: gain(f) - level, 10.0, top.x, xtol=1e-13)
    f2 = brentq(lambda f: gain(f) - level, top.x, 14.0, xtol=1e-13)
    assert 12.0 / (f2 - f1) == pytest.approx(50.0, rel=2 * zeta**2)


@pytest.mark.parametrize("extra, parameter", [
    (["--zeta", "0.01", "--q-factor", "50"], "q-factor"),
    (["--C", "1", "--loss-factor", "0.02"], "loss-factor"),
    (["--q-factor", "0"], "q-factor"),
    (["--loss-factor", "-0.1"], "loss-factor"),
    (["--q-factor", "50 Hz"], "q-factor"),
])  # fmt: skip
def test_damping_given_twice_or_out_of_range_is_refused(extra, parameter, capsys):
    argv = ["simulate", "--M", "40", "--fn", "12 Hz", "--m", "2", "--contact", "rigid", "--e",
            "0.6", "--force", "50 N", "--freq", "12 Hz", *extra]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and f"error: {parameter}:" in err, err


def test_a_sine_quoted_as_rms_or_peak_to_peak_is_its_amplitude(capsys):
    """ "35.3553 N rms" is F0 = 50 N (√2·rms: a sine's RMS is its amplitude over √2); "2 mm pk-pk"
    is X_b = 1 mm; "0.5 g rms" is A_b = 0.5·√2·9.80665 m/s²; "50 N peak" is 50 N; each
    conversion stated on stderr; a level that cannot be read names its option."""
    cases = [
        (["--force", "35.35533905932738 N rms"], "F0", 50.0, 1e-15),
        (["--force", "50 N peak"], "F0", 50.0, 0.0),
        (["--base", "2 mm pk-pk"], "X_b", 0.001, 1e-15),
        (["--base-acc", "0.5 g RMS"], "A_b", 0.5 * math.sqrt(2) * 9.80665, 1e-15),
        (["--base-vel", "20 mm/s peak-to-peak"], "V_b", 0.01, 1e-15),
    ]
    for extra, key, value, rel in cases:
        ns, given = _ns(["frf", "--M", "40", "--fn", "12", "--m", "2", *extra])
        apply_engineer_inputs(ns, given)
        assert getattr(ns, key) == pytest.approx(value, rel=rel, abs=0), extra
    assert "is the amplitude 50 N of the sine" in capsys.readouterr().err
    argv = ["simulate", "--M", "40", "--fn", "12 Hz", "--zeta", "0.01", "--m", "2", "--gap",
            "9 mm", "--contact", "rigid", "--e", "0.6", "--freq", "12 Hz", "--periods", "20"]  # fmt: skip
    assert main([*argv, "--force", "2 kg rms"]) == 2
    assert "error: force:" in capsys.readouterr().err


DESIGN_WITH_GAP = ["design", "--gap", "5 mm", "--gaps", "1 mm,2 mm", "--force", "1", "--contact",
                   "rigid", "--e", "0.5", "--omega-range", "1:2:1"]  # fmt: skip


@pytest.mark.parametrize(
    ("argv", "parameter"),
    [
        (["simulate", "--fn", "12"], "fn"),
        (["simulate", "--fn", "12", "--M", "1", "--K", "10"], "fn"),
        (["simulate", "--fn", "-12", "--M", "1"], "fn"),
        (["simulate", "--fn", "12 m", "--M", "1"], "fn"),
        (DESIGN_WITH_GAP, "gap"),
        (["contact-duration", "--gap", "5 mm"], "gap"),
    ],
)
def test_refusals_name_the_option(argv, parameter, capsys):
    assert main(argv) == 2
    assert f"error: {parameter}:" in capsys.readouterr().err


def test_the_clearance_is_the_total_free_play_in_help():
    text = build_parser()._subparsers._group_actions[0].choices["simulate"].format_help()
    assert "total clearance d" in " ".join(text.split()) and "d/2" in text


PERIODIC = ["periodic", "--M", "40", "--fn", "12", "--zeta", "0.01", "--m", "2", "--gap", "10 mm",
            "--force", "50", "--contact", "rigid", "--e", "0.6"]  # fmt: skip


@pytest.mark.parametrize(
    ("frequency", "shown"),
    [
        (["--freq", "12"], "Ω 12 Hz:"),  # given in Hz: shown in Hz
        (["--omega", "75.39822368615503"], "Ω 75.3982 rad/s:"),
        (["--omega", "75.39822368615503", "--show", "omega=Hz"], "Ω 12 Hz:"),
        (["--freq", "12", "--show", "omega=rpm"], "Ω 720 rpm:"),
    ],
)
def test_frequencies_come_back_in_the_users_unit(frequency, shown, capsys):
    assert main([*PERIODIC, *frequency]) == 0
    assert capsys.readouterr().out.startswith(shown)


def test_frf_text_in_hz_and_json_in_si(capsys):
    argv = [a if a != "periodic" else "frf" for a in PERIODIC] + [
        "--freq-range", "11.5:12.5:0.25", "--no-sweeps"]  # fmt: skip
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert text.startswith("peak with the damper:")  # the answer first (issue 80)
    assert "\nΩ 11.5–12.5 Hz:" in text and "rad/s" not in text.split("note:")[0]
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    omegas = [p["omega"] for p in data["points"]]
    assert min(omegas) == pytest.approx(2 * math.pi * 11.5, rel=0.01)  # SI: rad/s


def test_design_csv_headers_carry_units():
    from symimpact.model.display import csv_header

    for name, unit in (("peak_amplitude", "m"), ("peak_omega", "rad/s"), ("baseline_peak", "m"),
                       ("baseline_omega", "rad/s"), ("gap", "m")):  # fmt: skip
        assert csv_header(name) == f"{name} [{unit}]"


def test_map_value_takes_the_tables_names(tmp_path, capsys):
    argv = ["map", "--vary", "gap=6 mm:9 mm:3 mm", "--vary", "m=0.2,0.25", "--t-end", "10",
            "--workers", "1", "--quiet", "--plot", str(tmp_path / "heat.png")]  # fmt: skip
    assert main([*argv, "--value", "DI"]) == 0
    by_table_name = capsys.readouterr().out
    assert main([*argv, "--value", "damping_inclination"]) == 0
    by_output_name = capsys.readouterr().out
    best = [line for line in by_output_name.splitlines() if line.startswith("wrote")]
    assert best and best[0].replace("damping_inclination", "DI") in by_table_name


def test_the_command_line_starts_without_the_forced_package():
    # a signal in the first ~0.3 s meets Python's default handler (tests/test_signals.py): the
    # parser must not import the forced package and SciPy's optimisers (0.4 s) to build itself;
    # each command imports what it runs
    import subprocess
    import sys

    # nor NumPy, numba, pint, the maps or the generated kernels: `symimpact --version` and
    # `--help` had taken 0.97 s, now 0.1 s (the engine issue's goal: 0.2 s)
    code = ("import sys; from symimpact.cli import build_parser; build_parser(); "
            "heavy = [m for m in ('symimpact.forced', 'scipy.optimize', 'symimpact.maps.design', "
            "'numpy', 'numba', 'pint', 'symimpact.maps.engine', 'symimpact.generated.ritz') "
            "if m in sys.modules]; print(heavy); sys.exit(1 if heavy else 0)")  # fmt: skip
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr


def test_a_sweep_shows_the_primary_alone_beside_its_rows(capsys):
    """Issue 35 item 5: the sweep's table ends with DI and ζ_eq of the primary alone from the same
    start.  Against the closed-form decay x = (v₀/ω_d)·e^(−ζωₙt)·sin(ω_d t) of the default system
    (M 1 kg, K 100 N/m, C 1 N s/m, ẋ₀ 0.5 m/s): its positive maxima lie where
    tan(ω_d t) = ω_d/(ζωₙ), one damped period apart; DI is the least-squares slope through the
    first four against ωₙt (1e-9: the peak finder's located maxima), and ζ_eq is ζ (1e-12)."""
    import numpy as np

    assert main(["sweep", "--gap", "6 mm:8 mm:2 mm", "--quiet"]) == 0
    text = capsys.readouterr().out
    lines = text.splitlines()
    line = lines[next(i for i, s in enumerate(lines) if s.startswith("without the damper")) + 1]
    di_um = float(line.split("DI ")[1].split(" µm")[0])
    zeta_eq = float(line.split("ζ_eq ")[1].split(" ")[0])
    M, K, C, v0 = 1.0, 100.0, 1.0, 0.5
    wn = math.sqrt(K / M)
    zeta = C / (2 * math.sqrt(K * M))
    wd = wn * math.sqrt(1 - zeta**2)
    t = (np.arctan2(wd, zeta * wn) + 2 * np.pi * np.arange(4)) / wd
    X = v0 / wd * np.exp(-zeta * wn * t) * np.sin(wd * t)
    di = abs(np.polyfit(wn * t, X, 1)[0])
    assert di_um == pytest.approx(di * 1e6, rel=1e-5)  # printed to 6 digits
    assert zeta_eq == pytest.approx(zeta, abs=5e-6)  # printed to 5 decimals
    from symimpact.free.simulation import simulate
    from symimpact.model.system import ImpactSystem

    alone = simulate(ImpactSystem(M=M, K=K, C=C, m=0.25, gap=1e3, contact="linear", k1=1e6),
                     xdot0=v0, ydot0=v0, t_end=20.0)  # fmt: skip
    assert alone.n_impacts == 0
    assert alone.damping_inclination == pytest.approx(di, rel=1e-9)
    assert alone.zeta_eq == pytest.approx(zeta, rel=1e-12)
