"""What the subcommands share: the option groups (system, initial state, output, --show),
building the system from them, and writing results (text in display units, JSON, CSV)."""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from typing import Any

from ..model.display import csv_header, display_unit, shown

#: The defaults are one stated system in which impacts happen and DI is defined: the report's
#: reading of the paper's Table 2 (K in N/m, c1 = 5C = 5 N s/m, Ẋ0 = 0.5 m/s, t' = t·√(K/M) = 200).
SYSTEM_OPTIONS = [
    ("--M", "main mass M [kg]", "1 kg"),
    ("--K", "main stiffness K [N/m]", "100 N/m"),
    ("--C", "main damping C [N s/m] (or --zeta)", "1 N s/m"),
    ("--zeta", "damping ratio ζ = C/(2√(KM)) [1], instead of --C", None),
    ("--q-factor", "quality factor Q = 1/(2ζ) [1] of the primary alone, instead of --C", None),
    (
        "--loss-factor",
        "loss factor η = 2ζ [1] (at resonance, of viscous damping), instead of --C",
        None,
    ),
    ("--m", "impact mass m [kg]", "0.25 kg"),
    (
        "--fn",
        "natural frequency of the primary f_n [Hz] (or rad/s, rpm): with --M, K = M(2πf_n)²; "
        "with --K, M = K/(2πf_n)²",
        None,
    ),
    ("--gap", "total clearance d [m]: the free play, contact at |y − x| = d/2", "9 mm"),
    ("--a", "cubic coefficient a [N/m^3] (Eq. 9)", "0.1553 N/cm^3"),
    ("--b", "cubic coefficient b [N/m] (Eq. 9)", "0.8360 N/cm"),
    (
        "--k-hz",
        "Hertz stiffness K_Hz [N/m^1.5] (Eq. 8; the default is the paper's resilient, "
        "rubber-like contact — steel on steel is ~1e10: see --cavity)",
        "1000 N/m^1.5",
    ),
    ("--k1", "linear contact stiffness k1 [N/m] (Eq. 35); default fitted to K_Hz", None),
    ("--c1", "contact damping c1 [N s/m] (Eq. 10)", "5 N s/m"),
]


class Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, status 2, no usage dump
        self.exit(2, f"{self.prog}: error: {message}\n")


#: The compliant contact laws every command with --contact takes; commands add their own.
COMPLIANT_LAWS = ("cubic", "hertz", "linear", "perturbation")


def add_system(
    p: argparse.ArgumentParser,
    contact: bool = True,
    extra_laws: tuple[str, ...] = (),
    contact_default: str | None = "cubic",
) -> None:
    """The system options (SYSTEM_OPTIONS; with ``contact``, --contact too, taking the compliant
    laws and ``extra_laws``; ``contact_default`` None leaves the choice to the command)."""
    g = p.add_argument_group("system (SI numbers or quantities with units)")
    for flag, helptext, default in SYSTEM_OPTIONS:
        g.add_argument(
            flag,
            dest=flag[2:].replace("-", "_"),
            default=None if flag == "--C" else default,  # --zeta replaces the default C
            metavar="Q",
            help=f"{helptext}; default {default!r}" if default else helptext,
        )
    g.add_argument("--system", default=None, metavar="FILE",
                   help="the system's parameters from a file (TOML or JSON, keys named as these "
                   "options: e.g. one 'symimpact identify ... --out' wrote); an option typed on "
                   "the command line wins over the file")  # fmt: skip
    g.add_argument("--structure", default=None, metavar="FILE",
                   help="the primary as one mode of a structure file (JSON or TOML: a beam, modal "
                   "data or a finite-element model with named points; see 'symimpact modes "
                   "--structure'), referred to the damper's point --at: gives M, K and ζ "
                   "instead of --M, --K, --C (Step 15); a file that also lists \"dampers\" and "
                   "a \"force\" is the whole model of several modes, which 'simulate' runs")  # fmt: skip
    g.add_argument("--at", default=None, metavar="POINT",
                   help="with --structure: the named point the damper sits at (default: the "
                   "file's only point)")  # fmt: skip
    g.add_argument("--mode", default=None, type=int, metavar="I",
                   help="with --structure: which mode is the primary (default 1, the lowest)")  # fmt: skip
    g.add_argument("--impactor", default=None, metavar="TEXT",
                   help="the ball, '<material> sphere <diameter or mass>' (e.g. 'steel sphere 20 "
                   "mm', 'steel sphere 2 kg'): gives m instead of --m (Step 13)")  # fmt: skip
    g.add_argument("--cavity", default=None, metavar="TEXT",
                   help="with --impactor: the surface it strikes ('steel flat', 'polyurethane "
                   "flat', 'steel spherical cavity 30 mm'): gives K_Hz instead of --k-hz, and at "
                   "--impact-speed the material's e, χ and c1 (see 'symimpact contact')")  # fmt: skip
    g.add_argument("--impact-speed", default=None, metavar="Q",
                   help="the impact speed [m/s] at which --cavity's material law gives e (rigid), "
                   "χ (hunt-crossley) or c1 (compliant laws)")  # fmt: skip
    if contact:
        g.add_argument(
            "--contact",
            choices=COMPLIANT_LAWS + extra_laws,
            default=contact_default,
            help="contact law integrated numerically, or the perturbation solution (Eq. 31–33)"
            + (
                "; rigid: instantaneous impacts with Newton's e (Eq. F2)"
                if "rigid" in extra_laws
                else ""
            )
            + (
                "; hunt-crossley: K_Hz·δ^1.5·(1 + χ·δ̇) with --chi (Eq. F4)"
                if "hunt-crossley" in extra_laws
                else ""
            )
            + ("; default cubic" if contact_default == "cubic" else ""),
        )


