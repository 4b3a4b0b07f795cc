"""Periodic orbits of a structure of several modes with impact dampers and stops, by shooting:
:func:`shoot_structure`.

The stroboscopic map P takes the state s = (q, q̇, y, ẏ) — the N modal coordinates and their
rates, each damper's absolute displacement and speed — at t = 0 to the state k forcing periods
later; a period-k orbit is a fixed point of P.  P is the engine of several modes
(:mod:`symimpact.forced._modal`: Eq. F1 per mode in flight, Step 15's impact law, Eq. F7, a
pressed stop's spring and dashpot in the coupled closed form), and its Jacobian, the monodromy
matrix, is carried along the run, not differenced: each flight contributes its transition matrix
(per mode Step 8's Φᵢ(τ), or the coupled structure's Re(V e^{Λτ} V⁻¹) while a stop is pressed;
each free mass y += τẏ), each impact the saltation matrix S = D + (f⁺ − Df⁻)∇hᵀ/(∇h·f⁻) of the
impact law's Jacobian D, and each contact onset or exit of a stop the same with D = I (the state
is continuous there, the rate jumps by the dashpot's force).  Newton's method on P(s) − s = 0
with the Jacobian (monodromy − I) converges quadratically from a state near the orbit (a settled
state of a long run); the eigenvalues of the monodromy are the Floquet multipliers.

Orbits in which a mass sticks, a rigid stop holds its point, or chatter accumulates are not
differentiable by this chain yet (the one-mode engine's chain through them, :func:`symimpact.forced.shooting.rigid_monodromy`,
is not carried to N modes): they are refused in one line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import MethodNotApplicable, ParameterError
from ..model.checks import whole_number
from ..model.structure import Structure
from . import _rigid
from .structure_response import StructureResult, simulate_structure


@dataclass(frozen=True)
class StructureOrbit:
    """A periodic orbit of a structure (SI units): its state at t = 0, its Floquet multipliers
    and the run over its ``periods`` forcing periods from that state."""

    #: (q…, q̇…, y…, ẏ…) at t = 0 (and every ``periods`` forcing periods)
    state: np.ndarray
    periods: int
    multipliers: np.ndarray
    #: every multiplier lies inside the unit circle (but the two at +1 of a damper that meets no
    #: wall in the orbit, :func:`_orbit`)
    stable: bool
    #: Newton iterations taken, and the last relative residual ‖P(s) − s‖/‖s‖
    iterations: int
    residual: float
    #: the run over the orbit's periods from :attr:`state`
    run: StructureResult

    @property
    def amplitudes(self) -> dict[str, float]:
        """Every point's largest abs(x) over the orbit [m]."""
        return {p: float(self.run.period_max[:, j].max()) for j, p in enumerate(self.run.points)}

    @property
    def impacts(self) -> dict[str, int]:
        """Each damper's impacts and each stop's contacts in the orbit's periods."""
        out = {d.name: len(self.run.impacts(d.name)) for d in self.run.dampers}
        return out | {s.name: len(self.run.contacts(s.name)) for s in self.run.stops}

    def as_dict(self) -> dict[str, Any]:
        return {
            "omega": self.run.omega,
            "periods": self.periods,
            "state": [float(x) for x in self.state],
            "multipliers": [[float(m.real), float(m.imag)] for m in self.multipliers],
            "stable": self.stable,
            "amplitudes": self.amplitudes,
            "impacts": self.impacts,
            "iterations": self.iterations,
            "residual": self.residual,
        }


