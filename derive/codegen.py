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

from .board import Board, Bundle, FixedPoint, Kernel

TEMPLATES = Path(__file__).parent / "templates"
KERNEL_TEMPLATE = "kernels.py.j2"

_env = jinja2.Environment(
    loader=jinja2.FileSystemLoader(str(TEMPLATES)),
    keep_trailing_newline=True,
    trim_blocks=True,
    lstrip_blocks=True,
    undefined=jinja2.StrictUndefined,
)


def cite(equation: str) -> str:
    """How a generated file names an equation: ``paper Eq. 7``, or ``Eq. F1 (derived here, beyond
    the paper)`` for the forced-response steps, whose numbers start with F."""
    if equation.startswith("F"):
        return f"Eq. {equation} (derived here, beyond the paper)"
    return f"paper Eq. {equation}"


_env.filters["cite"] = cite
_env.filters["capitalize_first"] = lambda text: text[:1].upper() + text[1:]


class KernelPrinter(NumPyPrinter):
    """NumPy printer with floats written in full (``repr``) so no digit is lost."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_Max(self, expr) -> str:  # nested numpy.maximum: no functools import needed
        *rest, last = expr.args
        out = self._print(last)
        for a in reversed(rest):
            out = f"numpy.maximum({self._print(a)}, {out})"
        return out


class ScalarTwinPrinter(KernelPrinter):
    """The ``*_scalar`` twins: NumPy float64 arithmetic, and a case distinction (``Piecewise``)
    written as a conditional expression, so that numba compiles it and only the branch taken is
    evaluated."""

    def _print_Piecewise(self, expr: sp.Piecewise) -> str:
        *cases, (last, cond) = expr.args
        if cond != sp.true:
            raise ValueError("a kernel's Piecewise must end with an otherwise branch")
        out = self._print(last)
        for value, condition in reversed(cases):
            out = f"(({self._print(value)}) if ({self._print(condition)}) else ({out}))"
        return out

    def _print_Relational(self, expr) -> str:
        return PythonCodePrinter._print_Relational(self, expr)

    def _print_And(self, expr) -> str:
        return " and ".join(f"({self._print(a)})" for a in expr.args)


class ScalarKernelPrinter(PythonCodePrinter):
    """``math``-module printer for the scalar twins that a compiled loop (numba) can call."""

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_Assignment(self, expr) -> str:
        """``x = value``, also for a case distinction (SymPy would write the assignment into
        each branch of a conditional expression, which Python does not parse)."""
        return f"{self._print(expr.lhs)} = {self._print(expr.rhs)}"


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
    kernel: Kernel,
    printer_class: type = KernelPrinter,
    settings: dict | None = None,
    prefix: str = "_x",
) -> tuple[list[tuple[str, str]], str, int]:
    """Common-subexpression-eliminated assignments, the returned expression and the op count.

    ``printer_class(settings)`` prints them (default settings: the Python printers' fully
    qualified module names); ``prefix`` names the subexpressions (``_x0``, ``_x1``, ...)."""
    replacements, reduced, ops = _once(_reduced, kernel, prefix)
    printer = printer_class({"fully_qualified_modules": True} if settings is None else settings)
    lines = [(str(sym), printer.doprint(val)) for sym, val in replacements]
    return lines, printer.doprint(reduced), ops


def bundle_body(
    bundle: Bundle,
    printer_class: type = KernelPrinter,
    settings: dict | None = None,
    prefix: str = "_x",
) -> tuple[list[tuple[str, str]], list[str], int]:
    """:func:`kernel_body` of a :class:`~derive.board.Bundle`: the assignments of the common
    subexpressions of all its parts, each part's returned expression, and the op count."""
    replacements, reduced, ops = _once(_bundle_reduced, bundle, prefix)
    printer = printer_class({"fully_qualified_modules": True} if settings is None else settings)
    lines = [(str(sym), printer.doprint(val)) for sym, val in replacements]
    return lines, [printer.doprint(r) for r in reduced], ops


def _bundle_reduced(bundle: Bundle, prefix: str) -> tuple[list, list, int]:
    return _cse([k.expr for k in bundle.parts], prefix)


def bundle_ops(bundle: Bundle) -> tuple[int, int]:
    """(operations of the bundle, operations of its parts computed one by one)."""
    return (_once(_bundle_reduced, bundle, "_x")[2],
            sum(_once(_reduced, k, "_x")[2] for k in bundle.parts))  # fmt: skip