def system_from(ns: argparse.Namespace):
    """The :class:`~symimpact.model.system.ImpactSystem` the system options describe."""
    from ..model.system import ImpactSystem

    law = getattr(ns, "contact", None) or "cubic"
    kw: dict[str, Any] = {
        k: getattr(ns, k) for k in ("M", "K", "C", "zeta", "m", "gap", "k_hz", "k1", "c1")
    }
    if kw["C"] is None and kw["zeta"] is None:
        kw["C"] = dict((f, d) for f, _, d in SYSTEM_OPTIONS)["--C"]
    # the rigid law takes M, K, C, m and d from the system; its compliant law is not used.
    # Hunt–Crossley's elastic part is Hertz's (k_hz)
    law = {"perturbation": "cubic", "rigid": "cubic", "hunt-crossley": "hertz"}.get(law, law)
    if getattr(ns, "delta_max", None) is not None:  # set by --cavity: the fits cover the impact
        kw["delta_max"] = ns.delta_max
    return ImpactSystem(contact=law, a=ns.a, b=ns.b, **kw)


#: Options a command takes with the system group but does not use: (command, option) → why.
UNUSED = {
    ("design", "gap"): "design sweeps the clearance: give --gaps, not --gap",
    ("contact-duration", "gap"): "one contact's duration does not depend on the clearance",
}


#: The keys a --system file may hold: the system's options and the contact's.
SYSTEM_KEYS = (*(f[2:].replace("-", "_") for f, _, _ in SYSTEM_OPTIONS), "contact", "e", "chi",
               "impactor", "cavity", "impact_speed")  # fmt: skip
#: Options that say one thing in several ways: one typed on the command line replaces the
#: file's whole group (``--q-factor 50`` with a file's ``zeta``).
_ALTERNATIVES = (("C", "zeta", "q_factor", "loss_factor"),)


def _system_table(path: Any) -> dict[str, Any]:
    """The table a --system file holds (TOML by its suffix .toml, else JSON), refused in one
    line if it is neither or not a table."""
    import tomllib

    from ..errors import ParameterError
    from ..io import input_text, strict_json

    text = input_text(path, "system")
    if str(path).lower().endswith(".toml"):
        try:
            data: Any = tomllib.loads(text)
        except tomllib.TOMLDecodeError as err:
            raise ParameterError("system", f"{str(path)!r} is not TOML ({err})") from None
    else:
        data = strict_json(text, "system", str(path))
    if not isinstance(data, dict):
        raise ParameterError("system", f"{str(path)!r} must hold a table of parameters")
    return data


def read_system_file(path: Any) -> dict[str, Any]:
    """{key: value} of a --system file (:func:`_system_table`): keys of :data:`SYSTEM_KEYS`
    (hyphens or underscores), values numbers (SI) or quantity strings."""
    from ..errors import ParameterError

    data = _system_table(path)
    out: dict[str, Any] = {}
    for key, value in data.items():
        if key == "uncertainty":  # the fitted parameters' covariance (read_uncertainty)
            continue
        name = str(key).replace("-", "_")
        if name not in SYSTEM_KEYS:
            raise ParameterError("system", f"{key!r} in {str(path)!r} is not a system parameter "
                                 f"(one of {', '.join(SYSTEM_KEYS)})")  # fmt: skip
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            raise ParameterError("system", f"{key!r} in {str(path)!r} must be a number (SI) or a "
                                 "quantity with units")  # fmt: skip
        out[name] = value
    return out


def read_uncertainty(path: Any) -> dict[str, Any] | None:
    """The ``[uncertainty]`` table of a --system file ('symimpact identify decay --out' writes
    it): ``names`` (system keys), ``values`` and ``covariance`` (SI) of the fitted parameters,
    checked (a symmetric covariance with a non-negative diagonal); None if the file has none."""
    import numpy as np

    from ..errors import ParameterError

    table = _system_table(path).get("uncertainty")
    if table is None:
        return None
    try:
        names = [str(n) for n in table["names"]]
        values = np.array(table["values"], dtype=float)
        cov = np.array(table["covariance"], dtype=float)
    except (KeyError, TypeError, ValueError):
        raise ParameterError("system", f"{str(path)!r}: [uncertainty] needs names, values and "
                             "covariance (numbers, SI)") from None  # fmt: skip
    k = len(names)
    if (
        any(n not in SYSTEM_KEYS for n in names)
        or values.shape != (k,)
        or cov.shape != (k, k)
        or not np.all(np.isfinite(cov))
        or not np.allclose(cov, cov.T, rtol=1e-9, atol=0.0)
        or np.any(np.diag(cov) < 0)
    ):
        raise ParameterError("system", f"{str(path)!r}: [uncertainty] must name system "
                             "parameters with one value each and a symmetric k × k covariance")  # fmt: skip
    return {"names": names, "values": values, "covariance": cov}


def apply_system_file(ns: argparse.Namespace, given: set[str]) -> None:
    """--system FILE: its parameters in ``ns`` where the command takes them and the command
    line (``given``) does not already say them; each taken is added to ``given``, so the
    checks that follow read it as typed."""
    path = getattr(ns, "system", None)
    if path is None:
        return
    values = read_system_file(path)
    taken = []
    for key, value in values.items():
        if not hasattr(ns, key) or key in given or (ns.command, key) in UNUSED:
            continue
        if key in ("e", "chi") and getattr(ns, key) is not None:  # typed (their default is None)
            continue
        if any(key in group and given & set(group) for group in _ALTERNATIVES):
            continue
        setattr(ns, key, value if isinstance(value, str) else repr(value))
        given.add(key)
        taken.append(key)
    ns.system_taken = taken  # the keys the file gave (its uncertainty applies to these only)


