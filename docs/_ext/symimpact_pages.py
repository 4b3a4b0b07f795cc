"""Sphinx extension: write the pages that come from code into ``docs/_generated/`` before reading.

- ``derivations/<step>.md``: every line of each ``derive`` board (rendered with ``sympy.latex``),
  its checks, errata and kernels; the step's module docstring is the prose.
- ``errata.md``: ``generated/errata.md`` with the consequence of each difference in numbers,
  computed here with the generated kernels.
- ``tutorial.md``: the damper design tutorial, every command run and its output captured.
- ``cli.md``: the command line from the argument parser itself.
- ``report/``: ``symimpact reproduce --quick``, embedded.
- ``forced.md``: the forced-response checks (closed-form orbits against the simulator, the
  compliant contacts' rigid limit), computed at build time.

Nothing in these pages is typed in by hand, so they cannot drift from the code.
"""

from __future__ import annotations

import contextlib
import functools
import importlib
import inspect
import io
import pprint
import re
import shutil
import time
from pathlib import Path

import sympy as sp

HERE = Path(__file__).resolve().parent.parent
OUT = HERE / "_generated"


def _shown(value, shown=None, names=None, digits=7) -> list[str]:
    """A board value as Markdown: display math written the way a teacher writes it
    (:func:`derive.present.board_form`), a table for a table of numbers, else wrapped text."""
    from derive.present import board_form, latex_blocks

    form = board_form(value if shown is None else shown, names=names, digits=digits)
    if form is not None:
        main, where = latex_blocks(form)
        out = ["$$", main, "$$"]
        if where:
            out += ["", "where", "", "$$", where, "$$"]
        return out
    if (
        isinstance(value, dict)
        and value
        and all(isinstance(v, list | tuple) for v in value.values())
    ):
        width = max(len(v) for v in value.values())
        rows = ["| | " + " | ".join(str(i) for i in range(width)) + " |",
                "|---" * (width + 1) + "|"]  # fmt: skip
        rows += [
            f"| {_cell(k)} | " + " | ".join(_cell(x) for x in v) + " |" for k, v in value.items()
        ]
        return rows
    return ["```text", pprint.pformat(value, width=72, compact=True)[:3000], "```"]


def _prose(text: str) -> str:
    """Plain text from code (kernel docs, units, check names) for a page: exponents and
    subscripts written with ^ and _ become superscripts and subscripts."""
    text = re.sub(r"\^\{?([-+\d./]+|[a-zA-Z])\}?", r"<sup>\1</sup>", str(text))
    return re.sub(r"(?<![A-Za-z])([A-Za-zα-ωΑ-Ω])_(\{[^}]*\}|[A-Za-z0-9]+)",
                  lambda m: f"{m[1]}<sub>{m[2].strip('{}')}</sub>", text)  # fmt: skip


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


@functools.cache
def _boards() -> dict:
    """Every step's board, derived once per build, or read back from what the last derivation of
    this same code kept (derive/cache.py)."""
    from derive import cache

    return cache.boards()


def _board(step: str):
    """The board of one derivation step."""
    return _boards()[step]


def derivation_page(step: str) -> str:
    """One derivation step as MyST Markdown, from its board."""
    module = importlib.import_module(f"derive.{step}")
    b = _board(step)
    out = [
        f"# {b.title}",
        "",
        f"Paper equations: **{b.equations}**. Source: `derive/{step}.py`. As a notebook that "
        f"re-derives it live, with exercises: [notebooks](../notebooks.md).",
        "",
    ]
    doc = inspect.getdoc(module) or ""
    out += [doc, "", "## On the board", ""]  # the step's text is Markdown with $…$ math
    for line in b.lines:
        eq = f" (Eq. {line.equation})" if line.equation else ""
        out += [f"### `{line.name}`{eq}", ""]
        if line.text:
            out += [line.text, ""]
        out += [*_shown(line.value, line.shown, line.names), ""]
    out += ["## Checks", "", "| check | equation | status | detail |", "|---|---|---|---|"]
    out += [f"| {_cell(_prose(c.name))} | {_cell(c.equation)} | {c.status} | "
            f"{_cell(_prose(c.detail))} |"
            for c in b.checks]  # fmt: skip
    out.append("")
    if b.errata:
        out += ["## Where the paper's printed equation differs", ""]
        for e in b.errata:
            out += [f"**{e.equation}: {e.what}.** {e.consequence}", "", "Printed:", "",
                    *_shown(e.printed, digits=12), "", "Derived:", "",
                    *_shown(e.derived, digits=12), ""]  # fmt: skip
    if b.kernels:
        out += ["## Kernels emitted into `generated/`", "", "| kernel | equation | returns |",
                "|---|---|---|"]  # fmt: skip
        out += [f"| `{k.name}({', '.join(a.name for a in k.args)})` | {k.equation} | "
                f"{_cell(_prose(k.returns))} [{_prose(k.unit)}] |" for k in b.kernels]  # fmt: skip
        out += ["", "### The same kernels in every target", "",
                "As each target declares them (read from the generated files; the C library "
                "also has a `_batch` variant of each, and the Rust functions live in the module "
                f"`symimpact::{b.module}`):", ""]  # fmt: skip
        for k in b.kernels:
            out += ["```text", *target_signatures(b.module, k.name), "```", ""]
    return "\n".join(out)


