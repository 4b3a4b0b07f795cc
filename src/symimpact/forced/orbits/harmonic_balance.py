"""Multi-harmonic balance with the alternating frequency–time scheme (AFT): the method most
engineers use for forced nonlinear responses, beside the exact orbits of shooting.

A periodic motion of period T = 2πν/Ω (ν = 1 a harmonic orbit, ν > 1 a subharmonic one) is
written as a truncated Fourier series in θ = ωt, ω = Ω/ν, of each coordinate,

    q(t) = a₀ + Σₖ₌₁ᴴ (aₖ cos kθ + bₖ sin kθ),

and the equations of motion 𝐌q̈ + 𝐂q̇ + 𝐊q = f_ext(t) + f(q, q̇) are projected on the same
H + 1 harmonics (Galerkin): in the coefficients U,

    R(U, ω) = (𝐊 ⊗ I + ω 𝐂 ⊗ D + ω² 𝐌 ⊗ D²) U − F_ext − P f(E U, ω E_θ U) = 0,

where D is the derivative in θ on the coefficients (aₖ, bₖ) ↦ (k bₖ, −k aₖ), E and E_θ evaluate
a series and its θ-derivative at N equally spaced samples of a period, and P is the discrete
Fourier transform back to the coefficients (exact for series up to harmonic N/2 − 1): the AFT
scheme evaluates the nonlinear force where it is known, in time.  Its Jacobian is exact,
∂R/∂U = Lin − P (diag ∂f/∂q E + ω diag ∂f/∂q̇ E_θ), from the force law's own derivatives at
the samples; ∂R/∂ω likewise.  The paper's one-term balance (Eq. 11–15, free vibration) is the
case H = 1 of the same projection.

For the impact damper the coordinates are q = (x, y): the primary M (K, C to the base, the
forcing) and the impact mass m, free in its cavity, 𝐌 = diag(M, m), 𝐂 = diag(C, 0),
𝐊 = diag(K, 0).  The contact is one of the compliant laws of the forced simulation
(:mod:`symimpact.forced.engine._compliant`: cubic Eq. 8, Hertz Eq. 9, linear Eq. 35, each with
c₁, or Hunt–Crossley Eq. F4): with z = y − x, δ = s·z − d/2 on the wall s = ±1 and F(δ, δ̇) the
law, the force on m is −s·F while δ > 0 (and on M its opposite), 0 between the walls; F and its
slopes ∂F/∂δ, ∂F/∂δ̇ at the samples are Step 17's derived kernels, the same laws the
simulation's engine integrates (tests/test_aft_kernels.py compares the two).  Rigid
impacts have no force law and are not balanced here (a contact needs many harmonics; a rigid one
infinitely many): give a compliant law, or read the exact orbits of shooting.

*Stability* by Hill's method: a perturbation e^{λt}p(t) with p of period T gives the quadratic
eigenproblem (λ² Δ₂ + λ Δ₁ + Δ₀) P = 0 with Δ₂ = 𝐌 ⊗ I, Δ₁ = 𝐂 ⊗ I + 2ω 𝐌 ⊗ D −
P diag(∂f/∂q̇) E and Δ₀ = ∂R/∂U; of its 2n(2H + 1) exponents (n coordinates), the 2n whose
imaginary parts are smallest in modulus are taken as the Floquet exponents (the others are
copies shifted by multiples of iω and the truncation's spurious ones), and the multipliers are
e^{λT}.  That sorting is the common one in the literature; it is exact for H → ∞ and is checked
against the exact multipliers of shooting.  With a contact it can pick one of the truncation's
spurious exponents: on the README's primary with a Hertz contact at Ω = 34 rad/s it reported a
multiplier of 33 at H = 10 and 1.9 at H = 40 where shooting's largest is 0.955, so a balance's
stability is to be read beside shooting's, not instead of it.  And where the contact's damping
c₁δ̇ switches on with a step, the residual is discontinuous in the coefficients: Newton converges
while no sample sits at an onset (H up to 60 there), and may stall beyond.

*Continuation* in Ω by pseudo-arclength: the unknowns (U/s, Ω/Ω₀), scaled by the clearance's
half s = d/2 and the first frequency Ω₀; the predictor along the tangent of [∂R/∂U, ∂R/∂Ω],
Newton's corrector on the plane normal to it.

The curve over a band beside the exact one, and the comparison of the two, are
:mod:`symimpact.forced.orbits.hb_frf`'s.  :func:`hb_orbit` and :func:`hb_curve` check their input.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._threads import on_one_blas_thread
from ...errors import MethodNotApplicable, ParameterError
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import CompliantContact
from ..forcing import Forcing

#: Newton's tolerance on the correction relative to the clearance's half (a contact's samples
#: switching between iterates leave the last steps at some 1e-11 of it), and its most steps.
TOL = 1e-10
MAX_NEWTON = 40
#: Newton's step is halved at most this often until the residual falls; beyond, Newton has
#: stalled (a step of 2^-12 of its own length lowers a smooth residual unless it is at a
#: minimum of its norm that is no zero).
HALVINGS = 12
#: The harmonics a balance may carry, and the fewest time samples per harmonic (AFT): N ≥ 2H + 1
#: resolves the series itself without aliasing; a product of the series (the force) folds
#: harmonics above N/2 back, so N is asked to hold at least 4 samples a harmonic by default.
MAX_HARMONICS = 400
#: The continuation's corrector: Newton steps before the arc step is halved, and the smallest arc
#: step (in the scaled unknowns, where the coefficients and Ω/Ω₀ are of order 1).
CORRECTOR_STEPS = 8
MIN_ARC_STEP = 1e-5
DEFAULT_SAMPLES_PER_HARMONIC = 4


@dataclass(frozen=True)
class Basis:
    """The real Fourier basis of H harmonics at N samples of a period: coefficient order
    (a₀, a₁, b₁, …, a_H, b_H); ``E`` (N × 2H + 1) evaluates a series at θⱼ = 2πj/N, ``Et`` its
    θ-derivative, ``P`` (2H + 1 × N) the transform back, ``D`` the θ-derivative on the
    coefficients."""

    H: int
    N: int
    E: np.ndarray = field(repr=False)
    Et: np.ndarray = field(repr=False)
    P: np.ndarray = field(repr=False)
    D: np.ndarray = field(repr=False)

    @classmethod
    @functools.lru_cache(maxsize=64)
    def of(cls, H: int, N: int) -> Basis:
        """The basis of ``H`` harmonics at ``N`` samples, made once for each (H, N) (a curve asks
        for it at each orbit) and shared: its matrices are read-only."""
        theta = 2.0 * math.pi * np.arange(N) / N
        n = 2 * H + 1
        E, Et, P, D = np.zeros((N, n)), np.zeros((N, n)), np.zeros((n, N)), np.zeros((n, n))
        E[:, 0] = 1.0
        P[0, :] = 1.0 / N
        for k in range(1, H + 1):
            c, s = np.cos(k * theta), np.sin(k * theta)
            E[:, 2 * k - 1], E[:, 2 * k] = c, s
            Et[:, 2 * k - 1], Et[:, 2 * k] = -k * s, k * c
            P[2 * k - 1, :], P[2 * k, :] = 2.0 * c / N, 2.0 * s / N
            D[2 * k - 1, 2 * k], D[2 * k, 2 * k - 1] = k, -k
        for a in (E, Et, P, D):
            a.setflags(write=False)
        return cls(H, N, E, Et, P, D)

    def at(self, coefficients: np.ndarray, theta: np.ndarray, derivative: int = 0) -> np.ndarray:
        """The series of ``coefficients`` (2H + 1) and its ``derivative``-th θ-derivative at
        ``theta``: d^j/dθ^j of cos kθ and sin kθ are k^j·cos(kθ + jπ/2) and k^j·sin(kθ + jπ/2)."""
        c = np.asarray(coefficients, dtype=float)
        k = np.arange(1, self.H + 1)
        kt = np.multiply.outer(np.asarray(theta, dtype=float), k) + derivative * math.pi / 2.0
        kj = k.astype(float) ** derivative
        value = np.cos(kt) @ (c[1::2] * kj) + np.sin(kt) @ (c[2::2] * kj)
        return value + c[0] if derivative == 0 else value


#: f(q, q̇) → (f, ∂f/∂q, ∂f/∂q̇): q, q̇ of shape (n, N), f (n, N), the derivatives (n, n, N).
Force = Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


@dataclass
class Problem:
    """𝐌q̈ + 𝐂q̇ + 𝐊q = f_ext + f(q, q̇) with f_ext = Σ its harmonics (coefficients ``F_ext``,
    shape (n, 2H + 1), fixed in θ), balanced on ``basis``."""

    Mm: np.ndarray
    Cm: np.ndarray
    Km: np.ndarray
    F_ext: np.ndarray
    force: Force
    basis: Basis

    @property
    def n(self) -> int:
        return self.Mm.shape[0]

    def _linear(self, w: float) -> np.ndarray:
        """𝐊 ⊗ I + ω 𝐂 ⊗ D + ω² 𝐌 ⊗ D² (its three Kronecker products formed once)."""
        if not hasattr(self, "_kron"):
            I, D = np.eye(2 * self.basis.H + 1), self.basis.D
            self._kron = (np.kron(self.Km, I), np.kron(self.Cm, D), np.kron(self.Mm, D @ D))
        K, C, M = self._kron
        return K + w * C + (w * w) * M

    def _samples(self, U: np.ndarray, w: float):
        Q = U.reshape(self.n, -1)
        q, qt = Q @ self.basis.E.T, Q @ self.basis.Et.T
        return Q, q, qt, self.force(q, w * qt)

    def residual(self, U: np.ndarray, w: float) -> np.ndarray:
        """R(U, ω) of the module text."""
        _, _, _, (f, _, _) = self._samples(U, w)
        return self._linear(w) @ U - self.F_ext.ravel() - (f @ self.basis.P.T).ravel()

    def jacobian(self, U: np.ndarray, w: float):
        """(R, ∂R/∂U, ∂R/∂ω, P·diag(∂f/∂q̇)·E blocks) at (U, ω): the Jacobians exact, from the
        force law's derivatives at the samples."""
        b, n = self.basis, self.n
        _, _, qt, (f, fq, fv) = self._samples(U, w)
        L = self._linear(w)
        R = L @ U - self.F_ext.ravel() - (f @ b.P.T).ravel()
        m = 2 * b.H + 1
        _, KC, KM = self._kron

        def blocks(g: np.ndarray, E: np.ndarray) -> np.ndarray:
            """The n × n blocks P·diag(g[i, j])·E (each m × m) of each g as one (n m) × (n m)
            matrix."""
            each = (b.P * g[..., None, :]) @ E  # (…, n, n, m, m)
            return each.swapaxes(-3, -2).reshape(*g.shape[:-3], n * m, n * m)

        Bq, V = blocks(np.stack([fq, fv]), b.E)  # V = P diag(∂f/∂q̇) E, for Hill's Δ₁
        J = L - Bq - w * blocks(fv, b.Et)
        # q̇ = ω·(E_θ Q): the force moves with ω through the speeds
        dR_dw = (KC + 2.0 * w * KM) @ U - (np.einsum("ijs,js->is", fv, qt) @ b.P.T).ravel()
        return R, J, dR_dw, V

    def exponents(self, U: np.ndarray, w: float) -> np.ndarray:
        """Hill's Floquet exponents (module text): the 2n of the quadratic eigenproblem's
        exponents whose imaginary parts are smallest in modulus, largest real part first."""
        b, n = self.basis, self.n
        _, J, _, V = self.jacobian(U, w)
        I = np.eye(2 * b.H + 1)
        D2 = np.kron(self.Mm, I)
        D1 = np.kron(self.Cm, I) + 2.0 * w * np.kron(self.Mm, b.D) - V
        size = D2.shape[0]
        Minv = np.linalg.inv(D2)
        A = np.block([[np.zeros((size, size)), np.eye(size)], [-Minv @ J, -Minv @ D1]])
        lam = np.linalg.eigvals(A)
        lam = lam[np.argsort(np.abs(lam.imag), kind="stable")][: 2 * n]
        return lam[np.argsort(-lam.real, kind="stable")]