def apply_engineer_inputs(ns: argparse.Namespace, given: set[str]) -> None:
    """--fn (with --M or --K) in place of K or M, and refusals of options the command does not
    use (``given``: the options the user typed)."""
    import math

    from ..errors import ParameterError
    from ..model.units import positive_float

    for (command, option), why in UNUSED.items():
        if ns.command == command and option in given:
            raise ParameterError(option.replace("_", "-"), why)
    sine_amplitudes(ns)
    # the system options' --structure (``modes --structure`` only lists a structure: no --at)
    if getattr(ns, "structure", None) is not None and hasattr(ns, "at"):
        from ..model.structure_model import has_loads

        if has_loads(ns.structure) and ns.command in ONE_MODE_ONLY:
            raise ParameterError(
                "structure", f"{ns.structure} gives dampers, stops or loads, and {ns.command} "
                "does not run a structure of several modes: give --at POINT and --mode I with "
                "the damper's options (one mode of a file without them, its participation "
                "carried), or run simulate, periodic, frf, branch or design on this file")  # fmt: skip
        if has_loads(ns.structure):
            _structure_model(ns, given)
        else:
            _structure_mode(ns, given)
        return
    for option in ("at", "mode"):
        if option in given and hasattr(ns, "at"):
            raise ParameterError(option, "names a point or mode of --structure, which is not given")
    _damping_as_zeta(ns, given)
    if getattr(ns, "fn", None) is None:
        return
    f = positive_float("fn", ns.fn, "Hz")
    w2 = (2.0 * math.pi * f) ** 2
    if "K" in given and "M" in given:
        raise ParameterError("fn", "give --fn with --M (modal mass) or with --K, not both")
    if "K" in given:
        ns.M = positive_float("K", ns.K, "N/m") / w2
    elif "M" in given:
        ns.K = positive_float("M", ns.M, "kg") * w2
    else:
        raise ParameterError("fn", "give the modal mass --M (or the stiffness --K) with --fn")


#: A sine's amplitude option: (its flag, its SI unit).
_SINES = {"F0": ("force", "N"), "X_b": ("base", "m"), "V_b": ("base-vel", "m/s"),
          "A_b": ("base-acc", "m/s^2")}  # fmt: skip
#: How a sine's level is quoted, and the factor to its amplitude (peak): rms·√2, peak-to-peak/2.
_QUOTED = {"rms": math.sqrt(2.0), "peak": 1.0, "pk": 1.0, "pk-pk": 0.5, "peak-to-peak": 0.5}


def sine_amplitudes(ns: argparse.Namespace) -> None:
    """--force, --base, --base-vel and --base-acc as a test engineer quotes a sine: a level
    followed by "rms", "peak" (or "pk") or "pk-pk" (or "peak-to-peak"), e.g. "35.36 N rms" or
    "2 mm pk-pk", read as the amplitude of F0·cos(Ωt) (X_b·cos(Ωt), …): rms·√2, peak-to-peak/2;
    stated on stderr in one line.  Without a word the level is the amplitude, as before."""
    import re

    from ..model.units import si_float

    for key, (flag, unit) in _SINES.items():
        text = getattr(ns, key, None)
        if not isinstance(text, str):
            continue
        found = re.fullmatch(r"(?P<level>.*?)\s+(?P<how>rms|peak-to-peak|pk-pk|peak|pk)\s*",
                             text, re.IGNORECASE)  # fmt: skip
        if found is None:
            continue
        how = found["how"].lower()
        level = si_float(flag, found["level"], unit)
        amplitude = level * _QUOTED[how]
        setattr(ns, key, amplitude)
        if how not in ("peak", "pk"):
            print(f"symimpact {ns.command}: --{flag} {text.strip()!r} is the amplitude "
                  f"{amplitude:.6g} {unit} of the sine", file=sys.stderr)  # fmt: skip


def _damping_as_zeta(ns: argparse.Namespace, given: set[str]) -> None:
    """--q-factor Q or --loss-factor η as the damping ratio of the primary alone: ζ = 1/(2Q),
    ζ = η/2 (viscous damping: the half-power bandwidth is 2ζ·f_n = f_n/Q, and the energy lost a
    cycle at resonance over 2π times the energy held is η = 2ζ).  One damping only."""
    from ..errors import ParameterError
    from ..model.units import nonnegative_float, positive_float

    dampings = [o for o in ("C", "zeta", "q_factor", "loss_factor") if o in given]
    if len(dampings) > 1:
        flags = ", ".join("--" + o.replace("_", "-") for o in dampings)
        raise ParameterError(
            dampings[1].replace("_", "-"), f"give the damping once (given: {flags})"
        )
    if "q_factor" in given:
        ns.zeta = 1.0 / (2.0 * positive_float("q-factor", ns.q_factor))
    elif "loss_factor" in given:
        ns.zeta = nonnegative_float("loss-factor", ns.loss_factor) / 2.0


#: The options a structure file with dampers and a force replaces: the primary, the damper, the
#: contact and the force amplitude.
_MODEL_GIVES = ("M", "K", "C", "zeta", "q_factor", "loss_factor", "fn", "m", "gap", "a", "b",
                "k_hz", "k1", "c1", "at", "mode", "impactor", "cavity", "impact_speed", "contact",
                "e", "chi", "F0", "X_b", "V_b", "A_b")  # fmt: skip


