"""``symimpact periodic``: the periodic motions of the forced impact damper at one frequency —
the symmetric two-impact orbits in closed form (Eq. F3), or the orbit a brute-force run settles
near, found by shooting (Newton on the stroboscopic map, monodromy through Step 8's flights and
Step 9's saltation matrices, or through a compliant contact's variational equations) — each with
its amplitude, impact speed, admissibility and stability."""

from __future__ import annotations

from typing import Any

from .. import budgets
from .common import (
    add_forcing,
    add_output,
    add_system,
    emit,
    forcing_from,
    structure_forcing,
    system_from,
)

#: The methods ``--method`` takes.
METHODS = ("closed-form", "shooting", "hb")


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "periodic",
        help="periodic motions of the forced damper at one frequency (closed form, Eq. F3, or "
        "shooting)",
        epilog=budgets.text(),
    )
    add_system(p, extra_laws=("rigid", "hunt-crossley"))
    add_forcing(p)
    p.add_argument(
        "--method",
        choices=METHODS,
        default=None,
        help="closed-form: the symmetric two-impact orbits of the rigid law (Masri & Caughey), "
        "Eq. F3; shooting: the orbit a run from rest settles near, by Newton on the "
        "stroboscopic map (any impacting orbit, subharmonics with --multiple); hb: harmonic "
        "balance of a compliant contact from the same start (--harmonics, --time-samples), "
        "beside the shooting orbit; default closed-form (shooting for a --structure file with "
        "dampers or stops)",
    )
    g = p.add_argument_group("shooting")
    g.add_argument(
        "--chi",
        default=None,
        metavar="Q",
        help="Hunt–Crossley damping χ [s/m] of --contact hunt-crossley (Eq. F4)",
    )
    g.add_argument(
        "--warmup",
        default=None,
        metavar="N",
        help="forcing periods simulated from rest before Newton starts; default 300",
    )
    g.add_argument(
        "--multiple",
        default=None,
        metavar="K",
        help="look for an orbit of K forcing periods (K > 1: a subharmonic); default 1",
    )
    g = p.add_argument_group("harmonic balance (--method hb)")
    g.add_argument(
        "--harmonics",
        default=None,
        metavar="H",
        help="harmonics of the balance (of Ω/K with --multiple K); default 15",
    )
    g.add_argument(
        "--time-samples",
        default=None,
        metavar="N",
        help="time samples a period of the alternating frequency–time scheme, at least 2H + 1; "
        "default 4H",
    )
    p.add_argument(
        "--response",
        default=None,
        metavar="NAME",
        help="also each orbit's relative-displacement, acceleration (between impacts), force "
        "(into the base) or transmissibility, as frf --response",
    )
    add_output(p)


def _with_response(ns, rows: list[dict], orbits: list, starts: list, system, forcing, e) -> str:
    """Each orbit's ``--response`` (SI) added to its JSON row under the response's name; the
    text line that states them ('' without --response).  ``starts``: each orbit's (state at
    t = 0, forcing phase, periods)."""
    if ns.response is None:
        return ""
    from ..forced.responses import checked_response, orbit_response
    from .frf import response_text

    name = checked_response(ns.response, forcing)
    values = [orbit_response(name, system, forcing.at(forcing.omega, phase), e, state, k)
              for state, phase, k in starts]  # fmt: skip
    for row, v in zip(rows, values, strict=True):
        row[name.replace("-", "_")] = v
    return f"{name}: " + ", ".join(response_text(name, v) for v in values)


