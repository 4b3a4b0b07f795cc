"""Fortran 2008 target: one module (``generated/fortran/symimpact.f90``) with every kernel as a
pure elemental ``real(dp)`` function and every fixed-point iteration as a pure elemental
subroutine, and a check program at the recorded points of :mod:`derive.checkpoints`.

The backend is a printer, a naming rule and three templates:

- :class:`FortranKernelPrinter` is SymPy's ``FCodePrinter`` (free form, Fortran 2008) with
  floats written in full with the kind ``_dp`` (``real64``), integers as ``real(dp)`` values
  except in an exponent (``x**2`` stays an integer power), π as a literal, ``log1p`` as the
  module's own :data:`LOG1P` (Fortran has no ``log1p``) and ``sinc`` as its case distinction;
  a case distinction is ``merge``.  Lines are wrapped at 132 columns.
- Every function is named ``<module>_<kernel>`` after the Python function it mirrors (63
  characters at most).  Fortran does not tell ``M`` from ``m``: where two arguments of one kernel
  differ only in case, the one with capitals gets a trailing underscore (``M_`` beside ``m``);
  the argument list in each function's comment says so.
- ``derive/templates/fortran/symimpact.f90.j2``, ``check_kernels.f90.j2`` and ``README.md.j2``.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import Boolean
from sympy.printing.fortran import FCodePrinter
from sympy.printing.precedence import precedence

from .board import Arg, Board
from .codegen import _env, fixed_point_ast, numeric_constants, project

FOLDER = "fortran"
MAX_NAME = 63  # Fortran 2003 and later
PREFIX = "cse_"  # common subexpressions (a Fortran name starts with a letter)
LOG1P = "symimpact_log1p"
RESULT = "f_result"  # a kernel's result variable (no argument is named so)


class FortranKernelPrinter(FCodePrinter):
    """Fortran 2008 printer: ``_dp`` literals, integer exponents, log1p and sinc."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(
            {"standard": 2008, "source_format": "free", "name_mangling": False, **(settings or {})}
        )

    def _print_Float(self, expr, **_kwargs) -> str:
        return f"{float(expr)!r}_dp"

    def _print_NumberSymbol(self, expr, **_kwargs) -> str:
        return f"{float(expr)!r}_dp"

    _print_Pi = _print_NumberSymbol
    _print_Exp1 = _print_NumberSymbol

    def _print_Integer(self, expr, **_kwargs) -> str:
        return f"{int(expr)}.0_dp"

    def _print_Rational(self, expr, **_kwargs) -> str:
        return f"({int(expr.p)}.0_dp/{int(expr.q)}.0_dp)"

    def _print_Pow(self, expr, **_kwargs) -> str:
        base, exp = expr.args
        b = self.parenthesize(base, precedence(expr) + 1)
        if exp.is_Integer:
            return f"1.0_dp/{b}" if exp == -1 else f"{b}**{int(exp)}" if exp > 0 else \
                f"{b}**({int(exp)})"  # fmt: skip
        if exp == sp.Rational(1, 2):
            return f"sqrt({self._print(base)})"
        return f"{b}**({self._print(exp)})"

    def _print_log1p(self, expr, **_kwargs) -> str:
        return f"{LOG1P}({self._print(expr.args[0])})"

    def _print_sinc(self, expr, **_kwargs) -> str:
        x = expr.args[0]
        return self._print(sp.Piecewise((sp.sin(x) / x, sp.Ne(x, 0)), (sp.Float(1.0), True)))

    def _print_Infinity(self, expr, **_kwargs) -> str:
        return "ieee_value(1.0_dp, ieee_positive_inf)"

    def one_line(self, expr) -> str:
        """``expr`` printed on one line (the printer's own continuation lines joined)."""
        text = self.doprint(expr)
        return " ".join(part.strip().rstrip("&").strip() for part in text.split("\n"))

    def wrapped(self, statement: str, indent: int) -> list[str]:
        """``statement`` wrapped at 132 columns (continuation lines end in ``&``)."""
        return self._wrap_fortran([" " * indent + statement])


def fortran_names(args) -> dict[str, str]:
    """Argument name → Fortran name: unique without regard to case (module text)."""
    lower = [a.name.lower() for a in args]
    out = {}
    for a in args:
        clash = lower.count(a.name.lower()) > 1 and a.name != a.name.lower()
        out[a.name] = a.name + "_" if clash else a.name
    if len({n.lower() for n in out.values()}) != len(out):
        raise ValueError(f"arguments {list(out)} stay ambiguous in Fortran")
    return out


def fortran_name(module: str, name: str) -> str:
    """The Fortran name of kernel ``name`` of ``module`` (63 characters at most)."""
    full = f"{module}_{name}"
    if len(full) > MAX_NAME:
        raise ValueError(f"{full} is longer than Fortran's {MAX_NAME} characters")
    return full


def _renamed(args, *exprs):
    names = fortran_names(args)
    subs = {a.symbol: sp.Symbol(names[a.name], **a.symbol.assumptions0) for a in args
            if names[a.name] != a.name}  # fmt: skip
    return names, [sp.sympify(e).xreplace(subs) for e in exprs]


def _declarations(assignments) -> tuple[list[str], list[str]]:
    """(real, logical) names of the temporaries."""
    real, logical = [], []
    for sym, val in assignments:
        (logical if isinstance(val, (Relational, Boolean)) else real).append(str(sym))
    return real, logical


def _declaration_lines(p: FortranKernelPrinter, real, logical) -> list[str]:
    lines = p.wrapped(f"real(dp) :: {', '.join(real)}", 8) if real else []
    return lines + (p.wrapped(f"logical :: {', '.join(logical)}", 8) if logical else [])