def newton(problem: Problem, U: np.ndarray, w: float, scale: float,
           tol: float = TOL, max_iter: int = MAX_NEWTON,
           least_squares: bool = False) -> tuple[np.ndarray, int, float]:  # fmt: skip
    """R(U, ω) = 0 at fixed ω by Newton's method from ``U``, each step halved until the residual
    falls (a contact's samples switch on and off between iterates, where a full step can
    overshoot): (U, steps, last scaled step).  With ``least_squares`` each step is the shortest
    least-squares one (a structure's damper mass with no sample in contact floats: its mean is
    free, :mod:`symimpact.forced.orbits.hb_structure`)."""
    step = math.inf
    R, J, _, _ = problem.jacobian(U, w)
    norm = float(np.linalg.norm(R))
    for it in range(1, max_iter + 1):
        try:
            if least_squares:
                dU = np.linalg.lstsq(J, -R, rcond=1e-13)[0]
            else:
                dU = np.linalg.solve(J, -R)
        except np.linalg.LinAlgError:
            raise MethodNotApplicable(
                "hb", "the balance's Jacobian is singular: a fold, or no time sample in contact "
                "(raise time_samples) so that the impact mass floats") from None  # fmt: skip
        step = float(np.max(np.abs(dU))) / scale  # the full Newton step, whatever is taken
        if not math.isfinite(step):
            break
        lam = 1.0
        for _ in range(HALVINGS):  # the residual alone judges a step; the Jacobian once taken
            trial = U + lam * dU
            R_t = problem.residual(trial, w)
            norm_t = float(np.linalg.norm(R_t))
            if norm_t < norm or step < tol:
                break
            lam *= 0.5
        else:
            raise MethodNotApplicable(
                "hb", f"Newton stalled: no step along its direction down to 2^-{HALVINGS} lowers "
                "the residual (a contact's onset between samples makes it discontinuous there)")  # fmt: skip
        U, norm = trial, norm_t
        if step < tol:
            return U, it, step
        R, J, _, _ = problem.jacobian(U, w)
    raise MethodNotApplicable("hb", f"Newton did not converge (last step {step:.1e} of the scale)")