def run(ns) -> None:
    from ..errors import MethodNotApplicable, ParameterError
    from ..forced import periodic_orbits
    from ..model.display import display_unit, omega_text, shown
    from .frf import contact_of

    if getattr(ns, "structure_model", None) is not None:
        return _structure_orbit(ns)
    if ns.method is None:
        ns.method = "closed-form"
    if ns.response is not None:  # refused before any orbit is computed
        from ..forced.responses import checked_response

        rigid = ns.contact in (None, "rigid")
        checked_response(ns.response, forcing_from(ns), rigid=rigid)
    for key, flag in (("harmonics", "harmonics"), ("time_samples", "time-samples")):
        if ns.method != "hb" and getattr(ns, key) is not None:
            raise ParameterError(flag, "applies to --method hb")
    if ns.method == "shooting":
        e = contact_of(ns)
        return _shooting(ns, system_from(ns), forcing_from(ns), e)
    if ns.method == "hb":
        if ns.response is not None:
            raise ParameterError("response", "applies to --method closed-form or shooting")
        return _balance(ns, system_from(ns), forcing_from(ns), contact_of(ns))
    if ns.contact != "rigid":
        raise MethodNotApplicable(
            ns.method,
            f"contact {ns.contact!r}: the closed form holds for rigid impacts "
            "(--contact rigid --e E); --method shooting takes the compliant laws",
        )
    if ns.e is None:
        raise ParameterError("e", "contact rigid needs Newton's coefficient of restitution --e")
    system = system_from(ns)
    forcing = forcing_from(ns)
    for key in ("warmup", "multiple", "chi"):
        if getattr(ns, key) is not None:
            raise ParameterError(key, "applies to --method shooting")
    orbits = periodic_orbits(system, forcing, ns.e)
    out = [o.as_dict() for o in orbits]
    # t = 0 at the impact on the wall +d/2: the state just after it
    starts = [((o.X, o.V, system.gap / 2.0, o.U), o.impact_phase, 1) for o in orbits]
    extra = _with_response(ns, out, orbits, starts, system, forcing, ns.e)
    if not orbits:
        text = (
            f"Ω {omega_text(forcing.omega)}: no symmetric two-impact orbit (the phase condition "
            "a·cos φ + b·sin φ = c has no solution)"
        )
    else:
        lines = [f"Ω {omega_text(forcing.omega)}: {len(orbits)} symmetric two-impact orbit(s)"]
        unit = display_unit("x")  # the amplitude is a displacement of the main mass
        lines.append(
            f"impact phase [rad]  amplitude [{unit}]  impact speed [m/s]  admissible  stable  "
            f"largest |multiplier|  ∂A/∂d [1]  ∂A/∂e [{unit}]"
        )
        for o in orbits:
            lines.append(
                f"{o.impact_phase:18.6f}  {shown('x', o.amplitude):14.6g}  {o.impact_speed:18.6g}  "
                f"{'yes' if o.admissible else 'no':>10}  {'yes' if o.stable else 'no':>6}  "
                f"{o.multipliers[0]:20.6g}  {o.amplitude_slope_gap:9.4g}  "
                f"{shown('x', o.amplitude_slope_e):.4g}"
            )
        text = "\n".join(lines + ([extra] if extra else []))
    emit(ns, out, text)


def _shooting(ns, system, forcing, e) -> None:
    """--method shooting: one orbit, the closed form's JSON keys and the shooting's own, for
    rigid impacts or a compliant contact ``e``."""
    from ..errors import ParameterError
    from ..forced import shoot_from_rest
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..model.display import display_unit, impacts_text, omega_text, shown

    warmup = period_count("warmup", "300" if ns.warmup is None else ns.warmup)
    multiple = period_count("multiple", "1" if ns.multiple is None else ns.multiple)
    if not 1 <= multiple <= MAX_MULTIPLE:
        raise ParameterError("multiple", f"must be 1 to {MAX_MULTIPLE}, got {multiple}")
    o = shoot_from_rest(system, forcing, e, warmup=warmup, periods=multiple)
    out = [o.as_dict()]
    extra = _with_response(ns, out, [o], [(o.state, forcing.phase, multiple)], system, forcing, e)
    unit = display_unit("x")
    text = (
        f"Ω {omega_text(forcing.omega)}: an orbit of {multiple} forcing period(s) by shooting "
        f"({o.iterations} Newton steps, residual {o.residual:.1e}): amplitude "
        f"{shown('x', o.amplitude):.6g} {unit}, "
        f"{impacts_text(o.impacts_per_period, o.impact_events_per_period)}, "
        f"{'stable' if o.stable else 'unstable'} (largest |multiplier| {o.multipliers[0]:.6g})"
    ) + (f"\n{extra}" if extra else "")
    emit(ns, out, text)


