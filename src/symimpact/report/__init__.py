"""``symimpact reproduce``: the paper's tables and figures beside ours, as a report folder.

:func:`reproduce` runs the stages (:mod:`.contact_stage`: Fig. 2, 3a, 3b and Table 1;
:mod:`.vibration_stage`: Table 2, Fig. 4–7 and Table 3; :mod:`.beyond_stage`: accuracy map and
Lindstedt order study; :mod:`.forced_stage`: the forced response, frequency-response curves and
the clearance design map; :mod:`.loads_stage`: random and shock loads), each behind a progress bar, and writes ``index.html``, ``report.md``,
one PNG per figure and one CSV per table into a temporary folder that is renamed to the target
only when everything succeeded (:func:`symimpact.io.staged_folder`).
"""

from __future__ import annotations

import os
import platform
import shlex
import sys
import time
from collections.abc import Callable
from pathlib import Path

from tqdm import tqdm

from ..io import staged_folder
from .document import Section, html, markdown, write_csv

TITLE = (
    "symimpact — reproduction of “Free vibration analysis of nonlinear resilient impact dampers”"
)


def _stages(quick: bool = False) -> list[tuple[str, int, Callable[..., Section]]]:
    """(description, progress steps, builder) of each stage, in order."""
    from . import beyond_stage, contact_stage, forced_stage, loads_stage, vibration_stage

    return [
        ("contact (Fig. 2, 3, Table 1)", contact_stage.STEPS, contact_stage.section),
        ("free vibration (Fig. 4–7, Table 3)", vibration_stage.STEPS, vibration_stage.section),
        ("beyond (accuracy map, Lindstedt)", beyond_stage.STEPS, beyond_stage.section),
        ("forced (curves, design map)", forced_stage.steps(quick), forced_stage.section),
        ("loads (random, shock)", loads_stage.STEPS, loads_stage.section),
    ]


def plan() -> str:
    """What :func:`reproduce` writes, stage by stage (the text ``symimpact reproduce`` prints
    when it is given no folder)."""
    lines = ["symimpact reproduce writes a report folder (index.html, report.md, PNG, CSV):"]
    lines += [f"  {i}. {desc}: {steps} steps" for i, (desc, steps, _) in enumerate(_stages(), 1)]
    return "\n".join(lines)


def reproduce(
    out: str | os.PathLike,
    *,
    quick: bool = False,
    force: bool = False,
    progress: bool = True,
    command: str | None = None,
) -> tuple[Path, list[Section]]:
    """Write the reproduction report into the folder ``out`` and return it with its sections.

    ``quick`` uses coarser grids (a look at the report's shape); ``force`` replaces a
    non-empty ``out``.  ``command`` is recorded in the report (default: this process's argv).
    Tables 1 and 3 and Fig. 2–7 compare every printed number with ours (see :mod:`.paper`).
    """
    from .. import __version__

    started = time.perf_counter()
    command = command or " ".join(shlex.quote(a) for a in [Path(sys.argv[0]).name, *sys.argv[1:]])
    sections: list[Section] = []
    with staged_folder(out, force=force) as tmp:
        for desc, steps, build in _stages(quick):
            bar = tqdm(total=steps, desc=desc, unit="step", file=sys.stderr, disable=not progress)
            try:
                sections.append(build(tmp, quick, bar.update, earlier=sections))
            finally:
                bar.close()
        elapsed = time.perf_counter() - started
        meta = [
            ("package", f"symimpact {__version__}"),
            ("command", command),
            ("mode", "quick (coarse grids)" if quick else "full"),
            ("machine", f"Python {platform.python_version()} on {platform.platform()}"),
            ("run time", f"{elapsed:.1f} s"),
            ("paper", "Free vibration analysis of nonlinear resilient impact dampers (equation "
             "numbers are the paper's)"),
            ("errata", "generated/errata.md lists where the printed equations differ from the "
             "derivation; 'as printed' and 'derived' results are both shown where they differ"),
        ]  # fmt: skip
        for s in sections:
            for t in s.tables():
                with open(tmp / f"{t.name}.csv", "w", newline="", encoding="utf-8") as f:
                    write_csv(t, f)
        (tmp / "report.md").write_text(markdown(TITLE, meta, sections), encoding="utf-8")
        (tmp / "index.html").write_text(html(TITLE, meta, sections), encoding="utf-8")
    return Path(out), sections


__all__ = ["reproduce"]
