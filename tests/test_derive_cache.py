"""The boards kept per step (derive/cache.py): a step's key changes with the code its board
depends on and with nothing else.  Checked on copies of ``derive/`` with one file edited, against
the modules the interpreter itself loads with each step."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import derive
from derive import cache

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture
def copy(tmp_path: Path) -> Path:
    folder = tmp_path / "derive"
    shutil.copytree(ROOT / "derive", folder, ignore=shutil.ignore_patterns("__pycache__"))
    return folder


@pytest.fixture(scope="module")
def loaded() -> dict[str, set[str]]:
    """{step: the modules of ``derive`` Python loads on importing the step alone}: found by the
    interpreter (every ``derive.*`` module forgotten before each step), independent of the
    import parsing of derive/cache.py."""
    code = (
        "import importlib, json, sys\n"
        "import derive\n"
        "steps = derive.STEPS\n"
        "out = {}\n"
        "for step in steps:\n"
        "    for name in [m for m in sys.modules if m == 'derive' or m.startswith('derive.')]:\n"
        "        del sys.modules[name]\n"
        "    importlib.import_module('derive.' + step)\n"
        "    out[step] = sorted(m.split('.')[1] for m in sys.modules if m.startswith('derive.'))\n"
        "print(json.dumps(out))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, check=True)  # fmt: skip
    return {step: set(names) for step, names in json.loads(run.stdout).items()}


def _edit(path: Path) -> None:
    path.write_text(path.read_text(encoding="utf-8") + "\n# an edit\n", encoding="utf-8")


def _keys(folder: Path) -> dict[str, str]:
    return {step: cache.key(step, folder) for step in derive.STEPS}


def _changed_by_editing(copy: Path, name: str) -> set[str]:
    before = _keys(copy)
    _edit(copy / name)
    after = _keys(copy)
    return {step for step in derive.STEPS if before[step] != after[step]}


def test_a_step_s_sources_are_the_modules_python_loads_with_it(loaded):
    for step in derive.STEPS:
        deps = {p.stem for p in cache.sources(step)}
        assert deps == loaded[step] | {"__init__"}, step


def test_a_copy_has_the_checkout_s_keys(copy):
    assert _keys(copy) == _keys(ROOT / "derive")


def test_an_edit_to_one_step_changes_its_key_and_those_of_the_steps_that_load_it(copy, loaded):
    changed = _changed_by_editing(copy, "free_flight.py")
    assert changed == {s for s in derive.STEPS if "free_flight" in loaded[s]}
    # forced_flight and periodic_orbit import free_flight; modal_structure imports forced_flight
    assert {"free_flight", "forced_flight", "periodic_orbit", "modal_structure"} <= changed


def test_an_edit_to_the_step_the_walk_through_changes_changes_only_its_key(copy):
    assert _changed_by_editing(copy, "multiple_scales.py") == {"multiple_scales"}


@pytest.mark.parametrize("shared", ["board.py", "__init__.py"])
def test_an_edit_to_the_board_or_the_seeds_changes_every_key(copy, shared):
    assert _changed_by_editing(copy, shared) == set(derive.STEPS)


@pytest.mark.parametrize("tool", ["walkthrough.py", "codegen.py", "notebooks.py", "__main__.py"])
def test_an_edit_to_what_no_step_imports_changes_no_key(copy, tool):
    assert _changed_by_editing(copy, tool) == set()


def test_every_import_form_names_the_module(tmp_path):
    module = tmp_path / "m.py"
    module.write_text(
        "from .free_flight import free_decay\n"
        "from . import ritz, board\n"
        "import derive.lindstedt as l\n"
        "from derive import slow_flow\n"
        "from derive.hertz_contact import x\n"
        "def f():\n    from .beam_modes import roots\n"
        "import numpy\nfrom sympy import ritz as not_ours\nfrom .. import codegen\n",
        encoding="utf-8",
    )
    names = {p.stem for p in (ROOT / "derive").glob("*.py")}
    assert cache.imported_modules(module, names) == {
        "free_flight", "ritz", "board", "lindstedt", "slow_flow", "hertz_contact", "beam_modes"
    }  # fmt: skip


@pytest.mark.parametrize("name", ["nosuch", "board"])
def test_what_is_not_a_step_is_refused_by_name(name):
    with pytest.raises(ValueError, match=f"step: no step module {name}.py"):
        cache.key(name)


@pytest.mark.parametrize("step", ["contact_fits", "closed_forms", "slow_flow", "free_flight"])
def test_a_board_read_back_is_the_board_derived(step):
    # derived here and pickled, against its reading back (derive/cache.py rebuilds sums,
    # products, powers and functions unevaluated): every leaf, expressions as srepr writes
    # their structure.  Sums (contact_fits), integrals (closed_forms), conjugates and a
    # collected quartic (slow_flow) among them
    import io
    import pickle

    derived = derive.board(step)
    back = cache.load(io.BytesIO(pickle.dumps(derived, protocol=pickle.HIGHEST_PROTOCOL)))
    assert cache.differences(derived, back) == []
    assert derived.lines and len(cache._leaves(derived, "b", {})) > 20


def test_differences_name_what_differs():
    import sympy as sp

    x = sp.Symbol("x")
    a = {"value": x + 1, "seconds": 0.5, "names": ["p"]}
    assert cache.differences(a, dict(a)) == []
    assert cache.differences(a, {**a, "value": x + 2}) == ["board['value']"]
    assert cache.differences(a, {**a, "names": ["p", "q"]}) == ["board['names'][1]"]
    # the same value in another structure differs: x·(x + 1) against x² + x
    assert cache.differences({"v": x * (x + 1)}, {"v": x**2 + x}) == ["board['v']"]


def test_points_read_back_are_the_points_found(boards):
    # the recorded points (derive/checkpoints.py) are kept on disk under a digest of what they
    # are found from: those recorded in this process (found, or read back from an earlier
    # one) against finding them again here, for one kernel of every step and every iteration
    from derive import checkpoints

    recorded = checkpoints.recorded(list(boards.values()))
    first = {}
    for module, k, points in recorded["kernels"]:
        first.setdefault(module, (k, points))
    assert len(first) >= 14
    for k, points in first.values():
        assert checkpoints.kernel_points(k) == points, k.name
    for _, fp, points in recorded["iterations"]:
        assert checkpoints.iteration_points(fp) == points, fp.name


def test_a_point_s_digest_follows_what_it_is_found_from(boards):
    import dataclasses

    from derive import checkpoints

    k = boards["closed_forms"].kernels[0]
    arg = k.args[0]
    wider = dataclasses.replace(k, args=(dataclasses.replace(arg, high=arg.high * 2), *k.args[1:]))
    other = dataclasses.replace(k, expr=k.expr + 1)
    renamed = dataclasses.replace(k, name=k.name + "_2", note="another note")
    digests = {checkpoints.digest(x) for x in (k, wider, other)}
    assert len(digests) == 3
    assert checkpoints.digest(renamed) == checkpoints.digest(k)  # the name finds no point


def test_a_step_derived_where_mpmath_s_precision_was_raised_is_the_one_in_generated():
    # Step 1 raises (β₁L)⁴ to the fourth power outside its own workdps blocks: in a process that
    # had set mpmath's global precision higher (a test module's mp.dps = 40, an xdist worker's
    # earlier tests), the Eq. 6 erratum and the tip-stiffness kernel got another last digit, and
    # the walk-through page built from that board showed erratum 1 as changed.  derive.board
    # derives at mpmath's default precision whatever the process set
    import mpmath
    import sympy as sp

    errata = (Path(derive.__file__).resolve().parent.parent / "generated" / "errata.md").read_text(
        encoding="utf-8"
    )
    before = mpmath.mp.dps
    try:
        mpmath.mp.dps = 50
        ritz = derive.board("ritz")
        assert mpmath.mp.dps == 50  # the process's own setting is left as it was
    finally:
        mpmath.mp.dps = before
    (derived,) = [e.derived for e in ritz.errata if e.key == "eq6_constant"]
    assert sp.latex(derived) in errata