#: The commands that take one mode of a structure (--at, --mode) but not a file's dampers,
#: stops and loads: the sampled loads and the free-vibration maps.
ONE_MODE_ONLY = ("random", "shock", "sweep-sine", "sweep", "map")


def _structure_model(ns: argparse.Namespace, given: set[str]) -> None:
    """--structure with a file that gives dampers or stops and a force: the structure of several
    modes for :func:`symimpact.forced.structure_response.simulate_structure`
    (``ns.structure_model``), which ``simulate`` runs, ``periodic`` shoots, ``frf`` and
    ``branch`` continue and ``design`` sweeps."""
    from ..errors import ParameterError
    from ..model.structure_model import read_model

    flags = {"F0": "force", "X_b": "base", "V_b": "base-vel", "A_b": "base-acc"}
    for option in _MODEL_GIVES:
        # the forcing options have no default: given is not None
        if option in given or (option in ("e", "chi", *flags) and getattr(ns, option, None)
                               is not None):  # fmt: skip
            raise ParameterError(flags.get(option, option.replace("_", "-")), f"{ns.structure} "
                                 "gives the structure, its dampers (with their contact) and the "
                                 "force: leave it out")  # fmt: skip
    for option in ("x0", "xdot0", "y0", "ydot0"):
        if option in given:
            raise ParameterError(option, "a structure's run starts from rest")
    ns.structure_model = read_model(ns.structure)


def structure_forcing(ns: argparse.Namespace) -> Any:
    """The harmonic force of a structure file's model at --omega or --freq (and --phase): a
    :class:`~symimpact.forced.Forcing` (each refusal one line naming the option)."""
    from ..errors import ParameterError
    from ..forced import Forcing

    if ns.omega is None and ns.freq is None:
        raise ParameterError("omega", "give the forcing frequency: --omega Ω or --freq f")
    if ns.omega is not None and ns.freq is not None:
        raise ParameterError("omega", "give the forcing frequency once: --omega or --freq")
    return Forcing(F0=ns.structure_model.F0, omega=ns.omega, freq=ns.freq,
                   phase=0.0 if ns.phase is None else ns.phase)  # fmt: skip


def structure_band(ns: argparse.Namespace) -> tuple[float, float, float]:
    """(low, high, step) [rad/s] of --omega-range or --freq-range for a structure file's curve
    (each refusal one line naming the option)."""
    import numpy as np

    from ..errors import ParameterError
    from ..maps.points import parse_range

    if (ns.omega_range is None) == (ns.freq_range is None):
        raise ParameterError("omega-range", "give the band once: --omega-range or --freq-range")
    name = "omega-range" if ns.omega_range is not None else "freq-range"
    if ns.omega_range is not None:
        omegas = parse_range(name, ns.omega_range)
    else:
        omegas = 2 * np.pi * parse_range(name, ns.freq_range)
    if len(omegas) < 2 or omegas[0] <= 0:
        raise ParameterError(name, "the band needs at least two positive frequencies")
    return float(omegas[0]), float(omegas[-1]), float(omegas[1] - omegas[0])


def _structure_mode(ns: argparse.Namespace, given: set[str]) -> None:
    """--structure, --at and --mode: the primary as one mode of the structure referred to the
    damper's point a, M = Mᵢ/φᵢ(a)², K = ωᵢ²M, ζ = ζᵢ (Step 15: the displacement at a is the
    mode's coordinate; Eq. 5–6 for a beam)."""
    from ..errors import ParameterError
    from ..model.structure import read_structure

    for option in ("M", "K", "C", "zeta", "q_factor", "loss_factor", "fn"):
        if option in given:
            raise ParameterError(
                option.replace("_", "-"), "--structure gives the primary: leave it out"
            )
    s = read_structure(ns.structure)
    if ns.at is None:
        if len(s.points) > 1:
            raise ParameterError("at", f"name the damper's point ({', '.join(s.points)})")
        at = s.points[0]
    else:
        at = str(ns.at)
        if at not in s.points:
            raise ParameterError("at", f"no point {at!r} in {ns.structure} ({', '.join(s.points)})")
    i = 1 if ns.mode is None else ns.mode
    if not 1 <= i <= len(s.modes):
        raise ParameterError("mode", f"a mode from 1 to {len(s.modes)} of the structure, got {i}")
    mode = s.modes[i - 1]
    phi = mode.shape[at]
    if mode.node_at(at):
        raise ParameterError("at", f"mode {i} has a node at {at!r}: it does not move the damper "
                                   "(choose another point or mode)")  # fmt: skip
    ns.M = mode.mass / phi**2
    ns.K = mode.omega**2 * ns.M
    ns.zeta, ns.C = mode.zeta, None
    ns.reduced_base = (mode.participation * phi, i, at)  # for base_participation
    ns.reduced_structure = s  # for the whole structure's closed forms beside the reduction
    print(f"symimpact {ns.command}: the primary is mode {i} ({mode.frequency:.5g} Hz, ζ "
          f"{mode.zeta:.4g}) of the {s.source} model at {at!r}: M {ns.M:.6g} kg, K {ns.K:.6g} "
          "N/m", file=sys.stderr)  # fmt: skip


