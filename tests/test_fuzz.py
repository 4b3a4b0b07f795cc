"""Fuzzing (issue 7): generated inputs, good and bad, through the command line and the public API.

Each entry point gets FUZZ_EXAMPLES (≥ 1000) generated inputs.  None may end in a traceback or
an exception other than the package's own ``SymimpactError`` (a ``ValueError``), and nothing
printed or returned may be NaN.  On the command line a refusal is exit status 2 with one line on
stderr that names the parameter.

The inputs mix valid quantities, numbers at the edges (0, negative, NaN, ±inf, 1e308, 1e-308),
quantities of the wrong dimension, malformed unit strings, wrong types and unwritable paths.
Long runs are kept out of the vocabulary (end times ≤ 2 s, ranges of a few points) so that the
1000 cases of each entry point take seconds; what a huge end time or range does is tested where
it is handled (tests/test_simulation.py, tests/test_cli_units_sweep.py).
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import os
import re
import shutil
from collections import Counter
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from symimpact import cli
from symimpact.errors import SymimpactError

FUZZ_EXAMPLES = int(os.environ.get("SYMIMPACT_FUZZ_EXAMPLES", "1000"))
FUZZ = settings(
    max_examples=FUZZ_EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
    database=None,
)

EDGE_NUMBERS = ["0", "-0", "-1", "nan", "NaN", "inf", "-inf", "1e308", "1e-308", "3", "0.5"]
BAD_UNITS = ["5 kg", "5 m", "5 s", "2 N", "3 Pa", "1 m/s", "1 rad"]
MALFORMED = ["5 furlongz", "((", "", " ", "5 mm mm", "m", "1/0", "5 mm**", "1e999", "5..3", "--"]
GOOD = {  # a valid value per option of every subcommand (SI numbers or quantities)
    "M": ["1 kg", "0.5", "2 kg"],
    "K": ["100 N/cm", "1e4", "500 N/m"],
    "C": ["0.5 N*s/m", "0", "2"],
    "zeta": ["0.01", "0.1", "0"],
    "m": ["0.25 kg", "0.1", "100 g"],
    "gap": ["9 mm", "0.02", "5 mm"],
    "a": ["0.1553 N/cm^3", "1.5e5"],
    "b": ["0.836 N/cm", "80"],
    "k_hz": ["1000 N/m^1.5", "2000"],
    "k1": ["120 N/m", "300"],
    "c1": ["0", "0.5 N*s/m", "5"],
    "x0": ["0", "1 mm", "-2 mm"],
    "xdot0": ["0.5 m/s", "-0.3", "10 cm/s"],
    "y0": ["0", "1 mm"],
    "ydot0": ["0", "0.1 m/s"],
    "t_end": ["0.3 s", "1", "200 ms"],
    "v0": ["0.1 m/s", "1", "7.5 cm/s"],
    "E": ["200 GPa", "7e10"],
    "I": ["1e-10 m^4", "2e-9"],
    "rho": ["7800 kg/m^3", "2700"],
    "A": ["1e-4 m^2", "3e-4"],
    "L": ["0.5 m", "1"],
    "position": ["0.3 m", "0.5"],
    "delta_max": ["2 cm", "0.01"],
    "ba": ["impact", "out_of_phase", "in_phase", "free", "-2", "3", "1", "0.5"],
    "rest": ["1e-12", "0", "1e-6", "1", "-1", "nan", "x"],
    "workers": ["1", "0", "-1", "x", "2.5"],
    "chunk_size": ["1", "4", "0", "-3", "x"],
    "value": ["n_impacts", "effectiveness", "zeta_eq", "bogus"],
    "axes": ["gap,c1", "gap", "c1,gap", "x,y", ","],
    "best": ["max", "min", "n_impacts", "bogus"],
    "values": ["4 mm:10 mm:3 mm", "5 mm,9 mm", "1:1:0", "10:1:1", "1 kg:2 kg:1 kg"],
    "over": ["gap", "c1", "M", "bogus"],
    "scheduler": ["tcp://127.0.0.1:1", "nonsense"],
    # forced runs (simulate, periodic)
    "F0": ["2 N", "1"],
    "X_b": ["1 mm", "0.002"],
    "V_b": ["10 mm/s", "0.05"],
    "A_b": ["0.5 g", "2 m/s^2"],
    "omega": ["30 rad/s", "36"],
    "freq": ["5 Hz", "5.5"],
    "phase": ["0", "1 rad"],
    "e": ["0.6", "1", "0"],
    "chi": ["0.5 s/m", "1"],
    "periods": ["4", "6"],
    "discard": ["2", "3"],
    "warmup": ["20", "50"],
    "multiple": ["1", "2"],
    "omega_range": ["34:36:1", "30:31:0.5"],
    "gaps": ["20 mm", "20 mm,2 m"],
    "mass_ratios": ["0.05", "0.05,1e-6"],
    "freq_range": ["5:5.5:0.25"],
    "bounds": ["5 mm:40 mm", "1 N:3 N", "0.1:0.9", "40 mm:5 mm"],
}
#: A forced simulate lasts --periods (default 400); without it drawn, the fuzz asks for a few,
#: so that a compliant forced run (each contact integrated) stays well under a second
FORCING_FLAGS = {
    "--force",
    "--base",
    "--base-vel",
    "--base-acc",
    "--omega",
    "--freq",
    "--phase",
    "--e",
    "--chi",
}
RANGES = [
    "4 mm:10 mm:3 mm",
    "5 mm,9 mm",
    "0.1:0.3:0.1",
    "1:2:1",
    "1:1:0",
    "2:1:1",
    "1:3:-1",
    "1:1e30:1e-30",
    "nan:1:1",
    "1 kg:2 kg:1 kg",
    "a:b:c",
    "1:2",
    "",
    "0,1",
]
SWEPT = ["gap", "c1", "M", "m", "K", "zeta", "xdot0", "mass_ratio", "t_end", "bogus", ""]
SKIP = {"reproduce"}  # minutes per run; its bad input is covered by tests/test_reproduce.py


def _subcommands() -> dict[str, list]:
    """{name: its options}; a subcommand with kinds of its own (``identify impacts``) by its
    two words."""
    parser = cli.build_parser()
    for action in parser._actions:
        if action.choices and hasattr(action, "_name_parser_map"):
            out = {}
            for name, sub in action.choices.items():
                if name in SKIP:
                    continue
                out[name] = [a for a in sub._actions if a.option_strings and a.dest != "help"]
                for kinds in (a for a in sub._actions if hasattr(a, "_name_parser_map")):
                    for kind, q in kinds.choices.items():
                        out[f"{name} {kind}"] = [a for a in q._actions
                                                 if a.option_strings and a.dest != "help"]  # fmt: skip
            return out
    raise AssertionError("no subcommands")


SUBCOMMANDS = _subcommands()


@st.composite
def _token(draw, dest: str):
    pools = [EDGE_NUMBERS, BAD_UNITS, MALFORMED]
    if dest in GOOD:
        pools = [GOOD[dest]] * 4 + pools  # mostly valid values, so runs get past validation
    if dest == "t_end":  # no huge end times here (see the module docstring)
        pools = [GOOD[dest]] * 4 + [["0", "-1", "nan", "inf", "5 m", "x", ""]]
    if draw(st.integers(0, 19)) == 0:
        return draw(st.text(max_size=8))
    return draw(st.sampled_from(draw(st.sampled_from(pools))))


@st.composite
def _argv(draw, tmp: Path) -> list[str]:
    name = draw(st.sampled_from(sorted(SUBCOMMANDS)))
    actions = SUBCOMMANDS[name]
    argv = name.split()
    if len(argv) == 2:  # identify's kinds: the data file first
        argv.append(draw(st.sampled_from([str(tmp / "impacts.csv"), str(tmp / "bad.csv"),
                                          str(tmp / "none.csv"), str(tmp)])))  # fmt: skip
    for action in draw(st.lists(st.sampled_from(actions), max_size=6)) if actions else []:
        flag = draw(st.sampled_from(action.option_strings))
        if action.nargs == 0:
            argv.append(flag)
            continue
        dest = action.dest
        if action.choices:
            value = draw(st.sampled_from([*action.choices, "bogus", ""]))
        elif dest in ("plot", "csv", "out"):
            value = draw(
                st.sampled_from(
                    [
                        str(tmp / "f.png"),
                        str(tmp / "f.csv"),
                        str(tmp / "f.parquet"),
                        str(tmp / "f.txt"),
                        "/nonexistent/f.csv",
                        "/proc/f.png",
                        str(tmp),
                    ]
                )
            )
        elif dest == "sets":
            value = draw(
                st.sampled_from(
                    [str(tmp / "sets.csv"), str(tmp / "bad.csv"), str(tmp / "none.csv"), str(tmp)]
                )
            )
        elif dest == "vary":
            value = f"{draw(st.sampled_from(SWEPT))}={draw(st.sampled_from(RANGES))}"
        else:
            value = draw(_token(dest))
        argv += [flag, value] if draw(st.booleans()) else [f"{flag}={value}"]
    if name in ("sweep", "map", "design"):
        argv += ["--executor", "serial", "--quiet"]  # no process pools in a 1000-case loop
    flags = {a.split("=")[0] for a in argv}
    if name == "simulate" and flags & FORCING_FLAGS and "--periods" not in flags:
        argv += ["--periods", "4"]
    if draw(st.integers(0, 29)) == 0:
        argv.insert(draw(st.integers(0, len(argv))), draw(st.sampled_from(["--bogus", "x", "-"])))
    return argv


def _run_cli(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = cli.main(argv)
        except SystemExit as exc:  # argparse: --help (0) or a usage error (2)
            rc = exc.code if isinstance(exc.code, int) else 2
    return rc, out.getvalue(), err.getvalue()


def _no_nan_json(text: str) -> None:
    def refuse(const: str):
        raise AssertionError(f"{const} in JSON output")

    json.loads(text, parse_constant=refuse)


def _write_sets(tmp: Path) -> None:
    (tmp / "sets.csv").write_text("gap [mm],c1\n6,0\n9,1\n")
    (tmp / "impacts.csv").write_text("approach speed [m/s],rebound speed [m/s]\n0.5,0.4\n"
                                     "1,0.75\n2,1.3\n3,1.8\n")  # fmt: skip
    (tmp / "bad.csv").write_text("gap,nonsense\n1,2,3\nx\n")


@pytest.fixture(scope="module")
def fuzz_dir(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("fuzz")
    _write_sets(tmp)
    return tmp


def test_cli_fuzz(fuzz_dir):
    seen: dict[int, int] = {}

    @FUZZ
    @given(argv=_argv(fuzz_dir))
    # argparse stores [] for a one-value option written '--mode=--' (found by this fuzz)
    @example(argv=["ritz", "--E=", "--mode=--"])
    @example(argv=["frf", "--workers=--"])
    def case(argv):
        for f in ("f.csv", "f.png", "f.parquet", "f.txt"):  # --out refuses to overwrite
            path = fuzz_dir / f
            if path.is_dir():  # export --out makes a folder
                shutil.rmtree(path)
            path.unlink(missing_ok=True)
        _write_sets(fuzz_dir)  # (export --out DIR --force may have replaced the folder)
        rc, out, err = _run_cli(argv)
        seen[rc] = seen.get(rc, 0) + 1
        assert "Traceback" not in err, (argv, err)
        assert rc in (0, 2), (argv, rc, err)
        if rc == 2:
            lines = err.strip().splitlines()
            assert len(lines) == 1 and lines[0].startswith("symimpact"), (argv, err)
            assert re.search(r"error: \S", lines[0]), (argv, err)
        else:
            assert not re.search(r"\bnan\b", out, re.IGNORECASE), (argv, out)
            if "--json" in argv and out.strip():
                _no_nan_json(out)

    case()
    # the vocabulary must reach both outcomes, or the fuzz tests only one side.  Measured on
    # 2026-11-28 (the subcommands have grown options that each refuse more lists): 1.8-3.7 % of
    # the argument lists run (exit 0): 18, 25, 27, 37 and 37 in 1000 under the CI profile, the
    # derandomised draw and seeds 1-3.  1/200 lies four binomial standard deviations
    # (√(1000·0.029) ≈ 5.4 runs) below their mean of 29, so another seed does not fail it
    floor = FUZZ_EXAMPLES // 200
    assert seen.get(0, 0) >= floor and seen.get(2, 0) >= floor, seen


# --- the public API -------------------------------------------------------------------------

ODD_VALUES = st.sampled_from(
    [
        0,
        -1,
        -0.0,
        math.nan,
        math.inf,
        -math.inf,
        1e308,
        1e-308,
        True,
        None,
        [1, 2],
        {"a": 1},
        "5 kg",
        "5 furlongz",
        "",
        "((",
        complex(1, 1),
        np.float64("nan"),
        np.array([1.0, 2.0]),
    ]
)


@st.composite
def _values(draw, dest: str, odd_percent: int = 15):
    """A valid value for ``dest`` in (100 − odd_percent) % of draws, else an odd one (hypothesis's
    own choice among alternatives leans to the later ones, so the odds are drawn explicitly)."""
    if draw(st.integers(0, 99)) < 100 - odd_percent:
        return draw(st.sampled_from(GOOD[dest]))
    return draw(ODD_VALUES)


def _check_finite(obj, where) -> None:
    """Every number in a result (scalars, arrays, dicts, lists, dataclass fields) is finite."""
    if obj is None or isinstance(obj, (str, bool)):
        return
    if isinstance(obj, (int, float, np.floating, np.integer)):
        assert math.isfinite(float(obj)), where
    elif isinstance(obj, np.ndarray):
        assert np.all(np.isfinite(obj)), where
    elif isinstance(obj, dict):
        for k, v in obj.items():
            _check_finite(v, (where, k))
    elif isinstance(obj, (list, tuple)):
        for v in obj:
            _check_finite(v, where)
    elif hasattr(obj, "__dataclass_fields__"):
        for k in obj.__dataclass_fields__:
            _check_finite(getattr(obj, k), (where, k))


def _call(seen: Counter, fn, *args, **kwargs):
    """The call's result, or None when it raised the package's own error (one line)."""
    try:
        result = fn(*args, **kwargs)
    except SymimpactError as exc:
        assert str(exc).strip() and "\n" not in str(exc), repr(exc)
        seen[fn.__name__, "refused"] += 1
        return None
    seen[fn.__name__, "ran"] += 1
    return result


def _fuzz(body, **strategies) -> Counter:
    """Run ``body(seen, **drawn)`` on FUZZ_EXAMPLES draws; returns the outcomes per function."""
    seen: Counter = Counter()

    @FUZZ
    @given(**strategies)
    def case(**drawn):
        body(seen, **drawn)

    case()
    return seen


def _reached_both(seen: Counter, *names: str) -> None:
    """Each function both ran and refused on ≥ 2 % of the cases: the fuzz tested both sides."""
    for name in names:
        for outcome in ("ran", "refused"):
            assert seen[name, outcome] >= FUZZ_EXAMPLES // 50, (name, dict(seen))


SYSTEM_KEYS = ("M", "K", "C", "zeta", "m", "gap", "k_hz", "k1", "c1", "a", "b")


@st.composite
def _system_kwargs(draw):
    # in SYSTEM_KEYS' order: a set's iteration order follows PYTHONHASHSEED, which would make the
    # derandomized draws differ from one process to the next
    keys = sorted(draw(st.sets(st.sampled_from(SYSTEM_KEYS))), key=SYSTEM_KEYS.index)
    kw = {k: draw(_values(k)) for k in keys}
    for k in ("M", "K", "m", "gap"):  # the required ones, mostly valid
        kw.setdefault(k, draw(st.sampled_from(GOOD[k])))
    if not {"k_hz", "a", "k1"} & kw.keys():
        kw["k_hz"] = "1000 N/m^1.5"
    if "C" in kw and "zeta" in kw and draw(st.booleans()):
        del kw["zeta"]
    laws = ["cubic", "hertz", "linear"]
    kw["contact"] = draw(st.sampled_from(laws * 5 + ["bogus", None, 3]))
    return kw


def _system(seen: Counter, kw):
    from symimpact.model.system import ImpactSystem

    return _call(seen, ImpactSystem, **kw)


def _simulate_case(seen, kw, state, t_end, contact, rest):
    from symimpact.free.simulation import simulate

    system = _system(seen, kw)
    if system is None:
        return
    _check_finite(system.as_dict(), "system")
    res = _call(seen, simulate, system, *state, t_end=t_end, contact=contact, rest=rest)
    if res is not None:
        _check_finite(res.as_dict(), "simulate")


def test_api_fuzz_system_and_simulate():
    seen = _fuzz(
        _simulate_case,
        kw=_system_kwargs(),
        state=st.tuples(*(_values(n) for n in ("x0", "xdot0", "y0", "ydot0"))),
        t_end=_values("t_end"),
        contact=st.sampled_from([None, "cubic", "hertz", "linear", "perturbation", "bogus"]),
        rest=st.sampled_from([1e-12, 0.0, 1e-6, -1.0, 1.0, math.nan, "x"]),
    )
    _reached_both(seen, "ImpactSystem", "simulate")


def _contact_case(seen, kw, v0, method, ba, free):
    from symimpact.free import contact

    system = _system(seen, kw)
    if system is None:
        return
    _check_finite(_call(seen, contact.contact_duration, system, v0, method, ba=ba), "duration")
    _check_finite(_call(seen, contact.amplitude_ratio, system, ba=ba), "amplitude_ratio")
    _check_finite(_call(seen, contact.numerical_contact, system, v0, free=free), "numerical")


def test_api_fuzz_contact():
    seen = _fuzz(
        _contact_case,
        kw=_system_kwargs(),
        # odd more often than the system's values: a call is refused on v0 only when the system
        # (eleven values, each odd 15 % of the time) got through, about 4 cases in 10
        v0=_values("v0", odd_percent=35),
        method=st.sampled_from(["perturbation", "hertz", "linear", "numerical", "all", "bogus"]),
        ba=_values("ba"),
        free=st.booleans(),
    )
    _reached_both(seen, "contact_duration", "amplitude_ratio", "numerical_contact")


def _beam_case(seen, beam, position, k_hz, delta_max):
    from symimpact.model.system import beam_constants

    _check_finite(_call(seen, beam_constants, *beam, position=position), "beam_constants")
    rc, out, err = _run_cli(["fit", "--k-hz", str(k_hz), "--delta-max", str(delta_max)])
    assert rc in (0, 2) and "Traceback" not in err and not re.search(r"\bnan\b", out, re.I)
    seen["fit", "ran" if rc == 0 else "refused"] += 1


def test_api_fuzz_beam_and_fit():
    seen = _fuzz(
        _beam_case,
        beam=st.tuples(*(_values(n) for n in ("E", "I", "rho", "A", "L"))),
        position=st.one_of(st.none(), _values("position")),
        k_hz=_values("k_hz"),
        delta_max=_values("delta_max"),
    )
    _reached_both(seen, "beam_constants", "fit")


def _map_case(seen, kw, grid, chunk_size):
    from symimpact.maps import parameter_map

    system = _system(seen, kw)
    if system is None:
        return
    table = _call(
        seen,
        parameter_map,
        system,
        grid=grid,
        executor="serial",
        t_end=0.2,
        chunk_size=chunk_size,
        progress=False,
    )
    if table is not None:
        for col in table.columns:
            for v in table[col].to_numpy(dtype=object):  # missing is <NA>; a number is finite
                assert not isinstance(v, float) or math.isfinite(v), (col, v)


def test_api_fuzz_parameter_map():
    seen = _fuzz(
        _map_case,
        kw=_system_kwargs(),
        grid=st.dictionaries(
            st.sampled_from(["gap", "c1", "xdot0", "bogus"]),
            st.one_of(
                st.sampled_from(RANGES[:4] * 3 + RANGES),
                st.lists(_values("gap"), min_size=1, max_size=2),
            ),
            min_size=1,
            max_size=2,
        ),
        chunk_size=st.sampled_from([None, 1, 3, 0, -1, 2.5, "x"]),
    )
    _reached_both(seen, "parameter_map")