def law_at_samples(law: str, params: tuple, delta: np.ndarray, ddelta: np.ndarray):
    """(F, ∂F/∂δ, ∂F/∂δ̇) of the compliant ``law`` ("linear", "cubic", "hertz",
    "hunt-crossley") with its ``params`` (as Step 17's kernels take them) at the penetrations δ
    and rates δ̇ of the samples: Step 17's derived bundle ``force_<law>_and_derivatives``
    (:mod:`symimpact.generated.multi_harmonic_balance`) where δ > 0, zero between the walls
    (the bundle is not evaluated there: δ^1.5 of a negative δ)."""
    from ...generated import multi_harmonic_balance as step17

    bundle = getattr(step17, f"force_{law.replace('-', '_')}_and_derivatives")
    F, F_d, F_dd = np.zeros_like(delta), np.zeros_like(delta), np.zeros_like(delta)
    on = delta > 0.0
    if on.any():
        F[on], F_d[on], F_dd[on] = bundle(delta[on], ddelta[on], *params)
    return F, F_d, F_dd


def _contact_force(system: ImpactSystem, contact: CompliantContact) -> Force:
    """f(q, q̇) of the impact damper for q = (x, y) (module text), with its derivatives: at the
    samples in contact the law's force and slopes, Step 17's derived bundle
    ``force_<law>_and_derivatives`` (:mod:`symimpact.generated.multi_harmonic_balance`), and
    Step 17's chain rule through z = y − x (``aft_sample_slopes``)."""
    from ..simulation import _law_parameters

    _law_parameters(system, contact.law)  # a law without its parameters: refused in one line
    params = {
        "linear": (system.k1, system.c1),
        "cubic": (system.a, system.b, system.c1),
        "hertz": (system.k_hz, system.c1),
        "hunt-crossley": (system.k_hz, 0.0 if contact.chi is None else float(contact.chi)),
    }[contact.law]
    h = 0.5 * system.gap

    def force(q: np.ndarray, qd: np.ndarray):
        z, zd = q[1] - q[0], qd[1] - qd[0]
        s = np.where(z >= 0.0, 1.0, -1.0)
        F, F_d, F_dd = law_at_samples(contact.law, params, s * z - h, s * zd)
        f = np.stack([s * F, -s * F])  # on M, on m
        # ∂(−sF)/∂z = −F_δ and ∂(−sF)/∂ż = −F_δ̇ on either wall (s² = 1); z = y − x
        fq = np.stack([[-F_d, F_d], [F_d, -F_d]])
        fv = np.stack([[-F_dd, F_dd], [F_dd, -F_dd]])
        return f, fq, fv

    return force


