"""Local worker processes shared by the stages that spread independent runs over the machine's
cores: the maps (:mod:`symimpact.maps.executors`) and the multi-start of a frequency-response
curve (:func:`symimpact.forced.orbits.coverage.attractors`).  A worker ends with the process that
started it, ignores Ctrl-C (the parent ends the pool), never starts a pool of its own, and runs
BLAS on one thread (the pool has one worker a core)."""

from __future__ import annotations

import multiprocessing
import os
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from ._interrupt import deliver_pending

#: True inside a worker started here: its own work runs in it, never on a nested pool.
IN_WORKER = False
#: Seconds between two looks, while this process waits on its workers, for a Ctrl-C that a
#: :func:`symimpact._interrupt.stretch` recorded (:func:`symimpact._interrupt.deliver_pending`).
LOOK = 0.05

#: Kinds of run counted as they end (:func:`counted`), for a progress bar: a multi-start's
#: landings on its grid (0) and in its refinement (1), any run of a curve (:data:`CURVE_RUNS`).
KINDS = 3
CURVE_RUNS = 2
#: In a worker of a counting pool: the pool's counters in shared memory.
_SHARED: Any = None
#: In this process: the runs of each kind ended here, and what is called at each (the progress
#: of runs made here, :func:`watching`).
_HERE = [0] * KINDS
_watchers: list[Callable[[], None]] = []


def counted(kind: int = 0, n: int = 1) -> None:
    """``n`` runs of ``kind`` (0 to KINDS − 1) have ended: counted here and, in a worker of a
    counting pool, in the pool's shared memory, where the process that waits on the runs reads
    them (:meth:`Pending.counts`, :func:`spread`'s ``counts``)."""
    _HERE[kind] += n
    if _SHARED is not None:
        with _SHARED.get_lock():
            _SHARED[kind] += n
    for watcher in _watchers:
        watcher()


def ended_here(kind: int) -> int:
    """The runs of ``kind`` this process has counted so far (:func:`counted`)."""
    return _HERE[kind]


@contextmanager
def watching(on_count: Callable[[], None] | None) -> Iterator[None]:
    """Within the block, ``on_count()`` is called each time this process counts a run (None:
    nothing)."""
    if on_count is None:
        yield
        return
    _watchers.append(on_count)
    try:
        yield
    finally:
        _watchers.remove(on_count)


def shared_counts() -> Any:
    """Counters for a pool's workers (:func:`spread`'s ``counts``), one a kind, in shared memory
    the forked workers inherit (the pool's default start method on Linux)."""
    return multiprocessing.Array("q", KINDS)


class CurveRuns:
    """A curve's progress callable (:class:`symimpact._progress.Stages`: stage, done, total)
    that counts each run it is told of as a :data:`CURVE_RUNS` run (:func:`counted`): the runs
    of the curves a design map draws, on whichever process draws them."""

    def __init__(self) -> None:
        self.last: dict[str, int] = {}

    def __call__(self, stage: str, done: int, total: int | None) -> None:
        more = done - self.last.get(stage, 0)
        self.last[stage] = done
        if more > 0:
            counted(CURVE_RUNS, more)


def worker_init(parent: int, shared: Any = None) -> None:
    """Pool workers end with the process that started them: on Linux the kernel sends SIGTERM
    when the parent dies (prctl PR_SET_PDEATHSIG), whatever killed it; Ctrl-C is left to the
    parent, which then ends the pool.  ``shared``: the pool's run counters (:func:`counted`)."""
    import signal

    global IN_WORKER, _SHARED
    IN_WORKER = True
    _SHARED = shared
    # what the parent watched its runs with (a progress bar) is the parent's: a forked worker
    # would otherwise draw it too, from its own copy
    _watchers.clear()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for sig in (signal.SIGTERM, signal.SIGHUP):  # not the handlers a forked worker inherits
        signal.signal(sig, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGTERM))  # PR_SET_PDEATHSIG
    if os.getppid() != parent:  # the parent died before the line above took effect
        os._exit(1)
    from ._threads import blas_on_one_thread_from_now

    blas_on_one_thread_from_now()  # the pool puts one worker on each core already


def can_spread() -> bool:
    """Whether this process may start worker processes: not a worker itself (of this pool, or a
    daemonic one such as a Dask worker's), and called from the main thread (a fork copies only
    the calling thread)."""
    return (
        not IN_WORKER
        and not multiprocessing.current_process().daemon
        and threading.current_thread() is threading.main_thread()
    )


#: The functions this process has run on a warm-up payload (:func:`warm_here`).
_WARMED: set[str] = set()


def warm_here(fn: Callable[[Any], Any], warm: Any) -> None:
    """``fn(warm)`` here, once a process, before workers are forked to run ``fn``: ``warm`` is
    a small payload that takes the same compiled code (one point, one frequency), so that the
    compilation happens once, in this process, and the forked workers inherit it; each worker
    had compiled the same engine at the same time (minutes of every core on a fresh install).
    Nothing when ``warm`` is None or this process has warmed ``fn`` before."""
    if warm is None or _key(fn) in _WARMED:
        return
    fn(warm)
    _WARMED.add(_key(fn))


