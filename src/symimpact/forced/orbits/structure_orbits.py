"""Periodic orbits of a structure of several modes with impact dampers and stops, by shooting:
:func:`shoot_structure`.

The stroboscopic map P takes the state s = (q, q̇, y, ẏ) — the N modal coordinates and their
rates, each damper's absolute displacement and speed — at t = 0 to the state k forcing periods
later; a period-k orbit is a fixed point of P.  P is the engine of several modes
(:mod:`symimpact.forced.engine._modal`: Eq. F1 per mode in flight, Step 15's impact law, Eq. F7, a
pressed stop's spring and dashpot in the coupled closed form), and its Jacobian, the monodromy
matrix, is carried along the run, not differenced: each flight contributes its transition matrix
(per mode Step 8's Φᵢ(τ), or the coupled structure's Re(V e^{Λτ} V⁻¹) while a stop is pressed;
each free mass y += τẏ), each impact the saltation matrix S = D + (f⁺ − Df⁻)∇hᵀ/(∇h·f⁻) of the
impact law's Jacobian D, and each contact onset or exit of a stop the same with D = I (the state
is continuous there, the rate jumps by the dashpot's force).  Newton's method on P(s) − s = 0
with the Jacobian (monodromy − I) converges quadratically from a state near the orbit (a settled
state of a long run); the eigenvalues of the monodromy are the Floquet multipliers.

*Through chatter and sticking.*  The chain is carried on through a chatter taken to its
accumulation point and the sticking that follows (:func:`symimpact.forced.engine._modal.run`): the
accumulation time t∞ = t₀ + Δ, Δ = 2w/(a(1 − e)), moves with the state just after the impact that
starts the chatter and with that impact's own time, so its row δt∞ is the chain rule of Δ's
closed form; the structure flies Δ (its Φ(τ)); the plastic closure at t∞ is a jump D with
S = D + (D f⁻ + ∂J/∂t − f⁺)δt∞, f⁺ the stuck structure's rate; while a mass rides on its point
its rows are its point's, δyₖ = φₖᵀδq and δẏₖ = φₖᵀδq̇, through the stuck structure's flights
(Re(V e^{Λτ} V⁻¹) of M + Σmₖφₖφₖᵀ) and the other dampers' impacts; and a release, where the wall
would begin to pull, has the identity as its saltation (the mass's and the point's accelerations
are both 0 there).  On one mode this is the one-mode engine's chain from its event log
(:func:`symimpact.forced.orbits.shooting.rigid_monodromy`) to 8e-11, and on three modes with two dampers
it is the limit of the map's central differences, which approach it as h²
(tests/test_structure_sticking_orbits.py).  Where the run is not differentiated so — a mass on
its wall at the section (the map's two sides differ there), an impulse that lets a stuck mass
go, sticking beside stops or a rigid stop holding its point, or e that varies with the speed —
the Jacobian is P's central differences (:func:`differenced_monodromy`: 2(2N + 2K) runs, steps
of 1e-5 of each block's scale, :data:`DIFFERENCE_STEP`, accurate to ~1e-9 of the map's scales on
one mode; a mass resting on its wall at the section is differenced one-sided, into its
clearance, with a step of 1e-8).  The map is differentiable through those events — the
accumulation time, the sticking phase's flight and the release time all move smoothly with the
state — so Newton converges as it does with the carried Jacobian, and the multipliers are the
differenced map's eigenvalues (a sticking phase makes two of them vanish per stuck mass).
:attr:`StructureOrbit.jacobian` says which was used.  An event met at zero rate (grazing) is
refused in one line: the map has no derivative there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ...errors import MethodNotApplicable, ParameterError
from ...model.checks import whole_number
from ...model.structure import Structure
from ..engine import _modal, _rigid
from ..simulation import impact_counts
from ..structure_response import StructureResult, simulate_structure


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
    #: ∂P/∂s at :attr:`state`, the monodromy matrix whose eigenvalues are :attr:`multipliers`
    monodromy: np.ndarray | None = None
    #: how :attr:`monodromy` was obtained: "carried" along the run, or "differenced" (module text)
    jacobian: str = "carried"

    @property
    def amplitudes(self) -> dict[str, float]:
        """Every point's largest abs(x) over the orbit [m]."""
        return {p: float(self.run.period_max[:, j].max()) for j, p in enumerate(self.run.points)}

    @property
    def impacts(self) -> dict[str, int]:
        """Each damper's impacts and each stop's contacts in the orbit's periods."""
        out = {d.name: len(self.run.impacts(d.name)) for d in self.run.dampers}
        return out | {s.name: len(self.run.contacts(s.name)) for s in self.run.stops}

    @property
    def impact_events(self) -> dict[str, int]:
        """Each damper's impacts and each stop's contacts in the orbit's periods with a chatter
        sequence (impacts on one wall that its accumulation point ends) counted once: unlike
        :attr:`impacts`, independent of how many impacts of a sequence are resolved before the
        jump to its limit (:func:`~symimpact.forced.simulation.impact_counts`).  A compliant
        damper's or linear stop's: its contacts, as :attr:`impacts` counts them."""
        run = self.run
        out = {}
        for row, name in enumerate([d.name for d in run.dampers] + [s.name for s in run.stops]):
            if row >= len(run.dampers) and run.stops[row - len(run.dampers)].contact != "rigid":
                out[name] = len(run.contacts(name))
                continue
            if row < len(run.dampers) and not run.dampers[row].rigid:
                out[name] = len(run.impacts(name))  # its onsets; an exit ends no impact
                continue
            mine = run.events[run.events[:, _modal.E_DAMPER] == row]
            out[name] = impact_counts(mine, -math.inf, math.inf)[1]
        return out

    def as_dict(self) -> dict[str, Any]:
        return {
            "omega": self.run.omega,
            "periods": self.periods,
            "state": [float(x) for x in self.state],
            "multipliers": [[float(m.real), float(m.imag)] for m in self.multipliers],
            "stable": self.stable,
            "amplitudes": self.amplitudes,
            "impacts": self.impacts,
            "impact_events": self.impact_events,
            "iterations": self.iterations,
            "residual": self.residual,
            "jacobian": self.jacobian,
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
    one line: an event met at zero rate (grazing), or no convergence in ``max_iterations``.
    Where the run is not differentiated (a mass on its wall at the section, a stuck mass let go
    by an impulse, sticking beside stops, e(v): module text) the Jacobian is differenced and
    Newton stops at max(``tol``, :data:`DIFFERENCED_TOL`)."""
    k = whole_number("periods", periods, 1)
    s = np.array(state, dtype=float).ravel()
    residual = math.inf
    how = "carried"
    for it in range(1, max_iterations + 1):
        image, G, res = stroboscopic_map(structure, dampers, force_at, F0, omega, s, k, stops,
                                         phase, base)  # fmt: skip
        if not np.all(np.isfinite(G)):
            kinds = set(res.events[:, _rigid.E_KIND].astype(int).tolist())
            held = {_rigid.KIND_ACCUMULATION, _rigid.KIND_RELEASE}
            N, K = len(structure.modes), len(res.dampers)
            ends = res.final_state[1 + 2 * N + 2 * K :]  # each damper stuck, each stop pressed
            rigid = [st.contact == "rigid" for st in res.stops]
            resting = np.any(ends[:K] != 0) or np.any(ends[K:][rigid] != 0)
            compliant = any(not d.rigid for d in res.dampers)
            if not (kinds & held or resting or compliant):
                raise MethodNotApplicable("shoot_structure", f"at Ω {float(omega):.6g} rad/s an "
                                          "impact or contact meets its wall at zero speed "
                                          "(grazing) within the orbit's periods: the map has no "
                                          "derivative there")  # fmt: skip
            G = differenced_monodromy(structure, dampers, force_at, F0, omega, s, k, stops,
                                      phase, base, image)  # fmt: skip
            how = "differenced"
        r = image - s
        scale = max(float(np.linalg.norm(s)), 1e-300)
        residual = float(np.linalg.norm(r)) / scale
        if residual <= (tol if how == "carried" else max(tol, DIFFERENCED_TOL)):
            return _orbit(s, k, G, it, residual, res, how)
        # least squares: a mass that meets no wall in the orbit adds two multipliers at exactly
        # +1 (it may rest anywhere in its clearance), and the step is the shortest one
        step = np.linalg.lstsq(G - np.eye(len(s)), -r, rcond=1e-13)[0]
        s = s + _inside(structure, dampers, s, step, phase, base) * step
        how = "carried"
    raise ParameterError("state", f"no convergence in {max_iterations} iterations (last "
                                  f"relative residual {residual:.2g}): start from a settled "
                                  "state nearer the orbit")  # fmt: skip


def _inside(structure: Structure, dampers: Any, s: np.ndarray, step: np.ndarray, phase: Any,
            base: Any) -> float:  # fmt: skip
    """The largest λ in (0, 1], halving from 1, with which s + λ·step keeps every mass inside
    its clearance, |y − x_b − φᵀq| ≤ d/2, where s keeps it (a Newton step from far can throw a
    mass through its wall, where the map is not the physical one)."""
    N = len(structure.modes)
    K = len(dampers)
    if K == 0:
        return 1.0
    phis = structure.shapes([d.at for d in dampers]).reshape(K, N)
    halves = np.array([d.gap / 2 for d in dampers])
    x_b = float(base) * math.cos(float(phase))

    def z(x: np.ndarray) -> np.ndarray:
        return x[2 * N : 2 * N + K] - phis @ x[:N] - x_b

    allowed = np.maximum(np.abs(z(s)), halves)
    lam = 1.0
    for _ in range(40):
        if np.all(np.abs(z(s + lam * step)) <= allowed):
            break
        lam /= 2
    return lam


#: Central differences' step, of each block's scale.  Against the one-mode engine's carried chain
#: through chatter and sticking (tests/test_structure_sticking_orbits.py) the error is 1.6e-10 to
#: 1.7e-9 of the scales at 1e-5, and grows as 1/h below it (rounding, amplified by the chatter's
#: dozens of impacts: 1.2e-7 at 1e-6, 1.1e-6 at 1e-7) and as h² above (at 1e-4 a step already
#: changes the chatter's sequence: 2e-2).  One-sided (a mass resting on its wall): 1e-8, truncation
#: and rounding both ~1e-8.
DIFFERENCE_STEP, ONE_SIDED_STEP = 1e-5, 1e-8
#: Newton's tolerance with a differenced Jacobian: where the number of impacts a chatter
#: sequence resolves before the jump to its limit changes, P jumps by ~1e-11 of the state (the
#: accumulation formula's error, Step 9), a floor Newton cannot go below (measured: 1.2e-11 on a
#: two-mode cantilever's sticking branch, tests/test_structure_sticking_orbits.py)
DIFFERENCED_TOL = 1e-10


def differenced_monodromy(structure: Structure, dampers: Any, force_at: Any, F0: Any,
                          omega: Any, state: Any, periods: Any = 1, stops: Any = (),
                          phase: Any = 0.0, base: Any = 0.0,
                          image: np.ndarray | None = None) -> np.ndarray:  # fmt: skip
    """∂P/∂s at s = ``state`` by central differences of the stroboscopic map over ``periods``
    (:func:`stroboscopic_map` without its carried chain; module text): column j is
    (P(s + hⱼeⱼ) − P(s − hⱼeⱼ))/(2hⱼ), hⱼ = 1e-5 of the scale of s's block (q, q̇, y or ẏ: its
    largest entry, at least the clearances' or the force's scale).  A damper resting on a wall of
    its clearance at s is differenced one-sided into it (``image``: P(s), if known)."""
    s = np.array(state, dtype=float).ravel()
    N = len(structure.modes)
    K = (len(s) - 2 * N) // 2

    def P(x: np.ndarray) -> np.ndarray:
        res = simulate_structure(structure, dampers, force_at, F0, omega, periods=periods,
                                 phase=phase, state=x, stops=stops, base=base,
                                 energy=False)  # fmt: skip
        return res.final_state[1 : 1 + 2 * N + 2 * K]

    w = float(omega)
    halves = [d.gap / 2 for d in dampers] + [st.gap for st in stops]
    length = min(halves)
    phis = structure.shapes([d.at for d in dampers]).reshape(K, N)
    peak = max((abs(m.shape[p]) for m in structure.modes for p in m.shape), default=1.0) or 1.0
    q_scale = max(float(np.max(np.abs(s[:N]))), length / peak)
    omegas = np.array([m.omega for m in structure.modes])
    v_scale = max(float(np.max(np.abs(s[N : 2 * N]))), min(w, omegas.min()) * q_scale)
    y_scale = max(float(np.max(np.abs(s[2 * N : 2 * N + K]), initial=0.0)), length)
    # a stiffer mode is stepped less, to the same energy as its rate's step: the map's curvature
    # in qᵢ grows as ωᵢ² (at 1e-5 of the block's scale the second of two cantilever modes gave
    # 1.9e-7 of the matrix; 5e-9 so)
    scales = np.concatenate([np.minimum(q_scale, v_scale / omegas), np.full(N, v_scale),
                             np.full(K, y_scale),
                             np.full(K, max(float(np.max(np.abs(s[2 * N + K :]), initial=0.0)),
                                            w * y_scale))])  # fmt: skip
    x_b = float(base) * math.cos(float(phase)) if not callable(base) else 0.0
    G = np.empty((len(s), len(s)))
    for j in range(len(s)):
        side = 0
        if 2 * N <= j < 2 * N + K:  # a mass on a wall of its clearance: step into it only
            d = dampers[j - 2 * N]
            z = s[j] - float(phis[j - 2 * N] @ s[:N]) - x_b
            if abs(z) >= d.gap / 2 * (1.0 - 1e-9):
                side = 1 if z > 0 else -1
        if side:
            h = ONE_SIDED_STEP * scales[j]
            e = np.zeros(len(s))
            e[j] = -side * h
            here = P(s) if image is None else image
            G[:, j] = (P(s + e) - here) / (-side * h)
            continue
        h = DIFFERENCE_STEP * scales[j]
        e = np.zeros(len(s))
        e[j] = h
        G[:, j] = (P(s + e) - P(s - e)) / (2 * h)
    return G


def _orbit(s: np.ndarray, k: int, G: np.ndarray, iterations: int, residual: float,
           res: StructureResult, how: str = "carried") -> StructureOrbit:  # fmt: skip
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
    return StructureOrbit(s, k, multipliers, stable, iterations, residual, res, G, how)
