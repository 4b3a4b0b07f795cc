"""``python -m derive [--check] [--reuse] [--notebooks DIR]``: re-derive and write ``generated/``.

Prints one row per derived result (name, paper equation, check status, time).  With ``--reuse``
the steps whose code did not change since their boards were kept (derive/cache.py) are read back
and only the others derived.  With ``--check`` nothing is written: the files are regenerated in
memory and compared with ``generated/``; any difference, missing or stale file is shown as a
unified diff and the exit status is 1.
"""

from __future__ import annotations

import argparse
import difflib
import sys
import time
from pathlib import Path

from . import (
    STEPS,
    backend_c,
    backend_fortran,
    backend_jax,
    backend_octave,
    backend_rust,
    board,
    cache,
)
from .codegen import (
    render_errata,
    render_fixed_points,
    render_module,
    render_package_init,
    render_template,
)

ROOT = Path(__file__).resolve().parent.parent
GENERATED = ROOT / "generated"


def _derived_in_workers(steps: list[str], jobs: int) -> dict[str, tuple[list[str], float]]:
    """Each of ``steps`` derived and kept by one of ``jobs`` worker processes, started afresh
    (``spawn``): each has its own interpreter, so its own hash seed (Python's random one unless
    PYTHONHASHSEED is set), and no step's work depends on another's (:func:`derive.board`)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
        return {step: (off, s) for step, off, s in pool.map(cache.derived_and_kept, steps)}


def generate(
    steps: tuple[str, ...] = STEPS, verbose: bool = True, reuse: bool = False, jobs: int = 1
):
    """Run the steps; return ({relative path: text}, [boards], all checks passed, [the steps
    derived, not read back]).

    Each derived board is kept for the docs build and the tests (derive/cache.py).  With
    ``reuse`` a step whose code is unchanged since its board was kept is read back, not derived;
    its rows show ``kept`` for a time.  With ``jobs`` above 1 the steps to derive are derived
    by that many worker processes, and their boards read back from where the workers kept them
    (the files are then rendered from the boards as read back, which :func:`cache.store` checked
    to be the boards derived)."""
    boards, derived = [], []
    ok = True
    if verbose:
        print(f"{'result':<52} {'paper Eq.':<10} {'status':<13} {'time':>8}")
        print("-" * 86)
    kept = {step: cache.kept(step) for step in steps} if reuse else {}
    todo = [step for step in steps if kept.get(step) is None]
    in_workers = _derived_in_workers(todo, jobs) if jobs > 1 and len(todo) > 1 else {}
    for step in steps:
        t0 = time.perf_counter()
        b = cache.kept(step) if step in in_workers else kept.get(step)
        was_kept = b is not None and step not in in_workers
        if step in in_workers:
            off, seconds = in_workers[step]
            t0 -= seconds
            if b is None:  # not kept: the board did not read back the same
                b = board(step)
        elif b is None:
            b = board(step)
            off = cache.store(step, b)
        if not was_kept:
            if off:  # the docs build and the tests would read another board than this one
                ok = False
                print(f"{step}: its board read back from .cache/ differs at {', '.join(off[:3])}")
            derived.append(step)
        boards.append(b)
        for c in b.checks:
            ok &= c.ok
            if verbose:
                seconds = f"{'kept':>8}" if was_kept else f"{c.seconds:>7.2f}s"
                print(f"{c.name[:52]:<52} {c.equation:<10} {c.status:<13} {seconds}")
                if not c.ok:
                    print(f"    {c.detail}")
        if verbose:
            seconds = f"{'kept':>8}" if was_kept else f"{time.perf_counter() - t0:>7.2f}s"
            print(f"{'  = step ' + step:<52} {b.equations:<10} {'':<13} {seconds}")
    files = {f"{b.module}.py": render_module(b) for b in boards}
    files["_broadcast.py"] = render_template("broadcast.py.j2")
    files["__init__.py"] = render_package_init(boards)
    files["errata.md"] = render_errata(boards)
    files["README.md"] = render_template(
        "README.md.j2",
        template="derive/templates/README.md.j2",
        boards=boards,
        n_kernels=sum(len(b.kernels) for b in boards),
    )
    files["fixed_points.py"] = render_fixed_points(boards)
    files.update(backend_c.render(boards))
    files.update(backend_octave.render(boards))
    files.update(backend_rust.render(boards))
    files.update(backend_fortran.render(boards))
    files.update(backend_jax.render(boards))
    return files, boards, ok, derived


def _present(folder: Path) -> set[str]:
    """Generated files under ``folder`` (relative paths; caches and hidden files left out)."""
    if not folder.exists():
        return set()
    return {
        p.relative_to(folder).as_posix()
        for p in folder.rglob("*")
        if p.is_file()
        and "__pycache__" not in p.parts
        and not p.name.startswith(".")
        and not p.name.endswith(".pyc")
    }


def compare(files: dict[str, str], folder: Path = GENERATED) -> list[str]:
    """Unified diffs between ``files`` and the folder (missing and stale files included)."""
    diffs = []
    present = _present(folder)
    for name in sorted(set(files) | present):
        old = (folder / name).read_text() if name in present else ""
        new = files.get(name, "")
        if old != new:
            diffs.extend(
                difflib.unified_diff(
                    old.splitlines(keepends=True),
                    new.splitlines(keepends=True),
                    f"generated/{name}" if name in present else "/dev/null",
                    f"generated/{name} (regenerated)" if name in files else "/dev/null",
                )
            )
    return diffs


def _notebooks(folder: str) -> int:
    try:
        from .notebooks import write_notebooks

        print(f"writing one notebook per derivation step into {folder}/", flush=True)
        write_notebooks(folder, say=lambda path, s: print(f"wrote {path} ({s:.1f} s)", flush=True))
    except ModuleNotFoundError as exc:
        print(
            f"--notebooks: {exc.name} is not installed (pip install -e '.[teach]')", file=sys.stderr
        )
        return 2
    except BrokenPipeError:  # the output piped into a program that stopped reading (head)
        sys.stderr.close()
        return 0
    except OSError as exc:
        print(f"--notebooks: cannot write to {folder!r} ({exc.strerror})", file=sys.stderr)
        return 2
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m derive", description=__doc__)
    parser.add_argument(
        "--check",
        action="store_true",
        help="regenerate in memory; exit 1 with a diff if generated/ differs",
    )
    parser.add_argument(
        "--reuse",
        action="store_true",
        help="read back the board of every step whose code is unchanged since it was kept in "
        ".cache/ (derive/cache.py) and derive only the others",
    )
    parser.add_argument("--quiet", action="store_true", help="print no summary table")
    parser.add_argument(
        "--jobs",
        type=int,
        default=1,
        metavar="N",
        help="derive the steps in N worker processes, each with its own hash seed (default 1)",
    )
    parser.add_argument(
        "--notebooks",
        metavar="DIR",
        help="write one Jupyter notebook per step into DIR (needs nbformat: the teach extra) "
        "and nothing else",
    )
    args = parser.parse_args(argv)
    if args.notebooks is not None:
        return _notebooks(args.notebooks)
    t0 = time.perf_counter()
    if args.jobs < 1:
        parser.error(f"--jobs: {args.jobs} is not a number of processes (1 or more)")
    files, boards, ok, derived = generate(verbose=not args.quiet, reuse=args.reuse, jobs=args.jobs)
    n_errata = sum(len(b.errata) for b in boards)
    n_kernels = sum(len(b.kernels) for b in boards)
    print(
        f"\n{len(boards)} steps, {n_kernels} kernels, {n_errata} errata; "
        f"derived in {time.perf_counter() - t0:.1f}s"
    )
    if args.reuse:
        print(f"derived again: {', '.join(derived) or 'none'}; the other steps' boards read back")
    if not ok:
        print("some derivation checks FAILED", file=sys.stderr)
    if args.check:
        diffs = compare(files)
        if diffs:
            sys.stdout.writelines(diffs)
            print("\ngenerated/ is out of date: run `python -m derive`", file=sys.stderr)
            return 1
        print("generated/ is up to date")
        return 0 if ok else 1
    GENERATED.mkdir(exist_ok=True)
    for name in _present(GENERATED) - set(files):
        if name.endswith((".py", ".md", ".c", ".h", ".m")):
            (GENERATED / name).unlink()
            print(f"removed stale generated/{name}")
    for name, text in sorted(files.items()):
        path = GENERATED / name
        path.parent.mkdir(exist_ok=True)
        if not path.exists() or path.read_text() != text:
            path.write_text(text)
            print(f"wrote generated/{name}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
