"""Commands under sampled loads say how long they will take before they start, and refuse a run
beyond their budget unless it is lifted (the surfaces' reliability issue, item 9).

- The budget's refusal comes before the work: an ensemble of 4e11 samples (1e6 realisations of
  1000 s at 400 samples a second) is refused in one line naming ``realisations``; at the
  engine's cheapest, the primary alone at about 20 ns a sample, it is 8000 s, beyond the budget
  of 3600 s by a factor 2 before the damper's engine (about 20 times dearer) is counted.
- With the budget made tiny (monkeypatched) a small run is refused, and ``--no-budget`` runs it
  and prints its estimate; the estimate's words are checked on chosen figures.
- A shock whose SRS the samples cannot resolve is refused before its runs (it had run for 48 s
  first).
- A sweep's envelope, now read for all periods at once, is the largest value of each period's
  samples and of the cubic through x and ẋ beside its largest sample, checked against that
  cubic evaluated on a dense grid.
"""

from __future__ import annotations

import time
from itertools import pairwise

import numpy as np
import pytest

from symimpact import budgets
from symimpact.cli import main
from symimpact.forced.loads.record_cost import duration_text
from symimpact.forced.loads.sweep_response import envelope

SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm"]
RANDOM = ["random", *SYSTEM, "--contact", "rigid", "--e", "0.6", "--force-psd", "2 N^2/Hz",
          "--band", "1:20"]  # fmt: skip


def test_an_ensemble_beyond_the_budget_is_refused_in_one_line(capsys):
    args = [*RANDOM, "--realisations", "1000000", "--duration", "1000 s"]
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith("symimpact random: error: realisations: gives a run of about")
    assert "beyond the budget of 1 h" in err[0] and "--no-budget" in err[0]


def test_no_budget_lifts_the_budget_and_the_estimate_is_printed(capsys, monkeypatch):
    monkeypatch.setattr(budgets, "MAX_SECONDS", 1e-9)
    monkeypatch.setattr(budgets, "SAY_SECONDS", 0.0)
    args = [*RANDOM, "--realisations", "2", "--duration", "20 s"]
    assert main(args) == 2
    assert "beyond the budget" in capsys.readouterr().err
    assert main([*args, "--no-budget"]) == 0
    out = capsys.readouterr()
    said = [line for line in out.err.splitlines() if "on this machine" in line]
    # 2 realisations of 20 s after the default settling, 27.6 s (ln 1000/(ζω_n)), at 400 samples
    # a second: 2 × 19 041 samples
    assert said and said[0].startswith("symimpact random: about ")
    assert "(3.81e+04 samples of records" in said[0]
    assert "2 realisations of 20 s" in out.out


@pytest.mark.parametrize(
    "seconds, text",
    [(4.04, "4 s"), (40.0, "40 s"), (192.0, "3.2 min"), (5.1 * 3600, "5.1 h"),
     (1.5 * 86400, "36 h"), (2.5 * 86400, "2.5 days")],
)  # fmt: skip
def test_durations_are_said_in_the_unit_a_person_reads(seconds, text):
    assert duration_text(seconds) == text


def test_a_shock_the_samples_cannot_resolve_is_refused_before_its_runs(capsys, monkeypatch):
    """A 1e6 s pulse sampled every 5000 s cannot hold the SRS's 50 Hz oscillators: refused
    without running the damper's engine (the engine, if reached, fails the test)."""
    from symimpact.forced.loads import record_cost as cost
    from symimpact.forced.loads import shock_response

    def reached(*args, **kwargs):
        raise AssertionError("the run started before the refusal")

    monkeypatch.setattr(shock_response, "damper_response", reached)
    monkeypatch.setattr(cost, "damper_response", reached)
    assert main(["shock", *SYSTEM, "--e", "0.6", "--force-peak", "20 N", "--pulse", "1e6"]) == 2
    err = capsys.readouterr().err
    assert "frequencies: reach" in err and "finer record" in err


def _dense_peak(x0: float, v0: float, x1: float, v1: float, h: float) -> float:
    """The largest |p| of the cubic Hermite interpolant on 20 001 points of the interval: a
    peak missed by at most (1/20 000)²/8 of |p''|h², below 1e-9 of the values here."""
    u = np.linspace(0.0, 1.0, 20_001)
    h00, h10 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u
    h01, h11 = -2 * u**3 + 3 * u**2, u**3 - u**2
    return float(np.max(np.abs(h00 * x0 + h10 * h * v0 + h01 * x1 + h11 * h * v1)))


@pytest.mark.parametrize("seed", range(6))
def test_a_sweeps_envelope_is_each_periods_largest_sample_or_cubic(seed):
    rng = np.random.default_rng(seed)
    n, dt = int(rng.integers(200, 2000)), 1e-3
    f = np.linspace(rng.uniform(2, 6), rng.uniform(8, 40), n)
    phase = 2 * np.pi * np.cumsum(f) * dt
    x = rng.uniform(0.1, 2) * np.sin(phase)
    v = rng.uniform(0.5, 1.5) * np.gradient(x, dt)
    if seed % 3 == 0:
        x = np.round(x, 1)  # ties between samples: the first is taken
    hits = np.sort(rng.uniform(0, n * dt, int(rng.integers(0, 40))))
    centres, peaks = envelope(x, f, dt, v, hits)
    # the periods, each 1/f long at its start, rounded to samples
    starts, t = [0], 0.0
    while round((t := t + 1.0 / f[starts[-1]]) / dt) < n:
        starts.append(round(t / dt))
    assert len(peaks) == len(starts) - 1
    for k, (a, b) in enumerate(pairwise(starts)):
        i = a + int(np.argmax(np.abs(x[a : b + 1])))
        want = abs(x[i])
        for j in (i - 1, i):
            inside = 0 <= j < n - 1
            if inside and not np.any((hits >= j * dt) & (hits <= (j + 1) * dt)):
                want = max(want, _dense_peak(x[j], v[j], x[j + 1], v[j + 1], dt))
        assert centres[k] == f[(a + b) // 2]
        assert peaks[k] == pytest.approx(want, rel=1e-9, abs=0.0)
        assert peaks[k] >= want * (1 - 1e-15)  # the roots give the exact largest value


def test_a_compilation_during_a_timed_piece_is_not_counted(monkeypatch):
    """The first contact of a compliant record compiles its force's code inside the piece being
    timed: an estimate of 1 h for a run of 12 s (benchmark 14).  Here a stand-in for the damper's
    run compiles a fresh function and waits 0.5 s on its second call (the first timed piece) and
    returns at once otherwise: counted, that piece would make 1e5 samples cost 0.5 s/16 each,
    3000 s; the piece is run again instead."""
    import numba

    from symimpact.forced.loads import record_cost
    from symimpact.forced.loads.records import Record
    from symimpact.model.system import ImpactSystem

    calls = []

    def stand_in(system, piece, **kwargs):
        calls.append(len(piece.values))
        if len(calls) == 2:
            numba.njit(lambda x: x + 1)(1)  # a real compilation event
            time.sleep(0.5)

    monkeypatch.setattr(record_cost, "damper_response", stand_in)
    system = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e5)
    record = Record(np.zeros(100_001), 1e-3)
    estimate = record_cost.record_estimate(system, record, e=0.6)
    assert calls[:3] == [3, 17, 17]  # the compiling piece, then the same piece again
    assert estimate.seconds < 60.0, estimate