@dataclass(frozen=True)
class HBOrbit:
    """A periodic orbit by harmonic balance (SI units).

    ``omega`` [rad/s]: Ω; ``subharmonic``: ν (period 2πν/Ω); ``harmonics``: H; ``samples``: N;
    ``x``, ``y`` [m]: the coefficients (a₀, a₁, b₁, …) of x and y in θ = Ωt/ν (the forcing's
    phase at t = 0 as given); ``amplitude`` [m]: max abs(x); ``exponents`` [1/s]: Hill's Floquet
    exponents; ``multipliers``: their e^{λT} moduli, descending; ``stable``: all < 1;
    ``iterations``: Newton steps; ``residual``: the balance's residual relative to the force."""

    omega: float
    subharmonic: int
    harmonics: int
    samples: int
    x: tuple[float, ...]
    y: tuple[float, ...]
    amplitude: float
    exponents: tuple[complex, ...]
    multipliers: tuple[float, ...]
    stable: bool
    iterations: int
    residual: float

    def state(self, t: float = 0.0) -> tuple[float, float, float, float]:
        """(x, ẋ, z, ẏ) at time ``t`` [s], z = y − x: the series evaluated."""
        basis = Basis.of(self.harmonics, 2 * self.harmonics + 1)
        w = self.omega / self.subharmonic
        th = np.array([w * t])
        X, Y = np.array(self.x), np.array(self.y)
        x, xd = basis.at(X, th)[0], w * basis.at(X, th, 1)[0]
        y, yd = basis.at(Y, th)[0], w * basis.at(Y, th, 1)[0]
        return float(x), float(xd), float(y - x), float(yd)

    def as_dict(self) -> dict[str, Any]:
        """JSON keys in SI: omega, amplitude, stable, multipliers, and the balance's own."""
        return {
            "omega": self.omega,
            "amplitude": self.amplitude,
            "stable": self.stable,
            "multipliers": list(self.multipliers),
            "period_multiple": self.subharmonic,
            "harmonics": self.harmonics,
            "time_samples": self.samples,
            "x": list(self.x),
            "y": list(self.y),
            "iterations": self.iterations,
            "residual": self.residual,
        }


