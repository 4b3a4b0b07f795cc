"""``symimpact contact``: the contact derived from the ball and the cavity (Step 13, Eq. F5)."""

from __future__ import annotations

from typing import Any

from .common import add_output, emit, wrapped

#: How each derived value is shown to a person: (label, unit, factor from SI, where it comes
#: from in short; --json gives the full sentence).
SHOWN = {
    "m": ("impactor mass m", "g", 1e3, "ρπD³/6"),
    "E_star": ("effective modulus E*", "GPa", 1e-9, "Step 13"),
    "R": ("effective radius R", "mm", 1e3, "Step 13"),
    "k_hz": ("Hertz stiffness K_Hz", "N/m^1.5", 1.0, "Step 13"),
    "max_penetration": ("largest penetration", "µm", 1e6, "Eq. 34"),
    "duration": ("contact duration", "µs", 1e6, "Eq. 34"),
    "peak_force": ("peak force", "N", 1.0, "Step 13"),
    "peak_pressure": ("peak pressure p0", "MPa", 1e-6, "Step 13"),
    "yield_speed": ("first yield at v0 =", "m/s", 1.0, "Step 13"),
    "e": ("restitution e", "", 1.0, None),
    "chi": ("Hunt–Crossley χ", "s/m", 1.0, "Step 11"),
    "k1": ("linear stiffness k1", "N/m", 1.0, "Eq. 9 fit"),
    "c1": ("linear damping c1", "N s/m", 1.0, "Step 9"),
}

#: Beyond this ratio of a forcing period to the contact duration the compliant simulation spends
#: most of its steps inside contacts: the rigid law (Eq. F2) with the derived e is the model.
STIFF_RATIO = 1e3


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "contact",
        help="the contact from materials and geometry: K_Hz, e, χ, c1, penetration, duration, "
        "yield (Step 13)",
    )
    p.add_argument(
        "--impactor",
        required=True,
        metavar="TEXT",
        help="'<material> sphere <diameter or mass>', e.g. 'steel sphere 20 mm' or 'steel "
        "sphere 2 kg'",
    )
    p.add_argument(
        "--cavity",
        required=True,
        metavar="TEXT",
        help="'<material> flat', '<material> sphere <diameter>', '<material> spherical cavity "
        "<diameter>', '<material> cylindrical bore <diameter>' or '<material> cylinder "
        "<diameter>'; a material is a name (steel = AISI 1045, mild steel = 1018, bearing steel "
        "= 52100, stainless steel = 304, hardened stainless steel = 440C, aluminium alloy, "
        "brass, bronze, lead, tungsten alloy, tungsten carbide, cast iron, ptfe, nylon, "
        "polyurethane, natural rubber) or 'E 200 GPa, nu 0.3, rho 7800 kg/m^3, Y 350 MPa'",
    )
    p.add_argument("--v0", required=True, metavar="Q", help="impact (approach) speed [m/s]")
    p.add_argument(
        "--M", default=None, metavar="Q", help="mass of the cavity's body [kg]; default massive"
    )
    p.add_argument(
        "--freq",
        default=None,
        metavar="Q",
        help="forcing frequency [Hz] (or rad/s with units), to say whether a compliant "
        "simulation can resolve the contact",
    )
    add_output(p)


def run(ns) -> None:
    from ..model.derived_contact import derived_contact
    from ..model.units import positive_float

    c = derived_contact(ns.impactor, ns.cavity, ns.v0, ns.M)
    out = c.as_dict()
    lines = [f"{ns.impactor} in {ns.cavity}, impact speed {c.v0:g} m/s"]
    for name, (label, unit, factor, tag) in SHOWN.items():
        value = out[name]
        text = "—" if value is None else f"{value * factor:.5g}"
        if tag is None:  # the restitution's origin in a word
            tag = c.sources[name].split(":")[0].split(" at ")[0].split(" (")[0]
        lines.append(f"  {label:<21} {text:>10} {unit:<8} [{tag}]")
    for body in dict.fromkeys((c.sources["impactor_material"], c.sources["cavity_material"])):
        lines.append(wrapped(body.split(";")[0]))
    lines.append("  (typical values of these grades; --json: every source)")
    if "steel" in (c.sources["impactor_material"].split(":")[0],
                   c.sources["cavity_material"].split(":")[0]):  # fmt: skip
        lines.append(wrapped("'steel' is AISI 1045: hardened bearing balls rebound more "
                             "(e 0.8–0.95), give 'bearing steel' (52100) or 'hardened stainless "
                             "steel' (440C)"))  # fmt: skip
    if ns.freq is not None:
        f = positive_float("freq", ns.freq, "Hz")
        ratio = 1.0 / (f * c.duration)
        if ratio > STIFF_RATIO:
            lines.append(wrapped(
                f"a forcing period is {ratio:.3g} contact durations: a compliant simulation "
                f"would spend its steps in the contacts; use --contact rigid --e {c.e:.3g}", ""
            ))  # fmt: skip
        out["period_over_duration"] = ratio
    emit(ns, out, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"contact": run}
