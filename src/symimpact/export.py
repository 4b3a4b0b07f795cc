"""``symimpact export``: copy the generated kernels of one target into a folder of their own.

The files are the ones ``python -m derive`` emitted into the checkout's ``generated/`` folder and
that ship inside the package (``symimpact.generated``): nothing is re-derived, so the runtime
still needs no SymPy.  Each target's folder carries its README (how to compile, call or import).
"""

from __future__ import annotations

import os
import shutil
from importlib import resources
from pathlib import Path

from .errors import ParameterError
from .io import staged_folder

#: Target → (subfolder of the generated package, file suffixes to copy).
TARGETS: dict[str, tuple[str, tuple[str, ...]]] = {
    "numpy": ("", (".py", ".md")),
    # the C library's CMake project (CMakeLists.txt) and its package templates (*.in)
    "c": ("c", (".c", ".h", ".md", ".txt", ".in")),
    "octave": ("octave", (".m", ".md")),
}


def target_files(target: str) -> list[Path]:
    """The generated files of ``target`` (``numpy``, ``c`` or ``octave``), sorted by name."""
    if target not in TARGETS:
        raise ParameterError("target", f"must be one of {', '.join(TARGETS)}, got {target!r}")
    sub, suffixes = TARGETS[target]
    folder = Path(str(resources.files("symimpact.generated")))
    folder = folder / sub if sub else folder
    files = sorted(p for p in folder.iterdir() if p.is_file() and p.suffix in suffixes)
    if not any(p.name == "README.md" for p in files):
        raise ParameterError("target", f"{target}: the installed package lacks its generated files")
    return files


def export_kernels(target: str, out: str | os.PathLike, force: bool = False) -> list[Path]:
    """Copy the kernels of ``target`` into the folder ``out``; returns the written paths.

    ``out`` must be new or empty unless ``force`` (then it is replaced as a whole).  The folder is
    written beside ``out`` and renamed at the end, so an interrupted export leaves nothing under
    ``out``.  Implements no equation itself: the files document theirs (Eq. 1–35).
    """
    files = target_files(target)
    with staged_folder(out, force=force) as tmp:
        for path in files:
            shutil.copyfile(path, tmp / path.name)
    return [Path(out) / p.name for p in files]