def _problem(system, forcing, contact, H, N, nu) -> Problem:
    basis = Basis.of(H, N)
    Mm = np.diag([system.M, system.m])
    Cm = np.diag([system.C, 0.0])
    Km = np.diag([system.K, 0.0])
    F_ext = _forcing_terms(system, forcing, H, nu)
    return Problem(Mm, Cm, Km, F_ext, _contact_force(system, contact), basis)


def _forcing_terms(system, forcing, H: int, nu: int) -> np.ndarray:
    """The forcing's coefficients on (x, y): (F + K·X_b) cos Θ − C·Ω·X_b sin Θ on x,
    Θ = νθ + φ (Eq. F1's absolute x with the base moving as X_b cos Θ)."""
    F_ext = np.zeros((2, 2 * H + 1))
    A = forcing.primary_force + system.K * forcing.X_b
    B = -system.C * forcing.omega * forcing.X_b
    c, s = math.cos(forcing.phase), math.sin(forcing.phase)
    F_ext[0, 2 * nu - 1] = A * c + B * s
    F_ext[0, 2 * nu] = -A * s + B * c
    return F_ext


def _amplitude(basis: Basis, X: np.ndarray) -> float:
    """max abs(x) of the series X: the largest of 64 samples a harmonic, refined by Newton on
    x' = 0 (the series' derivatives are exact)."""
    th = np.linspace(0.0, 2.0 * math.pi, 64 * basis.H + 1)
    v = basis.at(X, th)
    t = th[int(np.argmax(np.abs(v)))]
    for _ in range(50):
        d1 = basis.at(X, np.array([t]), 1)[0]
        d2 = basis.at(X, np.array([t]), 2)[0]
        if d2 == 0.0:
            break
        step = d1 / d2
        t -= step
        if abs(step) < 1e-15:
            break
    return float(max(abs(basis.at(X, np.array([t]))[0]), np.max(np.abs(v))))


def _checked(system, forcing, contact, harmonics, time_samples, subharmonic):
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    checks.instance("forcing", forcing, Forcing, "a Forcing")
    if not isinstance(contact, CompliantContact):
        raise ParameterError(
            "contact", "harmonic balance needs a compliant contact law (cubic, hertz, linear, "
            "hunt-crossley): a rigid impact has no force to balance")  # fmt: skip
    H = checks.whole_number("harmonics", harmonics, 1, MAX_HARMONICS)
    nu = checks.whole_number("subharmonic", subharmonic, 1, 64)
    if nu > H:
        raise ParameterError("harmonics", f"must be at least the period multiple {nu}: the "
                             f"forcing is harmonic {nu} of the orbit's base frequency")  # fmt: skip
    N = DEFAULT_SAMPLES_PER_HARMONIC * H if time_samples is None else time_samples
    N = checks.whole_number("time_samples", N, 1, 1 << 20)
    if N < 2 * H + 1:
        raise ParameterError("time_samples", f"must be at least 2H + 1 = {2 * H + 1} for H = {H} "
                             "harmonics (fewer samples alias the series itself)")  # fmt: skip
    return H, N, nu


def _start(system, forcing, contact, H, N, nu) -> np.ndarray:
    """Coefficients of the attractor a run from rest settles on (:func:`coefficients_of` of the
    state after 300 periods), its contacts checked against N samples a period."""
    from .shooting import settled_state

    state, _ = settled_state(system, forcing, contact, 300, (0.0, 0.0, 0.0, 0.0))
    return coefficients_of(system, forcing, contact, state, H, nu, time_samples=N)