def _cse_body(p: FortranKernelPrinter, exprs, targets) -> tuple[list[str], list[str]]:
    """(declaration lines, body lines) computing ``exprs`` into ``targets`` (Fortran names),
    their common subexpressions eliminated once over all of them."""
    replacements, reduced = sp.cse([numeric_constants(e) for e in exprs],
                                   symbols=sp.numbered_symbols(PREFIX), order="canonical")  # fmt: skip
    body = []
    for sym, val in replacements:
        body += p.wrapped(f"{sym} = {p.one_line(val)}", 8)
    for target, r in zip(targets, reduced, strict=True):
        body += p.wrapped(f"{target} = {p.one_line(r)}", 8)
    return _declaration_lines(p, *_declarations(replacements)), body


def items(boards: list[Board]) -> dict:
    """Template context of the module."""
    p = FortranKernelPrinter()
    seen: dict[str, str] = {}
    modules = []
    for b in boards:
        kernels = []
        for k in b.kernels:
            names, exprs = _renamed(k.args, k.expr)
            declarations, body = _cse_body(p, exprs, [RESULT])
            name = fortran_name(b.module, k.name)
            if name.lower() in seen:
                raise ValueError(f"{name} and {seen[name.lower()]} are one name in Fortran")
            seen[name.lower()] = name
            kernels.append({"k": k, "f": name, "names": names, "body": body,
                            "declarations": declarations,
                            "arglist": ", ".join(names[a.name] for a in k.args)})  # fmt: skip
        constants = [{"f": fortran_name(b.module, c.name), "const": c} for c in b.constants]
        bundles = []
        for bu in b.bundles:
            names, exprs = _renamed(bu.args, *(k.expr for k in bu.parts))
            outs = [f"out({j})" for j in range(1, len(exprs) + 1)]
            declarations, body = _cse_body(p, exprs, outs)
            name = fortran_name(b.module, bu.name)
            if name.lower() in seen:
                raise ValueError(f"{name} and {seen[name.lower()]} are one name in Fortran")
            seen[name.lower()] = name
            bundles.append({"b": bu, "f": name, "names": names, "body": body, "n": len(outs),
                            "parts": [fortran_name(b.module, k.name) for k in bu.parts],
                            "declarations": declarations,
                            "arglist": ", ".join(names[a.name] for a in bu.args)})  # fmt: skip
        balances = []
        for x in b.balances:
            names = fortran_names([Arg(sp.Symbol(n), "", "", 0, 0) for n in ("M", "C", "K", "m")]
                                  + list(x.params))  # fmt: skip
            balances.append({"x": x, "f": fortran_name(b.module, x.name), "names": names,
                             "force": fortran_name(b.module, x.force.name),
                             "arglist": ", ".join([*names.values()][:4] + ["gap"]
                                                  + [names[a.name] for a in x.params]),
                             "paramlist": ", ".join(names[a.name] for a in x.params)})  # fmt: skip
        modules.append({"board": b, "kernels": kernels, "constants": constants,
                        "bundles": bundles, "balances": balances})  # fmt: skip
    fixed = []
    for b in boards:
        for fp in b.fixed_points:
            names, (start, step) = _renamed(fp.args, fp.start, fp.step)
            hoisted, loop = fixed_point_ast(replace(fp, start=start, step=step), prefix=PREFIX)
            first, _, _, body = loop.args
            inner = body.body.args[1:-2]
            real, logical = _declarations([(a.lhs, a.rhs) for a in (*hoisted, *inner)])
            fixed.append({
                "fp": fp, "module": b.module, "f": fortran_name("fixed_points", fp.name),
                "names": names, "x": fp.iterate.name, "real": real, "logical": logical,
                "hoisted": [ln for a in hoisted for ln in p.wrapped(
                    f"{a.lhs} = {p.one_line(a.rhs)}", 8)],
                "start": p.wrapped(f"{fp.iterate.name} = {p.one_line(first.rhs)}", 8),
                "inner": [ln for a in inner for ln in p.wrapped(
                    f"{a.lhs} = {p.one_line(a.rhs)}", 12)],
                "step": p.wrapped(f"{fp.iterate.name} = {p.one_line(body.body.args[-2].rhs)}", 12),
                "declarations": _declaration_lines(p, real, logical),
            })  # fmt: skip
    return {"modules": modules, "fixed": fixed, "steps": [b.module for b in boards],
            "log1p": LOG1P, "result": RESULT}  # fmt: skip


def real_literal(decimal: str | float) -> str:
    """A decimal (``372450``, ``0.25``, ``3.4e+07``) or a float as a ``real(dp)`` literal."""
    if not isinstance(decimal, str):
        decimal = repr(float(decimal))
    if not any(c in decimal for c in ".eE"):
        decimal += ".0"
    return f"{decimal}_dp"


_env.filters["real_dp"] = real_literal


def render(boards: list[Board]) -> dict[str, str]:
    """``{path under generated/: text}`` of the Fortran target."""
    from . import checkpoints

    context = {**items(boards), **project(), **checkpoints.recorded(boards),
               "points": checkpoints.POINTS, "digits": checkpoints.DIGITS,
               "rtol": checkpoints.RTOL,
               "widest": max((len(bu.parts) for b in boards for bu in b.bundles), default=1),
               "f_name": fortran_name}  # fmt: skip
    out = {}
    for name in ("symimpact.f90", "check_kernels.f90", "README.md"):
        template = f"fortran/{name}.j2"
        out[f"{FOLDER}/{name}"] = _env.get_template(template).render(
            template=f"derive/templates/{template}", **context
        )
    return out
