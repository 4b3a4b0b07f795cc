"""C99 target: every kernel and fixed-point iteration as ``double`` functions in one header and
one source file (``generated/c/``), with restrict-qualified batch entry points.

The backend is a printer, a naming rule and two templates:

- :class:`CKernelPrinter` is SymPy's ``C99CodePrinter`` with floats written in full (``repr``
  round-trips every double) and π written as a literal (``M_PI`` is not ISO C99).
- ``symimpact_<module>_<kernel>`` names every function after the Python module it mirrors.
- ``derive/templates/c/symimpact.h.j2`` and ``symimpact.c.j2`` lay out the declarations and
  the definitions.  Nothing is allocated; a batch function loops over ``n`` elements of
  caller-owned arrays.
- ``CMakeLists.txt.j2``, ``symimpact.pc.in.j2`` and ``symimpactConfig.cmake.in.j2`` make it a
  library (static and shared, installed with a pkg-config file and a CMake package), and
  ``check_kernels.c.j2`` its test program: every kernel at the recorded points of
  :mod:`derive.checkpoints`.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.c import C99CodePrinter

from .board import Board
from .codegen import (
    _env,
    bundle_body,
    fixed_point_ast,
    fixed_point_latex,
    kernel_body,
    latex_of,
    project,
)

FOLDER = "c"
PREFIX = "symimpact"


class CKernelPrinter(C99CodePrinter):
    """C99 printer: full-precision float literals, π and e as literals (no ``M_PI``)."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__({"math_macros": {}, **(settings or {})})

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_NumberSymbol(self, expr: sp.Basic) -> str:
        return repr(float(expr))

    _print_Pi = _print_NumberSymbol
    _print_Exp1 = _print_NumberSymbol

    def _print_Assignment(self, expr) -> str:
        """``x = value;`` with a case distinction as a conditional expression (SymPy would write
        an if/else block, which cannot follow the ``const double`` of a hoisted temporary)."""
        if expr.rhs.has(sp.Piecewise):
            return f"{self._print(expr.lhs)} = {self._print(expr.rhs)};"
        return super()._print_Assignment(expr)


def c_name(module: str, name: str) -> str:
    """The C function name of kernel ``name`` of the Python module ``module``."""
    return f"{PREFIX}_{module}_{name}"


def _unused(args, *exprs) -> list[str]:
    used = set().union(*(sp.sympify(e).free_symbols for e in exprs))
    return [a.name for a in args if a.symbol not in used]


def _c_line(line: str) -> str:
    """A line of the printed loop: SymPy's 3-space indent becomes 4, ``};`` becomes ``}``."""
    if line == "};":
        return "}"
    stripped = line.lstrip(" ")
    return " " * (4 * ((len(line) - len(stripped)) // 3)) + stripped


def _loop_temporaries(loop) -> list[str]:
    """Names of the common subexpressions computed inside the loop (declared before it)."""
    from sympy.codegen.ast import Assignment, While

    body = next(a for a in loop.args if isinstance(a, While)).body
    return [str(a.lhs) for a in body.args if isinstance(a, Assignment) and str(a.lhs)[:2] == "_c"]


def items(boards: list[Board]) -> dict:
    """Template context shared by the header and the source."""
    printer = CKernelPrinter()
    modules = []
    for b in boards:
        kernels = []
        for k in b.kernels:
            lines, result, ops = kernel_body(k, CKernelPrinter, {})
            kernels.append(
                {
                    "k": k,
                    "c": c_name(b.module, k.name),
                    "lines": lines,
                    "result": result,
                    "ops": ops,
                    "latex": latex_of(k),
                    "unused": _unused(k.args, k.expr),
                }
            )
        constants = [
            {"c": c_name(b.module, c.name), "const": c, "n": len(c.values)} for c in b.constants
        ]
        bundles = []
        for bu in b.bundles:
            lines, results, ops = bundle_body(bu, CKernelPrinter, {})
            bundles.append({"b": bu, "c": c_name(b.module, bu.name), "lines": lines,
                            "results": results, "ops": ops, "n": len(results),
                            "parts": [c_name(b.module, k.name) for k in bu.parts],
                            "unused": _unused(bu.args, *(k.expr for k in bu.parts))})  # fmt: skip
        balances = [{"x": x, "c": c_name(b.module, x.name),
                     "force": c_name(b.module, x.force.name)} for x in b.balances]  # fmt: skip
        modules.append({"board": b, "kernels": kernels, "constants": constants,
                        "bundles": bundles, "balances": balances})  # fmt: skip
    fixed = []
    for b in boards:
        for fp in b.fixed_points:
            hoisted, loop = fixed_point_ast(fp)
            code = [printer.doprint(h) for h in hoisted] + printer.doprint(loop).split("\n")
            fixed.append(
                {
                    "fp": fp,
                    "module": b.module,
                    "c": c_name("fixed_points", fp.name),
                    "code": [_c_line(line) for line in code],
                    "x": fp.iterate.name,
                    "latex": fixed_point_latex(fp),
                    "unused": _unused(fp.args, fp.start, fp.step),
                    "inner": _loop_temporaries(loop),
                }
            )
    return {"modules": modules, "fixed": fixed, "steps": [b.module for b in boards]}


def render(boards: list[Board]) -> dict[str, str]:
    """``{path under generated/: text}`` of the C target: the header and the source, the library's
    build (CMake project, pkg-config and CMake package templates) and its check program at the
    recorded points of :mod:`derive.checkpoints`."""
    from . import checkpoints

    context = {**items(boards), **project(), **checkpoints.recorded(boards), "c_name": c_name,
               "points": checkpoints.POINTS, "digits": checkpoints.DIGITS,
               "rtol": checkpoints.RTOL}  # fmt: skip
    out = {}
    for name in ("symimpact.h", "symimpact.c", "README.md", "CMakeLists.txt", "symimpact.pc.in",
                 "symimpactConfig.cmake.in", "check_kernels.c"):  # fmt: skip
        template = f"c/{name}.j2"
        out[f"{FOLDER}/{name}"] = _env.get_template(template).render(
            template=f"derive/templates/{template}", **context
        )
    return out