def coefficients_of(system: ImpactSystem, forcing: Forcing, contact: CompliantContact,
                    state: Any, harmonics: int, subharmonic: int = 1,
                    phase: float | None = None,
                    time_samples: int | None = None) -> np.ndarray:  # fmt: skip
    """The coefficients (x then y, H = ``harmonics``) of the motion from ``state`` (x, ẋ, z, ẏ)
    at t = 0 over ν = ``subharmonic`` forcing periods: the compliant engine's samples (64 a
    period, H below 32 of them), transformed; in θ = Ωt/ν with the forcing's phase ``forcing.phase``
    at t = 0, or, given ``phase``, moved to the frame where the forcing's phase at θ = 0 is that
    one (a shift of θ by δ = (φ − phase)/ν turns (aₖ, bₖ) by kδ).  Given ``time_samples`` N, a
    motion with a contact shorter than the spacing of N samples a period (one that can fall
    between two samples) is refused (:func:`_check_contacts_resolved`)."""
    from ..simulation import simulate_forced

    per = 64 * max(1, math.ceil(harmonics / 16))
    x0, v0, z0, u0 = (float(c) for c in state)
    res = simulate_forced(system, forcing, contact=contact.law, chi=contact.chi,
                          periods=subharmonic, x0=x0, xdot0=v0, y0=x0 + z0, ydot0=u0,
                          samples_per_period=per)  # fmt: skip
    if time_samples is not None:
        _check_contacts_resolved(system, contact, res, time_samples, subharmonic)
    s = np.asarray(res.samples)[:-1]
    b = Basis.of(harmonics, len(s))
    X, Y = b.P @ s[:, 0], b.P @ (s[:, 0] + s[:, 2])
    if phase is not None and forcing.phase != phase:
        # x(θ) in the new frame is x(θ − δ) in this one: the forcing cos(νθ + φ) becomes
        # cos(νθ + φ − νδ) = cos(νθ + phase)
        delta = (forcing.phase - phase) / subharmonic
        k = np.arange(1, harmonics + 1)
        c, sn = np.cos(k * delta), np.sin(k * delta)
        for C in (X, Y):
            a, bk = C[1::2].copy(), C[2::2].copy()
            C[1::2], C[2::2] = a * c - bk * sn, a * sn + bk * c
    return np.concatenate([X, Y])


@on_one_blas_thread
def hb_orbit(system: ImpactSystem, forcing: Forcing, contact: CompliantContact,
             harmonics: Any = 15, time_samples: Any = None, subharmonic: Any = 1,
             start: Any = None) -> HBOrbit:  # fmt: skip
    """The periodic orbit of period 2πν/Ω (ν = ``subharmonic``) by harmonic balance with H =
    ``harmonics`` and N = ``time_samples`` (default 4H) time samples (module text), from ``start``
    (the coefficients of x then y) or from the attractor a run from rest settles on; with its
    Hill stability."""
    H, N, nu = _checked(system, forcing, contact, harmonics, time_samples, subharmonic)
    problem = _problem(system, forcing, contact, H, N, nu)
    w = forcing.omega / nu
    U0 = _start(system, forcing, contact, H, N, nu) if start is None else np.asarray(start, float)
    if U0.shape != (2 * (2 * H + 1),):
        raise ParameterError("start", f"must hold {2 * (2 * H + 1)} coefficients (x then y)")
    U, it, _ = newton(problem, U0, w, 0.5 * system.gap)
    return _orbit(problem, U, forcing.omega, nu, it)


def _check_contacts_resolved(system, contact, res, N: int, nu: int) -> None:
    """Refuse (``time_samples``, one line) the motion of the run ``res`` when a contact lasts
    less than one spacing of N samples over its ν periods (it can fall between two): each onset's
    duration from the derived closed forms at its approach speed (Eq. 34 for the Hertz and
    Hunt–Crossley laws, their elastic part; Eq. 35 for the linear law with its c₁), before
    Newton meets a Jacobian with no sample in contact."""
    from ...generated import closed_forms
    from ..engine import _rigid

    if contact.law == "cubic" or len(res.events) == 0:
        return  # no closed form for the cubic law's duration: not judged
    speeds = np.abs(res.events[:, _rigid.E_VREL])
    speeds = speeds[speeds > 0.0]
    if len(speeds) == 0:
        return
    v = float(np.max(speeds))  # the fastest onset's contact is the shortest
    if contact.law == "linear":
        tau = float(closed_forms.linear_contact_duration_scalar(system.m, system.M, system.k1,
                                                               system.c1))  # fmt: skip
    else:
        tau = float(closed_forms.hertz_contact_duration_scalar(system.m, system.M, system.k_hz, v))
    period = nu * res.forcing.period
    spacing = period / N
    if math.isfinite(tau) and 0.0 < tau < spacing:
        need = math.ceil(period / tau)
        raise ParameterError(
            "time_samples",
            f"the {contact.law} contact lasts about {1e3 * tau:.3g} ms ("
            + ("Eq. 35" if contact.law == "linear" else f"Eq. 34 at the approach speed {v:.3g} m/s")
            + f"), "
            f"less than the spacing of the N = {N} samples ({1e3 * spacing:.3g} "
            f"ms): the contact is stiffer than the sampling resolves; give at least {need} samples")  # fmt: skip


