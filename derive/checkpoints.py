"""Recorded check points: for every kernel and every fixed-point iteration, a few points of the
physical ranges its derivation declares and its value there computed by mpmath at 50 digits.

A target's own test program (the C library's ``check_kernels.c``, run by ``ctest``) checks its
kernels at these points without Python.  The points are written as six-digit decimals, so the
numbers a compiler reads are the numbers mpmath was given, on any machine.

- **Where.**  Argument i of candidate j sits at the fraction u = (1/2 + (j + 1)·α_i) mod 1 of its
  range (log-uniform where the range is declared so), α_i the fractional part of the square
  root of the i-th prime: a Weyl sequence, which fills the box of the ranges evenly and moves no
  two arguments together.  A candidate that breaks one of the kernel's constraints, or where
  its value is not real and finite, is passed over for the next.
- **What.**  The expression itself (``Kernel.expr``), evaluated by mpmath at 50 digits and
  rounded once to the nearest double; for an iteration, mpmath runs the same loop (start, step,
  the stopping rule of :func:`derive.codegen.fixed_point_ast`) at 50 digits and records the
  last iterate and the number of steps.
- **How close.**  ``RTOL`` = 1e-12 of the error scale (the value's size, plus the amplitude of
  an oscillating result, as in ``tests/test_kernels_vs_mpmath.py``): what double arithmetic
  reaches on these formulas where cancellation amplifies rounding (the Python tests' fallback
  bound), far below any error in a formula.  An iteration's step count may differ by one: its
  last step is a comparison of rounded numbers at the tolerance.
"""

from __future__ import annotations

import hashlib
import math
import os
import pickle
from dataclasses import dataclass
from pathlib import Path

import mpmath as mp
import sympy as sp

from .board import Board, FixedPoint, Kernel

#: Points recorded per kernel or iteration.
POINTS = 3
#: mpmath's working precision [decimal digits].
DIGITS = 50
#: Agreement asked of a target at a recorded point, relative to its error scale (module text).
RTOL = 1e-12
#: Candidate points tried before a kernel is declared to have too few valid ones.
CANDIDATES = 2000
_PRIMES = (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71)


@dataclass(frozen=True)
class CheckPoint:
    """One recorded point: ``args`` as the decimal strings a program compiles, ``value`` and
    ``scale`` as ``repr`` of doubles, ``steps`` the iteration's step count (None for a kernel)."""

    args: tuple[str, ...]
    value: str
    scale: str
    steps: int | None = None


def _decimal(arg, u: float) -> str:
    """The point at fraction ``u`` of ``arg``'s range, as a six-digit decimal."""
    if arg.log:
        v = math.exp(math.log(arg.low) + u * (math.log(arg.high) - math.log(arg.low)))
    else:
        v = arg.low + u * (arg.high - arg.low)
    return f"{v:.6g}"


def _candidates(args):
    """Candidate points (tuples of decimal strings) in the order they are tried."""
    alpha = [math.sqrt(p) % 1.0 for p in _PRIMES[: len(args)]]
    for j in range(CANDIDATES):
        yield tuple(_decimal(a, (0.5 + (j + 1) * alpha[i]) % 1.0) for i, a in enumerate(args))


def _real(value) -> mp.mpf | None:
    """``value`` as a real mpf, None where it is complex beyond rounding, infinite or NaN."""
    z = mp.mpc(value)
    if abs(z.imag) > mp.mpf(10) ** (10 - DIGITS) * max(abs(z.real), 1):
        return None
    if not mp.isfinite(z.real):
        return None
    return z.real


def kernel_points(kernel: Kernel) -> list[CheckPoint]:
    """:data:`POINTS` recorded points of ``kernel`` (module text)."""
    symbols = [a.symbol for a in kernel.args]
    exact = sp.lambdify(symbols, kernel.expr, "mpmath")
    magnitude = sp.lambdify(symbols, kernel.magnitude or 0, "mpmath")
    checks = [sp.lambdify(symbols, c, "mpmath") for c in kernel.constraints]
    out: list[CheckPoint] = []
    with mp.workdps(DIGITS):
        for args in _candidates(kernel.args):
            x = [mp.mpf(float(s)) for s in args]
            if not all(c(*x) for c in checks):
                continue
            try:
                value = _real(exact(*x))
            except (ZeroDivisionError, ValueError):
                continue
            if value is None:
                continue
            scale = abs(value) + abs(_real(magnitude(*x)) or 0)
            if scale == 0:
                continue
            out.append(CheckPoint(args, repr(float(value)), repr(float(scale))))
            if len(out) == POINTS:
                return out
    raise ValueError(f"{kernel.name}: fewer than {POINTS} valid points in {CANDIDATES} tried")


def iteration_points(fp: FixedPoint) -> list[CheckPoint]:
    """:data:`POINTS` recorded points of the iteration ``fp`` where mpmath's loop (module text)
    stops within ``fp.max_iter`` steps on a finite iterate."""
    symbols = [a.symbol for a in fp.args]
    start = sp.lambdify(symbols, fp.start, "mpmath")
    step = sp.lambdify([fp.iterate, *symbols], fp.step, "mpmath")
    out: list[CheckPoint] = []
    with mp.workdps(DIGITS):
        tol = mp.mpf(fp.tol)
        for args in _candidates(fp.args):
            x = [mp.mpf(float(s)) for s in args]
            try:
                value, previous, steps = _real(start(*x)), mp.inf, 0
                while value is not None and abs(value - previous) > tol * abs(value):
                    if steps == fp.max_iter:
                        break
                    previous, value, steps = value, _real(step(value, *x)), steps + 1
            except (ZeroDivisionError, ValueError):
                continue
            if value is None or steps >= fp.max_iter or value == 0:
                continue
            out.append(CheckPoint(args, repr(float(value)), repr(float(abs(value))), steps))
            if len(out) == POINTS:
                return out
    raise ValueError(f"{fp.name}: fewer than {POINTS} converging points in {CANDIDATES} tried")


