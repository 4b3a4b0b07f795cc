"""One Jupyter notebook per derivation step, written from the step's own module with nbformat.

The notebook re-derives live: its code cells are the statements of the step's ``derive()``, cut
after each one that writes on the board (a result, a check, an erratum, a kernel), so a student
runs the derivation one board line at a time in the paper's order.  Before each cell, a text cell
says what the cell writes (its sentence and equation number, taken from the board when the
notebook is made); after it, ``show(board)`` displays the new lines as the docs pages write
them, the checks with their status and the errata where they arise.  Then the step's exercises
(:mod:`derive.exercises`), and a last cell that checks the notebook's board against
``derive()``'s.

``python -m derive --notebooks DIR`` writes them; ``pip install -e ".[teach]"`` installs
JupyterLab to run them.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import textwrap
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from . import STEPS
from .board import RECORDS
from .exercises import EXERCISES
from .teach import ANSWER_RTOL

#: Board methods and local aliases of ``board.write`` whose call ends a cell.
_BOARD_CALLS = {"write", "check", "erratum", "kernel", "fixed_point", "constant"}
_WRITE_ALIASES = {"w", "wr"}


@dataclass
class _Cell:
    heading: str | None
    code: list[str] = field(default_factory=list)
    added: tuple[list, ...] = ([], [], [], [], [])
    headings: list[str] = field(default_factory=list)
    #: The lines of the step's module its statements span, (first, last) each.
    spans: list[tuple[int, int]] = field(default_factory=list)


def _writes(stmt: ast.stmt) -> bool:
    for node in ast.walk(stmt):
        if isinstance(node, ast.Call):
            f = node.func
            if isinstance(f, ast.Name) and f.id in _WRITE_ALIASES:
                return True
            if (
                isinstance(f, ast.Attribute)
                and f.attr in _BOARD_CALLS
                and isinstance(f.value, ast.Name)
                and f.value.id == "board"
            ):
                return True
    return False


def cells_of(step: str) -> list[_Cell]:
    """The statements of ``derive.<step>.derive()`` grouped into cells: each cell ends with a
    statement that writes on the board; a ``# --- title ---`` comment starts a section."""
    module = importlib.import_module(f"derive.{step}")
    source = inspect.getsource(module)
    lines = source.splitlines()
    fn = next(
        n for n in ast.parse(source).body if isinstance(n, ast.FunctionDef) and n.name == "derive"
    )
    cells: list[_Cell] = [_Cell(None)]
    previous_end = fn.body[0].lineno - 1
    for stmt in fn.body:
        if isinstance(stmt, ast.Return):
            break
        between = lines[previous_end : stmt.lineno - 1]
        comments = []
        for text in between:
            stripped = text.strip()
            if stripped.startswith("# ---"):
                title = stripped.strip("#- ").strip()
                if cells[-1].code:
                    cells.append(_Cell(title))
                else:
                    cells[-1].heading = title
                comments = []
            elif stripped:
                comments.append(text)
        cells[-1].code += comments + lines[stmt.lineno - 1 : stmt.end_lineno]
        cells[-1].spans.append((stmt.lineno, stmt.end_lineno or stmt.lineno))
        previous_end = stmt.end_lineno or stmt.lineno
        if _writes(stmt):
            cells.append(_Cell(None))
    if not cells[-1].code:
        heading = cells.pop().heading
        if heading and cells:
            cells[-1].heading = cells[-1].heading or heading
    for c in cells:
        c.code = textwrap.dedent("\n".join(c.code)).splitlines()
    return cells


def _placed(cells: list[_Cell], kept) -> bool:
    """Note what each cell adds to the board from ``kept``, the step's board derived by its
    ``derive()``, whose :attr:`~derive.board.Board.written_at` names the statement that wrote
    each record: no derivation runs.  False (nothing noted) where a record's statement is in no
    cell (a board that does not say where its records come from)."""
    lists = [getattr(kept, name) for name in RECORDS]
    where = getattr(kept, "written_at", None)
    if where is None or any(
        len(where.get(n, ())) != len(x) for n, x in zip(RECORDS, lists, strict=True)
    ):
        return False
    owner = {line: k for k, c in enumerate(cells) for a, b in c.spans for line in range(a, b + 1)}
    if not all(line in owner for name in RECORDS for line in where[name]):
        return False
    for k, c in enumerate(cells):
        c.added = tuple(
            [item for item, line in zip(items, where[name], strict=True) if owner[line] == k]
            for name, items in zip(RECORDS, lists, strict=True)
        )
    return True


