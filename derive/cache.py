"""The derivation boards kept on disk between processes of one checkout, one file per step.

Deriving all the steps takes minutes, and a checkout's tools ask for the same boards several
times: ``python -m derive --check``, the documentation build (each step's page is its board) and
the tests that read the boards. ``python -m derive`` (and ``--check``) stores each board it derived
in ``.cache/<step>-<key>.pickle`` at the checkout's root; :func:`boards` loads them from there
when the key matches and derives them (and stores them) otherwise.

A step's key is a SHA-256 over the code its board depends on — its own module, the package's
``__init__.py`` (the seeds) and every module of ``derive/`` those import, transitively (the board,
the checks' helpers, other steps: ``modal_structure`` reads ``forced_flight``, which reads
``free_flight``) — and the versions of Python, SymPy and mpmath. A board is never read back after
the code that derived it changed; a change to one step leaves the other steps' boards valid, so
``python -m derive --check --reuse`` derives again only what changed. ``--check`` alone always
derives: it is the check that the derivations emit ``generated/``. A file is written to a
temporary name and renamed, so a process never reads half a file.

A board is read back as it was stored (:func:`load`: expressions rebuilt from their stored
arguments, not evaluated again), and :func:`store` reads each board back before keeping it and
keeps it only when every value and expression came back the same (:func:`differences`).
"""

from __future__ import annotations

import ast
import hashlib
import os
import pickle
import sys
import tempfile
import time
from pathlib import Path

import mpmath
import sympy
from sympy.core.function import Application
from sympy.core.operations import AssocOp
from sympy.core.power import Pow

from . import STEPS, board

HERE = Path(__file__).resolve().parent
#: Where the boards are kept (ignored by git).
FOLDER = HERE.parent / ".cache"


