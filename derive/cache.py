"""The derivation boards kept on disk between processes of one checkout.

Deriving all the steps takes minutes, and a checkout's tools ask for the same boards several
times: ``python -m derive --check``, the documentation build (each step's page is its board) and
the tests that read the boards. ``python -m derive`` (and ``--check``) stores the boards it derived
in ``.cache/boards-<key>.pickle`` at the checkout's root; :func:`boards` loads them from there
when the key matches and derives them (and stores them) otherwise.

The key is a SHA-256 over every ``derive/*.py`` file and the versions of Python, SymPy and
mpmath, so a board is never read back after the code that derived it changed. ``--check`` itself
always derives: it is the check that the derivations emit ``generated/``. The file is written to
a temporary name and renamed, so a process never reads half a file.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import sys
import tempfile
from pathlib import Path

import mpmath
import sympy

from . import STEPS, board

HERE = Path(__file__).resolve().parent
#: Where the boards are kept (ignored by git).
FOLDER = HERE.parent / ".cache"


def key() -> str:
    """A hex digest of what the boards depend on: the derivation code and its libraries."""
    digest = hashlib.sha256()
    for path in sorted(HERE.glob("*.py")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    versions = f"{sys.version}|{sympy.__version__}|{mpmath.__version__}"
    digest.update(versions.encode())
    return digest.hexdigest()[:32]


def path() -> Path:
    """The file the current derivation code's boards are kept in."""
    return FOLDER / f"boards-{key()}.pickle"


def store(boards: dict) -> None:
    """Keep ``boards`` ({step: Board} of every step) for the current derivation code."""
    target = path()
    target.parent.mkdir(exist_ok=True)
    for old in target.parent.glob("boards-*.pickle"):
        if old != target:
            old.unlink(missing_ok=True)  # boards of code that has since changed
    fd, tmp = tempfile.mkstemp(dir=target.parent, suffix=".tmp")
    with os.fdopen(fd, "wb") as out:
        pickle.dump(boards, out, protocol=pickle.HIGHEST_PROTOCOL)
    os.replace(tmp, target)


def boards() -> dict:
    """{step: Board} of every step in lecture order: read back when the current derivation code
    derived them before in this checkout, derived (and kept) otherwise."""
    try:
        with path().open("rb") as f:
            kept = pickle.load(f)
        if list(kept) == list(STEPS):
            return kept
    except (OSError, EOFError, pickle.UnpicklingError):
        pass
    derived = {step: board(step) for step in STEPS}
    store(derived)
    return derived