def _record(step: str, cells: list[_Cell]) -> None:
    """Run the cells here, as the notebook will, and note what each adds to the board."""
    module = importlib.import_module(f"derive.{step}")
    ns = {k: v for k, v in vars(module).items() if not k.startswith("__")}
    seen = (0, 0, 0, 0, 0)
    for c in cells:
        exec(compile("\n".join(c.code), f"<{step} notebook cell>", "exec"), ns)
        board = ns["board"]
        lists = (board.lines, board.checks, board.errata, board.kernels, board.constants)
        c.added = tuple(items[k:] for items, k in zip(lists, seen, strict=True))
        seen = tuple(len(items) for items in lists)


def _merged(cells: list[_Cell]) -> list[_Cell]:
    """Cells that write nothing joined to the next cell (to the previous one at the end), so
    every code cell shows something; their section headings are kept in order."""
    out: list[_Cell] = []
    pending: _Cell | None = None
    for c in cells:
        c.headings = [h for h in (c.heading,) if h]
        if pending is not None:
            c.code = pending.code + c.code
            c.headings = pending.headings + c.headings
            pending = None
        if any(c.added):
            out.append(c)
        else:
            pending = c
    if pending is not None and out:
        out[-1].code += pending.code
        out[-1].headings += pending.headings
    return out


def _describe(c: _Cell) -> str:
    lines, checks, errata, kernels, constants = c.added
    out = [line for h in c.headings for line in (f"## {h}", "")]
    for line in lines:
        eq = f" (Eq. {line.equation})" if line.equation else ""
        out.append(f"- **`{line.name}`**{eq}: {line.text}")
    for k in checks:
        out.append(f"- check: {k.name} (Eq. {k.equation})")
    for e in errata:
        out.append(f"- erratum, Eq. {e.equation}: {e.what}")
    for k in constants:
        out.append(f"- constant `{k.name}` emitted to `generated/`: {k.doc}")
    if kernels:
        names = ", ".join(f"`{k.name}`" for k in kernels)
        out.append(f"- kernel{'s' if len(kernels) > 1 else ''} emitted to `generated/`: {names}")
    return "\n".join(out)


_BOOT = """# The derivation package lives in the symimpact checkout: open this notebook from inside the
# checkout (or set SYMIMPACT_CHECKOUT to its path).
import os
import pathlib
import sys

_here = pathlib.Path.cwd().resolve()
_places = [os.environ.get("SYMIMPACT_CHECKOUT"), _here, *_here.parents]
root = next((pathlib.Path(p) for p in _places
             if p and (pathlib.Path(p) / "derive" / "board.py").is_file()), None)
if root is None:
    raise RuntimeError("derive/ not found: open the notebook inside the symimpact checkout "
                       "or set SYMIMPACT_CHECKOUT")
sys.path.insert(0, str(root))
import derive.{step} as step  # noqa: E402  the step's own module: its helpers and constants

globals().update({{k: v for k, v in vars(step).items() if not k.startswith("__")}})
from derive.teach import check, show, show_value  # noqa: E402

print(f"derive/{step}.py from {{root}}")"""

_SAME = """# The board this notebook built, line by line, against the one derive() builds.
reference = step.derive()
same = [a.name == b.name and str(a.value) == str(b.value)
        for a, b in zip(board.lines, reference.lines, strict=True)]
print(f"{{sum(same)}} of {{len(reference.lines)}} board lines identical to derive.{step}.derive(); "
      f"checks passed: {{sum(c.ok for c in board.checks)}} of {{len(board.checks)}}")
assert all(same) and all(c.ok for c in board.checks)"""


