"""Regenerating after a change: a walk-through, run for real.

A reader changes one assumption of a derivation step in a working copy of the checkout,
regenerates in memory, and watches ``python -m derive --check`` show the diff, the step's own
checks fail and the errata table change, and the tests respond.  One derivation run: the
docs build executes it, and CI builds the docs.  The assumption: Eq. 10.2 written for the relative
coordinate z = y − x needs y in terms of z; with y = B·cos ωt and x = A·cos ωt,
y = B/(B − A)·z.  The paper's printed factor of Eq. 21 corresponds to the inverted relation
y = (B − A)/B·z — the change made here.

The snippets make the notebook ``13_regenerating.ipynb`` (``python -m derive --notebooks DIR``);
the docs build executes that notebook once (nbclient, a fresh kernel) and makes the page from its
cells and their printed output, and offers the executed notebook for download.  Its first cell
finds the checkout (``root``); every snippet runs in that one namespace.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from . import STEPS

OLD = "y_of_z = B / (B - A) * z"
NEW = "y_of_z = (B - A) / B * z"


@dataclass(frozen=True)
class Snippet:
    text: str
    code: str


SNIPPETS = (
    Snippet(
        "Work in a copy of the checkout, so nothing here touches your files: the derivation "
        "package, what it generates, the tests, the project file and the boards that earlier "
        "derivations kept (`.cache/`, when there is one).",
        """import difflib
import os
import shutil
import textwrap
import subprocess
import sys
import tempfile

work = Path(tempfile.mkdtemp(prefix="symimpact-try-")) / "checkout"
skip = shutil.ignore_patterns("__pycache__")
for part in ("derive", "generated", "tests"):
    shutil.copytree(root / part, work / part, ignore=skip)
shutil.copy(root / "pyproject.toml", work / "pyproject.toml")
if (root / ".cache").is_dir():
    shutil.copytree(root / ".cache", work / ".cache")
print("copied:", ", ".join(sorted(p.name for p in work.iterdir())))""",
    ),
    Snippet(
        "Change one assumption in `derive/multiple_scales.py`: the relation between the impact "
        "mass's motion y and the relative coordinate z (Eq. 21). The derivation has "
        "y = B/(B − A)·z; write the inverted relation, the one the paper's printed factor "
        "corresponds to.",
        f"""module = work / "derive" / "multiple_scales.py"
before = module.read_text(encoding="utf-8")
after = before.replace(
    {OLD!r},
    {NEW!r},
)
assert after != before, "the line to change was not found"
module.write_text(after, encoding="utf-8")
name = "derive/multiple_scales.py"
diff = difflib.unified_diff(before.splitlines(True),
                            after.splitlines(True),
                            "a/" + name, "b/" + name, n=0)
print("".join(diff))""",
    ),
    Snippet(
        "Regenerate in memory and compare with `generated/`: `python -m derive --check --reuse`. "
        "`--reuse` derives again only the steps whose code changed (a step's boards are kept "
        "under a hash of its own module and of the code it depends on, `derive/cache.py`) and "
        "reads the others back; without `.cache/` every step is derived, minutes. The "
        "step's own checks fail — the one that compares two free bodies with their reduced mass "
        "catches the wrong relation — and every generated file that holds the contact-duration "
        "kernels differs.",
        """# derive seeds SymPy's random numbers (derive.SYMPY_SEED) and this
# fixes the hash seed: the time SymPy's factorisation takes on the
# wrong relation depends on both
command = ["-m", "derive", "--check", "--reuse"]
run = subprocess.run([sys.executable, *command],
                     cwd=work, capture_output=True, text=True,
                     env=dict(os.environ, PYTHONHASHSEED="4242"))
lines = run.stdout.splitlines()
print(next(x for x in lines if x.startswith("derived again:")))
failed = []  # the table's FAIL rows, each with its detail line
for k, line in enumerate(lines):
    detail = line.startswith("    ") and "FAIL" in lines[k - 1]
    if "FAIL" in line or detail:
        failed.append(line)
print("\\n".join(" ".join(line.split()) for line in failed))
changed = [line[14:] for line in lines
           if line.startswith("--- generated/")]
print(f"\\n{len(changed)} files of generated/ differ:")
print(textwrap.fill(", ".join(changed), 60))
start = lines.index("--- generated/multiple_scales.py")
kernel = [line[1:].strip() for line in lines[start:]
          if line.startswith(("-    return", "+    return"))]
p = len(os.path.commonprefix(kernel[:2]))  # where they part
print("\\nfirst changed formula, generated/multiple_scales.py:")
print("was …" + kernel[0][max(p - 25, 0) : p + 20] + "…")
print("now …" + kernel[1][max(p - 25, 0) : p + 20] + "…")
print("\\nexit status:", run.returncode)""",
    ),
    Snippet(
        "The same comparison holds the errata table (`generated/errata.md`): the Eq. 21 "
        "erratum is no longer a difference between the paper and the derivation — they now "
        "agree, on the wrong relation. `python -m derive` would write exactly the files "
        "compared here; `--check` writes nothing.",
        """start = lines.index("--- generated/errata.md")