def _balance(ns, system, forcing, e) -> None:
    """--method hb: the orbit by harmonic balance (:func:`symimpact.forced.orbits.
    harmonic_balance.hb_orbit`) from the attractor a run from rest settles on, and beside it the
    exact orbit by shooting from the same run, with the balance's error in amplitude."""
    import numpy as np

    from ..errors import ParameterError
    from ..forced import shoot_from_rest
    from ..forced.orbits.harmonic_balance import hb_orbit
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..model.display import display_unit, omega_text, shown
    from .common import harmonics_of

    if ns.warmup is not None:
        raise ParameterError("warmup", "applies to --method shooting (the balance starts from "
                             "300 periods from rest)")  # fmt: skip
    multiple = period_count("multiple", "1" if ns.multiple is None else ns.multiple)
    if not 1 <= multiple <= MAX_MULTIPLE:
        raise ParameterError("multiple", f"must be 1 to {MAX_MULTIPLE}, got {multiple}")
    H, N = harmonics_of(ns, system, forcing, e, multiple)
    o = hb_orbit(system, forcing, e, harmonics=H, time_samples=N, subharmonic=multiple)
    exact = shoot_from_rest(system, forcing, e, periods=multiple)
    error = (o.amplitude - exact.amplitude) / exact.amplitude
    out = o.as_dict() | {"exact": exact.as_dict(), "hb_error": error}
    unit = display_unit("x")
    k = np.arange(1, o.harmonics + 1)
    size = np.hypot(np.array(o.x[1::2]), np.array(o.x[2::2]))
    top = k[np.argsort(-size, kind="stable")][:4]
    text = (
        f"Ω {omega_text(forcing.omega)}: an orbit of {multiple} forcing period(s) by harmonic "
        f"balance (H = {o.harmonics}, N = {o.samples}; {o.iterations} Newton steps, residual "
        f"{o.residual:.1e}): amplitude {shown('x', o.amplitude):.6g} {unit}, "
        f"{'stable' if o.stable else 'unstable'} by Hill's method (largest |multiplier| "
        f"{o.multipliers[0]:.6g})\n"
        f"shooting, the exact orbit: amplitude {shown('x', exact.amplitude):.6g} {unit}, "
        f"{'stable' if exact.stable else 'unstable'} (largest |multiplier| "
        f"{exact.multipliers[0]:.6g}); the balance's amplitude error {100 * error:+.3g} %\n"
        "largest harmonics of x: "
        + ", ".join(f"{j}: {shown('x', size[j - 1]):.4g} {unit}" for j in top)
        + ("" if o.stable == exact.stable else
           "\nnote: the balance and shooting disagree on stability; Hill's method sorts the "
           "exponents of a truncated balance and can keep a spurious one: shooting's is exact")
    )  # fmt: skip
    emit(ns, out, text)