@functools.cache
def _generated_text(relative: str) -> str:
    return (HERE.parent / "generated" / relative).read_text(encoding="utf-8")


def target_signatures(module: str, name: str) -> list[str]:
    """The signature of kernel ``name`` of step ``module`` in each target, as the generated
    files declare it (NumPy and JAX: the ``def`` line; C: the header's prototype; Octave: the
    function line; Rust: the ``pub fn`` line; Fortran: the function statement)."""
    full = f"{module}_{name}"
    found = {
        "NumPy": (f"{module}.py", rf"^def ({name}\(.*?\)):"),
        "C": ("c/symimpact.h", rf"^(double symimpact_{full}\(.*?\));"),
        "Octave": (f"octave/{full}.m", r"^function (.*)$"),
        "Rust": ("rust/src/lib.rs", rf"^ *(pub fn {name}\(.*?\) -> f64)"),
        "Fortran": ("fortran/symimpact.f90", rf"^ *(pure elemental function {full}\(.*?\))"),
        "JAX": (f"jax/{module}.py", rf"^def ({name}\(.*?\)):"),
    }
    out = []
    for target, (path, pattern) in found.items():
        if target == "Rust":  # the Rust function of this module: after its `pub mod` line
            text = _generated_text(path).split(f"pub mod {module} {{", 1)[1]
            text = text.split("\npub mod ", 1)[0]
        else:
            text = _generated_text(path)
        match = re.search(pattern, text, re.M)
        if match is None:
            raise RuntimeError(f"{target}: no declaration of {full} in generated/{path}")
        out += [f"{target}:", *_wrapped(match.group(1))]
    return out


#: Longest line of a code block on a page: what the content column shows without scrolling at
#: a 1000 px window (as the tutorial's, ``tutorial_page.CODE_COLUMNS``).
CODE_COLUMNS = 64


def _wrapped(signature: str, width: int = CODE_COLUMNS) -> list[str]:
    """A declaration ``head(arg, arg, …)tail`` in lines of at most ``width`` characters: the
    head indented 2 (its words split where it is too long), the arguments 6, packed."""
    head, _, rest = signature.partition("(")
    inner, _, tail = rest.rpartition(")")
    lines, words = [], head.split(" ")
    current = "  " + words[0]
    for w in words[1:]:
        if len(current) + 1 + len(w) + 1 > width:
            lines.append(current)
            current = "  " + w
        else:
            current += " " + w
    current += "("
    for i, a in enumerate(inner.split(", ") if inner else []):
        piece = a + ("," if i < len(inner.split(", ")) - 1 else "")
        if len(current) + 1 + len(piece) > width - len(tail) - 1:
            lines.append(current)
            current = "      " + piece
        else:
            current += ("" if current.endswith("(") else " ") + piece
    lines.append(current + ")" + tail)
    return lines


