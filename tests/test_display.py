"""Engineering units for people, SI for programs (issue 17, item 2)."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from symimpact.cli import main
from symimpact.model import display


def test_sweep_text_is_in_display_units_and_csv_in_si(tmp_path, capsys):
    out = tmp_path / "s.csv"
    assert main(["sweep", "--gap", "6 mm:8 mm:1 mm", "--csv", str(out), "--quiet"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "gap [mm]" in lines[0] and "DI [µm]" in lines[0]
    first = lines[1].split()
    assert float(first[0]) == 6.0  # mm, not 0.006
    assert 100 < float(first[4]) < 1e5  # DI in µm (about 1300 µm here), not 1.3e-03
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][:2] == ["run", "gap [m]"] and "damping_inclination [m]" in rows[0]
    assert float(rows[1][1]) == 0.006  # SI in the file
    di = float(rows[1][rows[0].index("damping_inclination [m]")])
    assert di * 1e6 == pytest.approx(float(first[4]), rel=1e-4)


def test_simulate_csv_headers_carry_si_units(tmp_path):
    out = tmp_path / "sim.csv"
    assert main(["simulate", "--t-end", "1", "--csv", str(out)]) == 0
    assert out.read_text().splitlines()[0] == "t [s],x [m],xdot [m/s],y [m],ydot [m/s]"


def test_show_picks_another_unit_and_refuses_a_wrong_one(capsys):
    assert main(["sweep", "--gap", "6 mm:7 mm:1 mm", "--show", "gap=µm", "--quiet"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "gap [µm]" in lines[0] and float(lines[1].split()[0]) == 6000.0
    assert display.display_unit("gap") == "mm"  # restored after the command
    assert main(["sweep", "--show", "gap=kg", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "show" in err and "dimension" in err


def test_plot_axes_carry_display_units(monkeypatch, tmp_path):
    import symimpact.report.plots as plots
    from symimpact.maps import parameter_map, table_rows
    from symimpact.model.system import ImpactSystem

    seen = {}

    def keep(fig, path, what="plot"):
        seen[str(path)] = [(a.get_xlabel(), a.get_ylabel()) for a in fig.axes]

    monkeypatch.setattr(plots, "atomic_savefig", keep)
    s = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
    grid = {"gap": [0.006, 0.009], "mass_ratio": [0.1, 0.25]}
    table = parameter_map(s, grid, executor="serial", xdot0=0.5, t_end=5.0, progress=False)
    plots.plot_sweep(table_rows(table)[:2], "gap", tmp_path / "a.png")
    plots.plot_map(table, "gap", "mass_ratio", path=tmp_path / "b.png")
    sweep_labels = seen[str(tmp_path / "a.png")]
    assert sweep_labels[0][1] == "DI [µm]" and sweep_labels[-1][0] == "gap [mm]"
    assert ("gap [mm]", "mass_ratio") in seen[str(tmp_path / "b.png")]


def test_a_psd_is_drawn_log_log_over_its_band(monkeypatch, tmp_path):
    """random --plot draws the PSD as a test engineer reads it (issue 80, item 6): both axes
    logarithmic, the frequency axis over the load's band and an octave either side, not
    0–1000 Hz linear; the band shaded."""
    import symimpact.report.plots as plots
    from symimpact.forced.loads.random_response import random_statistics
    from symimpact.model.system import ImpactSystem

    seen = {}

    def keep(fig, path, what="plot"):
        (ax,) = fig.axes
        seen.update(x=ax.get_xscale(), y=ax.get_yscale(), xlim=ax.get_xlim(),
                    lines=[line.get_xdata() for line in ax.get_lines()])  # fmt: skip

    monkeypatch.setattr(plots, "atomic_savefig", keep)
    s = ImpactSystem(M=40.0, K=40 * (2 * 3.141592653589793 * 12) ** 2, zeta=0.01, m=2.0,
                     gap=0.0092, contact="linear", k1=1e6)  # fmt: skip
    st = random_statistics(s, 0.25 / 95 * 9.80665**2, (5.0, 100.0), 10.0, 1 / 4000, e=0.6,
                           realisations=2, kind="base-acceleration")  # fmt: skip
    plots.plot_random(st, tmp_path / "psd.png", band=(5.0, 100.0))
    assert seen["x"] == seen["y"] == "log"
    assert all(x.min() >= 2.5 and x.max() <= 200.0 for x in seen["lines"])
    assert 2.0 < seen["xlim"][0] < 5.0 and 100.0 < seen["xlim"][1] < 250.0


def test_a_curve_draws_its_answer_first(monkeypatch, tmp_path):
    """frf --plot (issue 80, item 6): the stable branches bold and above the unstable ones,
    which are thin and dashed; the worst case marked with its value as the text states it; the
    primary without the damper in grey; one legend."""
    import symimpact.report.plots as plots
    from symimpact.forced import Forcing
    from symimpact.forced.orbits.frf import frequency_response
    from symimpact.model.system import ImpactSystem

    seen = {}

    def keep(fig, path, what="plot"):
        (ax,) = fig.axes
        lines = [line for line in ax.get_lines() if len(line.get_xdata())]  # no legend proxies
        labels = [line.get_label() for line in ax.get_lines()]
        seen.update(legends=[c for c in ax.get_children() if type(c).__name__ == "Legend"],
                    labels=labels, ylabel=ax.get_ylabel(),
                    solid=[(line.get_linewidth(), line.get_zorder()) for line in lines
                           if line.get_linestyle() == "-" and line.get_color() == "C0"],
                    dashed=[(line.get_linewidth(), line.get_zorder()) for line in lines
                            if line.get_linestyle() == "--" and line.get_color() == "C0"],
                    grey=[line.get_color() for line in lines
                          if line.get_label() == "without the damper"])  # fmt: skip

    monkeypatch.setattr(plots, "atomic_savefig", keep)
    s = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
    frf = frequency_response(s, Forcing(F0=2.0, omega=33.0), 0.6, np.arange(32.0, 35.01, 0.5),
                             sweeps=False, multistart=0, workers=1)  # fmt: skip
    plots.plot_frf(frf, tmp_path / "frf.png")
    assert len(seen["legends"]) == 1 and seen["grey"] == ["0.55"]
    assert min(w for w, _ in seen["solid"]) > 2 * max(w for w, _ in seen["dashed"])
    assert min(z for _, z in seen["solid"]) > max(z for _, z in seen["dashed"])
    (worst,) = [label for label in seen["labels"] if label.startswith("worst case")]
    assert worst == (f"worst case {frf.peak.amplitude * 1e3:.4g} mm at Ω {frf.peak.omega:.4g} "
                     "rad/s")  # fmt: skip
    # a transmissibility is drawn in dB, as vibration tests read it
    from symimpact.forced.orbits.response_curve import response_curve

    tr = response_curve(frf, "transmissibility", s, Forcing(F0=2.0, omega=33.0), 0.6)
    plots.plot_frf(tr, tmp_path / "tr.png")
    (worst,) = [label for label in seen["labels"] if label.startswith("worst case")]
    assert worst.startswith(f"worst case {20 * np.log10(tr.peak.amplitude):.4g} dB at Ω")
    assert seen["ylabel"] == "transmissibility [dB]"


def test_a_long_map_summary_names_each_input_with_its_unit(capsys):
    args = ["map", "--vary", "gap=4 mm:40 mm:4 mm", "--vary", "mass_ratio=0.1:0.7:0.1", "--quiet"]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "µm at gap = " in out and " mm, mass_ratio = " in out


def test_a_compilation_is_announced_on_a_terminal_only(monkeypatch, capsys):
    """Issue 17, item 7 and the engine issue: a first run compiled for minutes and printed
    nothing (then a notice said "10–20 s" of a compilation of 4 minutes).  numba's compile
    events (real compilations, not cache hits) print one line naming the measured time of the
    engine compiled, once an engine, when the command line runs on a terminal: here a function
    compiled for the first time, its module given a measured time of 42 s."""
    import sys

    import numba

    from symimpact import _interrupt, _notices

    assert _interrupt.INTERRUPTED  # the listener is registered with numba
    monkeypatch.setitem(_notices.COMPILE_SECONDS, __name__, 42.0)
    monkeypatch.setattr(_notices, "_said", set())
    monkeypatch.setattr(_notices, "command", None)

    def fresh(n):
        return n + 1

    assert main(["ritz"]) == 0  # not a terminal: no notice is set up
    capsys.readouterr()
    assert numba.njit(fresh)(1) == 2
    assert capsys.readouterr().err == ""
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    assert main(["ritz"]) == 0
    capsys.readouterr()
    assert numba.njit(fresh)(2) == 3  # a new dispatcher: compiles again
    assert numba.njit(fresh)(3) == 4  # once an engine and a process
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert err.startswith("symimpact ritz: compiling the simulation engine for this machine")
    assert "about 42 s of one core" in err and "Ctrl-C ends it" in err
    table = _notices.COMPILE_SECONDS
    assert (
        _notices.expected_seconds("symimpact.forced.engine._modal")
        == table["symimpact.forced.engine._modal"]
    )
    assert _notices.expected_seconds("symimpact.free._stepper") == table["symimpact.free._stepper"]
    assert _notices.expected_seconds("symimpact.forced._modal_x") is None  # a module, not a prefix
    assert _notices.expected_seconds("symimpact.model.units") is None


def test_a_compilation_notice_under_an_open_bar_starts_its_own_line(monkeypatch, capsys):
    """A curve's stage bar (frf at a terminal) is open mid-line when numba begins a compilation:
    the notice starts on a new line instead of running on after the bar (seen on a fresh
    clone: "frf starts:   0%| … | 0/6 [00:00<?, ?Ω/s]symimpact frf: compiling …")."""
    import sys

    from tqdm import tqdm

    from symimpact import _notices

    monkeypatch.setitem(_notices.COMPILE_SECONDS, __name__, 42.0)
    monkeypatch.setattr(_notices, "_said", set())
    monkeypatch.setattr(_notices, "command", "frf")
    bar = tqdm(total=6, desc="frf starts", file=sys.stderr)
    try:
        _notices.compiling(__name__)
    finally:
        bar.close()
    err = capsys.readouterr().err
    before, _, after = err.partition("symimpact frf: compiling")
    assert after and before.endswith("\n") and "frf starts" in before