def _orbit(problem: Problem, U: np.ndarray, omega: float, nu: int, it: int,
           stability: bool = True) -> HBOrbit:  # fmt: skip
    """The balanced coefficients ``U`` at ``omega`` as an orbit, with Hill's stability (without
    ``stability``: no exponents yet, for an arc that may be dropped; :func:`with_stability`
    adds them)."""
    b = problem.basis
    R = problem.residual(U, omega / nu)
    m = 2 * b.H + 1
    force = max(float(np.max(np.abs(problem.F_ext))), 1e-300)
    orbit = HBOrbit(
        omega=float(omega), subharmonic=nu, harmonics=b.H, samples=b.N,
        x=tuple(map(float, U[:m])), y=tuple(map(float, U[m:])),
        amplitude=_amplitude(b, U[:m]), exponents=(), multipliers=(), stable=False,
        iterations=it, residual=float(np.max(np.abs(R))) / force,
    )  # fmt: skip
    return with_stability(problem, orbit) if stability else orbit


def with_stability(problem: Problem, orbit: HBOrbit) -> HBOrbit:
    """``orbit`` with Hill's exponents, their multipliers' moduli (descending) and its
    stability (all below 1), from ``problem``'s Jacobian (which the external force does not
    enter)."""
    w = orbit.omega / orbit.subharmonic
    lam = problem.exponents(np.array(orbit.x + orbit.y), w)
    T = 2.0 * math.pi / w
    mult = sorted((float(abs(np.exp(x * T))) for x in lam), reverse=True)
    return dataclasses.replace(orbit, exponents=tuple(complex(x) for x in lam),
                               multipliers=tuple(mult), stable=all(v < 1.0 for v in mult))  # fmt: skip


@dataclass(frozen=True)
class HBCurve:
    """A branch of orbits by harmonic balance, followed in Ω by pseudo-arclength (module text):
    ``orbits`` in the order of the arc; ``folds`` [rad/s]: where Ω turns back along it (a
    saddle-node of the balance); ``ended``: why the branch stopped (the band's end, or what
    failed: a grazing, where a contact is lost, or Newton at the smallest step).  A fold's Ω
    is the extreme of the two points the arc turned between (to within one arc step)."""

    orbits: tuple[HBOrbit, ...]
    folds: tuple[float, ...]
    ended: str

    def as_dict(self) -> dict[str, Any]:
        """points (omega, amplitude, stable), folds and why the branch ended; SI."""
        return {
            "points": [{"omega": o.omega, "amplitude": o.amplitude, "stable": o.stable}
                       for o in self.orbits],
            "folds": list(self.folds),
            "ended": self.ended,
        }  # fmt: skip


@on_one_blas_thread
def hb_curve(system: ImpactSystem, forcing: Forcing, contact: CompliantContact, omega_range: Any,
             harmonics: Any = 15, time_samples: Any = None, subharmonic: Any = 1,
             max_points: int = 2000) -> HBCurve:  # fmt: skip
    """The branch through the orbit a run from rest settles on at the band's first Ω, followed by
    pseudo-arclength continuation in Ω (module text) until it leaves ``omega_range`` = (Ω₁, Ω₂)
    [rad/s] or cannot go on, each orbit with Hill's stability."""
    H, N, nu = _checked(system, forcing, contact, harmonics, time_samples, subharmonic)
    lo, hi = checks.bounds("omega_range", omega_range, "rad/s")
    if not lo > 0.0:
        raise ParameterError("omega_range", f"must lie above 0 rad/s, got {lo:g}")
    first = hb_orbit(system, forcing.at(lo), contact, H, N, nu)
    return arc(system, forcing.at(lo), contact, first, (lo, hi), +1, max_points)


