"""Rust target: a dependency-free crate (``generated/rust/``) with one module per derivation step,
every kernel an ``f64`` function and every fixed-point iteration a loop, and an integration test
at the recorded points of :mod:`derive.checkpoints` (``cargo test --offline``).

The backend is a printer, a naming rule and four templates:

- :class:`RustKernelPrinter` is SymPy's ``RustCodePrinter`` with floats written in full and
  typed (``0.5_f64``: a method call on an untyped literal does not compile), ``log1p`` as
  ``ln_1p`` and ``sinc`` as its case distinction (Rust's standard library has neither name).
- ``symimpact::<module>::<kernel>`` names every function after the Python function it mirrors;
  the iterations are ``symimpact::fixed_points::<name>``, returning (value, steps).
- ``derive/templates/rust/Cargo.toml.j2``, ``lib.rs.j2`` (doc comments carry each argument's
  unit and the equation), ``check_kernels.rs.j2`` (the test) and ``README.md.j2``.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.codeprinter import CodePrinter
from sympy.printing.rust import RustCodePrinter

from .board import Board
from .codegen import _env, bundle_body, fixed_point_ast, kernel_body, latex_of, project

FOLDER = "rust"


class RustKernelPrinter(RustCodePrinter):
    """Rust printer: typed full-precision float literals, ``ln_1p`` and ``sinc``."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings or {})

    def _print_Float(self, expr: sp.Float, **_kwargs) -> str:
        return f"{float(expr)!r}_f64"

    def _print_NumberSymbol(self, expr: sp.Basic, **_kwargs) -> str:
        return f"{float(expr)!r}_f64"

    _print_Pi = _print_NumberSymbol
    _print_Exp1 = _print_NumberSymbol

    def _print_Mul(self, expr, **_kwargs) -> str:
        """The generic product: SymPy's Rust printer rebuilds it with integers cast to floats
        and loses the parentheses of a sum inside (every integer here is an f64 already)."""
        return CodePrinter._print_Mul(self, expr)

    def _print_Add(self, expr, order=None, **_kwargs) -> str:
        return CodePrinter._print_Add(self, expr, order)

    def _print_Integer(self, expr, **_kwargs) -> str:
        """Every integer of a kernel is an f64 value (a powi exponent is printed apart)."""
        return f"{int(expr)}_f64"

    def _print_Pow(self, expr, **_kwargs) -> str:
        base, exp = expr.args
        b = self.parenthesize(base, 1000)  # a method call binds tighter than any operator
        if exp.is_Integer:
            return f"{b}.powi({int(exp)})" if exp != -1 else f"{b}.recip()"
        if exp == sp.Rational(1, 2):
            return f"{b}.sqrt()"
        if exp == sp.Rational(-1, 2):
            return f"{b}.sqrt().recip()"
        return f"{b}.powf({self._print(exp)})"

    def _print_Max(self, expr, **_kwargs) -> str:  # f64::max, as C's fmax
        out = self._print(expr.args[0])
        for a in expr.args[1:]:
            out = f"({out}).max({self._print(a)})"
        return out

    def _print_Min(self, expr, **_kwargs) -> str:
        out = self._print(expr.args[0])
        for a in expr.args[1:]:
            out = f"({out}).min({self._print(a)})"
        return out

    def _print_log1p(self, expr, **_kwargs) -> str:
        return f"({self._print(expr.args[0])}).ln_1p()"

    def _print_sinc(self, expr, **_kwargs) -> str:
        x = expr.args[0]
        return self._print(sp.Piecewise((sp.sin(x) / x, sp.Ne(x, 0)), (sp.Float(1.0), True)))

    def _print_Infinity(self, expr, **_kwargs) -> str:
        return "f64::INFINITY"


def _unused(args, *exprs) -> list[str]:
    used = set().union(*(sp.sympify(e).free_symbols for e in exprs))
    return [a.name for a in args if a.symbol not in used]


def _iteration(fp, printer: RustKernelPrinter) -> dict:
    """The pieces of an iteration's loop, printed: hoisted and inner temporaries, start, step."""
    hoisted, loop = fixed_point_ast(fp)
    start, _, _, body = loop.args
    inner = body.body.args[1:-2]
    step = body.body.args[-2]
    return {
        "hoisted": [(str(a.lhs), printer.doprint(a.rhs)) for a in hoisted],
        "inner": [(str(a.lhs), printer.doprint(a.rhs)) for a in inner],
        "start": printer.doprint(start.rhs),
        "step": printer.doprint(step.rhs),
    }


def items(boards: list[Board]) -> dict:
    """Template context of the crate."""
    printer = RustKernelPrinter()
    modules = []
    for b in boards:
        kernels = []
        for k in b.kernels:
            lines, result, _ = kernel_body(k, RustKernelPrinter, {})
            kernels.append({"k": k, "lines": lines, "result": result, "latex": latex_of(k),
                            "unused": _unused(k.args, k.expr)})  # fmt: skip
        bundles = []
        for bu in b.bundles:
            lines, results, _ = bundle_body(bu, RustKernelPrinter, {})
            bundles.append({"b": bu, "lines": lines, "results": results,
                            "unused": _unused(bu.args, *(k.expr for k in bu.parts))})  # fmt: skip
        modules.append({"board": b, "kernels": kernels, "bundles": bundles,
                        "balances": [{"x": x} for x in b.balances]})  # fmt: skip
    fixed = [
        {"fp": fp, "module": b.module, "unused": _unused(fp.args, fp.start, fp.step),
         "x": fp.iterate.name, **_iteration(fp, printer)}
        for b in boards
        for fp in b.fixed_points
    ]  # fmt: skip
    return {"modules": modules, "fixed": fixed, "steps": [b.module for b in boards]}


#: The crate documentation's example: (module, kernel, arguments).
EXAMPLE = ("closed_forms", "hertz_contact_duration", ("0.25", "1.0", "1000.0", "0.075"))


def _example(boards: list[Board]) -> str:
    """The example's value, from mpmath at 50 digits, to 12 significant digits."""
    import mpmath as mp

    module, name, args = EXAMPLE
    (k,) = [k for b in boards if b.module == module for k in b.kernels if k.name == name]
    f = sp.lambdify([a.symbol for a in k.args], k.expr, "mpmath")
    with mp.workdps(50):
        return mp.nstr(f(*(mp.mpf(a) for a in args)), 12)


def render(boards: list[Board]) -> dict[str, str]:
    """``{path under generated/: text}`` of the Rust crate."""
    from . import checkpoints

    context = {**items(boards), **project(), "example": _example(boards), **checkpoints.recorded(boards),
               "points": checkpoints.POINTS, "digits": checkpoints.DIGITS,
               "rtol": checkpoints.RTOL}  # fmt: skip
    files = {"Cargo.toml": "Cargo.toml", "lib.rs": "src/lib.rs",
             "check_kernels.rs": "tests/check_kernels.rs", "README.md": "README.md"}  # fmt: skip
    out = {}
    for name, path in files.items():
        template = f"rust/{name}.j2"
        out[f"{FOLDER}/{path}"] = _env.get_template(template).render(
            template=f"derive/templates/{template}", **context
        )
    return out
