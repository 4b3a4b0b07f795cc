"""A small table of the materials impact dampers are made of: E, ν, ρ and the yield strength Y,
each with the grade it describes and where the value comes from.

The values are *typical* handbook values for the named grade; a data sheet of the actual part
wins.  Any material can be given instead as text, e.g. ``"E 200 GPa, nu 0.3, rho 7800 kg/m^3,
Y 350 MPa"`` (:func:`material`).  Elastomers have no yield in the sense of Thornton's
elastic–plastic impact (Step 13): their losses are viscoelastic, and the table gives their rebound
resilience R (ISO 4662: the share of the impact energy returned, so e = √R) instead.  The moduli of
the elastomers follow from their Shore A hardness by Gent's relation (:func:`gent_modulus`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..errors import ParameterError
from .units import si_float


@dataclass(frozen=True)
class Material:
    """One material (SI units).

    ``E`` [Pa] Young's modulus, ``nu`` [1] Poisson's ratio in (−1, 0.5], ``rho`` [kg/m³] density,
    ``yield_strength`` [Pa] (None for elastomers), ``resilience`` [1] rebound resilience (ISO 4662)
    where the losses are viscoelastic, ``grade`` what the values describe, ``source`` where they
    come from.
    """

    name: str
    E: float
    nu: float
    rho: float
    yield_strength: float | None
    grade: str
    source: str
    resilience: float | None = None

    def __post_init__(self) -> None:
        if not (self.E > 0.0 and math.isfinite(self.E)):
            raise ParameterError(f"{self.name}: E", f"must be a positive modulus, got {self.E:g}")
        if not (-1.0 < self.nu <= 0.5):
            raise ParameterError(f"{self.name}: nu", f"must lie in (−1, 0.5], got {self.nu:g}")
        if not (self.rho > 0.0 and math.isfinite(self.rho)):
            raise ParameterError(
                f"{self.name}: rho", f"must be a positive density, got {self.rho:g}"
            )
        if self.yield_strength is not None and not self.yield_strength > 0.0:
            raise ParameterError(
                f"{self.name}: Y", f"must be positive, got {self.yield_strength:g}"
            )
        if self.resilience is not None and not 0.0 < self.resilience <= 1.0:
            raise ParameterError(f"{self.name}: resilience", "must lie in (0, 1]")


def gent_modulus(shore_a: float) -> float:
    """Young's modulus [Pa] of a rubber of Shore A hardness S (Gent, Trans. IRI 34, 1958;
    ASTM D2240's indenter): E = 0.0981(56 + 7.62336 S)/(0.137505(254 − 2.54 S)) MPa."""
    if not 0.0 < shore_a < 100.0:
        raise ParameterError("shore_a", f"must lie in (0, 100), got {shore_a:g}")
    return 1e6 * 0.0981 * (56.0 + 7.62336 * shore_a) / (0.137505 * (254.0 - 2.54 * shore_a))


_HANDBOOK = "typical handbook value for this grade (ASM Handbook Vol. 1–2; MatWeb data sheets)"

