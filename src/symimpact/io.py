"""Output files written atomically: a temporary file in the target folder, renamed at the end."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO

from .errors import ParameterError


def atomic_write(path: str | os.PathLike, write: Callable[[IO[str]], None], what: str) -> Path:
    """Call ``write(file)`` on a temporary file beside ``path`` and rename it to ``path``.

    An interrupted write leaves no partial file under ``path``.  A folder that does not exist or
    cannot be written raises :class:`ParameterError` naming ``what`` (the option).
    """
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise ParameterError(what, f"folder {str(folder)!r} does not exist")
    if target.is_dir():
        raise ParameterError(what, f"{str(target)!r} is a folder")
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{target.name}.", suffix=".tmp")
    except OSError as exc:
        raise ParameterError(what, f"cannot write in {str(folder)!r}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "w", newline="") as f:
            write(f)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return target


def atomic_savefig(fig, path: str | os.PathLike, what: str = "plot") -> Path:
    """Save a matplotlib figure as PNG atomically (see :func:`atomic_write`)."""
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise ParameterError(what, f"folder {str(folder)!r} does not exist")
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{target.name}.", suffix=".png")
    except OSError as exc:
        raise ParameterError(what, f"cannot write in {str(folder)!r}: {exc.strerror}") from None
    os.close(fd)
    try:
        fig.savefig(tmp, format="png", dpi=120)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return target