def errata_page() -> str:
    """generated/errata.md plus the consequence of each difference in numbers."""
    import numpy as np
    from symimpact.generated import closed_forms, lindstedt, ritz
    from symimpact.generated import multiple_scales as ms

    import derive

    src = (HERE.parent / "generated" / "errata.md").read_text(encoding="utf-8")
    intro = src.split("\n", 1)[1].split("\n| ", 1)[0]  # the file's own text, before its table
    intro = intro.replace("# Paper vs derivation", "# Paper vs derivation (errata)", 1)
    body = [intro.rstrip(), ""]
    number = 0
    for step in derive.STEPS:
        for e in _board(step).errata:
            number += 1
            body += [f"## {number}. Eq. {e.equation}: {e.what}", "",
                     f"From [{_board(step).title}](derivations/{step}.md): {e.consequence}.", "",
                     "Printed:", "", *_shown(e.printed, digits=12), "", "Derived:", "",
                     *_shown(e.derived, digits=12), ""]  # fmt: skip
    body = "\n".join(body) + "\n"
    rows = []
    k_d = float(ritz.tip_stiffness(1.0, 1.0, 1.0))
    k_p = float(ritz.tip_stiffness_printed(1.0, 1.0, 1.0))
    rows.append(("Eq. 6", "K·L³/(EI), printed vs derived", f"{k_p:.10f} vs {k_d:.10f}",
                 f"relative {k_p / k_d - 1:+.2e}"))  # fmt: skip
    # the printed α of Eq. 17 is taken from the board's erratum, at Table 2's start X₀ = 0
    (e17,) = [e for e in _board("lindstedt").errata if e.equation == "17"]
    syms = sorted(e17.printed.free_symbols, key=lambda q: q.name)  # omega, x0, xdot0
    with np.errstate(all="ignore"):  # evaluated in floats, as a program would
        a_p = sp.lambdify(syms, e17.printed, "numpy")(np.float64(100.0), np.float64(0.0), 0.5)
    a_d = float(lindstedt.duffing_amplitude(0.0, 0.5, 100.0, 0.0))
    rows.append(("Eq. 17", "α at X₀ = 0, Ẋ₀ = 0.5 m/s, ω = 100 rad/s", f"{a_p} vs {a_d:.6g} m",
                 "the printed form is 0/0 (undefined)"))  # fmt: skip
    from symimpact.generated import contact_fits

    from symimpact.free.contact import perturbation_duration

    a = float(contact_fits.cubic_fit_a(1000.0, 0.02))
    b = float(contact_fits.cubic_fit_b(1000.0, 0.02))
    for m in (0.15, 0.25):
        res = perturbation_duration(m, a, b, 0.0, 0.075, -1.0 / m)
        t_d, t_p = float(res.value), float(res.printed)
        rows.append((f"Eq. 21 (m = {m} kg)", "Eq. 31 fixed point, B/A = −M/m, Table 1's case",
                     f"{t_p:.5f} vs {t_d:.5f} s", f"ratio {t_p / t_d:.4f} (1 + m/M = {1 + m:.2f}, "
                     f"√ of it {(1 + m) ** 0.5:.4f})"))  # fmt: skip
    t0d = float(ms.contact_duration_start(0.25, 83.6, -4.0))
    t0p = float(ms.contact_duration_start_printed(0.25, 83.6, -4.0))
    rows.append(("Eq. 31", "T⁽⁰⁾ printed / derived (m = 0.25 kg, B/A = −4)", f"{t0p:.5f} / {t0d:.5f} s",
                 f"ratio {t0p / t0d:.4f}"))  # fmt: skip
    h_d = float(closed_forms.hertz_contact_duration(0.15, 1.0, 1000.0, 0.075))
    h_p = float(closed_forms.hertz_contact_duration_printed(0.15, 1.0, 1000.0, 0.075))
    rows.append(("Eq. 34", "Hertz duration, m = 0.15 kg, Ż₀ = 7.5 cm/s", f"{h_p:.7f} vs {h_d:.7f} s",
                 f"{(h_p / h_d - 1) * 1e6:+.1f} ppm"))  # fmt: skip
    table = ["## The consequences in numbers", "",
             "Computed when these pages are built, with the generated kernels (`*_printed` for "
             "the printed form).", "", "| erratum | quantity | printed vs derived | difference |",
             "|---|---|---|---|"]  # fmt: skip
    table += [f"| {_cell(a)} | {_cell(b)} | {_cell(c)} | {_cell(d)} |" for a, b, c, d in rows]
    return body + "\n" + "\n".join(table) + "\n"


def notebooks_page(folder: Path) -> str:
    """The teaching notebooks, written with ``python -m derive --notebooks`` into the build and
    offered for download."""
    from derive.notebooks import write_notebooks

    paths = write_notebooks(folder)
    import derive

    out = ["# Notebooks", "",
           "One Jupyter notebook per derivation step: each runs the step's own statements from "
           "`derive/` one board line at a time, in the paper's order, showing every result, "
           "check and erratum as it arises, and ends with exercises that change one assumption: "
           "each asks for a value, checks the reader's answer (`derive.teach.check`) and keeps "
           "its solution in a collapsed cell. A last notebook walks through [regenerating after a "
           "change](regenerating.md).", "",
           "Run them from the checkout:", "", "```console",
           "$ pip install -e \".[teach]\"        # JupyterLab, nbformat, ipykernel",
           "$ python -m derive --notebooks notebooks", "$ jupyter lab notebooks", "```", "",
           "or download them here (open them inside the checkout, or set `SYMIMPACT_CHECKOUT` "
           "to its path):", ""]  # fmt: skip
    titles = {step: _board(step).title for step in derive.STEPS}
    for path in paths:
        step = path.stem.split("_", 1)[1]
        title = titles.get(step, "Regenerating after a change")
        out.append(f"- {{download}}`{path.name} <notebooks/{path.name}>` — {title}")
    return "\n".join(out) + "\n"


