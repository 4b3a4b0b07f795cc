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
from ..units import nonnegative_float

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


def checked(system: Any, forcing: Any, e: Any, rigid_only: str | None = None):
    """(system, forcing, e) of an orbit's computation, checked: an
    :class:`~symimpact.system.ImpactSystem`, a :class:`~symimpact.forced.Forcing`, and a
    :class:`CompliantContact` or Newton's restitution e in [0, 1] (Eq. F2) as a float.
    ``rigid_only``: what refuses a compliant law (e.g. "the closed form")."""
    from ..checks import instance
    from ..system import ImpactSystem
    from .forcing import Forcing

    instance("system", system, ImpactSystem, "an ImpactSystem")
    instance("forcing", forcing, Forcing, "a Forcing")
    if rigid_only and not is_rigid(e):
        raise ParameterError("e", f"{rigid_only} is for rigid impacts: give Newton's e")
    return system, forcing, restitution_or_law(e)


def restitution_or_law(e: Any) -> Any:
    """``e`` checked: a :class:`CompliantContact` as it is, else Newton's restitution in [0, 1]
    (Eq. F2) as a float."""
    if not is_rigid(e):
        return e
    e = nonnegative_float("e", e)
    if e > 1.0:
        raise ParameterError("e", f"must lie in [0, 1], got {e:g}")
    return e


def contact_setting(e: Any) -> Any:
    """``e`` as a settings value of a stored map: the restitution, or the law's name with its
    χ (:meth:`CompliantContact.as_dict`)."""
    return e if is_rigid(e) else e.as_dict()


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
    if is_rigid(e):
        return f"rigid, e = {float(e):.4g}"
    return e.law + ("" if e.chi is None else f", χ = {e.chi:.4g} s/m")
