"""Harmonic balance on a structure of several modes carrying compliant impact dampers: the
scheme of :mod:`symimpact.forced.orbits.harmonic_balance` on the coordinates
q = (q₁ … q_N, y₁ … y_K), the modal coordinates and each damper's absolute displacement.

𝐌 = diag(M₁ … M_N, m₁ … m_K), 𝐂 = diag(2ζᵢωᵢMᵢ …, 0 …), 𝐊 = diag(ωᵢ²Mᵢ …, 0 …) (each mode's
equation, Step 15), the force F₀cos(Ωt + φ) at point p entering mode i as F₀φᵢ(p).  Damper k at
point a, with shape row φ(a), has z = y − φ(a)·q, δ = s·z − d/2 on the wall s = ±1 and, while
δ > 0, the law's force F(δ, δ̇) (Step 17's derived kernels ``force_<law>_and_derivatives``): −s·F
on the damper's mass and φᵢ(a)·s·F on mode i (Step 15's impulse spread by the shape, here a
force).  By the chain rule through z (Step 17's ``aft_sample_slopes`` with x = φ(a)·q):
∂/∂qⱼ of mode i's force is −φᵢφⱼF_δ, ∂/∂y of it φᵢF_δ, and of the damper's force φⱼF_δ and
−F_δ; the same with F_δ̇ in the speeds.  One mode of shape 1 is the one-mode balance.

A damper's mass with no sample in contact floats (its mean position is free): Newton steps by
least squares (the shortest step), as shooting a structure does.  The start, where none is
given, is the motion a run from rest settles on (the event-driven engine, then one period of the
modal equations sampled: :func:`_settled_start`); Newton refines it.  Rigid impacts have no force law: refused in one line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._threads import on_one_blas_thread
from ...errors import ParameterError
from ...model import checks
from ...model.units import positive_float, si_float
from .harmonic_balance import (
    DEFAULT_SAMPLES_PER_HARMONIC,
    MAX_HARMONICS,
    Basis,
    Problem,
    _amplitude,
    law_at_samples,
    newton,
)


@dataclass(frozen=True)
class HBStructureOrbit:
    """A periodic orbit of a structure by harmonic balance (SI units): ``omega`` [rad/s], H,
    N, the coefficients ``q`` (one row a mode) and ``y`` (one row a damper) in θ = Ωt, each
    (a₀, a₁, b₁, …); ``amplitudes`` each point's max abs(φ(p)·q) [m]; Hill's ``multipliers``
    (moduli, descending) and ``stable``; Newton's ``iterations`` at F₀."""

    omega: float
    harmonics: int
    samples: int
    q: np.ndarray
    y: np.ndarray
    amplitudes: dict[str, float]
    multipliers: tuple[float, ...]
    stable: bool
    iterations: int

    def as_dict(self) -> dict[str, Any]:
        return {"omega": self.omega, "harmonics": self.harmonics, "time_samples": self.samples,
                "amplitudes": self.amplitudes, "multipliers": list(self.multipliers),
                "stable": self.stable, "iterations": self.iterations,
                "q": self.q.tolist(), "y": self.y.tolist()}  # fmt: skip


def _params(d: Any) -> tuple[float, ...]:
    """Damper ``d``'s law parameters as Step 17's kernels take them; a rigid damper refused."""
    if d.rigid:
        raise ParameterError(f"dampers.{d.name}", "harmonic balance needs a compliant contact "
                             "law (linear, hertz, hunt-crossley): a rigid impact has no force "
                             "to balance")  # fmt: skip
    return {"linear": (d.k1, d.c1), "hertz": (d.k_hz, d.c1),
            "hunt-crossley": (d.k_hz, d.chi)}[d.contact]  # fmt: skip


def _force(structure: Any, dampers: Any):
    """f(q, q̇) → (f, ∂f/∂q, ∂f/∂q̇) on (modes, dampers) (module text)."""
    N, K = len(structure.modes), len(dampers)
    shapes = structure.shapes([d.at for d in dampers])  # (K, N)
    params = [_params(d) for d in dampers]

    def force(q: np.ndarray, qd: np.ndarray):
        S = q.shape[1]
        f = np.zeros((N + K, S))
        fq = np.zeros((N + K, N + K, S))
        fv = np.zeros((N + K, N + K, S))
        for k, (d, p) in enumerate(zip(dampers, params, strict=True)):
            phi = shapes[k]
            z = q[N + k] - phi @ q[:N]
            zd = qd[N + k] - phi @ qd[:N]
            s = np.where(z >= 0.0, 1.0, -1.0)
            F, F_d, F_dd = law_at_samples(d.contact, p, s * z - 0.5 * d.gap, s * zd)
            f[:N] += np.outer(phi, s * F)
            f[N + k] -= s * F
            for g, out in ((F_d, fq), (F_dd, fv)):
                out[:N, :N] -= np.einsum("i,j,s->ijs", phi, phi, g)
                out[:N, N + k] += np.outer(phi, g)
                out[N + k, :N] += np.outer(phi, g)
                out[N + k, N + k] -= g
        return f, fq, fv

    return force


