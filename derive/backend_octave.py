"""MATLAB/Octave target: one function file per kernel and per fixed-point iteration
(``generated/octave/``), vectorised with element-wise operators.

The backend is a printer, a naming rule and two templates:

- :class:`OctaveKernelPrinter` is SymPy's ``OctaveCodePrinter`` (``.*``, ``./``, ``.^``) with
  floats written in full, and the three statements SymPy's Octave printer lacks for the loop of
  Eq. 31: ``CodeBlock``, ``While`` and the augmented assignment ``x += 1``.
- ``<module>_<kernel>.m`` names each file (and function) after the Python function it mirrors.
- ``derive/templates/octave/kernel.m.j2`` and ``fixed_point.m.j2``.  A kernel broadcasts its
  arguments (implicit expansion) and returns NaN where the Python kernel does, i.e. where a
  result is not real; an iteration loops over the broadcast elements and returns the value and
  the steps taken.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.octave import OctaveCodePrinter

from .board import Board
from .codegen import (
    _env,
    bundle_body,
    fixed_point_ast,
    fixed_point_latex,
    kernel_body,
    latex_of,
)

FOLDER = "octave"
MAX_NAME = 63  # namelengthmax of MATLAB and Octave
PICK = "pick"  # the local element-wise selection function of a kernel with a case distinction


class OctaveKernelPrinter(OctaveCodePrinter):
    """Octave printer with full-precision floats and the loop statements of Eq. 31."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings or {})

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))

    def _print_CodeBlock(self, expr) -> str:
        return "\n".join(self._print(a) for a in expr.args)

    def _print_While(self, expr) -> str:
        body = self._print(expr.body)
        inner = "\n".join("  " + line for line in body.split("\n"))
        return f"while ({self._print(expr.condition)})\n{inner}\nend"

    def _print_Piecewise(self, expr) -> str:
        """``pick(condition, value, otherwise)``: a local function of the kernel file that selects
        element by element, so the branch not taken (e.g. a division by zero at a resonance)
        cannot turn the result into NaN as SymPy's ``(c).*(a) + (~c).*(b)`` would."""
        *cases, (last, cond) = expr.args
        if cond != sp.true:
            raise ValueError("a kernel's Piecewise must end with an otherwise branch")
        out = self._print(last)
        for value, condition in reversed(cases):
            out = f"{PICK}({self._print(condition)}, {self._print(value)}, {out})"
        return out

    def _print_log1p(self, expr) -> str:  # Octave has log1p; SymPy's printer does not know it
        return f"log1p({self._print(expr.args[0])})"

    def _print_And(self, expr) -> str:  # scalar loop conditions: short-circuit &&
        return " && ".join(f"({self._print(a)})" for a in expr.args)

    def _print_AddAugmentedAssignment(self, expr) -> str:
        lhs = self._print(expr.lhs)
        return f"{lhs} = {lhs} + {self._print(expr.rhs)};"


class OctaveArrayPrinter(OctaveKernelPrinter):
    """The kernels' printer: their conditions hold element by element (``&``, not ``&&``)."""

    def _print_And(self, expr) -> str:
        return " & ".join(f"({self._print(a)})" for a in expr.args)


def _indented(lines: list[str]) -> list[str]:
    """Two spaces per open ``while`` (SymPy's Octave indenter knows no ``while``)."""
    out, depth = [], 0
    for line in lines:
        text = line.strip()
        if text == "end":
            depth -= 1
        out.append("  " * depth + text)
        if text.startswith("while"):
            depth += 1
    return out


def octave_name(module: str, name: str) -> str:
    """The function (and file) name of kernel ``name`` of the Python module ``module``."""
    full = f"{module}_{name}"
    if len(full) > MAX_NAME:
        raise ValueError(f"{full}: longer than MATLAB's {MAX_NAME} characters")
    return full


def render(boards: list[Board]) -> dict[str, str]:
    """``{path under generated/: text}`` of the Octave target."""
    printer = OctaveKernelPrinter()
    steps = [b.module for b in boards]
    out: dict[str, str] = {}
    names = []

    def emit(template: str, name: str, **context) -> None:
        out[f"{FOLDER}/{name}.m"] = _env.get_template(f"octave/{template}").render(
            template=f"derive/templates/octave/{template}", name=name, **context
        )
        names.append(name)

    for b in boards:
        for c in b.constants:
            emit("constant.m.j2", octave_name(b.module, c.name), board=b, const=c)
        for k in b.kernels:
            lines, result, ops = kernel_body(k, OctaveArrayPrinter, {}, prefix="x_")
            emit(
                "kernel.m.j2",
                octave_name(b.module, k.name),
                board=b,
                k=k,
                lines=lines,
                result=result,
                ops=ops,
                latex=latex_of(k),
                argnames=", ".join(a.name for a in k.args),
                pick=PICK if any(f"{PICK}(" in text for _, text in [*lines, ("", result)]) else "",
            )
    for b in boards:
        for bu in b.bundles:
            lines, results, ops = bundle_body(bu, OctaveArrayPrinter, {}, prefix="x_")
            emit(
                "bundle.m.j2",
                octave_name(b.module, bu.name),
                board=b,
                b=bu,
                lines=lines,
                results=results,
                ops=ops,
                argnames=", ".join(a.name for a in bu.args),
                name_of=lambda kernel, m=b.module: octave_name(m, kernel),
                pick=PICK if any(f"{PICK}(" in text for text in [*(t for _, t in lines), *results])
                else "",
            )  # fmt: skip
    for b in boards:
        for x in b.balances:
            emit("balance.m.j2", octave_name(b.module, x.name), board=b, x=x,
                 force=octave_name(b.module, x.force.name),
                 params=", ".join(a.name for a in x.params))  # fmt: skip
    for b in boards:
        for fp in b.fixed_points:
            hoisted, loop = fixed_point_ast(fp, prefix="c_")
            hoisted_text = [printer.doprint(h) for h in hoisted]
            loop_text = _indented(printer.doprint(loop).split("\n"))
            emit(
                "fixed_point.m.j2",
                octave_name("fixed_points", fp.name),
                board=b,
                fp=fp,
                hoisted=hoisted_text,
                loop=loop_text,
                pick=PICK if any(f"{PICK}(" in t for t in [*hoisted_text, *loop_text]) else "",
                x=fp.iterate.name,
                latex=fixed_point_latex(fp),
                argnames=", ".join(a.name for a in fp.args),
            )
    out[f"{FOLDER}/README.md"] = _env.get_template("octave/README.md.j2").render(
        template="derive/templates/octave/README.md.j2",
        steps=steps,
        names=names,
        n_kernels=sum(len(b.kernels) for b in boards),
        n_fixed=sum(len(b.fixed_points) for b in boards),
    )
    return out