def imported_modules(path: Path, names: set[str]) -> set[str]:
    """The modules among ``names`` (module names of the ``derive`` package) that the module at
    ``path`` imports, in any form and anywhere in it (a function's body too):
    ``from .free_flight import …``, ``from . import ritz``, ``import derive.ritz``."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if node.level == 1 or (node.level == 0 and module.split(".")[0] == "derive"):
                parts = module.split(".")[1:] if node.level == 0 else module.split(".")
                parts = [p for p in parts if p]
                if parts:
                    found.add(parts[0])
                else:  # from . import x, y / from derive import x, y
                    found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                parts = alias.name.split(".")
                if parts[0] == "derive" and len(parts) > 1:
                    found.add(parts[1])
    return found & names


def sources(step: str, folder: Path = HERE) -> list[Path]:
    """The files of ``folder`` (the ``derive`` package) that the board of ``step`` depends on:
    the step's module and the package's ``__init__.py`` (its seeds), and every module of the
    package those import, transitively; sorted by name."""
    files = {p.stem: p for p in folder.glob("*.py")}
    if step not in files or step not in STEPS:
        raise ValueError(f"step: no step module {step}.py in {folder}")
    needed, todo = set(), [step, "__init__"]
    while todo:
        name = todo.pop()
        if name in needed:
            continue
        needed.add(name)
        todo.extend(imported_modules(files[name], set(files)) - needed)
    return sorted((files[name] for name in needed), key=lambda p: p.name)


def key(step: str, folder: Path = HERE) -> str:
    """A hex digest of what the board of ``step`` depends on: :func:`sources` and the libraries."""
    digest = hashlib.sha256()
    for path in sources(step, folder):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    versions = f"{sys.version}|{sympy.__version__}|{mpmath.__version__}"
    digest.update(versions.encode())
    return digest.hexdigest()[:32]


def path(step: str) -> Path:
    """The file the board of ``step`` is kept in, for the current derivation code."""
    return FOLDER / f"{step}-{key(step)}.pickle"


def store(step: str, kept_board) -> list[str]:
    """Keep ``kept_board`` (the Board of ``step``) for the current derivation code, and read it
    back: returns :func:`differences` between the two, [] when the board read back is the board
    given (a board that does not come back the same is not kept)."""
    target = path(step)
    target.parent.mkdir(exist_ok=True)
    for old in target.parent.glob(f"{step}-*.pickle"):
        if old != target:
            old.unlink(missing_ok=True)  # the board of code that has since changed
    for old in target.parent.glob("boards-*.pickle"):
        old.unlink(missing_ok=True)  # the one file of every step that this layout replaced
    tmp = written(target.parent, kept_board)
    with open(tmp, "rb") as f:
        off = differences(kept_board, load(f))
    if off:
        os.unlink(tmp)
    else:
        os.replace(tmp, target)
    return off


def derived_and_kept(step: str) -> tuple[str, list[str], float]:
    """Derive ``step`` and keep its board: (step, :func:`store`'s differences, seconds).  What a
    worker process of ``python -m derive --jobs N`` runs (a function of an importable module:
    a spawned worker finds it by name)."""
    t0 = time.perf_counter()
    return step, store(step, board(step)), time.perf_counter() - t0


def written(folder: Path, obj) -> str:
    """The path of a new temporary file in ``folder`` holding ``obj`` pickled; the caller renames
    it into place (``os.replace``), so a process reading the kept file never sees half of it."""
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=".tmp")
    with os.fdopen(fd, "wb") as out:
        pickle.dump(obj, out, protocol=pickle.HIGHEST_PROTOCOL)
    return tmp


def _as_stored(cls):
    """A stand-in for ``cls`` whose construction (pickle's NEWOBJ, ``cls.__new__(cls, *args)``)
    returns ``cls(*args, evaluate=False)``: the stored expression, not evaluated again."""

    def new(_, *args):
        return cls(*args, evaluate=False)

    return type(f"{cls.__name__}AsStored", (), {"__new__": new})


class _Unpickler(pickle.Unpickler):
    """Reads a board back as it was stored.  Sums, products, powers and function applications
    (``conjugate``, ``exp``, ``sin``, …) are built from their pickled arguments unevaluated: those
    are the arguments of an expression SymPy already evaluated, so building it again from them
    gives the stored expression, where evaluating them again (assumption queries on every power
    and product, whose order follows Python's hash seed) took 60–74 s for one board of
    ``slow_flow`` under three seeds of four on the 2-core machine, and 0.5 s under the fourth.
    Everything else (``Sum``, ``Integral``, relations, numbers) is built as pickle builds it:
    ``Sum`` and ``Integral`` built unevaluated gain a factor 1."""

    def find_class(self, module: str, name: str):
        cls = super().find_class(module, name)
        if isinstance(cls, type) and issubclass(cls, (AssocOp, Pow, Application)):
            return _as_stored(cls)
        return cls


def load(file):
    """The board pickled in the binary ``file``, read back as it was stored (:class:`_Unpickler`)."""
    return _Unpickler(file).load()


def _leaves(obj, where: str, out: dict) -> dict:
    """{path: text} of every leaf of ``obj`` (a board and what it holds): SymPy objects as
    ``srepr`` writes them (their structure, argument by argument), other values by ``repr``."""
    if isinstance(obj, sympy.Basic):
        out[where] = sympy.srepr(obj)
    elif isinstance(obj, dict):
        for k, v in obj.items():
            _leaves(v, f"{where}[{k!r}]", out)
    elif isinstance(obj, (list, tuple)):
        for k, v in enumerate(obj):
            _leaves(v, f"{where}[{k}]", out)
    elif hasattr(obj, "__dict__") and not isinstance(obj, type):
        for k, v in vars(obj).items():
            _leaves(v, f"{where}.{k}", out)
    else:
        out[where] = repr(obj)
    return out


def differences(a, b) -> list[str]:
    """Where the boards ``a`` and ``b`` differ: the paths of the leaves (values, expressions as
    ``srepr`` writes them) that one has and the other has not or has otherwise; [] when equal."""
    left, right = _leaves(a, "board", {}), _leaves(b, "board", {})
    return sorted(k for k in left.keys() | right.keys() if left.get(k) != right.get(k))


def kept(step: str):
    """The Board of ``step`` kept for the current derivation code, or None when there is none."""
    try:
        with path(step).open("rb") as f:
            return load(f)
    except (OSError, EOFError, pickle.UnpicklingError, AttributeError):
        return None


def boards() -> dict:
    """{step: Board} of every step in lecture order: read back when the current derivation code
    derived them before in this checkout, derived (and kept) otherwise."""
    out = {}
    for step in STEPS:
        out[step] = kept(step)
        if out[step] is None:
            out[step] = board(step)
            store(step, out[step])  # not kept when it would not come back the same
    return out