def _settled_start(
    structure: Any, dampers: Any, force_at: str, F: float, W: float, phi0: float, problem: Problem
) -> np.ndarray:
    """The coefficients of the motion a run from rest settles on: the event-driven engine's
    state after SETTLE periods (:func:`~symimpact.forced.structure_response.simulate_structure`),
    then one period of the modal equations with the balance's own force (SciPy's DOP853, rtol
    1e-10) sampled at the N sample times and transformed (P): a start Newton refines."""
    from scipy.integrate import solve_ivp

    from ..structure_response import simulate_structure

    n = problem.n
    run = simulate_structure(structure, dampers, force_at, F, W, periods=SETTLE, phase=phi0,
                             energy=False)  # fmt: skip
    s0 = np.asarray(run.final_state[1 : 1 + 2 * n], dtype=float)
    n_modes = n - len(dampers)
    state0 = np.concatenate([s0[:n_modes], s0[2 * n_modes : 2 * n_modes + len(dampers)],
                             s0[n_modes : 2 * n_modes], s0[2 * n_modes + len(dampers) :]])  # fmt: skip
    masses = np.diag(problem.Mm)
    damping, stiffness = np.diag(problem.Cm), np.diag(problem.Km)
    modal = np.zeros(n)
    modal[:n_modes] = F * structure.shapes([force_at])[0]

    def rhs(t, w):
        q, v = w[:n, None], w[n:, None]
        f = problem.force(q, v)[0][:, 0]
        acc = (modal * math.cos(W * t + phi0) - stiffness * w[:n] - damping * w[n:] + f) / masses
        return np.concatenate([w[n:], acc])

    T, N = 2.0 * math.pi / W, problem.basis.N
    sol = solve_ivp(rhs, (0.0, T), state0, method="DOP853", rtol=1e-10, atol=1e-14,
                    t_eval=np.arange(N) * T / N, max_step=T / N)  # fmt: skip
    return (sol.y[:n] @ problem.basis.P.T).ravel()


#: Forcing periods a run from rest takes to settle before the start is sampled.
SETTLE = 300


@on_one_blas_thread
def hb_structure_orbit(structure: Any, dampers: Any, force_at: str, F0: Any, omega: Any,
                       harmonics: Any = 15, time_samples: Any = None, phase: Any = 0.0,
                       start: Any = None) -> HBStructureOrbit:  # fmt: skip
    """The orbit of period 2π/Ω of ``structure`` with compliant ``dampers`` under F₀cos(Ωt + φ)
    at point ``force_at`` by harmonic balance with H = ``harmonics`` and N = ``time_samples``
    (default 4H) samples (module text), from ``start`` (the coefficients of q then y, one
    (2H + 1)-row each) or the motion a run from rest settles on; with Hill's stability (Step
    17's scheme)."""
    H = checks.whole_number("harmonics", harmonics, 1, MAX_HARMONICS)
    N = DEFAULT_SAMPLES_PER_HARMONIC * H if time_samples is None else time_samples
    N = checks.whole_number("time_samples", N, 2 * H + 1, 1 << 20)
    W = positive_float("omega", omega, "rad/s")
    F = si_float("F0", F0, "N")
    phi0 = si_float("phase", phase, "rad")
    if force_at not in structure.points:
        raise ParameterError("force_at", f"must be a point of the structure: "
                             f"{', '.join(structure.points)}")  # fmt: skip
    modes = structure.modes
    n_modes, K = len(modes), len(dampers)
    masses = [md.mass for md in modes] + [d.m for d in dampers]
    Mm = np.diag(masses)
    Cm = np.diag([2.0 * md.zeta * md.omega * md.mass for md in modes] + [0.0] * K)
    Km = np.diag([md.omega**2 * md.mass for md in modes] + [0.0] * K)
    basis = Basis.of(H, N)
    m = 2 * H + 1
    modal = F * structure.shapes([force_at])[0]  # F₀φᵢ(p)

    def forcing_terms(scale: float) -> np.ndarray:
        out = np.zeros((n_modes + K, m))
        out[:n_modes, 1] = scale * modal * math.cos(phi0)
        out[:n_modes, 2] = -scale * modal * math.sin(phi0)
        return out

    problem = Problem(Mm, Cm, Km, forcing_terms(1.0), _force(structure, dampers), basis)
    gaps = 0.5 * min(d.gap for d in dampers)
    if start is not None:
        U = np.asarray(start, dtype=float).ravel()
        if U.shape != ((n_modes + K) * m,):
            raise ParameterError("start", f"must hold {(n_modes + K) * m} coefficients")
        U, it, _ = newton(problem, U, W, gaps, least_squares=True)
    else:
        U = _settled_start(structure, dampers, force_at, F, W, phi0, problem)
        U, it, _ = newton(problem, U, W, gaps, least_squares=True)
    coeffs = U.reshape(n_modes + K, m)
    amplitudes = {p: _amplitude(basis, structure.shapes([p])[0] @ coeffs[:n_modes])
                  for p in structure.points}  # fmt: skip
    lam = problem.exponents(U, W)
    mult = tuple(sorted((float(abs(np.exp(x * 2.0 * math.pi / W))) for x in lam), reverse=True))
    return HBStructureOrbit(W, H, N, coeffs[:n_modes].copy(), coeffs[n_modes:].copy(), amplitudes,
                            mult, all(v < 1.0 for v in mult), it)  # fmt: skip
