"""``symimpact periodic``: the periodic motions of the forced impact damper at one frequency —
the symmetric two-impact orbits in closed form (Eq. F3), each with its amplitude, impact speed,
admissibility and stability."""

from __future__ import annotations

from typing import Any

from .common import add_forcing, add_output, add_system, emit, forcing_from, system_from

#: The methods ``--method`` takes.
METHODS = ("closed-form",)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "periodic",
        help="periodic motions of the forced damper at one frequency (closed form, Eq. F3)",
    )
    add_system(p, extra_laws=("rigid",))
    add_forcing(p)
    p.add_argument(
        "--method",
        choices=METHODS,
        default="closed-form",
        help="closed-form: the symmetric two-impact orbits of the rigid law (Masri & Caughey), "
        "Eq. F3; default closed-form",
    )
    add_output(p)


def run(ns) -> None:
    from ..display import display_unit, shown
    from ..errors import MethodNotApplicable, ParameterError
    from ..forced import periodic_orbits

    if ns.contact != "rigid":
        raise MethodNotApplicable(
            ns.method,
            f"contact {ns.contact!r}: the closed form holds for rigid impacts "
            "(--contact rigid --e E)",
        )
    if ns.e is None:
        raise ParameterError("e", "contact rigid needs Newton's coefficient of restitution --e")
    system = system_from(ns)
    forcing = forcing_from(ns)
    orbits = periodic_orbits(system, forcing, ns.e)
    out = [o.as_dict() for o in orbits]
    if not orbits:
        text = (
            f"Ω {forcing.omega:.6g} rad/s: no symmetric two-impact orbit (the phase condition "
            "a·cos φ + b·sin φ = c has no solution)"
        )
    else:
        lines = [f"Ω {forcing.omega:.6g} rad/s: {len(orbits)} symmetric two-impact orbit(s)"]
        unit = display_unit("x")  # the amplitude is a displacement of the main mass
        lines.append(
            f"impact phase [rad]  amplitude [{unit}]  impact speed [m/s]  admissible  stable  "
            "largest |multiplier|"
        )
        for o in orbits:
            lines.append(
                f"{o.impact_phase:18.6f}  {shown('x', o.amplitude):14.6g}  {o.impact_speed:18.6g}  "
                f"{'yes' if o.admissible else 'no':>10}  {'yes' if o.stable else 'no':>6}  "
                f"{o.multipliers[0]:.6g}"
            )
        text = "\n".join(lines)
    emit(ns, out, text)


#: The subcommands this module runs.
COMMANDS = {"periodic": run}