def notebook(step: str):
    """The notebook of one derivation step (an ``nbformat`` v4 notebook)."""
    import nbformat

    module = importlib.import_module(f"derive.{step}")
    from .cache import kept

    cells = cells_of(step)
    board = kept(step)  # the board the last derivation of this code kept, if any
    if board is None or not _placed(cells, board):
        _record(step, cells)
    cells = _merged(cells)
    doc = inspect.getdoc(module) or ""
    heading, _, body = doc.partition("\n")
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nb.cells.append(nbformat.v4.new_markdown_cell(
        f"# {heading}\n\n{body.strip()}\n\n"
        f"*This notebook runs the statements of `derive/{step}.py` one board line at a time. "
        "Run the cells in order; after each one, `show(board)` displays what it wrote on the "
        "board. Exercises at the end change one assumption at a time.*"))  # fmt: skip
    nb.cells.append(nbformat.v4.new_code_cell(_BOOT.format(step=step)))
    for c in cells:
        text = _describe(c)
        if text:
            nb.cells.append(nbformat.v4.new_markdown_cell(text))
        nb.cells.append(nbformat.v4.new_code_cell("\n".join([*c.code, "show(board)"])))
    exercises = EXERCISES.get(step, ())
    if exercises:
        nb.cells.append(nbformat.v4.new_markdown_cell(
            "## Exercises\n\nEach changes one assumption of the derivation above. Compute what "
            "it asks with the names the notebook defined, put the value in the answer cell and "
            "run the check below it. The solution is in the collapsed cell between them: "
            "expand it when you are done, or stuck."))  # fmt: skip
    for k, ex in enumerate(exercises, 1):
        nb.cells.extend(exercise_cells(k, ex))
    nb.cells.append(nbformat.v4.new_markdown_cell("## The notebook's board is the step's board"))
    nb.cells.append(nbformat.v4.new_code_cell(_SAME.format(step=step)))
    return nb


def exercise_cells(k: int, ex) -> list:
    """The cells of exercise ``k``: the question, the reader's answer cell (``answer_k = ...``),
    the solution, collapsed (source and output hidden in Jupyter), which sets ``expected_k``, and
    the check (:func:`derive.teach.check`)."""
    import nbformat

    solution = nbformat.v4.new_code_cell(
        f"# Solution of exercise {k}\n{ex.code}\nexpected_{k} = {ex.answer}"
    )
    solution.metadata["jupyter"] = {"source_hidden": True, "outputs_hidden": True}
    solution.metadata["tags"] = ["solution"]
    return [
        nbformat.v4.new_markdown_cell(
            f"### Exercise {k}: {ex.title}\n\n{ex.text}\n\n**Your turn.** {ex.ask}"
        ),
        nbformat.v4.new_code_cell(f"answer_{k} = ...  # your computation here"),
        solution,
        nbformat.v4.new_code_cell(
            f"check(answer_{k}, expected_{k}"
            + ("" if ex.rtol == ANSWER_RTOL else f", rtol={ex.rtol:g}")
            + ")"
        ),
    ]


def write_notebooks(
    folder: str | Path,
    steps: tuple[str, ...] = STEPS,
    say: Callable[[Path, float], None] | None = None,
) -> list[Path]:
    """Write ``<NN>_<step>.ipynb`` for each step into ``folder``, then the walk-through of
    :mod:`derive.walkthrough`; returns the paths.  ``say(path, seconds)`` is called as each
    notebook is written, so that a person waiting sees each one arrive."""
    import time

    import nbformat

    out = Path(folder)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for k, step in enumerate(steps, 1):
        start = time.perf_counter()
        path = out / f"{k:02d}_{step}.ipynb"
        nbformat.write(notebook(step), path)
        paths.append(path)
        if say is not None:
            say(path, time.perf_counter() - start)
    from .walkthrough import NOTEBOOK
    from .walkthrough import notebook as walkthrough_notebook

    start = time.perf_counter()
    path = out / NOTEBOOK
    nbformat.write(walkthrough_notebook(), path)
    if say is not None:
        say(path, time.perf_counter() - start)
    return [*paths, path]
