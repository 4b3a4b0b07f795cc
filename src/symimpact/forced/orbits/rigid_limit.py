"""The rigid limit of a compliant contact under forcing: :func:`rigid_limit`.

A rigid impact with Newton's e (Eq. F2) is the limit of a compliant contact whose stiffness grows
while its damping keeps the restitution at e: for the linear law c1 from Step 9's closed form
(``linear_c1_for_restitution``), for Hunt–Crossley χ from Step 11 at the orbit's impact speed
(:func:`symimpact.model.hunt_crossley.hunt_crossley_chi`).  Each compliant run starts on the stable rigid
two-impact orbit (Eq. F3) and is simulated to its steady state; the amplitude's error against the
rigid orbit falls like the contact duration — k^(−1/2) for the linear law, k^(−2/5) for Hertz.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ...errors import MethodNotApplicable, ParameterError
from ...generated import rigid_impact as ri
from ...model.hunt_crossley import hunt_crossley_chi
from ...model.system import ImpactSystem
from ...model.units import positive_float
from ..forcing import Forcing
from ..simulation import simulate_forced
from .periodic import PeriodicOrbit, periodic_orbits

#: The laws whose damping can be set from e in closed form (Step 9) or by Step 11's inversion.
LAWS = ("linear", "hunt-crossley")


@dataclass(frozen=True)
class RigidLimitRow:
    """One stiffness of :func:`rigid_limit` (SI units).

    ``stiffness``: k1 [N/m] (linear) or k_hz [N/m^1.5] (Hunt–Crossley); ``damping``: c1 [N s/m]
    or χ [s/m] giving restitution e; ``amplitude`` [m]: the compliant steady amplitude;
    ``relative_error``: (amplitude − rigid amplitude) / rigid amplitude; ``section_spread``: the
    largest change of the once-per-period state over the kept periods, relative to the state's
    scale (what is left of the transient from the rigid orbit to the compliant one).
    """

    stiffness: float
    damping: float
    amplitude: float
    relative_error: float
    section_spread: float


def rigid_limit(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    contact: str,
    stiffnesses: Sequence[Any],
    *,
    periods: int = 200,
    discard: int = 170,
) -> tuple[PeriodicOrbit, list[RigidLimitRow]]:
    """The stable rigid two-impact orbit (Eq. F3) at restitution ``e`` and, for each stiffness,
    the steady amplitude of the compliant ``contact`` ("linear" or "hunt-crossley", Eq. 35 or F4)
    with its damping set to give e (Step 9's c1, Step 11's χ), started on that orbit and run for
    ``periods`` forcing periods, the last ``periods − discard`` kept.  The default 200 and 170
    leave ~1e-8 of the transient in the section: at 60 periods it was ~2e-4 and the errors were
    7 % smaller than settled."""
    from ...model import checks
    from ..contact_law import checked

    checks.choice("contact", contact, tuple(LAWS))
    system, forcing, e = checked(system, forcing, e)
    periods = checks.whole_number("periods", periods, 1, 1_000_000)
    discard = checks.whole_number("discard", discard, 0, periods - 1)
    stable = [o for o in periodic_orbits(system, forcing, e) if o.stable]
    if not stable:
        raise MethodNotApplicable(
            "rigid_limit",
            f"no stable two-impact orbit at Ω = {forcing.omega:g} rad/s to converge to",
        )
    orbit = stable[0]
    # t = 0 at the orbit's impact on the wall +d/2
    f = forcing.at(forcing.omega, orbit.impact_phase)
    start = {
        "x0": orbit.X,
        "xdot0": orbit.V,
        "y0": orbit.X + 0.5 * system.gap,
        "ydot0": orbit.U,
    }
    rows = []
    if any(k <= 0 for k in checks.numbers("stiffnesses", stiffnesses)):
        raise ParameterError("stiffnesses", "must be positive")
    for k in stiffnesses:
        k = positive_float("stiffness", k)
        base = {n: getattr(system, n) for n in ("M", "K", "C", "m", "gap")}
        if contact == "linear":
            damping = float(ri.linear_c1_for_restitution(system.m, system.M, k, e))
            s = ImpactSystem(**base, contact="linear", k1=k, c1=damping)
            res = simulate_forced(s, f, contact="linear", periods=periods, discard=discard,
                                  **start)  # fmt: skip
        else:
            damping = hunt_crossley_chi(e, orbit.impact_speed)
            s = ImpactSystem(**base, contact="hertz", k_hz=k)
            res = simulate_forced(s, f, contact="hunt-crossley", chi=damping, periods=periods,
                                  discard=discard, **start)  # fmt: skip
        amp = res.steady.amplitude
        rows.append(
            RigidLimitRow(
                stiffness=k,
                damping=damping,
                amplitude=amp,
                relative_error=(amp - orbit.amplitude) / orbit.amplitude,
                section_spread=res.steady.section_spread,
            )
        )
    return orbit, rows
