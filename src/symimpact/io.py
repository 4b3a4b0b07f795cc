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


def _fsync(path: str | os.PathLike) -> None:
    """Flush a file's (or a folder's entries') data to the disk."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def output_target(path: str | os.PathLike, what: str) -> Path:
    """The file an output option ``what`` writes, checked before any work is done.

    A symbolic link is written through (the link stays, its target gets the new content), so
    the path returned is the resolved one: two runs given a link and its target see the same
    file (and the same lock).  Refused in one line naming ``what``: a folder that does not
    exist or cannot be written, a path that is a folder, and an existing path that is not a
    regular file (a device such as /dev/null, a FIFO, a socket), which a write by rename would
    replace."""
    target = Path(os.path.realpath(path))
    folder = target.parent
    if not folder.is_dir():
        raise ParameterError(what, f"folder {str(Path(path).parent)!r} does not exist")
    if target.is_dir():
        raise ParameterError(what, f"{str(path)!r} is a folder")
    if target.exists() and not target.is_file():
        raise ParameterError(
            what,
            f"{str(path)!r} is not a regular file (a device, FIFO or socket); outputs are "
            "written to regular files or new paths",
        )
    if not os.access(folder, os.W_OK | os.X_OK):
        raise ParameterError(what, f"cannot write in {str(folder)!r}")
    return target


@contextmanager
def _temporary_beside(
    path: str | os.PathLike, what: str, suffix: str, sync: bool = False
) -> Iterator[str]:
    """A temporary file name beside ``path``, renamed to ``path`` when the block succeeds.

    An interrupted write leaves no partial file under ``path``.  A folder that does not exist or
    cannot be written raises :class:`ParameterError` naming ``what`` (the option).  ``sync``:
    the file is flushed to disk before the rename, and the rename after it (a crash then leaves
    the old or the new file, never an empty one).
    """
    target = output_target(path, what)
    folder = target.parent
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
        if sync:
            _fsync(tmp)
        os.replace(tmp, target)
        if sync:
            _fsync(folder)  # the rename itself
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


#: Every folder that :func:`staged_folder` writes holds this file; ``--force`` replaces only
#: folders that hold it (or empty ones), never a folder of the user's.
MARKER = ".symimpact-output"


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # somebody else's process
        return True
    return True


def _remove_leftovers(parent: Path, name: str) -> None:
    """Remove ``.NAME.partial-PID-*`` and ``.NAME.old-PID-*`` folders that a run killed before it
    could clean up left beside the target (their process is gone)."""
    for p in parent.glob(f".{name}.*-*-*"):
        kind, _, rest = p.name[len(name) + 2 :].partition("-")
        pid = rest.split("-", 1)[0]
        if kind in ("partial", "old") and pid.isdigit() and p.is_dir() and not _alive(int(pid)):
            shutil.rmtree(p, ignore_errors=True)


@contextmanager
def staged_folder(out: str | os.PathLike, force: bool = False) -> Iterator[Path]:
    """Yield a temporary folder beside ``out``; on success it becomes ``out``.

    ``out`` must not exist, or be an empty folder, or (with ``force``) a folder this package
    wrote (it holds :data:`MARKER`), which is then replaced as a whole; any other non-empty
    folder is refused, as are a symbolic link (give the folder itself) and the current folder or
    one that contains it.  If the block fails or is interrupted, the temporary folder is removed
    and ``out`` is left as it was: no half-written output is ever found under ``out``.  Leftover
    temporary folders of killed runs are removed first.
    """
    target = Path(out)
    if target.is_symlink():
        raise ParameterError("out", f"{str(target)!r} is a symbolic link; give the folder itself")
    if target.exists() and not target.is_dir():
        raise ParameterError("out", f"{str(target)!r} exists and is not a folder")
    if target.is_dir():
        here = Path.cwd().resolve()
        if target.resolve() == here or target.resolve() in here.parents:
            raise ParameterError(
                "out", f"{str(target)!r} is the current folder or contains it; choose another"
            )
        if any(target.iterdir()):
            if not force:
                raise ParameterError(
                    "out", f"folder {str(target)!r} is not empty; pass --force to replace it"
                )
            if not (target / MARKER).is_file():
                raise ParameterError(
                    "out",
                    f"folder {str(target)!r} was not written by symimpact (no {MARKER} file); "
                    "--force replaces only symimpact's own output folders",
                )
    parent = target.absolute().parent
    if not parent.is_dir():
        raise ParameterError("out", f"folder {str(parent)!r} does not exist")
    _remove_leftovers(parent, target.name)
    try:
        tmp = Path(tempfile.mkdtemp(dir=parent, prefix=f".{target.name}.partial-{os.getpid()}-"))
    except OSError as exc:
        raise ParameterError("out", f"cannot write in {str(parent)!r}: {exc.strerror}") from None
    try:
        yield tmp
        (tmp / MARKER).write_text(
            "Written by symimpact; `--force` may replace this folder as a whole.\n",
            encoding="utf-8",
        )
        os.chmod(tmp, 0o755)
        if target.exists():
            old = Path(tempfile.mkdtemp(dir=parent, prefix=f".{target.name}.old-{os.getpid()}-"))
            os.replace(target, old / "previous")
            os.replace(tmp, target)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
