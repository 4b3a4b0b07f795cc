"""A curve's progress (issue 80, item 5): each stage counted in runs as they end, with the number
of runs known before it starts where it is, whether the runs are made here or on worker
processes; at a terminal a bar a stage on stderr, elsewhere (a pipe, a file, a test) nothing."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from symimpact import _pool
from symimpact._progress import Stages
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.coverage import FREQUENCIES, STARTS, check_frequencies
from symimpact.forced.orbits.frf import STAGES, frequency_response
from symimpact.model.system import ImpactSystem

ROOT = Path(__file__).resolve().parent.parent

#: The README's system (a 1 kg, 1000 N/m primary, a 50 g impact mass in a 20 mm clearance,
#: e 0.6, 2 N), over a short band near its resonance.
SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
BAND = np.arange(34.0, 36.0 + 1e-9, 0.25)


def _five_runs(n: int) -> int:
    """A pool payload: ``n`` runs, each counted as it ends."""
    for _ in range(n):
        _pool.counted(0)
    _pool.counted(1)
    return n


@pytest.mark.parametrize("workers", [1, 2])
def test_runs_are_counted_where_they_run(workers):
    """On two worker processes the counts come back through shared memory; run here (one
    worker) they are counted here, and the waiting caller is told at each."""
    told = []
    pending = _pool.Pending(_five_runs, [5, 3, 4], workers)
    assert pending.result(lambda: told.append(pending.counts()[:2])) == [5, 3, 4]
    assert pending.counts() == (12, 3, 0)
    assert told  # the caller was told while the runs ran
    if workers == 1:  # here: told at every counted run, in order
        expected, grid, refined = [], 0, 0
        for n in (5, 3, 4):
            for _ in range(n):
                grid += 1
                expected.append((grid, refined))
            refined += 1
            expected.append((grid, refined))
        assert told == expected


def test_a_design_maps_curves_count_their_runs_on_its_workers():
    """A design map's clearances run on worker processes; each curve's runs are counted
    (CurveRuns) into the pool's shared memory, where the waiting parent reads them, and run
    here they are counted here: the same number either way."""
    from symimpact.maps.design import design_map

    counted = {}
    for workers in (1, 2):
        before = _pool.ended_here(_pool.CURVE_RUNS)
        seen = []
        table = design_map(SYSTEM, Forcing(F0=2.0, omega=34.0), 0.6, BAND[:3],
                           {"gap": [0.02, 0.03]}, multistart=0, workers=workers,
                           runs=seen.append)  # fmt: skip
        assert len(table) == 2
        assert seen == sorted(seen) and seen[-1] > 0  # told while it ran, only adding up
        counted[workers] = (seen[-1], _pool.ended_here(_pool.CURVE_RUNS) - before)
    assert counted[1][0] == counted[2][0]  # the same runs counted, here or on the workers
    assert counted[1][1] == counted[1][0]  # here: every one in this process


def test_a_curve_tells_each_stage_in_order_and_counts_each_run():
    events: list[tuple[str, int, int | None]] = []
    frf = frequency_response(SYSTEM, Forcing(F0=2.0, omega=34.0), 0.6, BAND, workers=2,
                             progress=lambda *ev: events.append(ev))  # fmt: skip
    names = list(dict.fromkeys(name for name, _, _ in events))
    assert names == [s for s in STAGES if s in names]  # in the documented order
    assert {"starts", "multi-start", "sweeps", "branches", "coverage check"} <= set(names)
    for name in names:
        seen = [(done, total) for n, done, total in events if n == name]
        assert seen[0][0] == 0  # told when it begins
        dones = [d for d, _ in seen]
        assert dones == sorted(dones)  # runs only add up
        total = seen[0][1]
        if total is not None:  # a bar with its end known: reached, never passed
            assert dones[-1] == total, (name, dones[-1], total)
    totals = {n: t for n, d, t in events if d == 0}
    assert totals["starts"] == 6  # the default spread starts
    assert totals["sweeps"] == 2 * len(BAND)  # each frequency up and down
    assert totals["multi-start"] == STARTS * FREQUENCIES  # each initial state at each frequency
    assert totals["coverage check"] == STARTS * len(check_frequencies((34.0, 36.0)))
    branches = [d for n, d, _ in events if n == "branches"]
    assert branches[-1] == len(frf.branches)  # each branch grown once
    # told or not, the same curve
    quiet = frequency_response(SYSTEM, Forcing(F0=2.0, omega=34.0), 0.6, BAND, workers=2)
    assert [len(b.points) for b in quiet.branches] == [len(b.points) for b in frf.branches]
    assert quiet.peak.amplitude == frf.peak.amplitude


def test_a_bar_a_stage_with_its_count_and_time():
    out = io.StringIO()
    with Stages(True, "frf", file=out) as stages:
        stages.stage("sweeps", 4, unit="Ω")
        for _ in range(4):
            stages.advance()
        stages.stage("branches", None, unit="branch")
        stages.advance(3)
        stages.note("3 found")
    lines = [line.split("\r")[-1] for line in out.getvalue().split("\n")]  # (\r ends no line)
    assert lines[0].startswith("frf sweeps: 100%") and "4/4" in lines[0]
    assert lines[1].startswith("frf branches: 3branch") and "3 found" in lines[1]
    nothing = io.StringIO()
    with Stages(False, "frf", file=nothing) as stages:
        stages.stage("sweeps", 4)
        stages.advance(4)
    assert nothing.getvalue() == ""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="a pseudo-terminal (pty)")
def test_the_command_draws_its_stages_at_a_terminal_and_nothing_into_a_pipe():
    import fcntl
    import pty
    import struct
    import termios

    cmd = [sys.executable, "-c", "import sys; from symimpact.cli import main; sys.exit(main())",
           "frf", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
           "--force", "2 N", "--contact", "rigid", "--e", "0.6", "--omega-range", "34:36:0.25",
           "--multistart", "0"]  # fmt: skip
    env = os.environ | {"COLUMNS": "100"}
    main_fd, side = pty.openpty()
    fcntl.ioctl(side, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 100, 0, 0))
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=side, env=env, cwd=ROOT)
    os.close(side)
    seen = b""
    while True:
        try:
            chunk = os.read(main_fd, 65536)
        except OSError:  # the command has ended and closed its side
            break
        if not chunk:
            break
        seen += chunk
    out = proc.communicate(timeout=600)[0].decode()
    os.close(main_fd)
    assert proc.returncode == 0
    text = seen.decode().replace("\r\n", "\n")  # the terminal writes each newline as \r\n
    finals = [part.split("\r")[-1] for part in text.split("\n") if part.strip()]
    assert any(f.startswith("frf starts: 100%") and "6/6" in f for f in finals), finals
    assert any(f.startswith("frf sweeps: 100%") and "18/18" in f for f in finals), finals
    assert "peak with the damper" in out  # the answer on stdout, the bars beside it
    piped = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=ROOT, timeout=600)
    assert piped.returncode == 0
    assert "frf sweeps" not in piped.stderr and "%|" not in piped.stderr


def test_a_structure_curve_counts_its_runs_from_rest():
    """``frf --structure``: the runs from rest at every frequency of the band's grid (nearly all
    of its time) counted as they end, then its branches."""
    from symimpact.forced.orbits.structure_branch import curve_grid
    from symimpact.maps.structure_curve import structure_curve_map
    from symimpact.model.structure_model import model_from_dict

    model = model_from_dict({"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]],
                                    "zeta": 0.015},
                             "stops": [{"name": "s", "at": 0, "gap": 1, "side": "+",
                                        "contact": "linear", "k1": 100, "c1": 0}],
                             "force": {"at": 1, "amplitude": 0.1}})  # fmt: skip
    events = []
    curve = structure_curve_map(model.structure, model.dampers, model.force_at, model.F0, 0.6,
                                0.64, 0.005, model.stops, workers=2,
                                progress=lambda *ev: events.append(ev))  # fmt: skip
    runs = [(d, t) for n, d, t in events if n == "runs from rest"]
    n = len(curve_grid(0.6, 0.64, 0.005))
    assert runs[0] == (0, n) and runs[-1] == (n, n) and len(curve.settled) == n
    assert [d for n_, d, _ in events if n_ == "branches"][-1] == len(curve.branches)


def test_a_progress_that_is_neither_a_flag_nor_a_callable_is_refused_by_name():
    from symimpact.errors import ParameterError

    with pytest.raises(ParameterError, match="progress: must be True"):
        frequency_response(SYSTEM, Forcing(F0=2.0, omega=34.0), 0.6, BAND, progress="yes")


@pytest.mark.parametrize(
    "argv",
    [
        ["design", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N",
         "--contact", "rigid", "--e", "0.6", "--omega-range", "31:32:1", "--gaps",
         "40 mm,50 mm", "--multistart", "0", "--no-refine", "--workers", "1"],
        ["map", "--vary", "gap=6 mm:30 mm:2 mm", "--executor", "serial", "--xdot0", "0.5",
         "--t-end", "2"],
    ],
    ids=["design", "map"],
)  # fmt: skip
def test_nothing_is_drawn_into_a_file(argv, tmp_path):
    """stderr sent to a file (``2> log``) gets no bar: a cold ``design`` had written every
    redraw of its two bars into it, 60 kB on one line.  The same map's bar is drawn at a terminal
    (:func:`test_progress_bar_ends_on_the_last_run` in tests/test_maps.py, through the API)."""
    log = tmp_path / "log"
    with open(log, "w") as err:
        run = subprocess.run([sys.executable, "-m", "symimpact.cli", *argv], stdout=subprocess.PIPE,
                             stderr=err, text=True, cwd=tmp_path, timeout=600)  # fmt: skip
    assert run.returncode == 0, log.read_text()
    text = log.read_text()
    assert "%|" not in text and "run/s" not in text, text[:500]
