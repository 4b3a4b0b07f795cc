"""``symimpact fit``: cubic and linear fits of the Hertz law (Eq. 8–9, 35)."""

from __future__ import annotations

from typing import Any

from .common import add_output, emit


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("fit", help="cubic and linear fits of the Hertz law (Eq. 8–9, 35)")
    p.add_argument("--k-hz", default="1000 N/m^1.5", metavar="Q",
                   help="K_Hz [N/m^1.5]; default the paper's 1000 N/m^1.5, a resilient "
                   "(rubber-like) contact — 'symimpact contact' derives it from materials")  # fmt: skip
    p.add_argument("--delta-max", default="2 cm", metavar="Q", help="fit range [m]; default 2 cm")
    p.add_argument(
        "--continuous", action="store_true", help="continuous least squares, not 21 samples"
    )
    add_output(p)


def run(ns) -> None:
    from ..generated import contact_fits as cf
    from ..model.units import positive_float

    k = positive_float("k-hz", ns.k_hz, "N/m^1.5")
    d = positive_float("delta-max", ns.delta_max, "m")
    sfx = "_continuous" if ns.continuous else ""
    out = {
        "a": float(getattr(cf, f"cubic_fit_a{sfx}")(k, d)),
        "b": float(getattr(cf, f"cubic_fit_b{sfx}")(k, d)),
        "k1": float(getattr(cf, f"linear_fit_k1{sfx}")(k, d)),
    }
    emit(ns, out, f"a = {out['a']:.6g} N/m^3\nb = {out['b']:.6g} N/m\nk1 = {out['k1']:.6g} N/m")


#: The subcommands this module runs.
COMMANDS = {"fit": run}
