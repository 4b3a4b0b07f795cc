"""Bundled kernels (issue 38, item 1: derivatives generated with the common subexpressions shared
with the value): a value with its derivatives, or the flight's state with its transition matrix,
emitted as one function per target that returns every part, ``sympy.cse`` run over the parts
together (:meth:`derive.board.Board.bundle`).

Each part of each bundle is checked at the part's own recorded points (``derive/checkpoints.py``:
its 50-digit mpmath value) through the NumPy bundle and its ``_scalar`` twin, to 1e-12 of the
part's error scale, the tolerance every target is held to (the C, Rust and Fortran check
programs run the same points through their bundles); and the shared subexpressions are shown to
pay: a bundle has fewer operations than its parts computed one by one.
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from derive import checkpoints
from derive.codegen import bundle_ops

RTOL = checkpoints.RTOL


@pytest.fixture(scope="module")
def bundles(boards):
    """[(step, bundle, [(index, part, recorded points)])] of every bundle."""
    return checkpoints.recorded(list(boards.values()))["bundles"]


def test_the_issue_s_bundles_exist(bundles):
    names = {(step, b.name) for step, b, _ in bundles}
    for step, b, _ in bundles:  # each module lists its bundles and their parts for importers
        module = importlib.import_module(f"symimpact.generated.{step}")
        assert module.BUNDLES[b.name] == tuple(k.name for k in b.parts)
    for expected in (
        ("forced_flight", "forced_state"),
        ("forced_flight", "forced_transition"),
        ("rigid_impact", "velocities_after_and_derivatives"),
        ("closed_forms", "hertz_contact_duration_and_derivatives"),
        ("closed_forms", "linear_contact_duration_and_derivatives"),
        ("slow_flow", "clearance_for_response_and_derivatives"),
        ("periodic_orbit", "phase_residual_and_derivatives"),
    ):
        assert expected in names


def test_every_part_of_every_bundle_at_its_recorded_points(bundles):
    checked = 0
    for step, b, parts in bundles:
        module = importlib.import_module(f"symimpact.generated.{step}")
        whole, scalar = getattr(module, b.name), getattr(module, f"{b.name}_scalar")
        for j, part, points in parts:
            args = [np.array([float(p.args[i]) for p in points]) for i in range(len(b.args))]
            expected = np.array([float(p.value) for p in points])
            scale = np.array([float(p.scale) for p in points])
            got = whole(*args)[j]
            assert np.all(np.abs(got - expected) <= RTOL * scale), (b.name, part.name, got)
            for i, p in enumerate(points):
                one = scalar(*(float(a) for a in p.args))[j]
                assert abs(one - expected[i]) <= RTOL * scale[i], (b.name, part.name, i)
            checked += len(points)
    assert checked >= 3 * 40


def test_a_bundle_broadcasts_like_its_parts():
    from symimpact.generated import forced_flight as ff

    t = np.linspace(0.0, 0.2, 7)[:, None]
    args = (t, 1.0, 1000.0, 0.5, 2.0, 0.0, 30.0, np.array([0.1, 0.2]), 0.01, 0.0)
    x, v = ff.forced_state(*args)
    assert x.shape == v.shape == (7, 2)
    assert np.allclose(x, ff.forced_displacement(*args), rtol=1e-14, atol=1e-18)


def test_shared_subexpressions_pay(boards):
    """A bundle pays for itself by what its parts share; a contact law's force with its slopes
    (Step 17) is bundled for the balance's call at each sample whatever they share (k₁δ + c₁δ̇,
    k₁ and c₁ share nothing), and must not cost more than its parts."""
    for board in boards.values():
        laws = {x.force.name for x in board.balances}
        for b in board.bundles:
            together, alone = bundle_ops(b)
            assert together <= alone if b.name in laws else together < alone, b.name
