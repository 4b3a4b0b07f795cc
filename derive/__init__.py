"""SymPy derivations of the paper's results, one module per step, and the code generator.

Run ``python -m derive`` from the checkout to re-derive everything and rewrite ``generated/``;
``python -m derive --check`` regenerates in memory and fails with a diff when ``generated/``
differs.  Import a step and call ``derive()`` to get its :class:`~derive.board.Board`.
"""

from __future__ import annotations

import importlib

import mpmath as _mp
from sympy.core.random import seed as _sympy_seed

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
    "multi_harmonic_balance",
)


#: The seed of SymPy's own random numbers, set on import and before every step.  Its polynomial
#: factorisation (Wang's algorithm, under ``simplify`` and ``factor``) lifts from randomly chosen
#: points, which SymPy draws from a generator seeded by the operating system: the results are the
#: same, the time is not.  Unseeded, one ``derive --check`` of a fresh clone spent 39 minutes of
#: CPU in ``sampled_load``'s simplify (Hensel lifting), where its twin took 4 minutes in all.
SYMPY_SEED = 20261128
_sympy_seed(SYMPY_SEED)


#: mpmath's working precision [bits] outside a step's own ``workdps`` blocks: mpmath's default,
#: as in a fresh ``python -m derive``.  A step's arithmetic on mpmath numbers outside such a
#: block (Step 1's (β₁L)⁴ in its Eq. 6 erratum and the tip-stiffness kernel) rounds to it; a
#: process that had raised mpmath's global precision (a test module setting ``mp.dps = 40``)
#: derived another last digit there, and its boards differed from ``generated/``.
MPMATH_PREC = 53


def board(step: str):
    """Run one derivation step and return its board (SymPy's random numbers seeded first and
    mpmath's precision set to MPMATH_PREC, so a step's work does not depend on the steps before it,
    on the process it runs in, nor on the run)."""
    _sympy_seed(SYMPY_SEED)
    with _mp.workprec(MPMATH_PREC):
        return importlib.import_module(f"derive.{step}").derive()
