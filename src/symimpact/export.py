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

#: Target → (subfolder of the generated package, file suffixes to copy, whether its subfolders
#: are part of it).
TARGETS: dict[str, tuple[str, tuple[str, ...], bool]] = {
    "numpy": ("", (".py", ".md"), False),
    # the C library's CMake project (CMakeLists.txt) and its package templates (*.in)
    "c": ("c", (".c", ".h", ".md", ".txt", ".in"), False),
    # the same files under the name a CMake user looks for: the C target is a CMake project
    "c-cmake": ("c", (".c", ".h", ".md", ".txt", ".in"), False),
    "octave": ("octave", (".m", ".md"), False),
    # a crate: Cargo.toml, src/lib.rs, tests/check_kernels.rs
    "rust": ("rust", (".toml", ".rs", ".md"), True),
    "fortran": ("fortran", (".f90", ".md"), False),
    "jax": ("jax", (".py", ".md"), False),
}


def _folder(target: str) -> Path:
    sub = TARGETS[target][0]
    folder = Path(str(resources.files("symimpact.generated")))
    return folder / sub if sub else folder


def target_files(target: str) -> list[Path]:
    """The generated files of ``target`` (one of :data:`TARGETS`), sorted by path."""
    if target not in TARGETS:
        raise ParameterError("target", f"must be one of {', '.join(TARGETS)}, got {target!r}")
    _, suffixes, deep = TARGETS[target]
    folder = _folder(target)
    found = folder.rglob("*") if deep else folder.iterdir()
    files = sorted(p for p in found if p.is_file() and p.suffix in suffixes
                   and not {"target", "__pycache__"} & set(p.relative_to(folder).parts))  # fmt: skip
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
    folder = _folder(target)
    names = [p.relative_to(folder) for p in files]
    with staged_folder(out, force=force) as tmp:
        for path, name in zip(files, names, strict=True):
            (tmp / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, tmp / name)
    return [Path(out) / name for name in names]