def cli_page() -> str:
    """The command line, from the parser itself."""
    from symimpact.cli import build_parser

    parser = build_parser()
    out = ["# Command line", "", "Generated from `symimpact.cli.build_parser()`.", "",
           "```text", parser.format_help().rstrip(), "```", ""]  # fmt: skip
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    for name, p in sub.choices.items():
        out += [f"## `symimpact {name}`", "", "```text", p.format_help().rstrip(), "```", ""]
        for kinds in (a for a in p._actions if a.__class__.__name__ == "_SubParsersAction"):
            for kind, q in kinds.choices.items():  # identify's kinds of data
                out += [f"### `symimpact {name} {kind}`", "", "```text",
                        q.format_help().rstrip(), "```", ""]  # fmt: skip
    return "\n".join(out)


def _run_cli(argv: list[str]) -> str:
    from symimpact.cli import main

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        status = main(argv)
    if status != 0:
        raise RuntimeError(f"tutorial command failed: symimpact {' '.join(argv)}")
    return buf.getvalue().rstrip()


def report_page(folder: Path) -> str:
    """``symimpact reproduce --quick`` run into ``folder``, embedded as Markdown."""
    from symimpact import __version__
    from symimpact.report import TITLE, reproduce
    from symimpact.report.document import markdown

    _, sections = reproduce(folder, quick=True, force=True, progress=False,
                            command="symimpact reproduce --quick (docs build)")  # fmt: skip
    meta = [("package", f"symimpact {__version__}"),
            ("command", "symimpact reproduce --quick, run by the documentation build")]  # fmt: skip
    text = markdown(TITLE, meta, sections, links=False)
    return text.replace("](", "](report/")


def write_pages(app=None) -> None:
    """Write every generated page (called at ``builder-inited``), on both cores.

    The tutorial's commands, the forced checks (the first to compile the simulations' numba
    code on a fresh machine, minutes, unless CI's earlier stage compiled it) and then the quick
    report are written in a second process from the start, while this one writes the pages of
    the derivations (the boards; the notebooks, placed from the boards' notes of where each
    record was written, no step run again; the regenerating walk-through: about 90 s together):
    the build takes about the longer of the two instead of their sum.  (The report was written
    here after the derived pages until 2026-12-07: 65 s of the build's 181 s, while the second
    process had ended after its 15 s.)"""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    if OUT.exists():
        shutil.rmtree(OUT)
    OUT.mkdir(parents=True)
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        simulated = pool.submit(_write_simulated_pages)
        _write_derived_pages()
        simulated.result()


def _timed(name: str, text) -> None:
    """Write ``OUT/name`` from ``text()`` and print how long that took (the build's log shows
    where its time went)."""
    t0 = time.perf_counter()
    (OUT / name).write_text(text(), encoding="utf-8")
    print(f"docs: {name} written in {time.perf_counter() - t0:.0f} s", flush=True)


def _write_simulated_pages() -> None:
    """The pages computed with the runtime: the command line, the tutorial, the forced-response
    checks and the quick report."""
    from forced_page import forced_checks_page
    from tutorial_page import tutorial_page

    _timed("cli.md", cli_page)
    _timed("tutorial.md", lambda: tutorial_page(OUT / "tutorial", _run_cli))
    _timed("forced.md", forced_checks_page)
    _timed("report.md", lambda: report_page(OUT / "report"))


def _write_derived_pages() -> None:
    """The pages of the derivations: one per step, the errata, the notebooks and the executed
    walk-through."""
    import nbformat

    import derive
    from derive import walkthrough

    (OUT / "derivations").mkdir(parents=True)
    names = []
    t0 = time.perf_counter()
    for step in derive.STEPS:
        (OUT / "derivations" / f"{step}.md").write_text(derivation_page(step), encoding="utf-8")
        names.append(step)
    print(f"docs: derivations/*.md written in {time.perf_counter() - t0:.0f} s", flush=True)
    index = ["# Derivations", "",
             "One page per step of `derive/`, in lecture order. Every formula on these pages is "
             "rendered from the SymPy object the step produced (`derive.board(step).lines`); the "
             "prose is the step's own module text.", "", "```{toctree}", ":maxdepth: 1", "",
             *names, "```", ""]  # fmt: skip
    (OUT / "derivations" / "index.md").write_text("\n".join(index), encoding="utf-8")
    _timed("errata.md", errata_page)
    _timed("notebooks.md", lambda: notebooks_page(OUT / "notebooks"))

    def regenerating() -> str:
        # executed once: the page shows its cells' output, the download carries it
        walk = walkthrough.executed(HERE.parent)
        nbformat.write(walk, OUT / "notebooks" / walkthrough.NOTEBOOK)
        return walkthrough.page(walk)

    _timed("regenerating.md", regenerating)


def setup(app):
    app.connect("builder-inited", write_pages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
