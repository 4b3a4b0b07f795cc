"""Shared fixtures: the derivation boards are built once per test session (about 10 s)."""

from __future__ import annotations

import pytest

from derive import STEPS, board


@pytest.fixture(scope="session")
def boards():
    return {step: board(step) for step in STEPS}