end = next(k for k in range(start + 1, len(lines))
           if lines[k].startswith("--- "))
rows = [line for line in lines[start:end]
        if line.startswith(("-|", "+|"))]
for row in rows:  # # | equation | what | printed | derived
    cells = [c.strip() for c in row[2:].split("|")]
    print(f"{row[0]} erratum {cells[0]} ({cells[1]}):")
    print(f"{' ' * 13}printed {cells[3]}")
    print(f"{' ' * 13}derived {cells[4]}")""",
    ),
    Snippet(
        "Run the derivation tests on the working copy: the tests that pin the errata and the "
        "checks respond.",
        """tests = "tests/test_derivations.py"
run = subprocess.run([sys.executable, "-m", "pytest", "-q",
                      "--color=no", "-p", "no:cacheprovider", tests],
                     cwd=work, capture_output=True, text=True)
for line in run.stdout.splitlines():
    if line.startswith(("FAILED", "ERROR")):
        test = line.split(" - ")[0]
        print(test.replace(tests + "::", ""))
    elif line[:1].isdigit():
        print(line)""",
    ),
    Snippet(
        "Undo the change (in your own checkout: `git checkout derive/`); since `--check` wrote "
        "nothing, the copy's `generated/` is still the checkout's.",
        """module.write_text(before, encoding="utf-8")
same = all((work / p).read_bytes() == (root / p).read_bytes()
           for p in ("derive/multiple_scales.py",
                     "generated/errata.md",
                     "generated/multiple_scales.py"))
print("copy as the checkout again:", same)
shutil.rmtree(work.parent)""",
    ),
)

TITLE = "Regenerating after a change"
#: The walk-through's notebook, numbered after the steps' notebooks.
NOTEBOOK = f"{len(STEPS) + 1:02d}_regenerating.ipynb"
INTRO = (
    "What happens when a derivation changes: one assumption of a step is changed in a working "
    "copy, the formulas are regenerated in memory, and `python -m derive --check`, the step's checks, the "
    "errata table and the tests respond. Every output below was produced when this page was "
    "built, by executing the notebook `{name}` (offered on the notebooks page) on a fresh "
    "kernel."
)


def executed(root: Path):
    """The walk-through notebook of :func:`notebook`, executed with nbclient on a fresh kernel
    in ``root`` (the checkout) — what the docs page shows and offers for download.  A cell may
    take 1800 s, as in tests/test_notebooks.py: without kept boards (a fresh clone's first
    documentation build) its ``derive --check --reuse`` derives every step, and a whole
    derivation ran past 900 s alone on the 2-core machine once."""
    import nbclient

    nb = notebook()
    client = nbclient.NotebookClient(nb, timeout=1800, kernel_name="python3",
                                     resources={"metadata": {"path": str(root)}})  # fmt: skip
    client.execute()
    return nb


def _printed(cell) -> str:
    """What a code cell printed (its stream outputs), or the error it raised."""
    out = []
    for o in cell.get("outputs", []):
        if o.get("output_type") == "stream":
            out.append(o.get("text", ""))
        elif o.get("output_type") == "error":
            out.append(f"{o.get('ename')}: {o.get('evalue')}")
    return "".join(out).rstrip()


def page(nb) -> str:
    """The docs page from the executed notebook: text, code and real output of every snippet
    (the notebook's first code cell, which finds the checkout, is left out)."""
    out = [f"# {TITLE}", "", INTRO.format(name=NOTEBOOK), ""]
    code = [c for c in nb.cells if c.cell_type == "code"][1:]
    assert len(code) == len(SNIPPETS), "the notebook is not the walk-through's snippets"
    for k, (s, cell) in enumerate(zip(SNIPPETS, code, strict=True), 1):
        printed = _printed(cell)
        out += [f"## {k}.", "", s.text, "", "```python", s.code, "```", "", "```text",
                printed or "(no output)", "```", ""]  # fmt: skip
    return "\n".join(out)


def notebook():
    """The same walk-through as a notebook (nbformat v4); its first cell finds the checkout from
    ``SYMIMPACT_CHECKOUT`` or the folder it runs in and above (no path of this machine)."""
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nb.cells.append(nbformat.v4.new_markdown_cell(f"# {TITLE}\n\n{INTRO.format(name=NOTEBOOK)}"))
    boot = """import os
from pathlib import Path

_here = Path.cwd().resolve()
_places = [os.environ.get("SYMIMPACT_CHECKOUT"), _here, *_here.parents]
root = next((Path(p) for p in _places if p and (Path(p) / "derive" / "board.py").is_file()), None)
if root is None:
    raise RuntimeError("derive/ not found: open the notebook inside the symimpact checkout "
                       "or set SYMIMPACT_CHECKOUT")
print("checkout:", root.name)"""
    nb.cells.append(nbformat.v4.new_code_cell(boot))
    for s in SNIPPETS:
        nb.cells.append(nbformat.v4.new_markdown_cell(s.text))
        nb.cells.append(nbformat.v4.new_code_cell(s.code))
    return nb
