"""How a result is written on the board: the presentation of a SymPy value for a reader.

A derivation step computes with whatever form SymPy returns; a teacher does not copy that form to
the board.  :func:`board_form` turns a value into what a reader sees:

1. **The paper's symbols**: ``ba`` becomes B/A (and the fraction is then simplified, so
   ``ba/(ba - 1)`` reads B/(B − A)), ``k_hz`` reads K_Hz, ``beta_L`` reads βL.
2. **The paper's numbers**: a rational with a large denominator is written as the decimal the
   paper prints (12362361/4000000 → 12.362361, exact); a long number with no symbols (a 60-digit
   root, an exact algebraic fit coefficient) is rounded to 7 significant digits, and the line then
   says ≈ instead of =.
3. **Collected and factored**: of the value, its common factors pulled out and its factored form,
   the narrowest is kept.
4. **Named sub-expressions**: a result wider than the page keeps its shape and has its largest
   pieces named ("where R = …"), the step's own names first (:meth:`derive.board.Board.name`),
   then single capital letters the result does not use; a sum still too wide is broken across
   lines at its + and − signs.

The width of a formula is estimated from its LaTeX in em (the unit the page's font sets), with
fractions as wide as their wider part and exponents at 70 %; the docs test measures the rendered
pages in a browser, so an estimate that is off shows there.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import sympy as sp
from sympy.printing.latex import LatexPrinter

#: Widest formula line, in em of the page font (the content column is 660 px at a 1000 px
#: window with the docs theme; 17 px text gives 38 em, of which a margin is kept).
WIDTH_EM = 34.0
#: Significant digits of a rounded number (the paper prints 7: βL = 1.875104).
DIGITS = 7

#: How the paper writes the symbols whose SymPy names are spelled for code.
SYMBOL_TEX = {
    "k_hz": r"K_{Hz}",
    "beta_L": r"\beta L",
    "delta_max": r"\delta_{\max}",
    "zdot": r"\dot{z}",
    "zdot0": r"\dot{Z}_{0}",
    "xdot0": r"\dot{x}_{0}",
    "ydot0": r"\dot{y}_{0}",
    "c1": r"c_{1}",
    "k1": r"k_{1}",
    "omega0": r"\omega_{0}",
}

_NAME_POOL = "RSPQUVWGHNDFJ"


@dataclass
class Shown:
    """A value as written on the board: the result's lines of LaTeX (one display block), the
    definitions of the names it uses (name, LaTeX lines) and whether numbers were rounded."""

    lines: list[str]
    where: list[tuple[str, list[str]]] = field(default_factory=list)
    approx: bool = False
    #: name symbol → the sub-expression it stands for (a test substitutes them back).
    definitions: dict[sp.Symbol, sp.Basic] = field(default_factory=dict)


class _BoardPrinter(LatexPrinter):
    """SymPy's LaTeX printer, with a sum started by a positive term where it has one
    (B − A rather than −A + B)."""

    def _as_ordered_terms(self, expr, order=None):
        terms = list(super()._as_ordered_terms(expr, order=order))
        first = next((k for k, t in enumerate(terms) if not t.could_extract_minus_sign()), 0)
        return terms[first:] + terms[:first] if first else terms


def tex(value: Any) -> str:
    """LaTeX of a SymPy value with the paper's symbol names."""
    names = {s: SYMBOL_TEX[s.name] for s in _symbols(value) if s.name in SYMBOL_TEX}
    return _BoardPrinter({"symbol_names": names}).doprint(value)


def _symbols(value: Any) -> set[sp.Symbol]:
    if isinstance(value, sp.Basic | sp.MatrixBase):
        return {s for s in value.free_symbols if isinstance(s, sp.Symbol)}
    return set()


# --- width of a formula -------------------------------------------------------------------------

_NARROW = {",": 0.35, ".": 0.3, "(": 0.4, ")": 0.4, "[": 0.4, "]": 0.4, "|": 0.3, "!": 0.3}
_OPERATORS = {"+": 1.3, "-": 1.3, "=": 1.4, "<": 1.4, ">": 1.4}
_COMMAND_EM = {
    "cdot": 0.6, "quad": 1.0, "qquad": 2.0, ",": 0.17, ";": 0.28, ":": 0.22, "!": 0.0,
    "left": 0.0, "right": 0.0, "approx": 1.4, "leq": 1.4, "geq": 1.4, "neq": 1.4, "times": 1.2,
    "partial": 0.6, "infty": 1.0, "pm": 1.3, "mp": 1.3, "int": 0.8, "sum": 1.1, "prod": 1.1,
    "limits": 0.0, "displaystyle": 0.0, "max": 1.7, "min": 1.6, "log": 1.6, "exp": 1.7,
    "sin": 1.4, "cos": 1.6, "tan": 1.6, "sinh": 2.0, "cosh": 2.2, "tanh": 2.2, "Gamma": 0.65,
    "operatorname": 0.0, "mathrm": 0.0, "text": 0.0, "mathit": 0.0, "boldsymbol": 0.0,
}  # fmt: skip


