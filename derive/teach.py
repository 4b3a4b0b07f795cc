"""What a derivation notebook calls to show the board as it fills: :func:`show`.

A notebook (written by :mod:`derive.notebooks`) runs a step's own statements cell by cell; after
each cell, ``show(board)`` displays what the cell added to the board — each new result written
the way the docs pages write it (:mod:`derive.present`), its equation number and sentence, each
check with its status, each place the printed paper differs.  Outside Jupyter it prints text.
"""

from __future__ import annotations

from typing import Any

from .board import Board
from .present import board_form, latex_blocks

_SEEN: dict[int, tuple[int, ...]] = {}


def _display(markdown: str, latex: list[str]) -> None:
    try:
        from IPython.display import Markdown, Math, display
    except ImportError:  # plain Python: text
        if markdown:
            print(markdown)
        for block in latex:
            print(block)
        return
    if markdown:
        display(Markdown(markdown))
    for block in latex:
        display(Math(block))


def show_value(value: Any, digits: int = 7) -> None:
    """Display one SymPy value as the docs pages write it (see :mod:`derive.present`)."""
    form = board_form(value, digits=digits)
    if form is None:
        _display(f"`{value!r}`", [])
        return
    main, where = latex_blocks(form)
    _display("", [main])
    if where:
        _display("where", [where])


def show(board: Board) -> None:
    """Display what was added to ``board`` since the last call: results, checks, errata, kernels
    and constants."""
    lines, checks, errata, kernels, constants = _SEEN.get(id(board), (0, 0, 0, 0, 0))
    for line in board.lines[lines:]:
        eq = f" (Eq. {line.equation})" if line.equation else ""
        _display(f"**`{line.name}`**{eq} — {line.text}", [])
        value = line.value if line.shown is None else line.shown
        form = board_form(value, names=line.names)
        if form is None:
            text = repr(line.value)
            _display(f"`{text[:400]}{' …' if len(text) > 400 else ''}`", [])
            continue
        main, where = latex_blocks(form)
        _display("", [main])
        if where:
            _display("where", [where])
    for c in board.checks[checks:]:
        mark = "✔" if c.ok else "✘ **FAILED**"
        note = " — the printed paper differs here" if c.erratum else ""
        detail = f": {c.detail}" if c.detail else ""
        _display(f"{mark} check *{c.name}* (Eq. {c.equation}){detail}{note}", [])
    for e in board.errata[errata:]:
        _display(f"**Erratum, Eq. {e.equation}: {e.what}.** {e.consequence}. Printed, then "
                 "derived:", [])  # fmt: skip
        show_value(e.printed, digits=12)
        show_value(e.derived, digits=12)
    for k in board.kernels[kernels:]:
        _display(f"kernel `{k.name}({', '.join(a.name for a in k.args)})` → {k.returns} "
                 f"[{k.unit}] (Eq. {k.equation}), emitted to `generated/{board.module}.py`", [])  # fmt: skip
    for c in board.constants[constants:]:
        _display(f"constant `{c.name}` = ({', '.join(c.values)}), emitted to "
                 f"`generated/{board.module}.py`: {c.doc}", [])  # fmt: skip
    _SEEN[id(board)] = tuple(
        len(x) for x in (board.lines, board.checks, board.errata, board.kernels, board.constants)
    )


#: How close an exercise's answer must come to the solution's: a relative 1e-9, loose enough for
#: any double-precision route to the same number (a float sum, mpmath, SymPy's N), tight enough
#: that no other formula passes by chance.
ANSWER_RTOL = 1e-9


def _number(value: Any) -> complex:
    import sympy as sp

    return complex(sp.N(sp.sympify(value), 30))


def check(answer: Any, expected: Any, rtol: float = ANSWER_RTOL) -> bool | None:
    """Compare an exercise's ``answer`` with its hidden solution's ``expected`` (numbers, to the
    relative ``rtol``) and say so; ``None`` while the answer cell still holds ``...``."""
    if answer is ...:
        print("Not answered yet: compute the value in the cell above, assign it to the answer "
              "variable and run this cell again (the solution is in the hidden cell above).")  # fmt: skip
        return None
    try:
        got, want = _number(answer), _number(expected)
    except (TypeError, ValueError) as exc:
        print(f"Your answer is not a number ({type(answer).__name__}: {exc}).")
        return False
    if abs(got - want) <= rtol * max(abs(want), 1e-300):
        print(f"Right: {answer}.")
        return True
    print(
        f"Not yet: your {got.real if got.imag == 0 else got:.10g} is off by a relative "
        f"{abs(got - want) / max(abs(want), 1e-300):.2g}; look at the hidden solution."
    )
    return False