def _structure_orbit(ns) -> None:
    """A structure file with dampers or stops: the orbit a run from rest settles near, by
    shooting on the state of its N modes and K dampers (:func:`symimpact.forced.orbits.structure_orbits.
    shoot_structure`: the monodromy carried through every flight, impact and contact)."""
    import numpy as np

    from ..errors import ParameterError
    from ..forced.orbits.structure_orbits import shoot_structure
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..forced.structure_response import simulate_structure
    from ..model.display import omega_text
    from .common import quantity_text

    if ns.method == "closed-form":
        raise ParameterError("method", "closed-form is the one-mode primary's: a structure's "
                                       "orbits are found by --method shooting or hb")  # fmt: skip
    for key, why in (("response", "the responses of a structure's orbit are not built yet: "
                                  "--json gives every point's amplitude"),
                     ("chi", "the file gives each damper's and stop's contact")):  # fmt: skip
        if getattr(ns, key, None) is not None:
            raise ParameterError(key, why)
    model = ns.structure_model
    forcing = structure_forcing(ns)
    if ns.method == "hb":
        _structure_balance_checks(ns, model, forcing)
    elif ns.harmonics is not None or ns.time_samples is not None:
        raise ParameterError("harmonics" if ns.harmonics is not None else "time-samples",
                             "applies to --method hb")  # fmt: skip
    warmup = period_count("warmup", "300" if ns.warmup is None else ns.warmup)
    multiple = period_count("multiple", "1" if ns.multiple is None else ns.multiple)
    if not 1 <= multiple <= MAX_MULTIPLE:
        raise ParameterError("multiple", f"must be 1 to {MAX_MULTIPLE}, got {multiple}")
    args = (model.structure, model.dampers, model.force_at, model.F0, forcing.omega)
    X_b = model.base_at(forcing.omega)
    settled = simulate_structure(*args, periods=warmup, phase=forcing.phase, stops=model.stops,
                                 base=X_b)  # fmt: skip
    n = 2 * len(model.structure.modes) + 2 * len(model.dampers)
    start = settled.final_state[1 : 1 + n]
    try:
        o = shoot_structure(*args, start, multiple, model.stops, forcing.phase, base=X_b)
    except ParameterError as exc:  # Newton's start, named for the options that set it
        returns = []
        for k in range(1, 9):  # how near the settled motion comes back within 8 periods
            back = simulate_structure(*args, periods=k, phase=forcing.phase, state=start,
                                      stops=model.stops, base=X_b).final_state[1 : 1 + n]  # fmt: skip
            returns.append(float(np.max(np.abs(back - start)) / np.max(np.abs(start))))
        k = 1 + int(np.argmin(returns))
        raise ParameterError("multiple", f"no orbit of {multiple} period(s) near the state after "
                             f"--warmup {warmup} periods (Newton's method: {exc.reason}); that "
                             f"motion comes back nearest after {k} period(s) (to "
                             f"{returns[k - 1]:.1e} of the state): try --multiple {k}, or a "
                             "longer --warmup if it is still settling") from None  # fmt: skip
    big = max(abs(m) for m in o.multipliers)
    text = (
        f"Ω {omega_text(forcing.omega)}: an orbit of {multiple} forcing period(s) of the "
        f"{len(model.structure.modes)}-mode structure by shooting from {warmup} periods from rest "
        f"({o.iterations} Newton steps, residual {o.residual:.1e}"
        + (", Jacobian by central differences: the section falls where a mass rests on its "
           "wall, or the orbit sticks beside stops, lets a stuck mass go at an impact or has "
           "e(v)" if o.jacobian == "differenced" else "")
        + f"), {'stable' if o.stable else 'unstable'} (largest |multiplier| {big:.6g})\n"
        + "".join(f"{name}: {count} {'contacts' if name in {s.name for s in model.stops} else 'impacts'}"
                  f" in the orbit"
                  + (f" ({o.impact_events[name]} with each chatter sequence counted once)"
                     if o.impact_events[name] != count else "")
                  + "\n" for name, count in o.impacts.items())
        + "\n".join(f"amplitude at {p!r}: {quantity_text('x', a)}"
                    for p, a in o.amplitudes.items())
    )  # fmt: skip
    out = o.as_dict()
    if ns.method == "hb":
        from ..forced.orbits.hb_structure import hb_structure_orbit
        from .common import harmonic_counts

        H, N = harmonic_counts(ns)
        if N is not None and N < 2 * H + 1:
            raise ParameterError("time-samples", f"must be at least 2H + 1 = {2 * H + 1} for H = "
                                 f"{H} harmonics (fewer samples alias the series itself)")  # fmt: skip
        hb = hb_structure_orbit(model.structure, model.dampers, model.force_at, model.F0,
                                forcing.omega, harmonics=H, time_samples=N,
                                phase=forcing.phase)  # fmt: skip
        errors = {p: (hb.amplitudes[p] - a) / a for p, a in o.amplitudes.items() if a > 0}
        out = hb.as_dict() | {"exact": out, "hb_error": errors}
        text = (
            f"Ω {omega_text(forcing.omega)}: the {len(model.structure.modes)}-mode structure's "
            f"orbit by harmonic balance (H = {hb.harmonics}, N = {hb.samples}; {hb.iterations} "
            f"Newton steps), {'stable' if hb.stable else 'unstable'} by Hill's method (largest "
            f"|multiplier| {hb.multipliers[0]:.6g}); beside it shooting's exact orbit, "
            f"{'stable' if o.stable else 'unstable'} (largest |multiplier| {big:.6g})\n"
            + "\n".join(f"amplitude at {p!r}: {quantity_text('x', hb.amplitudes[p])} by the "
                        f"balance, {quantity_text('x', a)} exact: error {100 * errors[p]:+.3g} %"
                        for p, a in o.amplitudes.items() if p in errors)
            + ("" if hb.stable == o.stable else
               "\nnote: the balance and shooting disagree on stability; Hill's method sorts "
               "the exponents of a truncated balance and can keep a spurious one: shooting's "
               "is exact")
        )  # fmt: skip
    emit(ns, out, text)


def _structure_balance_checks(ns, model, forcing) -> None:
    """What the structure's balance does not take, refused in one line: stops, base motion,
    an orbit of several periods, and (in the balance itself) rigid dampers."""
    from ..errors import ParameterError

    if model.stops:
        raise ParameterError("method", "hb balances a structure's compliant dampers, not its "
                             "stops: --method shooting finds that orbit")  # fmt: skip
    if model.base_at(forcing.omega) != 0.0:
        raise ParameterError("method", "hb balances a force on the structure, not base motion: "
                             "--method shooting finds that orbit")  # fmt: skip
    rigid = [d.name for d in model.dampers if d.rigid]
    if rigid:
        raise ParameterError("method", f"hb needs a compliant contact law; damper {rigid[0]!r} "
                             "has rigid impacts, which have no force to balance: --method "
                             "shooting finds that orbit")  # fmt: skip
    if ns.multiple not in (None, "1", 1):
        raise ParameterError("multiple", "a structure's balance is of one forcing period: "
                             "--method shooting finds orbits of several")  # fmt: skip


#: The subcommands this module runs.
COMMANDS = {"periodic": run}
