"""Every command's --help renders: argparse formats each help text with %, so a "95 %" typed in
one (it was, in 'identify') broke 'symimpact --help' and the documentation's command-line page."""

from __future__ import annotations

import argparse

import pytest

from symimpact.cli import build_parser, main


def _parsers(parser: argparse.ArgumentParser, name: str = "symimpact"):
    yield name, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub, child in action.choices.items():
                yield from _parsers(child, f"{name} {sub}")


PARSERS = dict(_parsers(build_parser()))


@pytest.mark.parametrize("name", list(PARSERS))
def test_every_help_renders(name, capsys):
    assert PARSERS[name].format_help().startswith("usage:")
    with pytest.raises(SystemExit) as ended:
        main([*name.split()[1:], "--help"])
    assert ended.value.code == 0 and capsys.readouterr().out.startswith("usage:")
