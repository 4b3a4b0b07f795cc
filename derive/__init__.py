"""SymPy derivations of the paper's results, one module per step, and the code generator.

Run ``python -m derive`` from the checkout to re-derive everything and rewrite ``generated/``;
``python -m derive --check`` regenerates in memory and fails with a diff when ``generated/``
differs.  Import a step and call ``derive()`` to get its :class:`~derive.board.Board`.
"""

from __future__ import annotations

import importlib

# Load the submodule derive.board before the function board() below is defined: the first import
# of a submodule sets it as an attribute of the package, which would otherwise shadow board().
from . import board as _board_module  # noqa: F401

#: The derivation steps in lecture order (module names under ``derive/``).
STEPS = (
    "ritz",
    "contact_fits",
    "harmonic_balance",
    "lindstedt",
    "multiple_scales",
    "closed_forms",
    "free_flight",
    "forced_flight",
    "rigid_impact",
    "periodic_orbit",
    "hunt_crossley",
    "slow_flow",
    "hertz_contact",
    "beam_modes",
    "modal_structure",
    "sampled_load",
)


def board(step: str):
    """Run one derivation step and return its board."""
    return importlib.import_module(f"derive.{step}").derive()
