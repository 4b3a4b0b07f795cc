"""The blackboard every derivation step writes on.

A step is a plain function that builds a :class:`Board` top to bottom: it *writes* named
intermediate results (SymPy objects with a sentence of explanation and the paper's equation
number), *checks* each result against something independent, records every place where the
paper's printed equation differs from the derivation (*errata*), and declares the *kernels* to
emit into ``generated/``.  Documentation renders ``board.lines`` in order; ``python -m derive``
prints ``board.checks`` as the summary table.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

#: Derivative kernels' names for arguments whose names differ only in case.
SPELLED = {"m": "impact_mass", "M": "main_mass"}


@dataclass(frozen=True)
class Line:
    """One line on the board: a named intermediate result."""

    name: str
    value: Any
    text: str
    equation: str | None
    #: How the value is written on the board when SymPy's form is not how a teacher would write
    #: it: an expression in the symbols of ``names``, equal to ``value`` once they are
    #: substituted (a test checks it at random points).
    shown: Any = None
    names: dict | None = None


@dataclass(frozen=True)
class Check:
    """One row of the summary table."""

    name: str
    equation: str
    ok: bool
    detail: str
    seconds: float
    erratum: bool = False

    @property
    def status(self) -> str:
        if not self.ok:
            return "FAIL"
        return "ok (erratum)" if self.erratum else "ok"


@dataclass(frozen=True)
class Erratum:
    """A place where the printed equation differs from the derivation.

    ``printed`` and ``derived`` are SymPy expressions in the same symbols; ``point`` is a
    substitution at which they evaluate to different numbers (so a test can prove that the
    difference is real and has not silently disappeared).
    """

    key: str
    equation: str
    what: str
    printed: sp.Basic
    derived: sp.Basic
    consequence: str
    point: dict = field(default_factory=dict)

    def differs(self) -> bool:
        """True when the printed and derived forms differ numerically at ``point``."""
        p = sp.N(sp.sympify(self.printed).subs(self.point), 30)
        d = sp.N(sp.sympify(self.derived).subs(self.point), 30)
        if not d.is_finite:
            raise ValueError(f"erratum {self.key}: derived form not finite at its point")
        if not p.is_finite:  # the printed form breaks down (e.g. 0/0) where the derived does not
            return True
        return bool(abs(p - d) > 1e-20 * (1 + abs(d)))


@dataclass(frozen=True)
class Arg:
    """A kernel argument: the SymPy symbol, its SI unit, a description and a physical range.

    ``low``/``high`` bound the random points the tests draw (log-uniform when ``log``).
    """

    symbol: sp.Symbol
    unit: str
    doc: str
    low: float
    high: float
    log: bool = False

    @property
    def name(self) -> str:
        return self.symbol.name


@dataclass(frozen=True)
class Kernel:
    """A function to emit: ``name(*args) -> expr`` evaluated with NumPy, broadcasting."""

    name: str
    args: tuple[Arg, ...]
    expr: sp.Expr
    returns: str
    unit: str
    equation: str
    lhs: str
    note: str = ""
    printed: bool = False
    #: Inequalities (SymPy relationals in the arguments) a physical point must satisfy.
    constraints: tuple[sp.Basic, ...] = ()
    #: For oscillating results: the amplitude against which rounding near a zero crossing is
    #: judged (the test's error bound is rtol·(|value| + |magnitude|)).
    magnitude: sp.Expr | None = None
    #: For a derivative kernel (:meth:`Board.derivatives`): the value kernel's name and the
    #: argument it is differentiated in.
    derivative_of: tuple[str, str] | None = None


@dataclass(frozen=True)
class Bundle:
    """Kernels of the same arguments emitted as one function that returns all of them, their
    common subexpressions computed once (``sympy.cse`` over the parts together): a value with
    its derivatives, or a state with its transition matrix, as a caller wants them together."""

    name: str
    parts: tuple[Kernel, ...]
    returns: str

    @property
    def args(self) -> tuple[Arg, ...]:
        return self.parts[0].args

    @property
    def equation(self) -> str:
        return self.parts[0].equation


@dataclass(frozen=True)
class Balance:
    """The alternating frequency–time residual of the impact damper's harmonic balance with one
    compliant law (Step 17, Eq. F9–F10), emitted as a loop in every target: the coefficients U
    of x and y (H harmonics, order a₀, a₁, b₁, …) → N time samples → the law's force ``force``
    (a bundle of F, ∂F/∂δ, ∂F/∂δ̇ in (δ, δ̇, *params)) at each → the residual R(U, ω), its
    Jacobian ∂R/∂U and ∂R/∂ω."""

    name: str
    #: the law as a sentence names it ("Hunt–Crossley")
    law: str
    force: Bundle
    params: tuple[Arg, ...]
    equation: str


@dataclass(frozen=True)
class FixedPoint:
    """A fixed-point iteration to emit as a loop: ``x⁽⁰⁾ = start(args)``,
    ``x⁽ⁱ⁾ = step(x⁽ⁱ⁻¹⁾, args)`` until abs(x⁽ⁱ⁾ − x⁽ⁱ⁻¹⁾) ≤ tol·abs(x⁽ⁱ⁾) or ``max_iter``
    steps; the emitted function returns the last iterate and the number of steps taken."""

    name: str
    args: tuple[Arg, ...]
    iterate: sp.Symbol
    start: sp.Expr
    step: sp.Expr
    returns: str
    unit: str
    equation: str
    lhs: str
    tol: float = 1e-14
    max_iter: int = 100
    note: str = ""
    printed: bool = False


@dataclass(frozen=True)
class Constant:
    """A module-level numeric constant of a generated file (computed, never typed in)."""

    name: str
    values: tuple[str, ...]
    doc: str
    digits: tuple[str, ...] = ()


#: The records of a board a notebook's text cells describe, in the order they describe them.
RECORDS = ("lines", "checks", "errata", "kernels", "constants")


class Board:
    """An ordered record of one derivation step."""

    def __init__(self, module: str, title: str, equations: str) -> None:
        self.module = module
        self.title = title
        self.equations = equations
        self.lines: list[Line] = []
        self.checks: list[Check] = []
        self.errata: list[Erratum] = []
        self.kernels: list[Kernel] = []
        self.constants: list[Constant] = []
        self.fixed_points: list[FixedPoint] = []
        self.bundles: list[Bundle] = []
        self.balances: list[Balance] = []
        self.values: dict[str, Any] = {}
        #: For each record a notebook describes (its lines, checks, errata, kernels, constants),
        #: the line of the step's ``derive()`` whose statement wrote it, in order (None where no
        #: ``derive()`` of this step was running: a notebook's cells): :mod:`derive.notebooks`
        #: places each record after its cell without running the step again.
        self.written_at: dict[str, list[int | None]] = {k: [] for k in RECORDS}
        self._clock = time.perf_counter()

    def _note(self, records: str) -> None:
        """Note in :attr:`written_at` the line of this step's ``derive()`` now running (the
        statement that called, directly or through helpers, the board method writing to
        ``records``)."""
        frame, module = sys._getframe(2), f"derive.{self.module}"
        while frame is not None and not (
            frame.f_code.co_name == "derive" and frame.f_globals.get("__name__") == module
        ):
            frame = frame.f_back
        self.written_at[records].append(None if frame is None else frame.f_lineno)

    def write(
        self,
        name: str,
        value: Any,
        text: str = "",
        equation: str | None = None,
        shown: Any = None,
        names: dict | None = None,
    ) -> Any:
        """Write a named intermediate result on the board and return it unchanged.

        ``shown`` and ``names``: the form a reader sees, when it differs from the value's own
        (see :class:`Line`); :mod:`derive.present` writes either on the page."""
        self.lines.append(Line(name, value, text, equation, shown, names))
        self._note("lines")
        self.values[name] = value
        return value

    def check(self, name: str, equation: str, ok: bool, detail: str = "", erratum: bool = False):
        """Record a checked result; the time is the wall time since the previous check."""
        now = time.perf_counter()
        self.checks.append(Check(name, equation, bool(ok), detail, now - self._clock, erratum))
        self._note("checks")
        self._clock = now

    def erratum(self, **kwargs: Any) -> Erratum:
        e = Erratum(**kwargs)
        self.errata.append(e)
        self._note("errata")
        return e

    def kernel(self, **kwargs: Any) -> Kernel:
        k = Kernel(**kwargs)
        self.kernels.append(k)
        self._note("kernels")
        return k

    def derivatives(
        self, kernel: Kernel, wrt: tuple[str, ...], given: dict[str, sp.Expr] | None = None
    ) -> list[Kernel]:
        """Declare the partial derivatives of ``kernel`` with respect to the arguments named in
        ``wrt``: one kernel ``<name>_d_<arg>`` each, its expression ``sympy.diff`` of the value's,
        its unit the value's over the argument's, its error scale :func:`rounding_scale` of the
        derivative (the sum of its terms' sizes: what rounding cannot beat).

        An argument in the condition of a case distinction (a ``Piecewise``, e.g. the resonant
        flight M·Ω² = K) is refused: differentiating case by case is wrong on the case's own set,
        unless ``given`` holds the derivative the step derived for it (its case as a limit).
        An argument the value does not depend on gets no kernel (its derivative is zero)."""
        given = given or {}
        cases = set().union(*(c.free_symbols for pw in kernel.expr.atoms(sp.Piecewise)
                               for _, c in pw.args))  # fmt: skip
        by_name = {a.name: a for a in kernel.args}
        lower = [a.name.lower() for a in kernel.args]
        out = []
        for name in wrt:
            a = by_name[name]
            if a.symbol not in kernel.expr.free_symbols:
                continue  # identically zero: nothing to emit
            if a.symbol in cases and name not in given:
                raise ValueError(f"{kernel.name}: {name} appears in a case condition")
            # names that differ only in case (m, M) are one name in Fortran and in a file system
            # that ignores case (the Octave files): spelled out
            suffix = SPELLED[name] if lower.count(name.lower()) > 1 else name
            d = given[name] if name in given else sp.diff(kernel.expr, a.symbol)
            out.append(
                self.kernel(
                    name=f"{kernel.name}_d_{suffix}",
                    args=kernel.args,
                    expr=d,
                    returns=f"∂/∂{name} of: {kernel.returns[0].lower()}{kernel.returns[1:]} "
                    f"(its partial derivative in {a.doc[0].lower()}{a.doc[1:]})",
                    unit=unit_quotient(kernel.unit, a.unit),
                    equation=kernel.equation,
                    lhs=rf"\partial {kernel.lhs} / \partial {sp.latex(a.symbol)}",
                    note=f"sympy.diff of {kernel.name} in {name}"
                    + (" (the case's own limit derived on the board)" if name in given else ""),
                    printed=kernel.printed,
                    constraints=kernel.constraints,
                    magnitude=rounding_scale(d),
                    derivative_of=(kernel.name, name),
                )
            )
        return out

    def bundle(self, name: str, parts: list[Kernel], returns: str) -> Bundle:
        """Declare :class:`Bundle` ``name`` of ``parts`` (kernels of this board with the same
        arguments, in the order the function returns them)."""
        names = [a.name for a in parts[0].args]
        for k in parts:
            if [a.name for a in k.args] != names or not any(k is j for j in self.kernels):
                raise ValueError(f"{name}: {k.name} is not a kernel of this board with {names}")
        b = Bundle(name, tuple(parts), returns)
        self.bundles.append(b)
        return b

    def balance(self, **kwargs: Any) -> Balance:
        """Declare a :class:`Balance` (the force's bundle must be this board's)."""
        b = Balance(**kwargs)
        if not any(b.force is x for x in self.bundles):
            raise ValueError(f"{b.name}: its force is not a bundle of this board")
        self.balances.append(b)
        return b

    def fixed_point(self, **kwargs: Any) -> FixedPoint:
        f = FixedPoint(**kwargs)
        self.fixed_points.append(f)
        return f

    def constant(self, **kwargs: Any) -> Constant:
        c = Constant(**kwargs)
        self.constants.append(c)
        self._note("constants")
        return c


def unit_quotient(top: str, bottom: str) -> str:
    """The unit of a quantity in ``top`` per unit of ``bottom`` (``"m"``, ``"m/s"`` → ``"s"``),
    simplified by pint and written as the kernels' units are (``N/m^1.5``, ``1`` for none)."""
    import pint

    ureg = pint.UnitRegistry()
    units = (ureg(top) / ureg(bottom)).units
    text = f"{units:~C}".replace("**", "^").replace("*", " ")
    return text or "1"


def rounding_scale(expr: sp.Expr) -> sp.Expr:
    """An error scale of ``expr``: its sums replaced by the sums of their terms' sizes (products
    and integer powers of those), cos and sin by 1, any other function by its size — what the
    terms of an expression amount to before they cancel, which is what rounding is relative to."""
    if isinstance(expr, sp.Piecewise):
        return sp.Piecewise(*[(rounding_scale(x), c) for x, c in expr.args])
    if expr.is_Add:
        return sp.Add(*[rounding_scale(a) for a in expr.args])
    if expr.is_Mul:
        return sp.Mul(*[rounding_scale(a) for a in expr.args])
    if expr.is_Pow and expr.exp.is_Integer:
        return rounding_scale(expr.base) ** expr.exp
    if isinstance(expr, (sp.cos, sp.sin)):
        return sp.Integer(1)
    return sp.Abs(expr)
