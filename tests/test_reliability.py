"""The forced paths give no silent wrong number: each case here was a wrong number, or a clobbered
file, before it was fixed (the reliability issue's "What was seen", item 0).

- Frequencies with units are read by what they count (an angle or cycles), not by spelling:
  "324.7 rpm" is 34.0 rad/s, "5.41 hertz" is 2π·5.41 rad/s, in single values, in bands and
  as pint quantities.  The reference values are the definitions (1 rev = 2π rad, 1 Hz = one
  cycle a second, 1° = π/180 rad), computed here in exact decimal arithmetic by mpmath.
- A compliant run started inside a wall counts the contact's elastic energy at the start.
- Ranges do not mix quantities and bare numbers; an option given twice is refused.
- Outputs go only to regular files or new paths, are checked before the computation, and a map's
  lock holds for a symbolic link and its target alike.
"""

from __future__ import annotations

import json
import math
import os

import mpmath
import numpy as np
import pytest

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.forced import Forcing
from symimpact.maps.points import parse_range
from symimpact.model.units import si

SYS = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm", "--force", "2 N"]
RIGID = ["--contact", "rigid", "--e", "0.6"]

mpmath.mp.dps = 40
TWO_PI = 2 * mpmath.pi
#: Ω [rad/s] of each text, from the unit's definition.
OMEGAS = {
    "324.7 rpm": mpmath.mpf("324.7") * TWO_PI / 60,
    "5.41 hertz": mpmath.mpf("5.41") * TWO_PI,
    "5.41 Hz": mpmath.mpf("5.41") * TWO_PI,
    "0.25 kHz": mpmath.mpf("250") * TWO_PI,
    "2.5 rev/s": mpmath.mpf("2.5") * TWO_PI,
    "3 revolution/minute": mpmath.mpf("3") * TWO_PI / 60,
    "1.5 cycle/s": mpmath.mpf("1.5") * TWO_PI,
    "1.5 turn/s": mpmath.mpf("1.5") * TWO_PI,
    "1948 deg/s": mpmath.mpf("1948") * mpmath.pi / 180,
    "34 rad/s": mpmath.mpf("34"),
    "2040 rad/min": mpmath.mpf("2040") / 60,
}
#: Reading a quantity multiplies the shortest decimals of the number and of the unit's factor: a
#: few units in the last place of a double.
ULPS = 4e-16


@pytest.mark.parametrize("text", list(OMEGAS))
def test_a_frequency_is_read_by_what_it_counts(text):
    omega = float(OMEGAS[text])
    assert si("omega", text) == pytest.approx(omega, rel=ULPS)
    assert si("freq", text) == pytest.approx(omega / (2 * math.pi), rel=ULPS)
    assert Forcing(omega=text).omega == pytest.approx(omega, rel=ULPS)
    assert Forcing(freq=text).omega == pytest.approx(omega, rel=2 * ULPS)


def test_pint_quantities_are_read_alike():
    import pint

    ureg = pint.UnitRegistry()
    assert Forcing(omega=ureg.Quantity(5.41, "Hz")).omega == pytest.approx(
        float(OMEGAS["5.41 Hz"]), rel=ULPS
    )
    assert Forcing(freq=ureg.Quantity(324.7, "rpm")).freq == pytest.approx(
        float(OMEGAS["324.7 rpm"] / TWO_PI), rel=ULPS
    )


@pytest.mark.parametrize("text", ["30 /s", "30 /min"])
def test_a_rate_that_names_no_angle_is_refused(text):
    with pytest.raises(ParameterError, match="names no angle"):
        si("omega", text)