def base_participation(ns: argparse.Namespace) -> float:
    """Γφ(a) of a one-mode reduction (:func:`_structure_mode`) under base motion (Eq. F7 at the
    point a: M·ẍ + C·ẋ + K·x = −M·Γφ(a)·ẍ_b, the damper's mass −m·ẍ_b, where a primary on its
    base takes 1: a cantilever's first mode at its tip has 1.566, and runs had been 36 % low in
    displacement without a word), which the record engines carry and a harmonic forcing's
    ``inertia`` (Γφ − 1)·M (:class:`~symimpact.forced.Forcing`); stated on stderr where it is
    not 1.  1 for a primary on its base."""
    reduced = getattr(ns, "reduced_base", None)
    if reduced is None:
        return 1.0
    gp, i, at = reduced
    if abs(gp - 1.0) > 1e-9 and not getattr(ns, "quiet", False):
        print(f"symimpact {ns.command}: the supports drive mode {i} at {at!r} by its "
              f"participation Γφ = {gp:.4g} (Eq. F7): its load is −Γφ·M·a_b, the damper's "
              "−m·a_b", file=sys.stderr)  # fmt: skip
    return gp


def _material_restitution(ns: argparse.Namespace, body: Any, cavity: str, said: list) -> None:
    """``--e material``: e per impact from the materials (Step 13, Eq. F5), a
    :class:`~symimpact.forced.contact_law.MaterialRestitution` with the contact's yield speed;
    a constant where the law does not depend on the speed (a resilient material's √R, or no
    yield strength: elastic, e = 1)."""
    from ..forced.contact_law import MaterialRestitution
    from ..model.derived_contact import cavity_body, derived_contact

    contact = derived_contact(body, cavity, 1.0, M=ns.M)
    resilient = any(b.material.resilience is not None for b in (body, cavity_body(cavity)))
    if contact.yield_speed is None or resilient:
        ns.e = contact.e
        said.append(f"e {contact.e:.4g} at every impact speed ({contact.sources['e']})")
        return
    ns.e = MaterialRestitution(contact.yield_speed)
    said.append(
        f"e of the materials at each impact: 1 up to the yield speed {contact.yield_speed:.4g} "
        "m/s, Thornton's law above (Step 13)"
    )


def apply_materials(ns: argparse.Namespace, given: set[str]) -> None:
    """--impactor, --cavity and --impact-speed (Step 13, :mod:`symimpact.model.derived_contact`):
    replace m, K_Hz and, at the impact speed, the law's e, χ or c1 in ``ns`` (``given``: the
    options the user typed, which these may not contradict)."""
    from ..errors import ParameterError

    if ns.command == "contact":  # its own --impactor/--cavity: the derived contact is its output
        return
    imp = getattr(ns, "impactor", None)
    cav = getattr(ns, "cavity", None)
    speed = getattr(ns, "impact_speed", None)
    _thornton_restitution(ns)
    material_e = str(getattr(ns, "e", None)).strip().lower() == "material"
    # periodic's --method: closed-form unless named (a structure file shoots, but takes no --e)
    if (
        material_e
        and ns.command == "periodic"
        and getattr(ns, "method", None) in (None, "closed-form")
    ):
        raise ParameterError(
            "e", "material: the closed form (Eq. F3) needs a constant e; --method shooting "
            "follows the materials' e at each impact"
        )  # fmt: skip
    if material_e and (imp is None or cav is None):
        raise ParameterError(
            "e", "material: the restitution of the materials needs --impactor and --cavity"
        )
    if imp is None and cav is None and speed is None:
        return
    if imp is None:
        raise ParameterError("cavity" if cav is not None else "impact-speed", "needs --impactor")
    from ..model.derived_contact import derived_contact, impactor_body, sphere_mass

    for option, flag in (("m", "--m"), ("mass_ratios", "--mass-ratios")):
        if option in given:
            raise ParameterError(
                flag[2:], f"the impactor fixes m: give {flag} or --impactor, not both"
            )
    body = impactor_body(imp)
    ns.m = sphere_mass(body)
    said = [f"m {ns.m * 1e3:.5g} g ({imp})"]
    if cav is None:
        if speed is not None:
            raise ParameterError("impact-speed", "needs --cavity (the surface struck)")
        _say(ns, said)
        return
    for option, flag in (("k_hz", "--k-hz"), ("a", "--a"), ("b", "--b"), ("k1", "--k1")):
        if option in given:
            raise ParameterError(flag[2:], f"--cavity gives the contact: give {flag} or --cavity")
    law = getattr(ns, "contact", None) or "cubic"
    needs = []
    if material_e and law != "rigid":
        raise ParameterError("e", "material: applies to rigid impacts (--contact rigid)")
    if material_e:
        _material_restitution(ns, body, cav, said)
    elif law == "rigid" and getattr(ns, "e", None) is None:
        needs.append("e")
    elif law == "hunt-crossley" and getattr(ns, "chi", None) is None:
        needs.append("chi")
    elif law not in ("rigid", "hunt-crossley") and "c1" not in given:
        needs.append("c1")
    if needs and speed is None:
        raise ParameterError(
            "impact-speed", f"the materials give {needs[0]} at an impact speed: give "
            f"--impact-speed (e.g. '0.5 m/s') or --{needs[0]}"
        )  # fmt: skip
    contact = derived_contact(body, cav, 1.0 if speed is None else speed, M=ns.M)
    ns.k_hz, ns.a, ns.b, ns.k1 = contact.k_hz, None, None, None
    ns.delta_max = contact.max_penetration
    said.append(f"K_Hz {contact.k_hz:.5g} N/m^1.5 ({imp} on {cav})")
    at = f"e {contact.e:.4g} at {contact.v0:g} m/s ({contact.sources['e'].split(':')[0]})"
    if "e" in needs:
        ns.e = contact.e
        said.append(at)
    if "chi" in needs:
        ns.chi = contact.chi
        said.append(f"χ {contact.chi:.5g} s/m for {at}")
    if "c1" in needs:
        from ..free.contact import c1_for_restitution

        ns.c1 = 0.0
        system = system_from(ns)
        ns.c1 = 0.0 if contact.e >= 1.0 else c1_for_restitution(system, contact.e, speed)
        said.append(f"c1 {ns.c1:.5g} N s/m for {at}")
    _say(ns, said)


