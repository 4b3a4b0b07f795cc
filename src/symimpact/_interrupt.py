"""Ctrl-C, SIGTERM and SIGHUP while compiled code runs: seen within milliseconds, delivered only
where Python can take them.

CPython runs a signal's Python handler only between bytecodes.  While a compiled (numba) loop
runs, a Ctrl-C waits; when the loop returns, the handler runs inside numba's conversion of the
results to Python objects, and the KeyboardInterrupt it raises there left a half-built result:
a segmentation fault (compliant runs) or "SystemError: returned a result with an exception set"
(rigid runs).  So, around every compiled call (:func:`call`):

* Python's C-level handler also writes the signal's number to a pipe (``signal.set_wakeup_fd``);
  the compiled loops read that pipe every few thousand steps (:func:`stop_requested`, one
  ``read`` system call, well under 1 % of a step's cost) and return the status
  :data:`INTERRUPTED` at once when it holds SIGINT, SIGTERM or SIGHUP;
* SIGINT's Python handler is replaced by one that only records the signal while compiled code
  runs; the previous handler (Python's, which raises KeyboardInterrupt, or the caller's own) is
  called once the call has returned and its result is whole.  A SIGINT that is ignored (map
  workers ignore it) stays ignored.

Outside the main thread no signal reaches Python, and the loops are given no pipe.
"""

from __future__ import annotations

import _signal
import os
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numba
import numba.core.event
import numpy as np
from numba import types

from . import _notices
from ._compiled import compiled

#: Status of a compiled run that stopped because a signal asked it to (every loop's own statuses
#: are small numbers; this one is shared).
INTERRUPTED = 99
#: Steps of a compiled loop between two looks at the pipe (a power of two, for a mask).
EVERY = 1024

# ``read(2)`` called from compiled code by its symbol name, so the cached machine code stays valid
# in every process (a ctypes address would not be).
_read = types.ExternalFunction("read", types.intp(types.intc, types.intp, types.uintp))


@compiled
def stop_requested(watch: np.ndarray) -> bool:
    """True when the watch pipe holds SIGINT, SIGTERM or SIGHUP.  ``watch`` (int64, 3) holds the
    pipe's read end (−1: none), a one-byte buffer and, once seen, the signal's number."""
    if watch[2] != 0:  # seen before: every loop on the way out stops too
        return True
    fd = watch[0]
    if fd < 0:
        return False
    while True:
        watch[1] = 0
        if _read(fd, watch.ctypes.data + 8, 1) <= 0:
            return False
        s = watch[1]
        if s > 255:  # the byte landed at the other end of the word (big-endian)
            s = s >> 56
        if s == 2 or s == 15 or s == 1:  # SIGINT, SIGTERM, SIGHUP (POSIX numbers)
            watch[2] = s
            return True


class _Pipe:
    """The process's wakeup pipe, made on first use (again after a fork)."""

    def __init__(self) -> None:
        self.pid = -1
        self.r = self.w = -1

    def ends(self) -> tuple[int, int]:
        if self.pid != os.getpid():
            r, w = os.pipe()
            os.set_blocking(r, False)
            os.set_blocking(w, False)
            self.r, self.w, self.pid = r, w, os.getpid()
        return self.r, self.w

    def drain(self) -> None:
        try:
            while os.read(self.r, 512):
                pass
        except OSError:  # empty (EAGAIN)
            pass


_PIPE = _Pipe()
_recorded: list[int] = []
_compiled_depth = 0
#: A watch with no pipe: for compiled calls outside :func:`call` (tests, other threads).
NO_WATCH = np.array([-1, 0, 0], dtype=np.int64)


_SIGINT = int(signal.SIGINT)
_SIG_IGN = int(signal.SIG_IGN)