def test_bands_are_read_by_what_they_count():
    np.testing.assert_allclose(
        parse_range("omega-range", "4 Hz:6 Hz:0.5 Hz"), 2 * np.pi * np.arange(4, 6.01, 0.5),
        rtol=ULPS,
    )  # fmt: skip
    np.testing.assert_allclose(
        parse_range("freq-range", "25 rad/s:40 rad/s:5 rad/s"), np.arange(25, 41, 5) / (2 * np.pi),
        rtol=ULPS,
    )  # fmt: skip
    np.testing.assert_allclose(
        2 * np.pi * parse_range("freq-range", "240 rpm:300 rpm:30 rpm"), [8 * np.pi, 9 * np.pi,
        10 * np.pi], rtol=ULPS,
    )  # fmt: skip


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_the_command_line_runs_at_the_frequency_typed(capsys):
    out = _json(capsys, ["simulate", *SYS, "--freq", "324.7 rpm", *RIGID, "--periods", "2",
                         "--json"])  # fmt: skip
    assert out["forcing"]["omega"] == pytest.approx(float(OMEGAS["324.7 rpm"]), rel=ULPS)
    out = _json(capsys, ["simulate", *SYS, "--omega", "5.41 hertz", *RIGID, "--periods", "2",
                         "--json"])  # fmt: skip
    assert out["forcing"]["omega"] == pytest.approx(float(OMEGAS["5.41 Hz"]), rel=ULPS)
    out = _json(capsys, ["frf", *SYS, *RIGID, "--no-sweeps", "--omega-range",
                         "5.4 Hz:5.5 Hz:0.1 Hz", "--json"])  # fmt: skip
    band = [b["omega"] for b in out["baseline"]]  # the band's frequencies (JSON: 12 digits)
    np.testing.assert_allclose(band, [2 * np.pi * 5.4, 2 * np.pi * 5.5], rtol=1e-11)


def test_a_compliant_run_begun_inside_a_wall_counts_its_elastic_energy(capsys):
    # y0 15 mm with d/2 = 10 mm: 5 mm into a linear contact of 1e6 N/m stores k·δ²/2 = 12.5 J
    out = _json(capsys, ["simulate", *SYS, "--omega", "36", "--contact", "linear", "--k1", "1e6",
                         "--y0", "15 mm", "--periods", "20", "--json"])  # fmt: skip
    energy = out["energy"]
    assert energy["initial"] == pytest.approx(0.5 * 1e6 * 0.005**2, rel=1e-12)
    # the integrator's tolerance (rtol 1e-13 per step) over hundreds of contact steps
    assert energy["relative_residual"] < 1e-9


def test_a_range_mixing_units_and_bare_numbers_is_refused(capsys):
    argv = ["branch", *SYS, "--omega", "36", *RIGID, "--parameter", "gap", "--range", "5 mm:40"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "range" in err and "40 has none" in err


@pytest.mark.parametrize("command", ["frf", "design", "simulate", "periodic"])
def test_an_option_given_twice_is_refused(capsys, command):
    with pytest.raises(SystemExit) as ended:
        main([command, *SYS, "--force", "3 N", *RIGID, "--omega", "36"])
    assert ended.value.code == 2
    err = capsys.readouterr().err.strip()
    assert err == f"symimpact {command}: error: argument --force: given twice"


def _never(*args, **kwargs):
    raise AssertionError("the computation started before the output path was checked")


@pytest.mark.parametrize("option", ["--plot", "--csv"])
def test_outputs_are_checked_before_the_computation(capsys, monkeypatch, tmp_path, option):
    import symimpact.forced as forced

    monkeypatch.setattr(forced, "simulate_forced", _never)
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    for path, words in [
        ("/dev/null", "not a regular file"),
        (str(fifo), "not a regular file"),
        (str(tmp_path / "missing" / "x.png"), "does not exist"),
        (str(tmp_path), "is a folder"),
    ]:
        argv = ["simulate", *SYS, "--omega", "36", *RIGID, "--periods", "100000", option, path]
        assert main(argv) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and option[2:] in err and words in err, err
    assert fifo.exists() and not fifo.is_file()  # left as it was


def test_a_maps_lock_holds_for_a_link_and_its_target(tmp_path):
    from symimpact.maps.points import as_points
    from symimpact.maps.store import MapStore as Store
    from symimpact.model.system import table2_system

    real = tmp_path / "real.csv"
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    kwargs = {"system": table2_system(), "points": as_points({"gap": [0.009]}), "settings": {}}
    first = Store(real, **kwargs)
    try:
        with pytest.raises(ParameterError, match="another map is writing"):
            Store(link, **kwargs)
    finally:
        first.close()


def test_a_design_with_no_forcing_is_refused_in_one_line(capsys):
    # it was "internal error: ZeroDivisionError" (a peak ratio of 0/0)
    argv = [
        "design",
        *SYS[:8],
        "--force",
        "0",
        *RIGID,
        "--omega-range",
        "30:36:1",
        "--gaps",
        "40 mm:80 mm:40 mm",
    ]  # fmt: skip  (SYS without --gap, which design refuses)
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("symimpact design: error: force:"), err


@pytest.mark.slow  # a compliant curve of 11 frequencies (121 s of one core): in the slow set
def test_a_stiff_linear_contact_with_the_default_c1_gives_a_curve(capsys):
    # it was "internal error: LinAlgError" (a NaN test function handed to np.roots while locating
    # a bifurcation); the curve's most attracting stable points are checked against brute force
    # in test_compliant_orbits.  Without the multi-start (206 s with it, on CI's 2 cores): its
    # own branches locate bifurcations (a period doubling at 31.38 rad/s, grazings)
    argv = ["frf", *SYS, "--no-sweeps", "--contact", "linear", "--k1", "1e6", "--omega-range",
            "30:40:1", "--multistart", "0", "--json"]  # fmt: skip
    out = _json(capsys, argv)
    assert out["branches"] and all(np.isfinite(p["amplitude"]) for p in out["points"])
    assert out["bifurcations"], "no bifurcation located: the regression's path was not taken"


@pytest.mark.parametrize("command", ["periodic", "branch"])
def test_a_contact_too_stiff_to_differentiate_is_refused_naming_its_stiffness(capsys, command):
    # K_Hz 1e20 N/m^1.5: contacts of nanoseconds, whose exit rate vanishes below the state's
    # precision; it was "internal error: ZeroDivisionError" inside the compiled contact
    extra = {"periodic": ["--method", "shooting"],
             "branch": ["--parameter", "gap", "--range", "5 mm:40 mm"]}[command]  # fmt: skip
    argv = [command, *SYS, "--omega", "36", "--contact", "hunt-crossley", "--k-hz", "1e20",
            "--chi", "0.5", *extra]  # fmt: skip
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"symimpact {command}: error: k_hz:"), err
    assert "contact rigid" in err[0]