def _thornton_restitution(ns: argparse.Namespace) -> None:
    """``--e "thornton 0.05 m/s"``: Thornton's e per impact with a yield speed given (e.g. one
    'symimpact identify impacts' fitted), the law ``--e material`` takes from the materials
    (Step 13, Eq. F5): e = 1 up to the yield speed, T(v_y/v) above it."""
    import re

    from ..errors import ParameterError
    from ..model.units import positive_float

    found = re.fullmatch(r"\s*thornton\s+(?P<speed>\S.*?)\s*", str(getattr(ns, "e", None)), re.I)
    if found is None:
        return
    if ns.command == "periodic" and getattr(ns, "method", None) in (None, "closed-form"):
        raise ParameterError("e", "thornton: the closed form (Eq. F3) needs a constant e; "
                             "--method shooting follows e at each impact")  # fmt: skip
    if (getattr(ns, "contact", None) or "rigid") != "rigid":
        raise ParameterError("e", "thornton: applies to rigid impacts (--contact rigid)")
    from ..forced.contact_law import MaterialRestitution

    ns.e = MaterialRestitution(positive_float("e", found["speed"], "m/s"))


def _say(ns: argparse.Namespace, said: list[str]) -> None:
    """One line on stderr: what --impactor/--cavity put in place of the numbers."""
    print(f"symimpact {ns.command}: from the materials: {'; '.join(said)}", file=sys.stderr)


def add_initial(p: argparse.ArgumentParser, forced: bool = False) -> None:
    """The initial state and duration options (x0, xdot0, y0, ydot0, t_end).  With ``forced``
    the defaults of --xdot0 and --t-end are left to the command (None): a forced run starts at
    rest and lasts --periods forcing periods."""
    g = p.add_argument_group("initial state and duration")
    g.add_argument("--x0", default="0", metavar="Q", help="main-mass displacement [m]; default 0")
    g.add_argument(
        "--xdot0",
        default=None if forced else "0.5 m/s",
        metavar="Q",
        help="main-mass velocity [m/s]; default 0.5 m/s"
        + (" (free vibration) or 0 (forced)" if forced else ""),
    )
    g.add_argument("--y0", default="0", metavar="Q", help="impact-mass displacement [m]; default 0")
    g.add_argument(
        "--ydot0", default="0", metavar="Q", help="impact-mass velocity [m/s]; default 0"
    )
    g.add_argument(
        "--t-end",
        default=None if forced else "20 s",
        metavar="Q",
        help="end time [s]; default 20 s"
        + (" (forced runs use --periods instead)" if forced else ""),
    )


class _Once(argparse.Action):
    """An option that may be given once: a second value is refused, not silently kept."""

    def __call__(self, parser, namespace, values, option_string=None):
        if getattr(namespace, self.dest) is not None:
            parser.error(f"argument {option_string}: given twice")
        setattr(namespace, self.dest, values)


#: The refusal of a forcing without an amplitude.
AMPLITUDE_NEEDED = (
    "give the forcing amplitude: --force F0, or base motion --base X_b, --base-vel V_b or "
    "--base-acc A_b"
)


def add_forcing(p: argparse.ArgumentParser) -> None:
    """The harmonic forcing options (Eq. F1): --force F0 and/or --base X_b, at --omega Ω or
    --freq f, with --phase φ; each may be given once."""
    g = p.add_argument_group(
        "harmonic forcing F0·cos(Ωt + φ) and/or base motion X_b·cos(Ωt + φ) (Eq. F1)"
    )
    once = {"action": _Once, "default": None, "metavar": "Q"}
    g.add_argument("--force", dest="F0", help='force amplitude F0 on the main mass [N] ("35.4 N '
                   "rms\" is read as its amplitude, 50 N; so are 'peak' and 'pk-pk' levels)",
                   **once)  # fmt: skip
    g.add_argument(
        "--base", dest="X_b", help="base-motion amplitude X_b under the primary [m]", **once
    )
    g.add_argument(
        "--base-vel", dest="V_b", help="base velocity amplitude V_b [m/s] (X_b = V_b/Ω)", **once
    )
    g.add_argument(
        "--base-acc",
        dest="A_b",
        help='base acceleration amplitude A_b [m/s²] (X_b = A_b/Ω²); "0.5 g" is 0.5 standard '
        "gravity",
        **once,
    )
    g.add_argument("--omega", help="forcing frequency Ω [rad/s] (or --freq)", **once)
    g.add_argument("--freq", help="forcing frequency f [Hz], Ω = 2πf (or --omega)", **once)
    g.add_argument("--phase", help="forcing phase φ at t = 0 [rad]; default 0", **once)
    g.add_argument(
        "--e",
        help="Newton's coefficient of restitution of the rigid law, 0 ≤ e ≤ 1; 'material' with "
        "--impactor and --cavity: e of the materials at each impact's speed (Step 13); "
        "'thornton V': the same law with the yield speed V (e.g. from 'symimpact identify')",
        **once,
    )