#: Results already computed, by function, argument identity and further arguments; each entry
#: keeps its kernel alive, so an identity is never reused for another.  Every target prints the
#: same reduced expressions and docstrings: computing them once per process is most of the
#: difference between a derivation run of 3 and of 2 minutes (issue 38, CI's time).
_DONE: dict[tuple, tuple[object, object]] = {}


def _once(func, item, *rest):
    key = (func.__name__, id(item), *rest)
    got = _DONE.get(key)
    if got is None or got[0] is not item:
        got = _DONE[key] = (item, func(item, *rest))
    return got[1]


def _reduced(kernel: Kernel, prefix: str) -> tuple[list, sp.Expr, int]:
    """The kernel's expression with special-function constants evaluated, CSE-reduced (the
    subexpressions named ``prefix0``, ``prefix1``, ...), and its operation count."""
    replacements, (reduced,), ops = _cse([kernel.expr], prefix)
    return replacements, reduced, ops


def _cse(exprs, prefix: str) -> tuple[list, list, int]:
    """``sympy.cse`` of ``exprs`` together (special-function constants evaluated first, the
    subexpressions named ``prefix0``, ``prefix1``, ...) and the operation count of the result."""
    exprs = [numeric_constants(sp.sympify(e)) for e in exprs]
    replacements, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
    ops = sum(int(sp.count_ops(val)) for _, val in replacements)
    return replacements, reduced, ops + sum(int(sp.count_ops(r)) for r in reduced)


#: A derivative's formula written out longer than this (LaTeX characters) is no help to a reader
#: (the closed-form orbit's run to 200 000): its docstring states what it is the derivative of.
LONGEST_DERIVATIVE_LATEX = 4000


def latex_of(kernel: Kernel) -> str:
    """The kernel's formula in LaTeX, as ``lhs = expr``; a derivative kernel whose formula would
    be longer than :data:`LONGEST_DERIVATIVE_LATEX` as ``lhs = ∂/∂arg`` of its value kernel
    (written once per kernel: every target's docstring carries it)."""
    return _once(_latex, kernel)


def _latex(kernel: Kernel) -> str:
    written = f"{kernel.lhs} = {sp.latex(kernel.expr)}"
    if kernel.derivative_of is None or len(written) <= LONGEST_DERIVATIVE_LATEX:
        return written
    of, arg = kernel.derivative_of
    by_name = {a.name: a for a in kernel.args}
    name = of.replace("_", r"\_")
    return rf"{kernel.lhs} = \frac{{\partial}}{{\partial {sp.latex(by_name[arg].symbol)}}}\,\mathtt{{{name}}}"