# fmt: off
#: The table: name → Material.  Typical values of a common grade of each; see the module docstring.
MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (
        Material("steel", 205e9, 0.29, 7850.0, 530e6, "carbon steel AISI 1045, cold drawn",
                 _HANDBOOK),
        Material("bearing steel", 210e9, 0.30, 7810.0, 2000e6,
                 "AISI 52100 through-hardened (compressive yield)", _HANDBOOK),
        Material("mild steel", 205e9, 0.29, 7870.0, 370e6, "AISI 1018, cold drawn",
                 _HANDBOOK),
        Material("stainless steel", 193e9, 0.29, 8000.0, 215e6, "AISI 304, annealed",
                 _HANDBOOK),
        Material("hardened stainless steel", 200e9, 0.28, 7650.0, 1900e6,
                 "AISI 440C hardened and tempered at 316 °C (bearing balls)", _HANDBOOK),
        Material("tungsten carbide", 620e9, 0.22, 14950.0, 5300e6,
                 "WC–6 % Co cemented carbide",
                 _HANDBOOK + "; brittle: Y is its compressive strength, the contact fractures "
                 "rather than yields"),
        Material("nylon", 2.9e9, 0.39, 1140.0, 80e6, "PA 66, dry as moulded", _HANDBOOK),
        Material("aluminium alloy", 68.9e9, 0.33, 2700.0, 276e6, "6061-T6", _HANDBOOK),
        Material("brass", 97e9, 0.31, 8500.0, 310e6, "C36000 free-cutting brass, half hard",
                 _HANDBOOK),
        Material("bronze", 100e9, 0.34, 8930.0, 125e6, "C93200 bearing bronze, cast",
                 _HANDBOOK),
        Material("lead", 16e9, 0.44, 11340.0, 5.5e6,
                 "pure lead, annealed", _HANDBOOK + "; Y varies with purity and grain size"),
        Material("tungsten alloy", 310e9, 0.28, 17000.0, 620e6,
                 "90W–7Ni–3Fe heavy alloy (ASTM B777 class 1)", _HANDBOOK),
        Material("cast iron", 100e9, 0.26, 7200.0, 200e6,
                 "grey iron ASTM A48 class 30",
                 _HANDBOOK + "; no distinct yield: Y is the 0.1 % proof stress"),
        Material("ptfe", 0.5e9, 0.46, 2200.0, 10e6, "PTFE, unfilled", _HANDBOOK),
        Material("polyurethane", gent_modulus(90.0), 0.49, 1200.0, None,
                 "cast polyurethane, Shore 90A",
                 "E from the hardness by Gent's relation; ρ, ν, resilience typical of cast PU "
                 "(resilience 0.3–0.7 with the compound)", resilience=0.45),
        Material("natural rubber", gent_modulus(60.0), 0.499, 1100.0, None,
                 "filled natural rubber, Shore 60A",
                 "E from the hardness by Gent's relation; ρ, ν, resilience typical of filled NR "
                 "(resilience 0.6–0.8)", resilience=0.70),
    )
}
# fmt: on

_ALIASES = {
    "aluminum alloy": "aluminium alloy",
    "aluminium": "aluminium alloy",
    "aluminum": "aluminium alloy",
    "stainless": "stainless steel",
    "304": "stainless steel",
    "440c": "hardened stainless steel",
    "aisi 440c": "hardened stainless steel",
    "52100": "bearing steel",
    "aisi 52100": "bearing steel",
    "1045": "steel",
    "carbon steel": "steel",
    "1018": "mild steel",
    "carbide": "tungsten carbide",
    "wc": "tungsten carbide",
    "pa66": "nylon",
    "polyamide": "nylon",
    "tungsten": "tungsten alloy",
    "pu": "polyurethane",
    "rubber": "natural rubber",
    "teflon": "ptfe",
}

_PROPERTY = re.compile(r"^\s*(E|nu|ν|rho|ρ|Y)\s*[=:]?\s*(.+?)\s*$", re.IGNORECASE)


def material(text: str) -> Material:
    """The material named ``text`` (see :data:`MATERIALS`; case and a few aliases forgiven), or
    one given by its properties: ``"E 200 GPa, nu 0.3, rho 7800 kg/m^3, Y 350 MPa"`` (Y may be
    left out: the contact then stays elastic)."""
    key = " ".join(str(text).lower().split())
    key = _ALIASES.get(key, key)
    if key in MATERIALS:
        return MATERIALS[key]
    if "," in key or key.startswith(("e ", "e=")):
        values: dict[str, float] = {}
        for part in str(text).split(","):
            found = _PROPERTY.match(part)
            if not found:
                raise ParameterError("material", f"cannot read {part.strip()!r}: use E, nu, rho, Y")
            name = {"ν": "nu", "ρ": "rho"}.get(found[1], found[1])
            name = {"e": "E", "y": "Y"}.get(name.lower(), name.lower())
            unit = {"E": "Pa", "nu": None, "rho": "kg/m^3", "Y": "Pa"}[name]
            if name in values:
                raise ParameterError(f"material {name}", f"given twice in {str(text)!r}")
            values[name] = si_float(f"material {name}", found[2], unit)
        missing = {"E", "nu", "rho"} - set(values)
        if missing:
            raise ParameterError("material", f"missing {', '.join(sorted(missing))}")
        return Material("material", values["E"], values["nu"], values["rho"], values.get("Y"),
                        "given by the user", "the command line")  # fmt: skip
    known = ", ".join(sorted(MATERIALS))
    raise ParameterError("material", f"unknown {text!r}; known: {known} (or 'E …, nu …, rho …')")
