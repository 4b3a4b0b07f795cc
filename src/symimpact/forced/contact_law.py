"""The contact an orbit, a branch or a frequency-response curve is computed with.

Shooting, continuation, the frequency-response curve and the design map take it in their
argument ``e``: a number is Newton's coefficient of restitution of rigid impacts (Eq. F2), a
:class:`CompliantContact` a compliant law integrated through each contact — cubic (Eq. 8), Hertz
(Eq. 9), linear (Eq. 35), each with the system's c₁, or Hunt–Crossley (Eq. F4) with its χ.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from ..model.units import nonnegative_float

#: The compliant laws, by the names of ``symimpact simulate --contact``.
COMPLIANT = ("cubic", "hertz", "linear", "hunt-crossley")


@dataclass(frozen=True)
class CompliantContact:
    """A compliant contact law: ``law`` one of :data:`COMPLIANT` (its stiffness and c₁ are the
    system's), ``chi`` [s/m] Hunt–Crossley's damping (Eq. F4; only with that law)."""

    law: str
    chi: float | None = None

    def __post_init__(self) -> None:
        if self.law not in COMPLIANT:
            raise ParameterError("contact", f"must be one of {', '.join(COMPLIANT)}")
        if self.law == "hunt-crossley":
            if self.chi is None:
                raise ParameterError("chi", "the Hunt–Crossley law needs its damping χ [s/m]")
            object.__setattr__(self, "chi", nonnegative_float("chi", self.chi))
        elif self.chi is not None:
            raise ParameterError("chi", "applies to the Hunt–Crossley contact only")

    def as_dict(self) -> dict[str, Any]:
        """``{"contact": law}``, with ``"chi"`` for Hunt–Crossley (SI)."""
        return {"contact": self.law, **({"chi": self.chi} if self.chi is not None else {})}


@dataclass(frozen=True)
class MaterialRestitution:
    """Rigid impacts whose restitution follows the materials at each impact's approach speed v
    (Step 13, Eq. F5): e = 1 at or below the yield speed v_y [m/s] (the contact stays elastic),
    Thornton's elastic–perfectly-plastic e(v_y/v) above it.

    Simulations, records, shooting, continuation in Ω, a clearance or the load, frf and design
    take it: the saltation matrix of an impact then holds ê = e + w·de/dw (Step 13) in place of e
    in its velocity entries (:mod:`symimpact.forced.engine._chain`).  Chatter is not taken to an
    accumulation point (a sequence's speeds fall below v_y, where impacts no longer lose
    energy, so it does not accumulate).  The closed-form orbits (Eq. F3), continuation in e and
    a design's e ± 0.1 need a constant e and refuse it."""

    yield_speed: float

    def __post_init__(self) -> None:
        from ..model.units import positive_float

        object.__setattr__(self, "yield_speed", positive_float("yield_speed", self.yield_speed))

    def at(self, speed: Any) -> float:
        """e at the approach speed ``speed`` [m/s] (Eq. F5): the engines' own rule."""
        from .engine._rigid import restitution

        return float(restitution(1.0, self.yield_speed, nonnegative_float("speed", speed)))

    def as_dict(self) -> dict[str, Any]:
        """``{"e": "material", "yield_speed": v_y}`` (SI)."""
        return {"e": "material", "yield_speed": self.yield_speed}


def restitution_parameters(e: Any) -> tuple[float, float]:
    """(constant e, yield speed [m/s]) of the engines' parameter vectors: a number's (e, 0), a
    :class:`MaterialRestitution`'s (1, v_y), no restitution (a compliant run) (1, 0)."""
    if isinstance(e, MaterialRestitution):
        return 1.0, e.yield_speed
    return (1.0 if e is None else float(e)), 0.0


def checked(system: Any, forcing: Any, e: Any, rigid_only: str | None = None):
    """(system, forcing, e) of an orbit's computation, checked: an
    :class:`~symimpact.model.system.ImpactSystem`, a :class:`~symimpact.forced.Forcing`, and a
    :class:`CompliantContact` or Newton's restitution e in [0, 1] (Eq. F2) as a float.
    ``rigid_only``: what refuses a compliant law (e.g. "the closed form")."""
    from ..model.checks import instance
    from ..model.system import ImpactSystem
    from .forcing import Forcing

    instance("system", system, ImpactSystem, "an ImpactSystem")
    instance("forcing", forcing, Forcing, "a Forcing")
    if rigid_only and not is_rigid(e):
        raise ParameterError("e", f"{rigid_only} is for rigid impacts: give Newton's e")
    if rigid_only and isinstance(e, MaterialRestitution):
        raise ParameterError(
            "e", f"{rigid_only} needs a constant e; e of the materials (per impact) is followed by "
            "shooting (periodic --method shooting, frf, branch, design)"
        )  # fmt: skip
    return system, forcing, restitution_or_law(e)


def restitution_or_law(e: Any) -> Any:
    """``e`` checked: a :class:`CompliantContact` or a :class:`MaterialRestitution` (Eq. F5)
    as it is, else Newton's restitution in [0, 1] (Eq. F2) as a float."""
    if not is_rigid(e) or isinstance(e, MaterialRestitution):
        return e
    e = nonnegative_float("e", e)
    if e > 1.0:
        raise ParameterError("e", f"must lie in [0, 1], got {e:g}")
    return e


def contact_setting(e: Any) -> Any:
    """``e`` as a settings value of a stored map: the restitution, the material law's yield
    speed (:meth:`MaterialRestitution.as_dict`), or the law's name with its χ
    (:meth:`CompliantContact.as_dict`)."""
    return e.as_dict() if isinstance(e, CompliantContact | MaterialRestitution) else e


def is_constant(e: Any) -> bool:
    """Whether ``e`` is one restitution for every impact (a number), not a compliant law nor a
    :class:`MaterialRestitution`."""
    return not isinstance(e, CompliantContact | MaterialRestitution)


def is_rigid(e: Any) -> bool:
    """Whether ``e`` stands for rigid impacts (a restitution) rather than a compliant law."""
    return not isinstance(e, CompliantContact)


def simulation_arguments(e: Any) -> dict[str, Any]:
    """The keyword arguments of :func:`symimpact.forced.simulate_forced` for the contact ``e``."""
    if is_rigid(e):
        return {"contact": "rigid", "e": e}
    return {"contact": e.law, "chi": e.chi}


def contact_text(e: Any) -> str:
    """``rigid, e = 0.6`` or ``hunt-crossley, χ = 0.5 s/m``: the contact in words."""
    if isinstance(e, MaterialRestitution):
        return f"rigid, e of the materials at each impact (yield speed {e.yield_speed:.4g} m/s)"
    if is_rigid(e):
        return f"rigid, e = {float(e):.4g}"
    return e.law + ("" if e.chi is None else f", χ = {e.chi:.4g} s/m")