@on_one_blas_thread
def arc(system: ImpactSystem, forcing: Forcing, contact: CompliantContact, first: HBOrbit,
        band: tuple[float, float], direction: int, max_points: int = 2000,
        stability: bool = True) -> HBCurve:  # fmt: skip
    """The branch through the balanced orbit ``first`` (of ``forcing`` at its Ω, whose phase
    the whole branch keeps), followed by pseudo-arclength continuation (module text) with Ω
    rising (``direction`` +1) or falling (−1) from it, until Ω leaves ``band`` (Ω₁, Ω₂) [rad/s]
    or the corrector fails at the smallest step; ``first`` is the curve's first orbit.  Without
    ``stability`` the orbits after the first have no Hill exponents yet (a caller that may drop
    the arc adds them with :func:`with_stability`)."""
    lo, hi = band
    H, N, nu = first.harmonics, first.samples, first.subharmonic
    problem = _problem(system, forcing.at(first.omega), contact, H, N, nu)
    s, w0 = 0.5 * system.gap, first.omega
    m = 2 * (2 * H + 1)

    def parts(Y):
        """(R, ∂R/∂Y) in the scaled unknowns Y = (U/s, Ω/Ω₀), the forcing moved to Ω."""
        omega = Y[-1] * w0
        problem.F_ext = _forcing_terms(system, forcing.at(omega), H, nu)
        R, J, dR_dw, _ = problem.jacobian(Y[:-1] * s, omega / nu)
        A = np.empty((m, m + 1))
        A[:, :m] = J * s
        # Ω moves the forcing's amplitude only through a base's terms; ∂/∂Ω by differences of
        # those (exact for a force, where they do not move)
        dF = (_forcing_terms(system, forcing.at(omega * (1 + 1e-7)), H, nu)
              - _forcing_terms(system, forcing.at(omega * (1 - 1e-7)), H, nu)).ravel() / (2e-7 * omega)  # fmt: skip
        A[:, m] = (dR_dw / nu - dF) * w0
        return R, A

    def tangent(A, previous):
        """The unit null vector of A (m × m + 1): from the SVD at the first point, then from
        the bordered system [A; previousᵀ]·t = (0, 1), one LU solve instead of an SVD, whose
        solution points the way ``previous`` did (t·previous = 1 > 0)."""
        if previous is None:
            t = np.linalg.svd(A)[2][-1]
        else:
            rhs = np.zeros(A.shape[1])
            rhs[-1] = 1.0
            try:
                t = np.linalg.solve(np.vstack([A, previous]), rhs)
            except np.linalg.LinAlgError:  # previous ⟂ the null space (never on a smooth arc)
                t = np.linalg.svd(A)[2][-1]
                t = -t if t @ previous < 0 else t
        return t / np.linalg.norm(t)

    Y = np.concatenate([np.array(first.x + first.y) / s, [1.0]])
    R, A = parts(Y)
    t = tangent(A, None)
    if t[-1] * direction < 0:
        t = -t
    orbits, folds = [first], []
    ds, ended = 0.02, "the band's end"
    while len(orbits) < max_points:
        Yp = Y + ds * t
        Yc, ok = Yp.copy(), False
        for _ in range(CORRECTOR_STEPS):
            R, A = parts(Yc)
            G = np.concatenate([R / max(float(np.max(np.abs(problem.F_ext))), 1e-300),
                                [t @ (Yc - Yp)]])  # fmt: skip
            B = np.vstack([A / max(float(np.max(np.abs(problem.F_ext))), 1e-300), t])
            try:
                dY = np.linalg.solve(B, -G)
            except np.linalg.LinAlgError:
                break
            Yc = Yc + dY
            if not np.all(np.isfinite(Yc)) or not Yc[-1] > 0.0:  # diverged (Ω ≤ 0)
                break
            if np.max(np.abs(dY)) < TOL:
                ok = True
                break
        if not ok:
            ds /= 2.0
            if ds < MIN_ARC_STEP:
                ended = "Newton failed at the smallest step (a grazing, or a contact lost)"
                break
            continue
        _, A = parts(Yc)
        t_new = tangent(A, t)
        if t_new[-1] * t[-1] < 0:  # Ω turned between the two points: the fold, to a step
            turn = max if t[-1] > 0 else min
            folds.append(float(turn(Y[-1], Yc[-1]) * w0))
        Y, t = Yc, t_new
        omega = float(Y[-1] * w0)
        if not lo <= omega <= hi:
            break
        problem.F_ext = _forcing_terms(system, forcing.at(omega), H, nu)
        orbits.append(_orbit(problem, Y[:-1] * s, omega, nu, 0, stability))
        ds = min(ds * 1.5, 0.05)
    return HBCurve(tuple(orbits), tuple(folds), ended)
