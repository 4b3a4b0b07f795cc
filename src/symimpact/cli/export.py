"""``symimpact export``: copy the generated kernels of one target into a folder."""

from __future__ import annotations

from typing import Any

from .common import add_force


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "export",
        help="copy the generated kernels of one target (NumPy, C99, MATLAB/Octave, Rust, Fortran, JAX) into a "
        "folder, with a README on how to compile, call or import them",
    )
    p.add_argument(
        "--target",
        required=True,
        choices=("c", "c-cmake", "octave", "numpy", "rust", "fortran", "jax"),
        help="which kernels (c-cmake: the C target, which is a CMake project, under the name a "
        "CMake user looks for)",
    )
    p.add_argument(
        "--out", required=True, metavar="DIR", help="folder to create (new or empty unless --force)"
    )
    add_force(p)


def run(ns) -> None:
    from ..export import export_kernels

    paths = export_kernels(ns.target, ns.out, force=ns.force)
    print(f"wrote {len(paths)} {ns.target} files to {ns.out} (see {ns.out}/README.md)")


#: The subcommands this module runs.
COMMANDS = {"export": run}
