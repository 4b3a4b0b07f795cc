"""``symimpact reproduce``: the paper's tables and figures beside ours, as a report folder."""

from __future__ import annotations

from typing import Any

from .common import add_force, progress_drawn


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "reproduce",
        help="the paper's tables and figures beside ours, as a report folder (HTML, Markdown, "
        "PNG, CSV)",
    )
    p.add_argument(
        "out",
        nargs="?",
        default=None,
        help="report folder (created; must be new or empty unless --force); without it the "
        "command prints what it would write and stops, unless --quick (then symimpact-report)",
    )
    p.add_argument(
        "--quick",
        action="store_true",
        help="coarser grids, for a look at the report's shape (its numbers are not the full run's)",
    )
    add_force(p)
    p.add_argument("--quiet", action="store_true", help="no progress bars")


def run(ns) -> None:
    from ..errors import ParameterError
    from ..report import plan, reproduce

    if ns.out is None and not ns.quick:
        print(plan())
        raise ParameterError(
            "out",
            "give the report folder, e.g. `symimpact reproduce report` (full grids), or add "
            "--quick for coarse grids into symimpact-report",
        )
    if ns.out is None:
        ns.out = "symimpact-report"

    out, sections = reproduce(ns.out, quick=ns.quick, force=ns.force, progress=progress_drawn(ns))
    n_fig = sum(len(s.figures()) for s in sections)
    n_tab = sum(len(s.tables()) for s in sections)
    print(
        f"wrote {out}/index.html (open it in a browser), report.md, {n_fig} figures, {n_tab} tables"
    )


#: The subcommands this module runs.
COMMANDS = {"reproduce": run}
