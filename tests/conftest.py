"""Shared fixtures, and the hypothesis profiles every property test runs under.

Profiles (``--hypothesis-profile NAME``):

- ``ci`` (the default): no deadline (below), ``derandomize=True``, so each property test draws the
  same examples on every run and every machine (seeded from the test's own source), and no example
  database, so a failure seen on one machine is not replayed as a different run on another. The
  README's test command and CI use it.
- ``explore``: fresh random examples on every run.  Run
  ``python -m pytest --hypothesis-profile explore`` to look for new failures, or
  ``python -m pytest --hypothesis-seed N`` to replay one seed: a seed on the command line selects
  this profile's randomness (``derandomize`` would otherwise override the seed).
"""

from __future__ import annotations

import pytest
from hypothesis import settings

from derive import cache

# No deadline: hypothesis's default fails an example that takes over 200 ms of wall time, which
# a first call (pint building its registry) or a loaded machine (xdist workers on 2 cores) can
# take; it failed a units test here once under load (1 of 5 runs).  Time is measured in the
# benchmarks, never asserted in the tests.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True, deadline=None)
settings.register_profile("explore", derandomize=False, database=None, print_blob=True,
                          deadline=None)  # fmt: skip
# Loaded here, before any test module builds its @settings(...) from the current profile.
settings.load_profile("ci")


def pytest_configure(config: pytest.Config) -> None:
    if hasattr(config, "workerinput"):  # an xdist worker: one a core (-n auto), BLAS on one
        from symimpact._threads import blas_on_one_thread_from_now

        blas_on_one_thread_from_now()
    if not hasattr(config, "workerinput"):  # the main process, before any xdist worker starts
        # The generalised ufuncs of generated/fixed_points.py compile when imported and write
        # numba's on-disk cache.  Two workers doing so at once in a fresh checkout can leave
        # one with a cache the other half wrote: a segmentation fault at its next call (seen
        # once in tests/test_fixed_points.py; numba issue 10128).  Compiled here first, the
        # workers only read the cache.
        import symimpact.generated.fixed_points  # noqa: F401
    if config.getoption("hypothesis_profile", None):
        return  # the plugin loads the profile named on the command line
    if config.getoption("hypothesis_seed", None) is not None:
        # a seed asks for that seed's examples, which derandomize=True would ignore
        settings.register_profile("seeded", parent=settings.get_profile("ci"), derandomize=False)
        settings.load_profile("seeded")


@pytest.fixture(scope="session")
def boards():
    """{step: Board}: read back when this derivation code was derived before in the checkout (by
    ``python -m derive``, ``--check`` or the docs build; derive/cache.py), derived otherwise."""
    return cache.boards()


#: The slow set's modules that take longest, longest test first, with the seconds their slow
#: tests took on the 2-core machine (``pytest -n 2 --dist load -m slow --durations``, setup and
#: calls, 2026-12-07): run first, so that the fine-grained rest (test_limits' 95 cases, the
#: notebooks, the pages of test_docs) fills both cores at the end instead of one long test
#: holding one core while the other idles (test_surfaces_reliability's stiff curve, 289 s, had
#: been left to the end: one core idle for minutes).  Only the order changes; each module's
#: tests stay together and in their own order.
LONGEST_FIRST = (
    "test_readme_commands",  # 483 s in three tests (251 s the guide's design, 192 s task 1)
    "test_fuzz_forced",  # 224 s
    "test_design_refine",  # 221 s
    "test_jax_kernels",  # 188 s in three tests
    "test_robust_design",  # 146 s
    "test_reliability",  # 206 s before its stiff curve ran without the multi-start
    "test_reproduce",  # 90 s
    "test_notebooks",  # 18 notebooks, each a derivation: about 500 s in all
)


@pytest.hookimpl(tryfirst=True)  # before pytest-xdist's own hook reads the groups
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Under pytest-xdist (``-n auto``, as the README runs the tests), keep what shares a costly
    fixture on one worker: every module that reads the derivation boards on one (the sixteen steps
    are derived once, minutes, not once per worker), and each other module on one (its
    module-scoped fixtures, such as a report or a continuation, are computed once).  The modules
    of :data:`LONGEST_FIRST` are moved to the front, in that order."""
    rank = {name: k for k, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.module.__name__.rpartition(".")[2], len(rank)))
    with_boards = {item.module.__name__ for item in items if "boards" in item.fixturenames}
    for item in items:
        name = item.module.__name__
        item.add_marker(pytest.mark.xdist_group("boards" if name in with_boards else name))