def stroboscopic_map(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega: Any,
                     state: Any, periods: Any = 1, stops: Any = (), phase: Any = 0.0,
                     base: Any = 0.0) -> tuple[np.ndarray, np.ndarray, StructureResult]:  # fmt: skip
    """(P(s), ∂P/∂s, the run): the state ``periods`` forcing periods after s = ``state``
    (q…, q̇…, y…, ẏ…) and the monodromy carried along the run (module text); ``base``: the
    supports' displacement amplitude X_b [m] (:func:`~symimpact.forced.structure_response.
    simulate_structure`)."""
    res = simulate_structure(structure, dampers, force_at, F0, omega, periods=periods,
                             phase=phase, state=state, stops=stops, variational=True,
                             base=base)  # fmt: skip
    N, K = len(structure.modes), len(res.dampers)
    return res.final_state[1 : 1 + 2 * N + 2 * K].copy(), res.monodromy, res


def shoot_structure(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega: Any,
                    state: Any, periods: Any = 1, stops: Any = (), phase: Any = 0.0,
                    tol: float = 1e-11, max_iterations: int = 30,
                    base: Any = 0.0) -> StructureOrbit:  # fmt: skip
    """The period-``periods`` orbit near ``state`` (q…, q̇…, y…, ẏ…): Newton's method on
    P(s) − s = 0 with the carried monodromy (module text), to ‖P(s) − s‖ ≤ tol·‖s‖.  Refused in
    one line: an orbit in which a mass sticks or its chatter accumulates, an event met at zero
    rate (grazing), or no convergence in ``max_iterations``."""
    k = whole_number("periods", periods, 1)
    s = np.array(state, dtype=float).ravel()
    residual = math.inf
    for it in range(1, max_iterations + 1):
        image, G, res = stroboscopic_map(structure, dampers, force_at, F0, omega, s, k, stops,
                                         phase, base)  # fmt: skip
        if not np.all(np.isfinite(G)):
            kinds = set(res.events[:, _rigid.E_KIND].astype(int).tolist())
            held = {_rigid.KIND_ACCUMULATION, _rigid.KIND_RELEASE}
            why = ("a mass sticks, a rigid stop holds its point, or chatter accumulates"
                   if kinds & held
                   else "an impact or contact meets its wall at zero speed (grazing)")  # fmt: skip
            raise MethodNotApplicable("shoot_structure", f"at Ω {float(omega):.6g} rad/s {why} "
                                      "within the orbit's periods: its monodromy is not carried "
                                      "through that yet")  # fmt: skip
        r = image - s
        scale = max(float(np.linalg.norm(s)), 1e-300)
        residual = float(np.linalg.norm(r)) / scale
        if residual <= tol:
            return _orbit(s, k, G, it, residual, res)
        # least squares: a mass that meets no wall in the orbit adds two multipliers at exactly
        # +1 (it may rest anywhere in its clearance), and the step is the shortest one
        step = np.linalg.lstsq(G - np.eye(len(s)), -r, rcond=1e-13)[0]
        s = s + step
    raise ParameterError("state", f"no convergence in {max_iterations} iterations (last "
                                  f"relative residual {residual:.2g}): start from a settled "
                                  "state nearer the orbit")  # fmt: skip


def _orbit(s: np.ndarray, k: int, G: np.ndarray, iterations: int, residual: float,
           res: StructureResult) -> StructureOrbit:  # fmt: skip
    """The orbit's multipliers (largest first) and stability.  A damper that meets no wall in
    the orbit flies freely: its (y, ẏ) block of the monodromy is [[1, kT], [0, 1]], two
    multipliers at +1 that only say it may rest anywhere in its clearance; the stability is
    the other multipliers'."""
    N = len(res.structure.modes)
    K = len(res.dampers)
    idle = [j for j, d in enumerate(res.dampers) if len(res.impacts(d.name)) == 0]
    keep = [i for i in range(len(s))
            if not any(i in (2 * N + j, 2 * N + K + j) for j in idle)]  # fmt: skip
    multipliers = np.linalg.eigvals(G)
    multipliers = multipliers[np.argsort(-np.abs(multipliers))]
    active = np.linalg.eigvals(G[np.ix_(keep, keep)]) if keep else np.zeros(0)
    stable = bool(np.all(np.abs(active) < 1.0))
    return StructureOrbit(s, k, multipliers, stable, iterations, residual, res)