def has_forcing(ns: argparse.Namespace) -> bool:
    """Whether any forcing option was given."""
    keys = ("F0", "X_b", "V_b", "A_b", "omega", "freq", "phase")
    return any(getattr(ns, k, None) is not None for k in keys)


def forcing_from(ns: argparse.Namespace):
    """The :class:`~symimpact.forced.Forcing` the forcing options describe."""
    from ..errors import ParameterError

    if all(getattr(ns, k, None) is None for k in ("F0", "X_b", "V_b", "A_b")):
        raise ParameterError("force", AMPLITUDE_NEEDED)
    if ns.omega is None and ns.freq is None:
        raise ParameterError("omega", "give the forcing frequency: --omega Ω or --freq f")
    if ns.omega is not None and ns.freq is not None:
        raise ParameterError("omega", "give the forcing frequency once: --omega or --freq")
    return forcing_of(ns, omega=ns.omega, freq=ns.freq, phase=0.0 if ns.phase is None else ns.phase)


def forcing_of(ns: argparse.Namespace, **frequency: Any):
    """The :class:`~symimpact.forced.Forcing` of --force/--base at ``frequency`` (omega or freq,
    and phase), a refusal naming the option the user typed."""
    from ..errors import ParameterError
    from ..forced import Forcing

    inertia = 0.0
    if any(getattr(ns, k, None) is not None for k in ("X_b", "V_b", "A_b")):
        # a mode reduced to a point, driven by its supports with Γφ: (Γφ − 1)·M more inertia
        if getattr(ns, "reduced_base", None) is not None:
            inertia = (base_participation(ns) - 1.0) * ns.M
    try:
        base = {k: getattr(ns, k) for k in ("V_b", "A_b") if getattr(ns, k, None) is not None}
        return Forcing(
            F0=0.0 if ns.F0 is None else ns.F0,
            X_b=0.0 if ns.X_b is None else ns.X_b,
            **base,
            **frequency,
            inertia=inertia,
        )
    except ParameterError as exc:
        flag = {"F0": "force", "X_b": "base", "V_b": "base-vel", "A_b": "base-acc"}.get(
            exc.parameter, exc.parameter
        )
        raise ParameterError(flag, exc.reason) from None


def add_show(p: Any) -> None:
    """--show NAME=UNIT: display units (:mod:`symimpact.model.display`)."""
    p.add_argument(
        "--show",
        action="append",
        default=[],
        metavar="NAME=UNIT",
        help="show a quantity in another unit in text and plots, e.g. --show gap=µm "
        "(defaults: mm for gaps and displacements, µm for DI, ms for durations; JSON and CSV "
        "stay SI)",
    )


def add_force(p: Any) -> None:
    """--force for a command that writes a folder (:func:`symimpact.io.staged_folder`)."""
    p.add_argument(
        "--force",
        action="store_true",
        help="replace a folder symimpact wrote before (never another non-empty folder)",
    )


def add_output(p: argparse.ArgumentParser, plot: bool = False) -> None:
    """--json and --show (with ``plot``: --plot and --csv too)."""
    p.add_argument("--json", action="store_true", help="machine-readable output on stdout (SI)")
    add_show(p)
    if plot:
        p.add_argument(
            "--plot", metavar="FILE.png", help="write a figure (a symbolic link: to its target)"
        )
        p.add_argument(
            "--csv", metavar="FILE", help="write a table (a symbolic link: to its target)"
        )


def emit(ns, data: dict[str, Any] | list[Any], text: str) -> None:
    """Print ``data`` as strict JSON (SI) with --json, else ``text``."""
    if ns.json:
        json.dump(jsonable(data), sys.stdout, indent=2, allow_nan=False)
        sys.stdout.write("\n")
    else:
        print(text)


#: Prose lines of a command's text are wrapped to this many columns: an 80-column terminal with
#: room, and the tutorial's code blocks, which fit 80 monospace characters in their 720 px column.
TEXT_WIDTH = 72


def wrapped(text: str, indent: str = "  ", width: int = TEXT_WIDTH) -> str:
    """``text`` as lines of at most ``width`` columns (:data:`TEXT_WIDTH`), the first indented
    by ``indent`` and the rest by two more spaces."""
    import textwrap

    return textwrap.fill(
        text, width, initial_indent=indent, subsequent_indent=indent + "  ",
        break_on_hyphens=False, break_long_words=False,
    )  # fmt: skip


def jsonable(v: Any) -> Any:
    """``v`` with NumPy values as Python ones and non-finite floats as None (JSON null)."""
    import numpy as np

    if isinstance(v, dict):
        return {str(k): jsonable(x) for k, x in v.items()}
    if isinstance(v, list | tuple):
        return [jsonable(x) for x in v]
    if isinstance(v, np.ndarray):
        return jsonable(v.tolist())
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def quantity_text(name: str, value: float) -> str:
    """``6 mm``-style text of an SI value in its display unit."""
    unit = display_unit(name)
    text = f"{shown(name, value):.6g}"
    return text if unit == "dimensionless" else f"{text} {unit}"


def fmt(v, spec: str) -> str:
    """A value for people: ``spec``-formatted, or "—" where it is missing (JSON has null)."""
    return "—" if v is None else format(v, spec)


def write_csv(path: str, what: str, rows: list[dict[str, Any]]) -> None:
    """``rows`` as CSV at ``path`` (atomically): SI values, SI units in the headers."""
    from ..io import atomic_write

    def write(f):  # SI values, each header with its SI unit ("gap [m]")
        names = list(rows[0]) if rows else []
        w = csv.writer(f)
        w.writerow([csv_header(n) for n in names])
        w.writerows([[r[n] for n in names] for r in jsonable(rows)])

    atomic_write(path, write, what)


