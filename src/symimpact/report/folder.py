"""The report folder, written atomically: a hidden temporary folder beside it, renamed at the end."""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from ..errors import ParameterError


@contextmanager
def staged_folder(out: str | os.PathLike, force: bool = False) -> Iterator[Path]:
    """Yield a temporary folder beside ``out``; on success it becomes ``out``.

    ``out`` must not exist, or be an empty folder, or (with ``force``) any folder, which is then
    replaced as a whole.  If the block fails or is interrupted, the temporary folder is removed
    and ``out`` is left as it was: no half-written report is ever found under ``out``.
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
            os.replace(target, old / "report")
            os.replace(tmp, target)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