def render_module(board: Board) -> str:
    """Source text of ``generated/<board.module>.py``."""
    kernels = []
    total_ops = 0
    for k in board.kernels:
        lines, result, ops = kernel_body(k)
        # The twin evaluates the same formula on NumPy float64 scalars: IEEE arithmetic, so a
        # singular point gives the same inf or NaN as the array kernel (Python floats and the
        # math module would raise ZeroDivisionError or ValueError there instead).
        scalar_lines, scalar_result, _ = kernel_body(k, ScalarTwinPrinter)
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
                "cases": sp.sympify(k.expr).has(sp.Piecewise),
            }
        )
    bundles = []
    for b in board.bundles:
        lines, results, ops = bundle_body(b)
        scalar_lines, scalar_results, _ = bundle_body(b, ScalarTwinPrinter)
        bundles.append(
            {
                "bundle": b,
                "lines": lines,
                "results": results,
                "scalar_lines": scalar_lines,
                "scalar_results": scalar_results,
                "ops": ops,
                "alone": bundle_ops(b)[1],
                "argnames": ", ".join(a.name for a in b.args),
                "cases": any(sp.sympify(k.expr).has(sp.Piecewise) for k in b.parts),
            }
        )
    return _env.get_template(KERNEL_TEMPLATE).render(
        board=board,
        kernels=kernels,
        bundles=bundles,
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


def project() -> dict[str, str]:
    """The package's version and one-line description (pyproject.toml): the compiled targets' too."""
    import tomllib
    from pathlib import Path

    with open(Path(__file__).resolve().parent.parent / "pyproject.toml", "rb") as f:
        project = tomllib.load(f)["project"]
    return {"version": project["version"], "description": project["description"]}


def render_template(name: str, **context) -> str:
    """Render a template that needs no derivation (e.g. the shared broadcasting helpers)."""
    return _env.get_template(name).render(**context)


# --- fixed-point iterations as loops (sympy.codegen.ast) ----------------------------------------
def fixed_point_names(fp: FixedPoint) -> dict[str, sp.Symbol]:
    """The loop's variables: the iterate, its previous value, the step counter and the limits."""
    x = fp.iterate.name
    return {
        "x": sp.Symbol(x, real=True),
        "previous": sp.Symbol(f"{x}_previous", real=True),
        "count": sp.Symbol("iterations", integer=True),
        "tol": sp.Symbol("tol", real=True),
        "max_iter": sp.Symbol("max_iter", integer=True),
    }


def fixed_point_ast(fp: FixedPoint, prefix: str = "_c") -> tuple[list, sp.Basic]:
    """The iteration as a target-independent AST: (hoisted assignments, loop block).

    ``prefix`` names the common subexpressions (``_c0``, ...; MATLAB needs a leading letter).

    Common subexpressions of the step that do not involve the iterate are computed once, before
    the loop.  The loop is the one :func:`symimpact.free.contact.perturbation_duration` runs on arrays::

        x = start; x_previous = inf; iterations = 0
        while abs(x - x_previous) > tol*abs(x) and iterations < max_iter:
            x_previous = x; x = step(x_previous); iterations += 1

    A NaN iterate ends the loop (the comparison is false); callers test the value for NaN.
    """
    from sympy.codegen.ast import Assignment, CodeBlock, While, aug_assign

    v = fixed_point_names(fp)
    step = numeric_constants(sp.sympify(fp.step)).subs(fp.iterate, v["previous"])
    start = numeric_constants(sp.sympify(fp.start))
    replacements, (step_reduced, start_reduced) = sp.cse(
        [step, start], symbols=sp.numbered_symbols(prefix), order="canonical"
    )
    hoisted, inner = [], []
    depends = {v["previous"]}
    for sym, val in replacements:
        if val.free_symbols & depends:
            depends.add(sym)
            inner.append(Assignment(sym, val))
        else:
            hoisted.append(Assignment(sym, val))
    loop = CodeBlock(
        Assignment(v["x"], start_reduced),
        Assignment(v["previous"], sp.oo),
        Assignment(v["count"], 0),
        While(
            sp.And(
                sp.Abs(v["x"] - v["previous"]) > v["tol"] * sp.Abs(v["x"]),
                sp.StrictLessThan(v["count"], v["max_iter"]),
            ),
            CodeBlock(
                Assignment(v["previous"], v["x"]),
                *inner,
                Assignment(v["x"], step_reduced),
                aug_assign(v["count"], "+", 1),
            ),
        ),
    )
    return hoisted, loop


def fixed_point_ops(fp: FixedPoint) -> int:
    """Operations of one step after common-subexpression elimination (hoisted part excluded)."""
    _, loop = fixed_point_ast(fp)
    body = loop.args[-1].body
    return sum(int(sp.count_ops(a.rhs)) for a in body.args if hasattr(a, "rhs"))


def fixed_point_latex(fp: FixedPoint) -> tuple[str, str]:
    """LaTeX of the start and of the step."""
    x = sp.latex(fp.iterate)
    return (
        f"{x}^{{(0)}} = {sp.latex(fp.start)}",
        f"{x}^{{(i)}} = {sp.latex(fp.step.subs(fp.iterate, sp.Symbol(x + '^{(i-1)}')))}",
    )


def render_fixed_points(boards: list[Board]) -> str:
    """Source text of ``generated/fixed_points.py`` (numba loops of every board's iterations)."""
    printer = ScalarKernelPrinter({"fully_qualified_modules": True})
    items = []
    for b in boards:
        for fp in b.fixed_points:
            hoisted, loop = fixed_point_ast(fp)
            loop_lines = printer.doprint(loop).split("\n")
            # the loop as printed: start, previous = inf, count = 0, "while COND:", the body
            assert loop_lines[3].startswith("while ") and loop_lines[3].endswith(":")
            items.append(
                {
                    "fp": fp,
                    "module": b.module,
                    "argnames": ", ".join(a.name for a in fp.args),
                    "hoisted": [printer.doprint(h) for h in hoisted],
                    "hoisted_names": [str(h.lhs) for h in hoisted],
                    "start": loop_lines[0],
                    "condition": loop_lines[3][len("while ") : -1],
                    "body": [line[4:] for line in loop_lines[4:]],
                    "code": [printer.doprint(h) for h in hoisted] + loop_lines,
                    "latex": fixed_point_latex(fp),
                    "x": fp.iterate.name,
                    "ops": fixed_point_ops(fp),
                }
            )
    return _env.get_template("fixed_points.py.j2").render(
        items=items, template="derive/templates/fixed_points.py.j2"
    )
