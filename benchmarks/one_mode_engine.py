"""The paper's one-mode system through the engine of several modes against the dedicated
one-mode engine it replaced (issue 36: "no slower").  The previous engine is read from the
repository's history (``src/symimpact/forced/engine/_rigid.py`` before commit 5d693b1, where its run
was removed) and compiled in this run beside the current one; both simulate the same rigid-impact
runs from rest, and the figures are medians of seven repeats each.

1. The README's system: M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, e 0.6, 2 N at
   30 rad/s, 200 periods.
2. Chatter: M 40 kg, K 227 396 N/m (12 Hz), C 60.3 N s/m, m 2 kg, d 10 mm, e 0.16 (the
   report's contact), 50 N at 12 Hz, 200 periods.

The event counts are printed beside the times, and the largest difference of the two engines'
impact times over their common events (the README case drifts apart late in its transient: its
impact times agree to rounding at first and the differences grow, as any two orderings of the
arithmetic do on a sensitive motion).  Asserts nothing.  Run from the checkout:
python -m benchmarks.one_mode_engine
"""

from __future__ import annotations

import importlib.util
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from symimpact._interrupt import NO_WATCH
from symimpact.forced.engine._modal import one_mode_run
from symimpact.forced.engine._rigid import N_PARAMS

from .timing import timed

#: The last commit whose ``_rigid.py`` held the dedicated one-mode run.
PREVIOUS = "5d693b1^"


def _previous_engine():
    """The pre-5d693b1 ``_rigid`` module, loaded as ``symimpact.forced._rigid_previous`` (its
    relative imports resolve in the package), or None where the history is not at hand."""
    root = Path(__file__).resolve().parents[1]
    try:
        source = subprocess.run(["git", "show", f"{PREVIOUS}:src/symimpact/forced/engine/_rigid.py"],
                                cwd=root, capture_output=True, text=True, check=True).stdout  # fmt: skip
    except (OSError, subprocess.CalledProcessError):
        return None
    path = Path(tempfile.mkdtemp(prefix="symimpact-previous-")) / "_rigid_previous.py"
    path.write_text(source, encoding="utf-8")
    name = "symimpact.forced._rigid_previous"
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def _params(M, K, C, m, h, e, F0, W):
    """The one-mode parameter vector (the layout both engines share)."""
    p = np.zeros(N_PARAMS)
    p[:] = [M, K, C, m, h, e, F0, 0.0, W, 0.0, 1e-7, 0.0]
    return p


CASES = {
    "README system, 200 periods": _params(1.0, 1000.0, 0.5, 0.05, 0.01, 0.6, 2.0, 30.0),
    "chatter (e 0.16, 12 Hz), 200 periods": _params(
        40.0, 227396.0, 60.3, 2.0, 0.005, 0.16, 50.0, 2 * math.pi * 12.0
    ),
}


def main() -> None:
    old = _previous_engine()
    if old is None:
        print(f"the previous engine ({PREVIOUS}) is not in this checkout's history: skipped")
        return
    for name, p in CASES.items():
        s0 = np.zeros(4)
        t_end = 200 * 2 * math.pi / p[8]

        def previous(p=p, s0=s0, t_end=t_end):
            return old.run(p, s0, t_end, 10**6, NO_WATCH.copy())

        def current(p=p, s0=s0, t_end=t_end):
            return one_mode_run(p, s0, t_end, 10**6, False, True, NO_WATCH.copy())

        previous()  # compiled before timing
        current()
        a, b = timed(previous, repeat=7), timed(current, repeat=7)
        n = min(a.out[2], b.out[2])
        first = np.abs(a.out[1][:n, 0] - b.out[1][:n, 0])
        print(f"{name}: previous engine {a.s()}, {a.out[2]} events; engine of several modes "
              f"{b.s()}, {b.out[2]} events; impact times agree to {first[:20].max():.1e} s over "
              f"the first 20 events")  # fmt: skip
        print(f"  ratio current / previous: {b.median / a.median:.2f}  (target <= 1)")


if __name__ == "__main__":
    main()
