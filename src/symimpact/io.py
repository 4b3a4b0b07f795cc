"""Output written atomically: a temporary file (or folder) beside the target, renamed at the end."""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO

from .errors import ParameterError


@contextmanager
def _temporary_beside(path: str | os.PathLike, what: str, suffix: str) -> Iterator[str]:
    """A temporary file name beside ``path``, renamed to ``path`` when the block succeeds.

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
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{target.name}.", suffix=suffix)
    except OSError as exc:
        raise ParameterError(what, f"cannot write in {str(folder)!r}: {exc.strerror}") from None
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; the result gets a normal file's mode
    try:
        yield tmp
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def atomic_write(path: str | os.PathLike, write: Callable[[IO[str]], None], what: str) -> Path:
    """Call ``write(file)`` on a temporary text file beside ``path`` and rename it to ``path``."""
    with _temporary_beside(path, what, ".tmp") as tmp, open(tmp, "w", newline="") as f:
        write(f)
    return Path(path)


def atomic_savefig(fig, path: str | os.PathLike, what: str = "plot") -> Path:
    """Save a matplotlib figure as PNG atomically (see :func:`atomic_write`)."""
    with _temporary_beside(path, what, ".png") as tmp:
        fig.savefig(tmp, format="png", dpi=120)
    return Path(path)


@contextmanager
def staged_folder(out: str | os.PathLike, force: bool = False) -> Iterator[Path]:
    """Yield a temporary folder beside ``out``; on success it becomes ``out``.

    ``out`` must not exist, or be an empty folder, or (with ``force``) any folder, which is then
    replaced as a whole.  If the block fails or is interrupted, the temporary folder is removed
    and ``out`` is left as it was: no half-written output is ever found under ``out``.
    """
    target = Path(out)
    if target.exists() and not target.is_dir():
        raise ParameterError("out", f"{str(target)!r} exists and is not a folder")
    if target.is_dir() and any(target.iterdir()) and not force:
        raise ParameterError(
            "out", f"folder {str(target)!r} is not empty; pass --force to replace it"
        )
    parent = target.absolute().parent
    if not parent.is_dir():
        raise ParameterError("out", f"folder {str(parent)!r} does not exist")
    try:
        tmp = Path(tempfile.mkdtemp(dir=parent, prefix=f".{target.name}.partial-"))
    except OSError as exc:
        raise ParameterError("out", f"cannot write in {str(parent)!r}: {exc.strerror}") from None
    try:
        yield tmp
        os.chmod(tmp, 0o755)
        if target.exists():
            old = Path(tempfile.mkdtemp(dir=parent, prefix=f".{target.name}.old-"))
            os.replace(target, old / "previous")
            os.replace(tmp, target)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
