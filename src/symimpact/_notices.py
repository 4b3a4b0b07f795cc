"""The command line's one-line notice when numba compiles an engine (a first run after an
install or an upgrade): what compiles, about how long it takes, and that Ctrl-C ends it.

numba's compile events (:mod:`symimpact._interrupt`, which holds the listener) call
:func:`compiling` when a compilation begins outside another; only real compilations are events
(a run that reads the engine from numba's cache says nothing).  Plain Python with no import, so
that the command line sets it up without loading numba.
"""

from __future__ import annotations

import sys

from ._progress import end_open_bar_line

#: CPU seconds of the first compilation of each engine (the module of the function compiled
#: first), measured with an empty NUMBA_CACHE_DIR by ``python -m benchmarks.first_run``
#: (benchmark 15, on the 2-core machine of benchmarks/RESULTS.md): the free stepper, the engine of
#: rigid forced runs (one mode or several), the continuation's Newton corrector and its chain
#: rule, the compliant contacts' engine and the sampled loads' rigid engine.  The engines not
#: listed compile in a few seconds, without a notice.
COMPILE_SECONDS = {
    "symimpact.free._stepper": 15.0,
    "symimpact.forced.engine._modal": 118.0,
    "symimpact.forced.orbits._corrector": 22.0,
    "symimpact.forced.engine._chain": 14.0,
    "symimpact.forced.engine._compliant": 11.0,
    "symimpact.forced.engine._record_rigid": 7.0,
}

#: The command whose compilations are announced (set by the command line on a terminal).
command: str | None = None
_said: set[str] = set()


def _engine(module: str) -> str | None:
    """The key of :data:`COMPILE_SECONDS` that names ``module`` (the longest prefix of it by
    whole names), or None."""
    names = [m for m in COMPILE_SECONDS if module == m or module.startswith(m + ".")]
    return max(names, key=len) if names else None


def expected_seconds(module: str) -> float | None:
    """The measured first compilation of the engine in ``module`` (:data:`COMPILE_SECONDS`), or
    None."""
    engine = _engine(module)
    return None if engine is None else COMPILE_SECONDS[engine]


def compiling(module: str) -> None:
    """Print the notice for a compilation of ``module`` beginning, once an engine and a
    process, when the command line asked for it (:data:`command`) and its time was measured
    (:data:`COMPILE_SECONDS`)."""
    engine = _engine(module)
    if command is None or engine is None or engine in _said:
        return
    _said.add(engine)
    seconds = COMPILE_SECONDS[engine]
    took = f"{seconds / 60:.0f} min" if seconds >= 90 else f"{seconds:.0f} s"
    end_open_bar_line()  # a curve's stage bar open mid-line: the notice on a line of its own
    print(
        f"symimpact {command}: compiling the simulation engine for this machine, once (about "
        f"{took} of one core; later runs read it from numba's cache in a second; Ctrl-C ends it)",
        file=sys.stderr,
        flush=True,
    )
