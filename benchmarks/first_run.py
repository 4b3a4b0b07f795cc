"""The first run after an install: each command's time with an empty numba cache, split into the
compilations of each engine (the function numba compiled first, outside another; CPU-bound, one
core), then the same command warm.  The figures of symimpact._notices.COMPILE_SECONDS, which
the command line's notice quotes, come from this benchmark's output.  One cold run each (a
cold run fills the cache, so it cannot be repeated in a process); the warm figure is the median
of five.  Prints figures, asserts nothing.
Run from the checkout: python -m benchmarks.first_run
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time

from .timing import timed

SYSTEM = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20mm"]
FORCED = [*SYSTEM, "--force", "2N", "--omega", "34rad/s"]
COMMANDS = [
    ("free simulate", ["simulate", "--gap", "9 mm"]),
    ("forced simulate, rigid", ["simulate", *FORCED, "--contact", "rigid", "--e", "0.6"]),
    ("forced simulate, Hertz", ["simulate", *FORCED, "--contact", "hertz", "--k-hz", "1e6"]),
    ("periodic, rigid", ["periodic", *FORCED, "--contact", "rigid", "--e", "0.6"]),
    ("frf, rigid, one worker", ["frf", *SYSTEM, "--force", "2N", "--omega-range", "30:40:1",
                                "--contact", "rigid", "--e", "0.6", "--workers", "1"]),
    ("random, rigid", ["random", *SYSTEM, "--e", "0.6", "--force-psd", "2 N^2/Hz", "--band", "1:20",
                       "--realisations", "2", "--duration", "10 s"]),
]  # fmt: skip

#: Run in a fresh interpreter: the commands in turn in one process (as a person would meet them,
#: each compiling what the ones before left), numba's compile events timed at the outermost level.
PROBE = """
import json, sys, time
from numba.core import event
depth, start, spent = [0], [0.0], {}
class Timer(event.Listener):
    def on_start(self, ev):
        if depth[0] == 0:
            start[0] = time.process_time()
            d = ev.data["dispatcher"].py_func
            start.append(d.__module__ + "." + d.__qualname__)
        depth[0] += 1
    def on_end(self, ev):
        depth[0] -= 1
        if depth[0] == 0:
            name = start.pop()
            spent[name] = spent.get(name, 0.0) + time.process_time() - start[0]
event.register("numba:compile", Timer())
from symimpact.cli import main
for label, argv in json.loads(sys.argv[1]):
    spent.clear()
    t, c = time.perf_counter(), time.process_time()
    assert main(argv) == 0, label
    print(json.dumps({"label": label, "wall": time.perf_counter() - t,
                      "cpu": time.process_time() - c, "compiles": dict(spent)}), flush=True)
"""


def main() -> None:
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        run = subprocess.run([sys.executable, "-c", PROBE, json.dumps(COMMANDS)], env=env,
                             capture_output=True, text=True)  # fmt: skip
        if run.returncode != 0:
            raise SystemExit(f"the cold runs failed:\n{run.stderr[-3000:]}")
        rows = [json.loads(line) for line in run.stdout.splitlines() if line.startswith("{")]
        print("cold (empty NUMBA_CACHE_DIR, the commands in turn in one process):")
        for r in rows:
            print(f"  {r['label']:<26} {r['wall']:7.1f} s wall, {r['cpu']:7.1f} s CPU")
            for name, seconds in sorted(r["compiles"].items(), key=lambda kv: -kv[1]):
                if seconds >= 0.5:
                    print(f"      compiled {name}: {seconds:.1f} s CPU")
        print("warm (the cache filled above; a fresh process each, median of 5):")
        for label, argv in COMMANDS:
            t = timed(lambda argv=argv: subprocess.run(
                [sys.executable, "-m", "symimpact.cli", *argv], env=env, capture_output=True,
                check=True))  # fmt: skip
            print(f"  {label:<26} {t.s()}")
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "symimpact.cli", "--version"], env=env, check=True,
                       capture_output=True)  # fmt: skip
        print(f"  symimpact --version        {time.perf_counter() - start:.3f} s (one run)")


if __name__ == "__main__":
    main()