def _group(s: str, i: int) -> tuple[str, int]:
    """The brace group (or single token) starting at ``s[i]``: (content, index after it)."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        return "", i
    if s[i] == "{":
        depth, j = 0, i
        while j < len(s):
            if s[j] == "{":
                depth += 1
            elif s[j] == "}":
                depth -= 1
                if depth == 0:
                    return s[i + 1 : j], j + 1
            j += 1
        return s[i + 1 :], len(s)
    if s[i] == "\\":
        m = re.match(r"\\([A-Za-z]+|.)", s[i:])
        assert m is not None
        return m.group(0), i + m.end()
    return s[i], i + 1


def width_em(latex: str) -> float:
    """Estimated rendered width of one line of LaTeX math, in em."""
    total, i = 0.0, 0
    while i < len(latex):
        c = latex[i]
        if c == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", latex[i:])
            assert m is not None
            name = m.group(1)
            i += m.end()
            if name in ("frac", "dfrac", "tfrac"):
                num, i = _group(latex, i)
                den, i = _group(latex, i)
                scale = 0.8 if name == "tfrac" else 1.0
                total += scale * max(width_em(num), width_em(den)) + 0.3
            elif name == "sqrt":
                if latex[i : i + 1] == "[":
                    j = latex.index("]", i)
                    total += 0.5 * width_em(latex[i + 1 : j])
                    i = j + 1
                arg, i = _group(latex, i)
                total += width_em(arg) + 1.0
            elif name in ("operatorname", "mathrm", "text", "mathit", "boldsymbol"):
                arg, i = _group(latex, i)
                total += width_em(arg) * (0.9 if name == "text" else 1.0)
            elif name in ("dot", "ddot", "hat", "bar", "tilde", "overline"):
                arg, i = _group(latex, i)
                total += width_em(arg)
            elif name in ("begin", "end"):
                _, i = _group(latex, i)
            elif name == "\\":
                pass
            else:
                total += _COMMAND_EM.get(name, 0.62)  # a Greek letter or a symbol
        elif c in "^_":
            arg, i = _group(latex, i + 1)
            total += 0.7 * width_em(arg) + 0.05
        elif c in "{} &":
            i += 1
        else:
            total += _OPERATORS.get(c, _NARROW.get(c, 0.55 if c.isdigit() else 0.58))
            i += 1
    return total


# --- numbers and symbols as the paper writes them -----------------------------------------------


def _terminating(q: sp.Rational) -> bool:
    d = int(q.q)
    for p in (2, 5):
        while d % p == 0:
            d //= p
    return d == 1


def _decimal_text(q: sp.Rational) -> str:
    """Exact decimal digits of a terminating rational."""
    f = Fraction(int(q.p), int(q.q))
    places = 0
    while f.denominator != 1:
        f *= 10
        places += 1
    digits = str(abs(f.numerator)).rjust(places + 1, "0")
    text = digits[: len(digits) - places] + ("." + digits[len(digits) - places :] if places else "")
    return ("-" if q < 0 else "") + text


def readable_numbers(expr: sp.Basic, digits: int = DIGITS) -> tuple[sp.Basic, bool]:
    """``expr`` with the numbers written as the paper writes them; True when any was rounded.

    A rational with a numerator or denominator above 1000 becomes a decimal (exact when it terminates within 12
    significant digits); a float, or a sub-expression without symbols whose LaTeX is longer than
    16 characters (an exact algebraic number), is rounded to :data:`DIGITS` digits — unless it
    is a plain exact constant a reader works with, as 3/(4π²) (:func:`_plain_exact`).
    """
    rounded = False

    def number(value: sp.Basic) -> sp.Basic:
        nonlocal rounded
        if isinstance(value, sp.Rational) and not isinstance(value, sp.Integer):
            if value.q <= 1000 and abs(value.p) <= 1000:
                return value  # a fraction a reader works with (3/8, 33/140)
            if _terminating(value) and len(_decimal_text(value).replace("-", "")) <= 13:
                return sp.Float(_decimal_text(value), 15)
        if isinstance(value, sp.Integer) and abs(value) < 10**9:
            return value
        if isinstance(value, sp.Float) and len(_float_digits(value)) <= digits:
            return value
        rounded = True
        return sp.Float(sp.N(value, digits + 5), digits)

    def walk(e: sp.Basic) -> sp.Basic:
        if isinstance(e, sp.Number):
            return number(e)
        if not e.args:
            return e
        if (not e.free_symbols and not isinstance(e, sp.Number) and len(sp.latex(e)) > 16
                and not _plain_exact(e)):  # fmt: skip
            try:
                return number(sp.Float(sp.N(e, 30), 30))
            except (TypeError, ValueError):
                pass
        new = [walk(a) for a in e.args]
        return e.func(*new) if any(n is not a for n, a in zip(new, e.args, strict=True)) else e

    return walk(expr), rounded


def _plain_exact(e: sp.Basic) -> bool:
    """Whether the constant ``e`` reads best as it stands: built from whole numbers and fractions
    up to 1000, π and Euler's e by sums, products, powers and roots, at most 40 LaTeX characters
    (3/(4π²), √2/2) — not an algebraic number from a solve or a 60-digit root."""
    if len(sp.latex(e)) > 40:
        return False
    for a in sp.preorder_traversal(e):
        if isinstance(a, sp.Rational):
            if abs(a.p) > 1000 or a.q > 1000:
                return False
        elif a.is_Atom and a not in (sp.pi, sp.E):
            return False  # a float, a root object, anything but small exact numbers
        elif not isinstance(a, sp.Add | sp.Mul | sp.Pow) and not a.is_Atom:
            return False  # a function (a logarithm, a Bessel value): its decimal is read
    return True


def _float_digits(x: sp.Float) -> str:
    return re.sub(r"[^0-9]", "", str(x)).lstrip("0").rstrip("0")


def paper_symbols(expr: sp.Basic) -> sp.Basic:
    """``ba`` (the amplitude ratio) written as B/A, with the fraction simplified."""
    ba = next((s for s in expr.free_symbols if getattr(s, "name", "") == "ba"), None)
    if ba is None:
        return expr
    A, B = sp.symbols("A B")
    new = expr.subs(ba, B / A)
    candidates = [new, sp.cancel(new), sp.factor(new)]
    for c in candidates[1:]:
        n, d = sp.fraction(c)
        if d != 1:  # −B/(A − B) read as B/(B − A)
            candidates.append(sp.Mul(sp.expand(-n), sp.Pow(sp.expand(-d), -1), evaluate=False))
    return min(candidates, key=lambda e: (width_em(tex(e)), tex(e).lstrip().startswith("-")))


def _shapes(expr: sp.Basic) -> list[sp.Basic]:
    """The value, its common factors pulled out, and (for a moderate size) its factored form."""
    out = [expr]
    if isinstance(expr, sp.Expr) and not expr.is_Atom:
        out.append(sp.factor_terms(expr))
        if sp.count_ops(expr) < 150:
            try:
                out.append(sp.factor(expr))
            except (sp.PolynomialError, NotImplementedError, TypeError):
                pass
            out.append(sp.expand(expr, deep=False))  # a sum of fractions, not a fraction of sums
    return out


def nested_fractions(latex: str) -> int:
    """Fractions written inside the numerator or denominator of another (set small, hard to
    read on a board)."""
    count, i = 0, 0
    while (i := latex.find("\\frac", i)) >= 0:
        num, j = _group(latex, i + 5)
        den, _ = _group(latex, j)
        count += num.count("\\frac") + den.count("\\frac")
        i += 5
    return count


def _readability(e: sp.Basic, limit: float = 10**9) -> tuple[bool, int, float]:
    """Sort key of the forms of a result: fits the board, fewest nested fractions, narrowest."""
    text = tex(e)
    w = width_em(text)
    return (w > limit, nested_fractions(text), w)


# --- naming and breaking ------------------------------------------------------------------------


def _nodes(expr: sp.Basic) -> list[sp.Basic]:
    out = []
    for node in sp.preorder_traversal(expr):
        if node is expr or node.is_Atom or isinstance(node, sp.Tuple):
            continue
        out.append(node)
    return out


def _name_pool(used: set[str]) -> list[sp.Symbol]:
    letters = [c for c in _NAME_POOL if c not in used]
    letters += [f"R_{i}" for i in range(1, 60) if f"R_{i}" not in used]
    return [sp.Symbol(c) for c in letters]


def _pick(expr: sp.Basic, limit: float) -> sp.Basic | None:
    """The sub-expression to name: the one whose naming narrows ``expr`` most (repeated pieces
    count once per occurrence), among those that fit on a line themselves or can be broken."""
    counts: dict[sp.Basic, int] = {}
    for node in _nodes(expr):
        counts[node] = counts.get(node, 0) + 1
    best, gain = None, 0.0
    whole = width_em(tex(expr))
    for node, n in counts.items():
        w = width_em(tex(node))
        if w < 3.0 or w > 0.6 * whole:
            continue  # too small to be worth a name, or so big the result would be only a name
        if w > limit and not isinstance(node, sp.Add):
            continue  # too wide to define on one line: one of its parts is named instead
        g = n * (w - 1.0)
        if g > gain:
            best, gain = node, g
    if best is None:  # everything is too wide: name the widest node all the same
        nodes = [n for n in counts if width_em(tex(n)) >= 3.0]
        best = max(nodes, key=lambda n: width_em(tex(n)), default=None)
    return best


def _break_sum(lhs: str, expr: sp.Basic, limit: float) -> list[str] | None:
    """``lhs = expr`` across lines at the top-level signs when every term fits, else None.

    A product with one wide sum among its factors is written c·[t₁ + t₂ … ] with the bracket's
    terms across lines, as on a board."""
    coefficient, opening, closing = "", "", ""
    if isinstance(expr, sp.Mul):
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if len(sums) != 1:
            return None
        rest = sp.Mul(*[f for f in expr.args if f is not sums[0]])
        if width_em(tex(rest)) > limit / 2:
            return None
        coefficient = "" if rest == 1 else ("-" if rest == -1 else tex(rest))
        opening, closing, expr = r"\left[", r"\right]", sums[0]
    if not isinstance(expr, sp.Add):
        return None
    texts = []
    for k, t in enumerate(expr.as_ordered_terms()):
        s = tex(t)
        if k and not s.startswith("-"):
            s = "+ " + s
        texts.append(s)
    if any(width_em(s) > limit - 4 for s in texts):
        return None
    head = f"{lhs} {coefficient} {opening}".strip()
    lines, current = [], head
    for s in texts:
        candidate = f"{current} {s}"
        if width_em(candidate) + 1 > limit and current not in (head, r"&\quad"):
            lines.append(current + (r" \right." if opening else ""))
            current = r"&\quad " + (r"\left. " if opening else "") + s
        else:
            current = candidate
    lines.append(current + (" " + closing if closing else ""))
    return lines


@dataclass
class _State:
    pool: list[sp.Symbol]
    definitions: dict[sp.Symbol, sp.Basic] = field(default_factory=dict)
    order: list[sp.Symbol] = field(default_factory=list)


def _fit(lhs: str, expr: sp.Basic, limit: float, state: _State) -> list[str]:
    """Lines of ``lhs = expr`` no wider than ``limit``, naming pieces into ``state``."""
    for _ in range(40):
        one = f"{lhs} {tex(expr)}".strip()
        if width_em(one) <= limit:
            return [one]
        broken = _break_sum(lhs, expr, limit)
        if broken is not None:
            return broken
        node = _pick(expr, limit)
        if node is None:
            return [one]
        name = state.pool.pop(0)
        state.definitions[name] = node
        state.order.append(name)
        expr = expr.xreplace({node: name})
    return [f"{lhs} {tex(expr)}"]


def board_form(
    value: Any,
    lhs: str = "",
    names: dict[sp.Symbol, sp.Basic] | None = None,
    limit: float = WIDTH_EM,
    digits: int = DIGITS,
) -> Shown | None:
    """``value`` as written on the board (see the module text), or None for a value that is not
    SymPy math (shown as text by the caller).

    ``lhs``: LaTeX written before the value ("K ="); ``names``: the step's own names for
    sub-expressions, used where they occur (symbol → expression); ``digits``: significant
    digits of a rounded number (more where two numbers that differ late are compared).
    """
    if isinstance(value, dict) and value and all(isinstance(v, sp.Basic) for v in value.values()):
        items = [(tex(k), v) for k, v in value.items()]
    elif isinstance(value, list | tuple) and value and all(isinstance(v, sp.Basic) for v in value):
        if all(isinstance(v, sp.Number) for v in value):
            return _number_list(value, limit, digits)
        return _expression_list(value, names or {}, limit, digits)
    elif isinstance(value, sp.Basic):
        items = [(lhs, value)]
    else:
        return None
    used = set().union(*(_names_in(v) for _, v in items)) | set(names or {})
    state = _State(_name_pool({str(s) for s in used}))
    lines, approx = [], False
    own = names or {}
    for left, v in items:
        suffix = ""
        if isinstance(v, sp.Eq) and width_em(tex(v.lhs)) <= limit / 3:
            left, v = f"{left} {tex(v.lhs)}".strip(), v.rhs
        elif isinstance(v, sp.Eq):  # a long left side: written first, "= 0" after it
            suffix, v = f" = {tex(v.rhs)}", v.lhs
        v, rounded = _prepare(v, own, digits)
        approx |= rounded
        for symbol in sorted(v.free_symbols & set(own), key=sp.default_sort_key):
            if symbol not in state.definitions:
                state.definitions[symbol] = own[symbol]
                state.order.append(symbol)
        if left:
            relation = r"&\approx" if rounded else "&="
            left = (left[:-1].rstrip() if left.endswith("=") else left) + f" {relation}"
        elif rounded:
            left = r"\approx"
        fitted = _fit(left, v, limit - width_em(suffix), state)
        fitted[-1] += suffix
        lines += fitted
    where = []
    k = 0
    while k < len(state.order):
        name = state.order[k]
        k += 1
        body = state.definitions[name]
        for symbol in sorted(body.free_symbols & set(own), key=sp.default_sort_key):
            if symbol not in state.definitions:
                state.definitions[symbol] = own[symbol]
                state.order.append(symbol)
        body, _ = readable_numbers(body)
        defined = _fit(f"{tex(name)} &=", body, limit, state)
        where.append((tex(name), defined))
    return Shown(lines, where, approx, dict(state.definitions))


def _names_in(v: sp.Basic) -> set[str]:
    return {s.name for s in v.free_symbols if isinstance(s, sp.Symbol)}


def _prepare(
    v: sp.Basic, own: dict[sp.Symbol, sp.Basic], digits: int = DIGITS
) -> tuple[sp.Basic, bool]:
    v = paper_symbols(v)
    for symbol, sub in own.items():
        v = v.subs(sub, symbol)
    v, rounded = readable_numbers(v, digits)
    v = min(_shapes(v), key=lambda e: _readability(e, WIDTH_EM))
    return v, rounded


def _rows(texts: list[str], limit: float) -> list[str]:
    """Formulas side by side, separated by commas, in rows no wider than ``limit``."""
    lines, current = [], ""
    for text in texts:
        candidate = f"{current},\\quad {text}" if current else text
        if current and width_em(candidate) > limit:
            lines.append(current + ",")
            current = text
        else:
            current = candidate
    return [*lines, current] if current else lines


def _expression_list(values, own, limit: float, digits: int) -> Shown:
    """A list of results: side by side in rows that fit (:func:`_rows`); a result wider than a
    row is written on its own (named pieces and all)."""
    shown = [board_form(v, names=own, limit=limit, digits=digits) for v in values]
    lines: list[str] = []
    where: list = []
    definitions: dict = {}
    pending: list[str] = []
    for form in shown:
        assert form is not None
        if len(form.lines) > 1 or form.where:
            lines += _rows(pending, limit) + form.lines
            where += form.where
            definitions.update(form.definitions)
            pending = []
        else:
            pending.append(form.lines[0])
    lines += _rows(pending, limit)
    return Shown(lines, where, any(f.approx for f in shown if f), definitions)


def _number_list(values, limit: float, digits: int = DIGITS) -> Shown:
    """A list of numbers in rows that fit (one ≈ for the list is the caller's to say)."""
    shown = [readable_numbers(v, digits) for v in values]
    return Shown(_rows([tex(r) for r, _ in shown], limit), [], any(r for _, r in shown))


def latex_blocks(shown: Shown) -> tuple[str, str | None]:
    """(the result's display math, the where-definitions' display math or None)."""

    def block(lines: list[str]) -> str:
        if len(lines) == 1 and "&" not in lines[0]:
            return lines[0]
        body = " \\\\\n".join(line if "&" in line else f"& {line}" for line in lines)
        return "\\begin{aligned}\n" + body + "\n\\end{aligned}"

    main = block(shown.lines)
    if not shown.where:
        return main, None
    rows = [line for _, defined in shown.where for line in defined]
    return main, block(rows)
