"""Worker processes do not compile the engine at the same time: before a pool forks, the process
runs its function once on a small payload (:func:`symimpact._pool.warm_here`), and the workers
inherit what that compiled.  On a fresh install each worker of ``frf``'s multi-start and of a
map had compiled the same engine at once (the engine issue: a design sat at "0/10" for 42
minutes).

Here "compiling" is a module-level flag that a process's first call sets, as numba's dispatcher
keeps its compiled code: with a warm-up every payload runs in a process that had it set (the
workers are forked from the warmed parent); the control, without one, has workers that set it
themselves.  Where no smaller payload takes the same code (a design map's clearance), the first
payload itself runs here and its result is kept.  In a child process of its own, so that the
pools fork a plain interpreter.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

SCRIPT = textwrap.dedent(
    """
    import json, os
    from symimpact import _pool

    COMPILED = set()

    def run(x):
        # (payload, whether this process's code was compiled by an earlier call, worker?)
        compiled_before = bool(COMPILED)
        COMPILED.add(x)
        return [x, compiled_before, os.getpid() != PARENT]

    def pending(x):
        return run(x)

    def spread(x):
        return run(x)

    def control(x):
        return run(x)

    def first(x):
        return run(x)

    PARENT = os.getpid()
    out = {
        "pending": _pool.Pending(pending, [1, 2, 3, 4], 2, warm=0).result(),
        "spread": list(_pool.spread(spread, [1, 2, 3, 4], 2, warm=0)),
    }
    COMPILED.clear()
    out["control"] = list(_pool.spread(control, [1, 2, 3, 4], 2))
    COMPILED.clear()
    out["first"] = list(_pool.spread(first, [1, 2, 3, 4], 2, warm=_pool.FIRST))
    print(json.dumps(out))
    """
)


def test_workers_inherit_the_warm_up_instead_of_compiling_each():
    run = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True,
                         timeout=120)  # fmt: skip
    assert run.returncode == 0, run.stderr[-2000:]
    out = json.loads(run.stdout)
    for how in ("pending", "spread"):
        rows = out[how]
        assert sorted(r[0] for r in rows) == [1, 2, 3, 4]
        assert all(r[2] for r in rows), rows  # each payload ran on a worker
        assert all(r[1] for r in rows), rows  # … whose code the warm-up had compiled
    control = out["control"]
    assert all(r[2] for r in control)
    assert not all(r[1] for r in control), control  # without it, workers compile themselves
    # FIRST: the first payload runs here (its result kept), the others on warmed workers
    first = out["first"]
    assert first[0][0] == 1 and sorted(r[0] for r in first) == [1, 2, 3, 4]
    assert first[0][2] is False and all(r[2] and r[1] for r in first[1:]), first
