"""``symimpact ritz``: Ritz constants of the cantilever (Eq. 1–6)."""

from __future__ import annotations

from typing import Any

from ..errors import SymimpactError
from .common import add_output, emit


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("ritz", help="Ritz constants of the cantilever (Eq. 1–6)")
    for flag, helptext in (
        ("--E", "Young modulus E [Pa]"),
        ("--I", "second moment of area I [m^4]"),
        ("--rho", "density ρ [kg/m^3]"),
        ("--A", "cross-section A [m^2]"),
        ("--L", "length L [m]"),
        ("--position", "damper position from the clamp [m]; default the tip"),
    ):
        p.add_argument(flag, metavar="Q", help=helptext)
    add_output(p)


def run(ns) -> None:
    from ..generated import ritz
    from ..system import beam_constants

    out: dict[str, Any] = {
        "beta_L": ritz.BETA_L[0],
        "stiffness_coefficient": float(ritz.stiffness_coefficient(ritz.BETA_L[0], 1.0)),
        "mass_coefficient": float(ritz.mass_coefficient(ritz.BETA_L[0], 1.0)),
    }
    beam = [ns.E, ns.I, ns.rho, ns.A, ns.L]
    if any(v is not None for v in beam):
        missing = [n for n, v in zip(("E", "I", "rho", "A", "L"), beam, strict=True) if v is None]
        if missing:
            raise SymimpactError(f"{missing[0]}: needed with the other beam parameters")
        K, M = beam_constants(*beam, position=ns.position)
        out.update(K=K, M=M)
        if ns.position is not None:
            from ..units import positive_float

            xi = positive_float("position", ns.position) / positive_float("L", ns.L)
            out["stiffness_coefficient"] = float(ritz.stiffness_coefficient(ritz.BETA_L[0], xi))
            out["mass_coefficient"] = float(ritz.mass_coefficient(ritz.BETA_L[0], xi))
    units = {"K": "N/m", "M": "kg", "stiffness_coefficient": "(× EI/L³)",
             "mass_coefficient": "(× ρAL)"}  # fmt: skip
    lines = [f"{k} = {v:.10g} {units.get(k, '')}".rstrip() for k, v in out.items()]
    emit(ns, out, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"ritz": run}