def _key(fn: Callable[[Any], Any]) -> str:
    return f"{fn.__module__}.{fn.__qualname__}"


#: ``warm`` of :func:`spread` meaning: run the first payload here and yield its result.
FIRST = object()


def spread(
    fn: Callable[[Any], Any], payloads: list, workers: int, warm: Any = None,
    counts: Any = None, on_wait: Callable[[], None] | None = None,
) -> Iterator[Any]:  # fmt: skip
    """``fn(p)`` for each payload on ``workers`` local processes, yielded as they finish, after
    a warm-up here (:func:`warm_here`; ``warm`` :data:`FIRST`: the first payload itself, run
    here once a process and its result yielded, where no smaller payload takes the same code);
    an interrupted, terminated or failed pool does not wait for the runs still going.
    ``counts`` (:func:`shared_counts`): where the workers count their runs (:func:`counted`);
    ``on_wait()`` is called every LOOK seconds while they run."""
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    if warm is FIRST:
        if payloads and _key(fn) not in _WARMED:
            yield fn(payloads[0])
            _WARMED.add(_key(fn))
            payloads = payloads[1:]
    else:
        warm_here(fn, warm)
    if not payloads:
        return
    pool = ProcessPoolExecutor(max_workers=workers, initializer=worker_init,
                               initargs=(os.getpid(), counts))  # fmt: skip
    finished = False
    try:
        pending = {pool.submit(fn, p) for p in payloads}
        while pending:
            done, pending = wait(pending, timeout=LOOK, return_when=FIRST_COMPLETED)
            deliver_pending()
            if on_wait is not None:
                on_wait()
            for f in done:
                yield f.result()
        finished = True
    finally:
        _close(pool, finished)


class Pending:
    """``[fn(p) for p in payloads]`` started at once on ``workers`` processes (where this
    process may start them, :func:`can_spread`, and there is more than one payload), while this
    process goes on (:func:`symimpact.forced.orbits.coverage.attractors` waits at once), after a
    warm-up here (:func:`warm_here`); :meth:`result`
    waits for them, in the payloads' order.  Run here, where it cannot spread, when
    :meth:`result` is called.  :meth:`cancel` ends the workers (a caller
    that fails before it needs the result).  :meth:`counts`: the runs ``fn`` has said ended
    (:func:`counted`), by kind, wherever they ran."""

    def __init__(
        self, fn: Callable[[Any], Any], payloads: list, workers: int, warm: Any = None
    ) -> None:
        self.fn, self.payloads = fn, payloads
        self.pool: Any = None
        self.futures: list = []
        self.shared: Any = None
        self.start = list(_HERE)
        if workers > 1 and len(payloads) > 1 and can_spread():
            from concurrent.futures import ProcessPoolExecutor

            warm_here(fn, warm)

            self.shared = shared_counts()
            self.pool = ProcessPoolExecutor(max_workers=min(workers, len(payloads)),
                                            initializer=worker_init,
                                            initargs=(os.getpid(), self.shared))  # fmt: skip
            self.futures = [self.pool.submit(fn, p) for p in payloads]

    def counts(self) -> tuple[int, ...]:
        """The runs of each kind ended so far (:func:`counted`)."""
        if self.shared is not None:
            with self.shared.get_lock():
                return tuple(self.shared[:])
        return tuple(n - s for n, s in zip(_HERE, self.start, strict=True))

    def result(self, on_wait: Callable[[], None] | None = None) -> list[Any]:
        """The results, in the payloads' order, once every run has ended; ``on_wait`` is called
        while they run (every LOOK seconds, or at each counted run where they run here)."""
        if self.pool is None:
            self.start = list(_HERE)
            with watching(on_wait):
                return [self.fn(p) for p in self.payloads]
        from concurrent.futures import FIRST_EXCEPTION, wait

        finished = False
        try:
            pending = set(self.futures)
            while pending:
                done, pending = wait(pending, timeout=LOOK, return_when=FIRST_EXCEPTION)
                deliver_pending()
                if on_wait is not None:
                    on_wait()
                for f in done:
                    f.result()  # a failed run raises at once, not after the others
            out = [f.result() for f in self.futures]
            finished = True
        finally:
            self._end(finished)
        return out

    def cancel(self) -> None:
        if self.pool is not None:
            self._end(False)

    def _end(self, finished: bool) -> None:
        _close(self.pool, finished)
        self.pool = None


def _close(pool: Any, finished: bool) -> None:
    """Shut ``pool`` down; one that did not finish (interrupted, terminated or failed) does not
    wait for its running runs: its workers are terminated first."""
    if not finished:
        for proc in list((getattr(pool, "_processes", None) or {}).values()):
            proc.terminate()
    pool.shutdown(wait=True, cancel_futures=True)
