"""``symimpact ritz``: Ritz constants of a beam (Eq. 1–6; Eq. F6 for the clamped–clamped and
simply supported beams), and its first modes at the damper's point."""

from __future__ import annotations

from typing import Any

from ..errors import ParameterError, SymimpactError
from .common import add_output, emit

SUPPORTS = ("cantilever", "clamped-clamped", "simply-supported")


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "ritz",
        help="Ritz constants of a beam (Eq. 1–6, F6): each mode's mass and stiffness at the "
        "damper's point",
    )
    for flag, helptext in (
        ("--E", "Young modulus E [Pa]"),
        ("--I", "second moment of area I [m^4]"),
        ("--rho", "density ρ [kg/m^3]"),
        ("--A", "cross-section A [m^2]"),
        ("--L", "length L [m]"),
        ("--position", "damper position from the clamp (or the left support) [m]; default the "
         "cantilever's tip, the other beams' midspan"),
    ):  # fmt: skip
        p.add_argument(flag, metavar="Q", help=helptext)
    p.add_argument("--support", choices=SUPPORTS, default="cantilever",
                   help="the beam's ends: clamped–free (default), clamped at both, or pinned at "
                   "both")  # fmt: skip
    p.add_argument("--mode", type=int, default=1, metavar="N",
                   help="the mode whose K and M are the primary (default 1)")  # fmt: skip
    p.add_argument("--modes", type=int, default=None, metavar="N",
                   help="list the first N modes (1–8) at the point, with the static flexibility "
                   "against the sum over them (needs the beam parameters)")  # fmt: skip
    add_output(p)


def run(ns) -> None:
    from ..model.beams import SUPPORTS as KERNELS
    from ..model.beams import beam_constants, beam_modes, static_flexibility

    kernels = KERNELS[ns.support]
    if not 1 <= ns.mode <= len(kernels.roots):
        raise ParameterError(
            "mode", f"a whole number from 1 to {len(kernels.roots)}, got {ns.mode}"
        )
    bl = kernels.roots[ns.mode - 1]
    xi = kernels.default_xi
    out: dict[str, Any] = {
        "beta_L": bl,
        "stiffness_coefficient": float(kernels.stiffness(bl, xi)),
        "mass_coefficient": float(kernels.mass(bl, xi)),
    }
    if ns.support != "cantilever" or ns.mode != 1:
        out = {"support": ns.support, "mode": ns.mode, **out}
    beam = [ns.E, ns.I, ns.rho, ns.A, ns.L]
    given = any(v is not None for v in beam)
    if ns.modes is not None and not given:
        raise ParameterError("modes", "needs the beam parameters (--E, --I, --rho, --A, --L)")
    lines = []
    if given:
        missing = [n for n, v in zip(("E", "I", "rho", "A", "L"), beam, strict=True) if v is None]
        if missing:
            raise SymimpactError(f"{missing[0]}: needed with the other beam parameters")
        K, M = beam_constants(*beam, position=ns.position, support=ns.support, mode=ns.mode)
        out.update(K=K, M=M)
        if ns.position is not None:
            from ..model.units import positive_float

            xi = positive_float("position", ns.position) / positive_float("L", ns.L)
            out["stiffness_coefficient"] = float(kernels.stiffness(bl, xi))
            out["mass_coefficient"] = float(kernels.mass(bl, xi))
        if ns.modes is not None:
            modes = beam_modes(ns.support, *beam, position=ns.position, n=ns.modes)
            exact = static_flexibility(ns.support, ns.E, ns.I, ns.L, ns.position)
            summed = sum(1.0 / m.K for m in modes if not m.node)
            out["modes"] = [m.as_dict() for m in modes]
            out["static_flexibility"] = exact
            out["static_flexibility_of_the_modes"] = summed
            lines += [
                f"{'mode':>4}  {'βL':>9}  {'f [Hz]':>11}  {'M at the point [kg]':>19}  "
                f"{'K at the point [N/m]':>20}  {'Γ at the point':>14}  {'mass share [%]':>14}",
                *(
                    f"{m.number:>4}  {m.beta_L:9.6f}  {m.frequency:11.5g}  "
                    + (f"{'node':>19}  {'node':>20}" if m.node else f"{m.M:19.6g}  {m.K:20.6g}")
                    + f"  {m.participation:14.6g}  {m.mass_share * 100:14.4g}"
                    for m in modes
                ),
                f"static flexibility at the point {exact * 1e3:.6g} mm/N; the sum over these "
                f"{len(modes)} modes, Σ1/K, {summed * 1e3:.6g} mm/N "
                f"({(1 - summed / exact) * 100:.3g} % short)",
                f"these {len(modes)} modes move {sum(m.mass_share for m in modes) * 100:.4g} % of "
                "the beam's mass when its supports move (Γ: the supports' motion drives a mode as "
                "a base motion Γ·x_b, Eq. F7)",
            ]
    units = {"K": "N/m", "M": "kg", "stiffness_coefficient": "(× EI/L³)",
             "mass_coefficient": "(× ρAL)"}  # fmt: skip
    head = [f"{k} = {v:.10g} {units.get(k, '')}".rstrip() if isinstance(v, float)
            else f"{k} = {v}" for k, v in out.items()
            if k not in ("modes", "static_flexibility", "static_flexibility_of_the_modes")]  # fmt: skip
    emit(ns, out, "\n".join(head + lines))


#: The subcommands this module runs.
COMMANDS = {"ritz": run}