def call(fn: Any, *args: Any) -> Any:
    """``fn(*args, watch)``: a compiled loop, given the pipe to watch, with SIGINT deferred to its
    return (see the module text).  The previous SIGINT handler is called there if a SIGINT came,
    so a KeyboardInterrupt is raised from here, in Python, with the result discarded.  Inside a
    :func:`stretch` the stretch's deferral and pipe serve the call."""
    global _compiled_depth
    st = _stretch
    if st is not None and st.pid != os.getpid():
        st = None  # a process forked within a stretch: the stretch and its pipe are the parent's
    if st is not None and not _compiled_depth and _recorded:
        _end_stretch(st)  # came while the stretch ran Python: delivered before the run
        st = None
    if st is not None and not _compiled_depth:
        _compiled_depth = 1
        try:
            out = fn(*args, st.watch)
        finally:
            _compiled_depth = 0
        if _recorded or st.watch[2]:
            _end_stretch(st)
        return out
    if (
        threading.current_thread() is not threading.main_thread()
        or _compiled_depth
        or numba.config.DISABLE_JIT  # run as Python (debugging): the pipe cannot be read
    ):
        return fn(*args, NO_WATCH.copy())
    r, w = _PIPE.ends()
    watch = np.array([r, 0, 0], dtype=np.int64)
    # ``_signal``, the C module ``signal`` wraps: the wrappers convert numbers and handlers to
    # enums, 5 to 9 µs a call (measured), which around a one-period run of 50 µs (shooting's
    # Newton steps call it thousands of times) doubled its cost
    previous = _signal.getsignal(_SIGINT)
    defer = previous not in (_SIG_IGN, None)
    try:
        old_fd = _signal.set_wakeup_fd(w, warn_on_full_buffer=False)
    except ValueError:  # a signal-less interpreter (embedded): nothing to watch
        return fn(*args, NO_WATCH.copy())
    # cleared before _record is installed: a SIGINT recorded between the two would be lost (the
    # run then went on to the end, exit 0)
    _recorded.clear()
    if defer:
        _deferred[0] = previous
        _signal.signal(_SIGINT, _record)
    _compiled_depth = 1
    try:
        out = fn(*args, watch)
    finally:
        _compiled_depth = 0
        if defer:
            _signal.signal(_SIGINT, previous)
        _signal.set_wakeup_fd(old_fd)
        _PIPE.drain()  # (_signal.signal above ran a pending SIGINT's handler, _record)
    _deliver(previous, watch)
    return out


def deliver_pending() -> None:
    """Where Python waits inside a :func:`stretch` — on worker processes
    (:class:`symimpact._pool.Pending`), which ignore Ctrl-C — a SIGINT the stretch recorded is
    delivered now (the stretch ends as :func:`call` ends it), not once the wait is over: the
    multi-start's workers of ``frf`` had let a Ctrl-C wait up to 4 s for their runs."""
    st = _stretch
    if st is not None and st.pid == os.getpid() and not _compiled_depth and _recorded:
        _end_stretch(st)


def _deliver(previous: Any, watch: np.ndarray) -> None:
    """Once the deferral has ended: call the previous SIGINT handler if a SIGINT came (Python's
    own raises KeyboardInterrupt), and raise KeyboardInterrupt if a compiled run was cut short
    by a signal (its result is not one)."""
    if _recorded or watch[2] == _SIGINT:
        _recorded.clear()
        if callable(previous):  # Python's own raises KeyboardInterrupt
            previous(signal.SIGINT, None)
        elif previous == signal.SIG_DFL:
            signal.raise_signal(signal.SIGINT)
    if watch[2]:  # the run was cut short: its result is not one
        raise KeyboardInterrupt(f"signal {int(watch[2])}")


class _Stretch:
    """The deferral of a :func:`stretch`: the handler and wakeup descriptor it replaced, and
    the watch its calls share."""

    def __init__(self, previous: Any, defer: bool, old_fd: int, read_end: int) -> None:
        self.previous, self.defer, self.old_fd = previous, defer, old_fd
        self.watch = np.array([read_end, 0, 0], dtype=np.int64)
        self.pid = os.getpid()


_stretch: _Stretch | None = None


def _end_stretch(st: _Stretch) -> None:
    """Restore what the stretch replaced, then deliver what came (:func:`_deliver`)."""
    global _stretch
    if _stretch is not st or st.pid != os.getpid():
        return
    _stretch = None
    if st.defer:
        _signal.signal(_SIGINT, st.previous)
    _signal.set_wakeup_fd(st.old_fd)
    _PIPE.drain()
    _deliver(st.previous, st.watch)


