"""Turn the kernels a derivation step declares into NumPy source text through jinja2 templates.

SymPy does the hard parts: ``sympy.cse`` (canonical order, so the output does not depend on
``PYTHONHASHSEED``) and ``NumPyPrinter``.  This module only orders, formats and renders.
"""

from __future__ import annotations

from pathlib import Path

import jinja2
import sympy as sp
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter

from .board import Board, Kernel

TEMPLATES = Path(__file__).parent / "templates"
KERNEL_TEMPLATE = "kernels.py.j2"

_env = jinja2.Environment(
    loader=jinja2.FileSystemLoader(str(TEMPLATES)),
    keep_trailing_newline=True,
    trim_blocks=True,
    lstrip_blocks=True,
    undefined=jinja2.StrictUndefined,
)


class KernelPrinter(NumPyPrinter):
    """NumPy printer with floats written in full (``repr``) so no digit is lost."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))


class ScalarKernelPrinter(PythonCodePrinter):
    """``math``-module printer for the scalar twins that a compiled loop (numba) can call."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))


def numeric_constants(expr: sp.Expr) -> sp.Expr:
    """Evaluate constant special-function subexpressions (Gamma, Beta, ...) to 30 digits.

    The printer can then write them as floats: e.g. the Hertz constant of Eq. 34 keeps its exact
    Gamma-function form on the board but becomes a 17-digit float in the kernel.
    """

    def is_special_constant(e: sp.Basic) -> bool:
        return (
            isinstance(e, sp.Expr)
            and not e.free_symbols
            and not e.is_Rational
            and e.has(sp.gamma, sp.beta, sp.zeta)
        )

    return expr.replace(is_special_constant, lambda e: sp.Float(e.evalf(30), 30))


def kernel_body(
    kernel: Kernel, printer_class: type = KernelPrinter
) -> tuple[list[tuple[str, str]], str, int]:
    """Common-subexpression-eliminated assignments, the returned expression and the op count."""
    expr = numeric_constants(sp.sympify(kernel.expr))
    replacements, (reduced,) = sp.cse([expr], symbols=sp.numbered_symbols("_x"), order="canonical")
    printer = printer_class({"fully_qualified_modules": True})
    lines = [(str(sym), printer.doprint(val)) for sym, val in replacements]
    ops = sum(int(sp.count_ops(val)) for _, val in replacements) + int(sp.count_ops(reduced))
    return lines, printer.doprint(reduced), ops


def latex_of(kernel: Kernel) -> str:
    """The kernel's formula in LaTeX, as ``lhs = expr``."""
    return f"{kernel.lhs} = {sp.latex(kernel.expr)}"


def render_module(board: Board) -> str:
    """Source text of ``generated/<board.module>.py``."""
    kernels = []
    total_ops = 0
    for k in board.kernels:
        lines, result, ops = kernel_body(k)
        scalar_lines, scalar_result, _ = kernel_body(k, ScalarKernelPrinter)
        total_ops += ops
        kernels.append(
            {
                "kernel": k,
                "lines": lines,
                "result": result,
                "scalar_lines": scalar_lines,
                "scalar_result": scalar_result,
                "ops": ops,
                "latex": latex_of(k),
                "argnames": ", ".join(a.name for a in k.args),
            }
        )
    return _env.get_template(KERNEL_TEMPLATE).render(
        board=board,
        kernels=kernels,
        total_ops=total_ops,
        template=f"derive/templates/{KERNEL_TEMPLATE}",
    )


def render_package_init(boards: list[Board]) -> str:
    return _env.get_template("__init__.py.j2").render(boards=boards)


def render_errata(boards: list[Board]) -> str:
    rows = []
    for b in boards:
        for e in b.errata:
            rows.append(
                {
                    "e": e,
                    "module": b.module,
                    "printed": sp.latex(e.printed),
                    "derived": sp.latex(e.derived),
                }
            )
    return _env.get_template("errata.md.j2").render(rows=rows)


def render_template(name: str, **context) -> str:
    """Render a template that needs no derivation (e.g. the shared broadcasting helpers)."""
    return _env.get_template(name).render(**context)
