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


#: The largest input file read (a structure file, a matrix, a record, a PSD table): a larger
#: file is refused before any of it is read (512 MiB holds a dense 8000 × 8000 matrix as .npy,
#: or a record of tens of millions of samples as text).
MAX_INPUT_BYTES = 512 * 2**20


def input_file(path: object, what: str, limit: int = MAX_INPUT_BYTES) -> Path:
    """The regular file an input option ``what`` names, checked before a byte of it is read.

    Refused in one line naming ``what``: a value that is not a path, a path that does not
    exist, a folder, anything not a regular file once links are followed (a FIFO would block the
    read forever, a device such as /dev/zero never end it) and a file larger than ``limit``
    bytes."""
    import stat

    if not isinstance(path, str | os.PathLike) or isinstance(path, bytes):
        raise ParameterError(what, f"expected a file path, got {type(path).__name__}")
    p = Path(path)
    try:
        st = os.stat(p)  # follows links: a link to /dev/zero is a device
    except FileNotFoundError:
        raise ParameterError(what, f"cannot read {str(p)!r} (no such file)") from None
    except (OSError, ValueError) as exc:
        raise ParameterError(
            what, f"cannot read {str(p)!r} ({getattr(exc, 'strerror', exc)})"
        ) from None
    if stat.S_ISDIR(st.st_mode):
        raise ParameterError(what, f"{str(p)!r} is a folder, not a file")
    if not stat.S_ISREG(st.st_mode):
        raise ParameterError(
            what, f"{str(p)!r} is not a regular file (a FIFO, device or socket); give a file"
        )
    if st.st_size > limit:
        raise ParameterError(
            what,
            f"{str(p)!r} holds {st.st_size / 2**20:.0f} MiB; inputs are read up to "
            f"{limit / 2**20:.0f} MiB",
        )
    return p


def input_text(path: object, what: str, limit: int = MAX_INPUT_BYTES) -> str:
    """The text of the input file ``path`` (UTF-8), checked by :func:`input_file`; a file that
    is not text (a binary file) is refused naming ``what``."""
    p = input_file(path, what, limit)
    try:
        with open(p, "rb") as f:
            raw = f.read(limit + 1)
    except OSError as exc:
        raise ParameterError(what, f"cannot read {str(p)!r} ({exc.strerror})") from None
    if len(raw) > limit:  # grown since it was looked at
        raise ParameterError(what, f"{str(p)!r} is larger than {limit / 2**20:.0f} MiB")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ParameterError(
            what, f"{str(p)!r} is not UTF-8 text (byte {exc.start}: a binary file?)"
        ) from None


def strict_json(text: str, what: str, source: str = "") -> object:
    """``text`` parsed as JSON, refusing what :func:`json.loads` lets pass silently: a key given
    twice in one object (JSON would keep the last; TOML refuses it), and nesting deeper than
    Python's recursion allows.  Refused in one line naming ``what``, the key and its line."""
    import json

    dup: list[str] = []

    def pairs(items: list) -> dict:
        out: dict = {}
        for k, v in items:
            if k in out and not dup:
                dup.append(k)
            out[k] = v
        return out

    try:
        data = json.loads(text, object_pairs_hook=pairs)
    except json.JSONDecodeError as exc:
        raise ParameterError(what, f"{source}is not valid JSON ({exc})") from None
    except RecursionError:  # json recurses once per level of nesting
        raise ParameterError(what, f"{source}nests arrays or objects too deeply to read") from None
    if dup:
        raise ParameterError(
            what,
            f"{source}gives the key {dup[0]!r} twice in one object (line "
            f"{_duplicate_line(text, dup[0])}); give each key once",
        )
    return data


def _duplicate_line(text: str, key: str) -> int:
    """The line of the first key ``key`` repeated in one object of the JSON ``text`` (parsed
    again by the pure-Python scanner, which reports where each object starts and ends)."""
    import json
    import json.decoder
    import json.scanner
    import re

    spans: list[tuple[int, int]] = []
    found: list[int] = []
    pattern = re.compile(re.escape(json.dumps(key)) + r"\s*:")

    def parse_object(s_and_end, *args):
        start = s_and_end[1]
        obj, end = json.decoder.JSONObject(s_and_end, *args)
        if not found:
            inner = [(a, b) for a, b in spans if a >= start]
            hits = [m.start() for m in pattern.finditer(text, start, end)
                    if not any(a <= m.start() < b for a, b in inner)]  # fmt: skip
            if len(hits) > 1:
                found.append(hits[1])
        spans.append((start, end))
        return obj, end

    decoder = json.JSONDecoder(object_pairs_hook=list)
    decoder.parse_object = parse_object
    decoder.scan_once = json.scanner.py_make_scanner(decoder)
    try:
        decoder.decode(text)
    except (ValueError, RecursionError):
        return 0
    return text.count("\n", 0, found[0]) + 1 if found else 0


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
    IN_PROGRESS.add(tmp)
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
    finally:
        IN_PROGRESS.discard(tmp)


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


#: The temporary files and folders being written now (:func:`_temporary_beside`,
#: :func:`staged_folder`): a signal handler that ends the process at once, without unwinding,
#: removes them first (:func:`remove_in_progress`).
IN_PROGRESS: set[str] = set()


def remove_in_progress() -> None:
    """Remove every temporary file or folder still being written (called by the command line's
    signal handler before ``os._exit``, which runs no ``finally`` block)."""
    for p in list(IN_PROGRESS):
        if os.path.isdir(p) and not os.path.islink(p):
            shutil.rmtree(p, ignore_errors=True)
        else:
            try:
                os.unlink(p)
            except OSError:
                pass
        IN_PROGRESS.discard(p)


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
    IN_PROGRESS.add(str(tmp))
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
    finally:
        IN_PROGRESS.discard(str(tmp))