@contextmanager
def stretch() -> Iterator[None]:
    """A stretch of Python that makes many short compiled calls through :func:`call` — a
    continuation's Newton steps, tens of thousands of one-period runs of 30 µs — under one
    deferral: the SIGINT handler and the wakeup pipe are set once, where setting them around
    each call cost as much as the run.  A SIGINT that comes is delivered as :func:`call`
    delivers it, by the next call once its run has returned (or before it starts, if it came
    while Python ran), or when the stretch ends; the stretch's deferral then ends.  Nested
    stretches, other threads and runs as Python (``NUMBA_DISABLE_JIT``) leave each call to its
    own deferral, and so does a process forked within a stretch (its calls defer on their own)."""
    global _stretch
    if (
        (_stretch is not None and _stretch.pid == os.getpid())
        or _compiled_depth
        or threading.current_thread() is not threading.main_thread()
        or numba.config.DISABLE_JIT
    ):
        yield
        return
    r, w = _PIPE.ends()
    previous = _signal.getsignal(_SIGINT)
    defer = previous not in (_SIG_IGN, None)
    try:
        old_fd = _signal.set_wakeup_fd(w, warn_on_full_buffer=False)
    except ValueError:  # a signal-less interpreter (embedded)
        yield
        return
    _recorded.clear()
    if defer:
        _deferred[0] = previous
        _signal.signal(_SIGINT, _record)
    st = _Stretch(previous, defer, old_fd, r)
    _stretch = st
    try:
        yield
    finally:
        _end_stretch(st)


# -- signals while numba compiles ------------------------------------------------------------
#
# A first call compiles: minutes of numba's passes, in Python, inside :func:`call`'s deferral.
# A SIGINT recorded there waited for the compilation's end (a Ctrl-C was ignored for 16
# minutes on a first run).  Nothing half-built can be left by a KeyboardInterrupt raised while
# numba compiles (the compiled call has not started), so there the deferral delivers at once:
# numba's compile events (numba.core.event, "numba:compile") count the compilations under way.

_compiling = [0]
#: The SIGINT handler the deferral replaced (:func:`call`, :func:`stretch`), delivered to at
#: once while numba compiles.
_deferred: list[Any] = [None]


def _record(signum: int, frame: Any) -> None:
    """SIGINT while compiled code runs: recorded, delivered once the call returns; while numba
    compiles (Python, before the compiled call starts), delivered at once."""
    if _compiling[0] and _deferred[0] is not None:
        _deliver_now(signum, frame)
        return
    _recorded.append(signum)


def _deliver_now(signum: int, frame: Any) -> None:
    """Call the handler the deferral replaced (Python's own raises KeyboardInterrupt; the
    command line's ends the process)."""
    previous = _deferred[0]
    if callable(previous):
        previous(signum, frame)
    elif previous == signal.SIG_DFL:
        raise KeyboardInterrupt
    else:  # ignored meanwhile: kept for the call's end, as before
        _recorded.append(signum)


class _Compiling(numba.core.event.Listener):
    """numba's compile events: the depth of the compilations under way in the main thread (a
    cache hit is no event: only real compilations count)."""

    def on_start(self, ev: Any) -> None:
        if threading.current_thread() is threading.main_thread():
            if not _compiling[0]:  # the command line's notice (symimpact._notices)
                _notices.compiling(getattr(ev.data["dispatcher"].py_func, "__module__", ""))
            _compiling[0] += 1
            # a SIGINT recorded after the deferral began and before this first compilation
            # (numba typing the arguments) had waited for the whole compilation, minutes (CI,
            # 2026-12-07: a Ctrl-C 1.19 s into a cold run); it is delivered now (numba sends
            # the end event, which takes the count down, even when this start event raises)
            if _recorded and _signal.getsignal(_SIGINT) is _record:
                _deliver_now(_recorded.pop(), None)

    def on_end(self, ev: Any) -> None:
        if threading.current_thread() is threading.main_thread():
            _compiling[0] = max(0, _compiling[0] - 1)


numba.core.event.register("numba:compile", _Compiling())
