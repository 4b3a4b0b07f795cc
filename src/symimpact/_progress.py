"""Progress of a computation of several stages, each counted in runs as they end: one line a
stage on stderr (a bar with its rate and remaining time where the stage's number of runs is known
before it starts, a count and the time taken where it is not), or a callable for a program.

A frequency-response curve (:func:`symimpact.forced.orbits.frf.frequency_response`) is the user:
its stages (branches from spread starts, the multi-start, the sweeps, branch switching and
jumps, the coverage check) take seconds to many minutes, and a person waiting at a terminal sees
which one runs, how far it is and about how long it has left (issue 80, item 5).

Plain Python: tqdm is imported only when a bar is drawn.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

#: A program's progress callable: ``(stage, done, total)`` each time a run of ``stage`` ends
#: (``total`` None where the stage's number of runs is not known before it starts), and
#: ``(stage, 0, total)`` when the stage begins.
Callback = Callable[[str, int, "int | None"], None]


def end_open_bar_line() -> None:
    """Where a tqdm bar is open mid-line on stderr, end that line, so that a message printed
    next gets its own.  tqdm is read from sys.modules and its class with getattr, never
    imported: a signal handler calls this, and a signal that lands while tqdm is being imported
    finds it without its class yet."""
    bar = getattr(sys.modules.get("tqdm"), "tqdm", None)
    if bar is not None and getattr(bar, "_instances", None):
        sys.stderr.write("\n")


class Stages:
    """The progress of one command's stages: :meth:`stage` begins one (and ends the one
    before), :meth:`advance` counts its runs, :meth:`close` ends the last.

    ``progress``: True draws a bar a stage on ``file`` (stderr), each left in place when its
    stage ends (runs, time taken, rate); False or None draws nothing; a callable
    (:data:`Callback`) is called instead.  ``desc`` begins each bar's label (the command)."""

    def __init__(self, progress: bool | Callback | None, desc: str = "", file: Any = None) -> None:
        if not (progress is None or isinstance(progress, bool) or callable(progress)):
            from .errors import ParameterError

            raise ParameterError("progress", "must be True (a bar on stderr), False or None, or "
                                             "a callable (stage, done, total)")  # fmt: skip
        self.callback: Callback | None = progress if callable(progress) else None
        self.draw = progress is True
        self.desc = desc
        self.file = file
        self.name: str | None = None
        self.done = 0
        self.total: int | None = None
        self.bar: Any = None

    @property
    def enabled(self) -> bool:
        """Whether anything is reported (a bar or a callable)."""
        return self.draw or self.callback is not None

    def stage(self, name: str, total: int | None = None, unit: str = "run") -> None:
        """Begin stage ``name`` of ``total`` runs (None: not known before it runs), ending the
        stage before."""
        self._end()
        self.name, self.done, self.total = name, 0, total
        if self.callback is not None:
            self.callback(name, 0, total)
        if self.draw:
            from tqdm import tqdm

            self.bar = tqdm(
                total=total,
                desc=f"{self.desc} {name}".strip(),
                unit=unit,
                file=self.file if self.file is not None else sys.stderr,
                leave=True,  # each stage's last line stays: what it did and how long it took
                smoothing=0.1,
            )

    def advance(self, n: int = 1) -> None:
        """``n`` more runs of the current stage have ended."""
        if self.name is None or n <= 0:
            return
        self.done += n
        if self.callback is not None:
            self.callback(self.name, self.done, self.total)
        if self.bar is not None:
            self.bar.update(n)

    def reach(self, done: int) -> None:
        """The current stage has ended ``done`` runs in all (counted elsewhere, e.g. by worker
        processes, :func:`symimpact._pool.counted`): advanced by the difference."""
        self.advance(done - self.done)

    def note(self, text: str) -> None:
        """A short note beside the current stage's bar (what its count does not show)."""
        if self.bar is not None:
            self.bar.set_postfix_str(text, refresh=False)

    def close(self) -> None:
        """End the last stage."""
        self._end()
        self.name = None

    def _end(self) -> None:
        if self.bar is not None:
            self.bar.refresh()  # tqdm draws at most every 0.1 s: the final count first
            self.bar.close()
            self.bar = None

    def __enter__(self) -> Stages:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
