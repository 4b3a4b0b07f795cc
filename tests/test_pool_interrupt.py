"""A Ctrl-C while a :func:`symimpact._interrupt.stretch` waits on worker processes
(:class:`symimpact._pool.Pending`, :func:`symimpact._pool.spread`).

Inside a stretch SIGINT is only recorded, to be delivered after the next compiled call; the
workers ignore it.  ``frf``'s multi-start waits on its workers inside such a stretch, and a
Ctrl-C there waited for their runs to end (measured: up to 4 s, against the 3 s that
tests/test_signals.py allows).  Here, in a child process of its own (pytest's handlers stay out
of it), two workers sleep 20 s while the child waits on them inside a stretch, and the child
sends itself SIGINT 1 s after the wait began: the KeyboardInterrupt must come within 2 s of the
signal (the waits look every 0.05 s; the rest is the workers' termination and the pool's
shutdown, well under a second here), not after the 20 s."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent(
    """
    import os, signal, sys, threading, time
    from symimpact import _interrupt, _pool

    # Ctrl-C as a terminal's command has it: a job a shell starts in the background inherits
    # SIGINT ignored (POSIX), and so does every process it starts, this one included
    signal.signal(signal.SIGINT, signal.default_int_handler)

    def sleeper(x):
        time.sleep(20.0)
        return x

    def main(how):
        with _interrupt.stretch():
            sent = []
            def send():
                sent.append(time.monotonic())
                os.kill(os.getpid(), signal.SIGINT)
            threading.Timer(1.0, send).start()
            try:
                if how == "pending":
                    _pool.Pending(sleeper, [1, 2], 2).result()
                else:
                    list(_pool.spread(sleeper, [1, 2], 2))
            except KeyboardInterrupt:
                print(f"{time.monotonic() - sent[0]:.3f}")
                return 0
        return 1

    sys.exit(main(sys.argv[1]))
    """
)


@pytest.mark.parametrize("how", ["pending", "spread"])
def test_a_ctrl_c_while_a_stretch_waits_on_workers_ends_the_wait(how):
    done = subprocess.run([sys.executable, "-c", SCRIPT, how], capture_output=True, text=True,
                          timeout=60)  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert float(done.stdout) < 2.0
