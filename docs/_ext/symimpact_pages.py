"""Sphinx extension: write the pages that come from code into ``docs/_generated/`` before reading.

- ``derivations/<step>.md``: every line of each ``derive`` board (rendered with ``sympy.latex``),
  its checks, errata and kernels; the step's module docstring is the prose.
- ``errata.md``: ``generated/errata.md`` with the consequence of each difference in numbers,
  computed here with the generated kernels.
- ``tutorial.md``: the damper design tutorial, every command run and its output captured.
- ``cli.md``: the command line from the argument parser itself.
- ``report/``: ``symimpact reproduce --quick``, embedded.

Nothing in these pages is typed in by hand, so they cannot drift from the code.
"""

from __future__ import annotations

import contextlib
import functools
import importlib
import inspect
import io
import shutil
from pathlib import Path

import sympy as sp

HERE = Path(__file__).resolve().parent.parent
OUT = HERE / "_generated"


def _latex(value) -> str | None:
    if isinstance(value, sp.Basic | sp.MatrixBase):
        return sp.latex(value)
    if isinstance(value, list | tuple) and value and all(isinstance(v, sp.Basic) for v in value):
        return r",\quad ".join(sp.latex(v) for v in value)
    if isinstance(value, dict) and value and all(isinstance(v, sp.Basic) for v in value.values()):
        return r",\quad ".join(f"{sp.latex(k)} = {sp.latex(v)}" for k, v in value.items())
    return None


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


@functools.cache
def _board(step: str):
    """The board of one derivation step, derived once per build."""
    return importlib.import_module(f"derive.{step}").derive()


def derivation_page(step: str) -> str:
    """One derivation step as MyST Markdown, from its board."""
    module = importlib.import_module(f"derive.{step}")
    b = _board(step)
    out = [
        f"# {b.title}",
        "",
        f"Paper equations: **{b.equations}**. Source: `derive/{step}.py`.",
        "",
    ]
    doc = inspect.getdoc(module) or ""
    out += ["```{eval-rst}", doc, "```", "", "## On the board", ""]
    for line in b.lines:
        eq = f" (Eq. {line.equation})" if line.equation else ""
        out += [f"### `{line.name}`{eq}", ""]
        if line.text:
            out += [line.text, ""]
        tex = _latex(line.value)
        if tex is not None:
            out += ["$$", tex, "$$", ""]
        else:
            text = repr(line.value)
            out += ["```text", text if len(text) < 2000 else text[:2000] + " …", "```", ""]
    out += ["## Checks", "", "| check | equation | status | detail |", "|---|---|---|---|"]
    out += [f"| {_cell(c.name)} | {_cell(c.equation)} | {c.status} | {_cell(c.detail)} |"
            for c in b.checks]  # fmt: skip
    out.append("")
    if b.errata:
        out += ["## Where the paper's printed equation differs", ""]
        for e in b.errata:
            out += [f"**{e.equation}: {e.what}.** {e.consequence}", "", "Printed:", "", "$$",
                    sp.latex(e.printed), "$$", "", "Derived:", "", "$$", sp.latex(e.derived), "$$",
                    ""]  # fmt: skip
    if b.kernels:
        out += ["## Kernels emitted into `generated/`", "", "| kernel | equation | returns |",
                "|---|---|---|"]  # fmt: skip
        out += [f"| `{k.name}({', '.join(a.name for a in k.args)})` | {k.equation} | "
                f"{_cell(k.returns)} [{k.unit}] |" for k in b.kernels]  # fmt: skip
        out.append("")
    return "\n".join(out)


def errata_page() -> str:
    """generated/errata.md plus the consequence of each difference in numbers."""
    import numpy as np
    from symimpact.generated import closed_forms, lindstedt, ritz
    from symimpact.generated import multiple_scales as ms

    src = (HERE.parent / "generated" / "errata.md").read_text(encoding="utf-8")
    body = src.split("\n", 1)[1]  # drop the generator comment
    body = body.replace("# Paper vs derivation", "# Paper vs derivation (errata)", 1)
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

    from symimpact.contact import perturbation_duration

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


def cli_page() -> str:
    """The command line, from the parser itself."""
    from symimpact.cli import build_parser

    parser = build_parser()
    out = ["# Command line", "", "Generated from `symimpact.cli.build_parser()`.", "",
           "```text", parser.format_help().rstrip(), "```", ""]  # fmt: skip
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    for name, p in sub.choices.items():
        out += [f"## `symimpact {name}`", "", "```text", p.format_help().rstrip(), "```", ""]
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
    """Write every generated page (called at ``builder-inited``)."""
    from tutorial_page import tutorial_page

    import derive

    if OUT.exists():
        shutil.rmtree(OUT)
    (OUT / "derivations").mkdir(parents=True)
    names = []
    for step in derive.STEPS:
        (OUT / "derivations" / f"{step}.md").write_text(derivation_page(step), encoding="utf-8")
        names.append(step)
    index = ["# Derivations", "",
             "One page per step of `derive/`, in lecture order. Every formula on these pages is "
             "rendered from the SymPy object the step produced (`derive.board(step).lines`); the "
             "prose is the step's own module text.", "", "```{toctree}", ":maxdepth: 1", "",
             *names, "```", ""]  # fmt: skip
    (OUT / "derivations" / "index.md").write_text("\n".join(index), encoding="utf-8")
    (OUT / "errata.md").write_text(errata_page(), encoding="utf-8")
    (OUT / "cli.md").write_text(cli_page(), encoding="utf-8")
    (OUT / "tutorial.md").write_text(tutorial_page(OUT / "tutorial", _run_cli), encoding="utf-8")
    (OUT / "report.md").write_text(report_page(OUT / "report"), encoding="utf-8")


def setup(app):
    app.connect("builder-inited", write_pages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