#: Points already found, by the identity of their kernel or iteration (which is kept alive with
#: them): the C, Rust and Fortran backends and the tests ask for the same boards' points, and
#: finding them is most of a derivation's time (mpmath at 50 digits).
_FOUND: dict[int, tuple[object, list[CheckPoint]]] = {}


def _structure(expr, memo: dict) -> bytes:
    """A SHA-256 of ``expr``'s structure: its class and, in order, the digests of its arguments;
    an atom (symbol with its assumptions, number) by ``sympy.srepr``.  Each distinct object is
    hashed once (``memo``, by identity), so a large expression that shares its subexpressions
    costs what its distinct nodes cost, where ``srepr`` of the whole writes every shared one out
    again (50 s for the 175 kernels on the 2-core machine, against 0.17 s this way)."""
    got = memo.get(id(expr))
    if got is None:
        if isinstance(expr, sp.Basic) and expr.args:
            h = hashlib.sha256(type(expr).__name__.encode() + b"(")
            for a in expr.args:
                h.update(_structure(a, memo))
        else:
            h = hashlib.sha256(sp.srepr(expr).encode())
        got = memo[id(expr)] = h.digest()
    return got


def digest(item: Kernel | FixedPoint) -> str:
    """A hex digest of everything the points of ``item`` are found from: its arguments and their
    ranges, and its expressions' structure (:func:`_structure`: the kernel, its magnitude and
    constraints; the iteration's start, step, tolerance and step limit)."""
    if isinstance(item, Kernel):
        exprs = (item.expr, item.magnitude or sp.S.Zero, *item.constraints)
        numbers = ()
    else:
        exprs = (item.iterate, item.start, item.step)
        numbers = (item.tol, item.max_iter)
    memo: dict = {}
    h = hashlib.sha256(type(item).__name__.encode())
    for a in item.args:
        h.update(_structure(a.symbol, memo) + f"|{a.low!r}|{a.high!r}|{a.log}".encode())
    for e in exprs:
        h.update(_structure(sp.sympify(e), memo))
    h.update(repr(numbers).encode())
    return h.hexdigest()


def _kept_path() -> Path:
    """The file that keeps the points found by this module's code (``.cache/`` of the checkout,
    beside the boards of derive/cache.py), under a hash of this file and mpmath's and SymPy's
    versions: points found by other code are never read back."""
    versions = f"{mp.__version__}|{sp.__version__}".encode()
    code = hashlib.sha256(Path(__file__).read_bytes() + b"\0" + versions).hexdigest()[:32]
    from .cache import FOLDER

    return FOLDER / f"points-{code}.pickle"


def _read_kept() -> dict[str, list[CheckPoint]]:
    try:
        with _kept_path().open("rb") as f:
            return pickle.load(f)
    except (OSError, EOFError, pickle.UnpicklingError, AttributeError):
        return {}


def _keep(found: dict[str, list[CheckPoint]]) -> None:
    """Add ``found`` ({digest: points}) to the kept file (written to a temporary name and
    renamed: a process reading it never sees half a file; two writing it at once each write all
    they found with what was there)."""
    from .cache import written

    target = _kept_path()
    try:
        target.parent.mkdir(exist_ok=True)
        for old in target.parent.glob("points-*.pickle"):
            if old != target:
                old.unlink(missing_ok=True)  # points of code that has since changed
        os.replace(written(target.parent, {**_read_kept(), **found}), target)
    except OSError:
        pass  # a read-only checkout: the points are found again next time


def _once(item, find, kept: dict, found: dict) -> list[CheckPoint]:
    got = _FOUND.get(id(item))
    if got is None or got[0] is not item:
        key = digest(item)
        points = kept.get(key)
        if points is None:
            points = found[key] = find(item)
        got = _FOUND[id(item)] = (item, points)
    return got[1]


def recorded(boards: list[Board]) -> dict:
    """``{"kernels": [(module, kernel, points)], "iterations": [(module, fp, points)],
    "bundles": [(module, bundle, [(index, part, points)])]}``; each kernel's and iteration's
    points found once per process (:data:`_FOUND`) and kept on disk for the next one, under the
    :func:`digest` of what they are found from."""
    kept, found = _read_kept(), {}

    def points(item):
        return _once(item, kernel_points if isinstance(item, Kernel) else iteration_points,
                     kept, found)  # fmt: skip

    out = {
        "kernels": [(b.module, k, points(k)) for b in boards for k in b.kernels],
        "iterations": [(b.module, fp, points(fp)) for b in boards for fp in b.fixed_points],
        # a bundle is checked part by part, at each part's own points
        "bundles": [
            (b.module, bu, [(j, k, points(k)) for j, k in enumerate(bu.parts)])
            for b in boards
            for bu in b.bundles
        ],
    }
    if found:
        _keep(found)
    return out
