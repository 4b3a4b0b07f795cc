"""Sibling commands take the same options for the same things (issue 80, item 4): every command
that runs many simulations has --quiet, --workers, --json, --csv and --plot, the two that draw a
curve's multi-start have --multistart, and each shared option means the same (one help text)."""

from __future__ import annotations

import argparse

import pytest

from symimpact.cli import build_parser, main

#: The commands that run many simulations (a curve, a design map, an ensemble, a map).
MANY = ("frf", "design", "random", "map", "sweep")
SHARED = {"--quiet", "--workers", "--json", "--csv", "--plot"}


def _options(command: str) -> dict[str, argparse.Action]:
    parser = build_parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return {s: a for a in sub.choices[command]._actions for s in a.option_strings}


@pytest.mark.parametrize("command", MANY)
def test_commands_of_many_runs_share_their_options(command):
    assert SHARED <= set(_options(command)), SHARED - set(_options(command))


def test_the_curves_share_multistart_and_one_help_for_each_shared_option():
    frf, design = _options("frf"), _options("design")
    assert frf["--multistart"].help == design["--multistart"].help
    helps = {c: _options(c)["--quiet"].help for c in MANY}
    assert len(set(helps.values())) == 1, helps


@pytest.mark.parametrize("value, ok", [("0", True), ("-1", False), ("1001", False)])
def test_frf_takes_multistart_as_design_does(value, ok, capsys):
    """frf --multistart 0 (refused before, issue 80) draws the curve without the multi-start;
    out of range is one line naming the option."""
    argv = ["frf", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
            "--force", "2 N", "--contact", "rigid", "--e", "0.6", "--omega-range", "34:35:0.5",
            "--no-sweeps", "--quiet", "--json", "--multistart", value, "--workers", "1"]  # fmt: skip
    code = main(argv)
    out = capsys.readouterr()
    if ok:
        assert code == 0 and '"branches"' in out.out
    else:
        assert code == 2 and "error: multistart:" in out.err and out.err.count("\n") == 1