def structure_rows(branches: Any, points: Any, settled: Any = (),
                   parameter: str = "omega") -> list[dict[str, Any]]:  # fmt: skip
    """The CSV of a structure's branches, SI (the JSON's numbers): one row an orbit (``kind``
    "orbit", its branch, period and stability) and one a run from rest of ``settled`` (``kind``
    "from rest", settled over its last periods, no period or stability), each with Ω, the
    ``parameter`` it is continued in (a branch in Ω: Ω alone) and the amplitude (largest
    abs(x)) at every named point."""
    rows = []
    for i, b in enumerate(branches):
        for o, v in zip(b.orbits, b.values, strict=True):
            along = {} if parameter == "omega" else {parameter: float(v)}
            rows.append({"kind": "orbit", "branch": i, "periods": o.periods,
                         "omega": o.run.omega, **along, "stable": bool(o.stable),
                         **{f"amplitude at {p} [m]": o.amplitudes[p] for p in points}})  # fmt: skip
    for r in settled:
        rows.append({"kind": "from rest", "branch": "", "periods": "", "omega": r["omega"],
                     "stable": "", **{f"amplitude at {p} [m]": r["amplitudes"][p] for p in points}})  # fmt: skip
    return rows


SYSTEM_DEFAULTS = {flag[2:].replace("-", "_"): default for flag, _, default in SYSTEM_OPTIONS}


#: --quiet's help, one text for every command that runs many simulations.
QUIET_HELP = ("no progress bar, run-time estimate or notice of a first compilation on stderr "
              "(warnings and errors stay)")  # fmt: skip

#: --multistart's help (frf and design: the curve's multi-start brute force).
MULTISTART_HELP = ("frequencies of the curve's multi-start brute force (default "
                   "symimpact.forced.orbits.coverage.FREQUENCIES; 0: none — faster, may miss "
                   "motions no branch reaches)")  # fmt: skip


def add_quiet(g: Any) -> None:
    """--quiet (:data:`QUIET_HELP`)."""
    g.add_argument("--quiet", action="store_true", help=QUIET_HELP)


def progress_drawn(ns: argparse.Namespace) -> bool:
    """Whether a command shows its progress (its bars, and the notice of a first compilation,
    :mod:`symimpact._notices`): on stderr when it is a terminal, unless --quiet; never into a
    pipe or a file (a log would hold every redraw of every bar: a cold ``design`` wrote 60 kB of
    them), whatever stdout holds (--json included)."""
    return sys.stderr.isatty() and not getattr(ns, "quiet", False)


def add_multistart(g: Any) -> None:
    """--multistart N (:data:`MULTISTART_HELP`)."""
    g.add_argument("--multistart", type=int, default=None, metavar="N", help=MULTISTART_HELP)


def add_budget(p: Any) -> None:
    """``--no-budget``: run a command whose estimate exceeds the budget."""
    from ..budgets import MAX_SECONDS

    p.add_argument(
        "--no-budget", action="store_true",
        help=f"run even when the estimate, timed on a piece of the first record before the run "
        f"starts, exceeds {MAX_SECONDS / 3600:g} h (estimates from 10 s up are printed)",
    )  # fmt: skip


def announce(ns: argparse.Namespace, estimate: Any, name: str, also: str = "") -> None:
    """Refuse ``estimate`` (a :class:`~symimpact.forced.loads.record_cost.Estimate`) beyond the budget
    unless --no-budget, naming ``name``; print it on stderr from ten seconds up, with ``also``
    (the work it leaves out, in words)."""
    from ..budgets import SAY_SECONDS
    from ..forced.loads.record_cost import within_budget

    within_budget(estimate, name, ns.no_budget)
    if estimate.high >= SAY_SECONDS and not getattr(ns, "quiet", False):
        print(f"symimpact {ns.command}: {estimate.text()}{also}", file=sys.stderr, flush=True)


def harmonic_counts(ns) -> tuple[int, int | None]:
    """(H, N) as ``--harmonics`` (default 15) and ``--time-samples`` (None: the balance's
    default 4H) give them, each a whole number in its range."""
    from ..forced.orbits.harmonic_balance import MAX_HARMONICS
    from .loads import count

    H = count("harmonics", "15" if ns.harmonics is None else ns.harmonics, 1, MAX_HARMONICS)
    N = None if ns.time_samples is None else count("time-samples", ns.time_samples, 1, 1 << 20)
    return H, N


def harmonics_of(ns, system, forcing, e, multiple: int = 1) -> tuple[int, int]:
    """(H, N) of ``--harmonics`` (default 15) and ``--time-samples`` (default 4H) for a harmonic
    balance of period ``multiple`` (:mod:`symimpact.forced.orbits.harmonic_balance`), checked
    against the system and contact before anything runs; a refusal names the option as the
    command line spells it (``periodic`` and ``frf`` ``--method hb``)."""
    from ..errors import ParameterError
    from ..forced.orbits.harmonic_balance import _checked

    H, N = harmonic_counts(ns)
    try:
        H, N, _ = _checked(system, forcing, e, H, N, multiple)
    except ParameterError as exc:  # the API's names, as the command line spells its options
        flag = {"time_samples": "time-samples", "subharmonic": "multiple"}
        raise ParameterError(flag.get(exc.parameter, exc.parameter), exc.reason) from None
    return H, N
