"""``symimpact reproduce``: the paper's tables and figures beside ours, as a report folder."""

from __future__ import annotations

from typing import Any

from .common import add_force


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
        default="symimpact-report",
        help="report folder (created; must be new or empty unless --force); "
        "default symimpact-report",
    )
    p.add_argument("--quick", action="store_true", help="coarser grids: seconds, not a minute")
    add_force(p)
    p.add_argument("--quiet", action="store_true", help="no progress bars")


def run(ns) -> None:
    from ..report import reproduce

    out, sections = reproduce(ns.out, quick=ns.quick, force=ns.force, progress=not ns.quiet)
    n_fig = sum(len(s.figures()) for s in sections)
    n_tab = sum(len(s.tables()) for s in sections)
    print(
        f"wrote {out}/index.html (open it in a browser), report.md, {n_fig} figures, {n_tab} tables"
    )


#: The subcommands this module runs.
COMMANDS = {"reproduce": run}
