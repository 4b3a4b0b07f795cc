"""What a run under a sampled load will cost on this machine, measured before it starts.

A record's run costs about the same for each of its samples (Eq. F8 on each interval, plus the
impacts or contacts in it), so the time of a piece of the first record, run with the damper
and without it as the command will run them, times the samples of the whole command, is its
estimate.  A piece is :data:`PIECE_SAMPLES` samples, or fewer where they take
:data:`PIECE_SECONDS`, from rest: the record's first (a random record is stationary), and for a
sweep also those where it crosses the primary's natural frequency, where its impacts crowd: the
estimate is then a span, from the cheaper piece's rate to the costlier's.
The engine is compiled before the piece is timed, and a piece during which numba compiled is
run again.  A command whose estimate exceeds :data:`symimpact.budgets.MAX_SECONDS` is refused
before it starts unless its budget is lifted (``--no-budget``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import Any

from ... import budgets
from ...errors import ParameterError
from ...model.system import ImpactSystem
from ..simulation import CHATTER
from .record_flight import primary_response
from .record_response import damper_response
from .records import Record

#: The samples of a piece timed.
PIECE_SAMPLES = 20_000
#: ... or as many of them as take this long [s] (a record whose intervals hold many impacts).
PIECE_SECONDS = 0.2


@dataclass(frozen=True)
class Estimate:
    """``seconds`` [s] of one core for ``samples`` samples in all (records run with the damper
    and without it), timed on ``piece`` samples of the first record; ``high`` [s]: the same
    at the costliest piece's rate where several pieces were timed (a sweep's impacts crowd near
    the primary's natural frequency: the run takes between the two), else ``seconds``."""

    seconds: float
    samples: int
    piece: int
    high: float

    def plus(self, seconds: float) -> Estimate:
        """The estimate with ``seconds`` [s] more (the work around the runs, timed apart)."""
        return replace(self, seconds=self.seconds + seconds, high=self.high + seconds)

    def text(self) -> str:
        """ "about 3.2 min on this machine (4.1e+06 samples of records, timed on 20,000)", or
        "about 3 s to 26 s …" where the pieces differ."""
        low, high = duration_text(self.seconds), duration_text(self.high)
        span = low if low == high else f"{low} to {high}"
        return (
            f"about {span} on this machine ({self.samples:.3g} samples of records, timed on "
            f"{self.piece:,})"
        )


def duration_text(seconds: float) -> str:
    """``seconds`` for people: "40 s", "3.2 min", "5.1 h", "2.4 days"."""
    if seconds >= 2 * 86400.0:
        return f"{seconds / 86400.0:.2g} days"
    if seconds >= 3600.0:
        return f"{seconds / 3600.0:.2g} h"
    if seconds >= 60.0:
        return f"{seconds / 60.0:.2g} min"
    return f"{seconds:.2g} s"


def _piece_times(
    system: ImpactSystem, record: Record, first: int, e: Any, chatter: Any, gamma: float = 1.0
) -> tuple[float, float, int]:
    """(seconds with the damper and without, seconds without, intervals) of the piece of
    ``record`` from sample ``first``: :data:`PIECE_SAMPLES` samples, or fewer where they take
    :data:`PIECE_SECONDS` (pieces of 16, then 2n + 13 samples, until one does); a piece during
    which numba compiled (a path the first pieces did not take) is run again, its time not
    counted: a first contact's force compiled inside the timing had made an estimate of 1 h for
    a run of 12 s."""
    from numba.core.event import install_recorder

    last = min(len(record.values) - first, PIECE_SAMPLES + 1)
    n = min(last, 17)
    while True:
        piece = Record(record.values[first : first + n], record.dt, record.kind)
        with install_recorder("numba:compile") as compiled:
            start = time.perf_counter()
            damper_response(system, piece, e=e, chatter=chatter, participation=gamma)
            middle = time.perf_counter()
            primary_response(system, piece, participation=gamma)
            end = time.perf_counter()
        if compiled.buffer:  # a path first met here compiled (a contact's force): not timed
            continue
        if n == last or end - start >= PIECE_SECONDS:
            return end - start, end - middle, max(1, n - 1)
        n = min(last, 2 * n + 13)


def record_estimate(
    system: ImpactSystem,
    record: Record,
    runs: int = 1,
    *,
    e: Any,
    marches: int = 0,
    chatter: Any = CHATTER,
    starts: tuple[int, ...] = (0,),
    participation: Any = 1.0,
) -> Estimate:
    """The time of ``runs`` runs of records as long as ``record`` — each with the damper
    (:func:`damper_response`, rigid impacts ``e`` or a compliant law) and without it
    (:func:`primary_response`), and ``marches`` more marches of a linear oscillator over it (an
    SRS's oscillators) — from the time of pieces of ``record`` on this machine, each from rest
    at one of the samples ``starts``: the cheapest and the costliest piece's time a sample,
    times the samples (``seconds`` and ``high``); ``participation`` as for
    :func:`damper_response`."""
    piece = Record(record.values[:3], record.dt, record.kind)
    # compiles the engines, untimed
    damper_response(system, piece, e=e, chatter=chatter, participation=participation)
    primary_response(system, piece, participation=participation)
    rates, timed = [], 0
    for first in sorted({min(max(0, int(k)), len(record.values) - 2) for k in starts}):
        both, alone, intervals = _piece_times(system, record, first, e, chatter, participation)
        rates.append((both + marches * alone) / intervals)  # seconds a sample
        timed += intervals
    work = runs * (len(record.values) - 1)
    return Estimate(work * min(rates), int(runs * len(record.values)), timed, work * max(rates))


def within_budget(estimate: Estimate, name: str, lifted: bool = False) -> Estimate:
    """``estimate``, or a :class:`ParameterError` naming ``name`` (the input that sets the
    work) when it exceeds :data:`symimpact.budgets.MAX_SECONDS` (its lower figure, where it has two) and the
    budget is not ``lifted``."""
    if estimate.seconds > budgets.MAX_SECONDS and not lifted:
        raise ParameterError(
            name,
            f"gives a run of {estimate.text()}, beyond the budget of "
            f"{duration_text(budgets.MAX_SECONDS)}: give less work, or --no-budget to run it",
        )
    return estimate
