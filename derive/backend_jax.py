"""JAX target: one module per derivation step (``generated/jax/``), every kernel a jit-compiled
function of ``jax.numpy`` that broadcasts, ``vmap``-s and differentiates, every fixed-point
iteration a ``jax.lax.while_loop``.

The backend is a printer, a naming rule and three templates:

- :class:`JaxKernelPrinter` is SymPy's ``JaxPrinter`` with floats written in full (``repr``).
  It writes a case distinction as ``jax.numpy.select``, which traces under ``jit``.
- ``symimpact.generated.jax.<module>.<kernel>`` mirrors the NumPy kernel's name and arguments.
- ``derive/templates/jax/module.py.j2``, ``__init__.py.j2`` and ``README.md.j2``.  The package
  turns on JAX's 64-bit floats when imported (``jax_enable_x64``): the kernels are checked to
  1e-12, beyond float32.
"""

from __future__ import annotations

import sympy as sp
from sympy.printing.numpy import JaxPrinter

from .board import Board
from .codegen import _env, bundle_body, fixed_point_ast, kernel_body, latex_of

FOLDER = "jax"


class JaxKernelPrinter(JaxPrinter):
    """SymPy's JAX printer with full-precision floats."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__({"fully_qualified_modules": True, **(settings or {})})

    def _print_Float(self, expr: sp.Float) -> str:
        return repr(float(expr))


def _iteration(fp, printer: JaxKernelPrinter) -> dict:
    """The pieces of an iteration's loop, printed: hoisted and inner temporaries, start, step."""
    hoisted, loop = fixed_point_ast(fp)
    start, _, _, body = loop.args
    return {
        "hoisted": [(str(a.lhs), printer.doprint(a.rhs)) for a in hoisted],
        "inner": [(str(a.lhs), printer.doprint(a.rhs)) for a in body.body.args[1:-2]],
        "start": printer.doprint(start.rhs),
        "step": printer.doprint(body.body.args[-2].rhs),
    }


def render(boards: list[Board]) -> dict[str, str]:
    """``{path under generated/: text}`` of the JAX target."""
    printer = JaxKernelPrinter()
    out = {}
    for b in boards:
        kernels = []
        for k in b.kernels:
            lines, result, _ = kernel_body(k, JaxKernelPrinter, {})
            kernels.append({"k": k, "lines": lines, "result": result, "latex": latex_of(k),
                            "argnames": ", ".join(a.name for a in k.args)})  # fmt: skip
        bundles = []
        for bu in b.bundles:
            lines, results, _ = bundle_body(bu, JaxKernelPrinter, {})
            bundles.append({"b": bu, "lines": lines, "results": results,
                            "argnames": ", ".join(a.name for a in bu.args)})  # fmt: skip
        fixed = [{"fp": fp, "x": fp.iterate.name, **_iteration(fp, printer),
                  "argnames": "".join(f"{a.name}, " for a in fp.args)}
                 for fp in b.fixed_points]  # fmt: skip
        template = "jax/module.py.j2"
        out[f"{FOLDER}/{b.module}.py"] = _env.get_template(template).render(
            template=f"derive/templates/{template}", board=b, kernels=kernels, fixed=fixed,
            bundles=bundles, balances=[{"name": x.name, "law": x.law, "equation": x.equation,
                                        "force": x.force, "params": x.params,
                                        "paramnames": ", ".join(a.name for a in x.params)}
                                       for x in b.balances],
        )  # fmt: skip
    for name in ("__init__.py", "README.md"):
        template = f"jax/{name}.j2"
        out[f"{FOLDER}/{name}"] = _env.get_template(template).render(
            template=f"derive/templates/{template}", boards=boards,
            n_kernels=sum(len(b.kernels) for b in boards),
            n_fixed=sum(len(b.fixed_points) for b in boards),
        )  # fmt: skip
    return out