UNDAMPED = ["--M", "1", "--K", "1000", "--C", "0", "--m", "0.05", "--gap", "1 km", "--force",
            "2 N", *RIGID, "--periods", "100"]  # fmt: skip


def _undamped_from_rest(omega: float, t: float) -> tuple[float, float]:
    """x(t), ẋ(t) of M ẍ + K x = F0 cos Ωt from rest, M = 1, K = 1000, F0 = 2: exact, in mpmath
    at 50 digits (a detuning of 1e-16 costs 16 of them)."""
    with mpmath.workdps(50):
        W, w, t = mpmath.mpf(omega), mpmath.sqrt(1000), mpmath.mpf(t)
        a = 2 / (w**2 - W**2)
        x = a * (mpmath.cos(W * t) - mpmath.cos(w * t))
        v = a * (-W * mpmath.sin(W * t) + w * mpmath.sin(w * t))
        return float(x), float(v)


@pytest.mark.parametrize("detuning", [1e-2, 1e-4, 1e-6])
def test_an_undamped_flight_near_resonance_keeps_its_digits(detuning):
    from symimpact.forced import simulate_forced
    from symimpact.model.system import ImpactSystem

    omega = math.sqrt(1000) * (1 + detuning)
    system = ImpactSystem(M=1, K=1000, C=0, m=0.05, gap=1000, k_hz=1000)
    res = simulate_forced(system, Forcing(F0=2, omega=omega), contact="rigid", e=0.6,
                          periods=100)  # fmt: skip
    x, v = _undamped_from_rest(omega, res.t_end)
    amplitude = float(np.max(res.period_max))
    # the flight keeps ~1e-16·K/|K − MΩ²| of the motion (simulation.CANCELLATION): 5e-11 at
    # 1e-6; the bound 1e-9 is the one the refusal below guarantees
    assert abs(res.final_state[0] - x) < 1e-9 * amplitude
    assert abs(res.final_state[1] - v) < 1e-9 * amplitude * omega


def test_undamped_resonance_exactly_is_computed_and_next_to_it_refused(capsys):
    # the Ω, 2e-16 off ωₙ: it gave 999.999 mm with an energy residual of 0.36
    assert main(["simulate", *UNDAMPED, "--omega", "31.6227766016838"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "omega:" in err[0] and "resonance" in err[0], err
    # at ωₙ itself the kernel's resonant branch (growth like t) holds: 626.7 mm after 100 periods
    out = _json(capsys, ["simulate", *UNDAMPED, "--omega", repr(math.sqrt(1000)), "--json"])
    x, _ = _undamped_from_rest(math.sqrt(1000), out["t_end"])
    assert out["final_state"][0] == pytest.approx(x, rel=1e-12)
    assert out["energy"]["relative_residual"] < 1e-12
