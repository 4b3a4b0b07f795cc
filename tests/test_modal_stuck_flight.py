"""The stuck (coupled) structure's flight in the modal engine (:func:`_modal_flight._held_free`) and the
search for a stuck mass's release (:func:`_modal_search._release`), against the matrix exponential.

While a mass rides on its point the structure is M_s q̈ + Cq̇ + Kq = F cos(Ωt + φ) with
M_s = diag(Mᵢ) + mφφᵀ.  The engine writes its flight from A's eigen-decomposition, one exponential
for each conjugate pair of eigenvalues and its columns formed once per flight; the reference here
is SciPy's ``expm`` of the real first-order matrix (scaling and squaring, no eigenvectors) plus
the harmonic particular solution, each state to 1e-12 of the motion's scale (V's condition
number is about 400 here, so rounding may reach 400 ulps; measured: 1.9e-14).  An over-damped mode
(ζ = 3) gives the coupled structure real eigenvalues, which count once."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import expm
from scipy.optimize import brentq

from symimpact.forced.engine import _modal_flight, _modal_ledger, _modal_search
from symimpact.forced.engine._rigid import N_PARAMS, P_C, P_F0, P_K, P_M, P_PHI, P_W, P_XB

W, PHASE = 2 * math.pi * 7.0, 0.4
SHAPE = np.array([[1.0, -0.7, 0.4]])  # the stuck mass's point
MASS = np.array([0.2])
EPS = np.finfo(float).eps
TWO_POINTS = np.array([SHAPE[0], [0.3, 1.0, -0.2]])  # the stuck mass's point and another


def _parameters(zetas):
    """Three modes of 6, 25 and 57 Hz, modal masses 1, 0.8 and 1.2 kg, forced at Ω (7 Hz)."""
    pm = np.zeros((3, N_PARAMS))
    for i, (m, w, z) in enumerate(zip((1.0, 0.8, 1.2), (6.0, 25.0, 57.0), zetas, strict=True)):
        w = 2 * math.pi * w
        pm[i, P_M], pm[i, P_K], pm[i, P_C] = m, m * w * w, 2 * z * w * m
        pm[i, P_F0] = (3.0, -1.0, 0.5)[i]
        pm[i, P_W], pm[i, P_PHI] = W, PHASE
    return pm


def _config(pm):
    e, nothing = np.zeros(0), np.zeros(0, dtype=np.int64)
    return _modal_flight._config(pm, SHAPE, MASS, np.array([1]), np.zeros((0, 3)), e, e, e, nothing,
                          nothing, 0.0)  # fmt: skip


def _inverse_mass(pm):
    """M_s⁻¹ of the structure carrying the stuck mass, M_s = diag(Mᵢ) + mφφᵀ."""
    return np.linalg.inv(np.diag(pm[:, P_M]) + MASS[0] * np.outer(SHAPE[0], SHAPE[0]))


def _reference(pm):
    """(A, b, X̂): X' = AX + b cos(Ωt + φ), X = (q, q̇), and its harmonic solution's amplitude."""
    Mi = _inverse_mass(pm)
    A = np.block([[np.zeros((3, 3)), np.eye(3)],
                  [-Mi @ np.diag(pm[:, P_K]), -Mi @ np.diag(pm[:, P_C])]])  # fmt: skip
    b = np.concatenate([np.zeros(3), Mi @ pm[:, P_F0]])
    Xhat = np.linalg.solve(1j * W * np.eye(6) - A, b)
    return A, b, Xhat


def _exact(pm, t0, X0, tau):
    A, _, Xhat = _reference(pm)

    def particular(t):
        return (Xhat * np.exp(1j * (W * t + PHASE))).real

    return expm(A * tau) @ (X0 - particular(t0)) + particular(t0 + tau)


def test_conjugate_pairs_count_once_and_real_eigenvalues_once_each():
    lam = np.array([-1 + 5j, -2.0, -1 - 5j, -3 + 0j, -0.5 - 2j, -0.5 + 2j])
    w = _modal_flight._pair_weights(lam)
    assert list(w) == [2.0, 1.0, 0.0, 1.0, 0.0, 2.0]
    # an eigenvalue without its conjugate (not met for a real A): every term kept once
    assert list(_modal_flight._pair_weights(np.array([-1 + 5j, -1 - 4j]))) == [1.0, 1.0]


def test_a_stuck_flight_is_the_matrix_exponential():
    for zetas in ((0.01, 0.02, 0.03), (0.01, 3.0, 0.03)):  # the second: an over-damped mode
        pm = _parameters(zetas)
        cfg = _config(pm)
        weights = cfg[11][-1, : cfg[2]].real
        assert not cfg[6] and cfg[5]
        if zetas[1] > 1:
            assert np.any(weights == 1.0)  # real eigenvalues, each once
        rng = np.random.default_rng(11)
        starts = [(0.37, rng.normal(size=3) * 1e-3, rng.normal(size=3) * 1e-2) for _ in range(2)]
        q, v = np.empty(3), np.empty(3)
        for t0, q0, v0 in (*starts, starts[0]):  # two flights, then the first again: the cache
            taus = np.linspace(0.0, 3 * 2 * math.pi / W, 17)
            exact = np.array([_exact(pm, t0, np.concatenate([q0, v0]), tau) for tau in taus])
            scale_q, scale_v = np.max(np.abs(exact[:, :3])), np.max(np.abs(exact[:, 3:]))
            for tau, X in zip(taus, exact, strict=True):
                _modal_flight._states(pm, cfg, 1, t0, q0, v0, tau, q, v)
                assert np.max(np.abs(q - X[:3])) < 1e-12 * scale_q
                assert np.max(np.abs(v - X[3:])) < 1e-12 * scale_v


def test_a_stuck_flight_projected_on_points_is_the_matrix_exponential():
    """The flight read at two points (:func:`_modal_flight._held_rows`, :func:`_modal_flight._rows_at`): φᵀq,
    φᵀq̇ and φᵀq̈ against the same reference, q̈ from the equation of motion (the residual
    M_s⁻¹(F cos θ − Cq̇ − Kq)), each to 1e-12 of its scale (as the states: V's condition)."""
    shapes = TWO_POINTS
    for zetas in ((0.01, 0.02, 0.03), (0.01, 3.0, 0.03)):
        pm = _parameters(zetas)
        cfg = _config(pm)
        Mi = _inverse_mass(pm)
        rng = np.random.default_rng(5)
        t0, q0, v0 = 0.21, rng.normal(size=3) * 1e-3, rng.normal(size=3) * 1e-2
        rows, out = np.zeros((2, 3, 8), dtype=np.complex128), np.zeros((2, 4))
        _modal_flight._held_rows(pm, cfg, shapes, t0, q0, v0, rows, out)
        # the sum's own start: φᵀq0 to c's rounding, up to V's condition (400) in ulps of the terms
        ulp = EPS * np.abs(rows[:, 0]).max(axis=1)
        assert np.all(np.abs(out[:, 3] - shapes @ q0) < 400 * ulp)
        taus = np.linspace(0.0, 2 * 2 * math.pi / W, 13)
        got, want = [], []
        for tau in taus:
            X = _exact(pm, t0, np.concatenate([q0, v0]), tau)
            force = pm[:, P_F0] * math.cos(W * (t0 + tau) + PHASE)
            acc = Mi @ (force - pm[:, P_C] * X[3:] - pm[:, P_K] * X[:3])
            _modal_flight._rows_at(rows, cfg[11], cfg[1], cfg[2], W, tau, out)
            got.append(out[:, :3].copy())
            want.append(np.stack([shapes @ X[:3], shapes @ X[3:], shapes @ acc], axis=1))
        got, want = np.array(got), np.array(want)
        scale = np.max(np.abs(want), axis=(0, 1))
        assert np.all(np.max(np.abs(got - want), axis=(0, 1)) < 1e-12 * scale)


def test_a_stuck_flight_starts_exactly_where_the_last_one_ended():
    """At τ = 0 the coupled flight gives back its start to the bit, read whole (the state) and
    projected on points (out[r, 0] − out[r, 3] = 0): its closed form's own value there differs
    from the start by the rounding of the coefficients c = V⁻¹(…) (the raw sum, checked
    nonzero here), and a search that measured displacements from the start saw a mass that had
    just left its wall beyond it.  Over τ of 1e-9 of a period the change in φᵀq then matches
    its Taylor polynomial φᵀq̇₀τ + φᵀq̈₀τ²/2 (the next term is 1e-16 of it) to 16 ulps of the
    sum's largest term, the sums' own rounding."""
    shapes = TWO_POINTS
    T = 2 * math.pi / W
    offsets = []
    for zetas in ((0.01, 0.02, 0.03), (0.01, 3.0, 0.03)):
        pm = _parameters(zetas)
        cfg = _config(pm)
        Mi = _inverse_mass(pm)
        rng = np.random.default_rng(7)
        q, v, qr, vr = np.empty(3), np.empty(3), np.empty(3), np.empty(3)
        rows, out = np.zeros((2, 3, 8), dtype=np.complex128), np.zeros((2, 4))
        for _ in range(20):
            t0, q0, v0 = rng.uniform(0, T), rng.normal(size=3) * 1e-3, rng.normal(size=3) * 1e-2
            _modal_flight._states(pm, cfg, 1, t0, q0, v0, 0.0, q, v)
            assert np.array_equal(q, q0) and np.array_equal(v, v0)
            _modal_flight._held_sum(pm, cfg[11], cfg[1], cfg[2], cfg[3], 0.0, qr, vr)
            offsets.append(np.max(np.abs(qr - q0)))
            _modal_flight._held_rows(pm, cfg, shapes, t0, q0, v0, rows, out)
            _modal_flight._rows_at(rows, cfg[11], cfg[1], cfg[2], W, 0.0, out)
            assert np.array_equal(out[:, 0], out[:, 3])
            tau = 1e-9 * T
            force = pm[:, P_F0] * math.cos(W * t0 + PHASE)
            acc = Mi @ (force - pm[:, P_C] * v0 - pm[:, P_K] * q0)
            taylor = shapes @ v0 * tau + shapes @ acc * tau**2 / 2
            _modal_flight._states(pm, cfg, 1, t0, q0, v0, tau, q, v)
            terms = np.abs(cfg[11][:3, : cfg[2] + 1]).max() * np.abs(shapes).sum(axis=1)
            assert np.all(np.abs(shapes @ (q - q0) - taylor) < 16 * EPS * terms)
            _modal_flight._rows_at(rows, cfg[11], cfg[1], cfg[2], W, tau, out)
            terms = np.abs(rows[:, 0]).max(axis=1)
            assert np.all(np.abs(out[:, 0] - out[:, 3] - taylor) < 16 * EPS * terms)
    assert max(offsets) > 0.0  # the raw sum misses the start: what the flight corrects


def test_the_release_is_the_first_time_the_wall_would_pull():
    """From rest on the wall s = +1 at a phase where the point accelerates away from the mass
    (ẍₐ < 0), the release is the first zero of ẍₐ: the engine's certified search against ẍₐ
    sampled 20 000 times a period from the matrix exponential and the first sign change refined
    by Brent's method (1e-12 of the period: the engine's regula falsi stops at 4e-16 of the
    time, the zero's condition is ẍₐ's slope there)."""
    pm = _parameters((0.01, 0.02, 0.03))
    cfg = _config(pm)
    t0, q0, v0 = 0.0, np.zeros(3), np.zeros(3)
    T = 2 * math.pi / W
    Mi = _inverse_mass(pm)

    def accel(tau):
        X = _exact(pm, t0, np.concatenate([q0, v0]), tau)
        force = pm[:, P_F0] * math.cos(W * (t0 + tau) + PHASE)
        load = force - pm[:, P_C] * X[3:] - pm[:, P_K] * X[:3]
        return SHAPE[0] @ (Mi @ load)

    stuck = np.array([1 if accel(0.0) < 0 else -1])
    g0 = stuck[0] * accel(0.0)
    assert g0 < 0
    grid = np.linspace(0.0, T, 20_001)
    g = np.array([stuck[0] * accel(t) for t in grid])
    first = int(np.argmax(g > 0))
    assert first > 0
    root = brentq(lambda t: stuck[0] * accel(t), grid[first - 1], grid[first], xtol=1e-16,
                  rtol=1e-15)  # fmt: skip
    work = np.empty((22, 3))
    watch = np.array([-1, 0, 0], dtype=np.int64)
    # the flight read whole (the state and the point's acceleration from it), then through its
    # projection on the point (the closed form's derivatives, :func:`_modal_flight._held_rows`)
    none, none_out = np.zeros((0, 3, 1), dtype=np.complex128), np.zeros((0, 4))
    rows, out = np.zeros((1, 3, 8), dtype=np.complex128), np.zeros((1, 4))
    assert not cfg[6]
    _modal_flight._held_rows(pm, cfg, SHAPE, t0, q0, v0, rows, out)
    for r, o in ((none, none_out), (rows, out)):
        tau, which = _modal_search._release(pm, cfg, 1, stuck, SHAPE, t0, q0, v0, 2 * T, watch, work, r,
                                     o, 0.0)  # fmt: skip
        assert which == 0
        assert abs(tau - root) < 1e-12 * T


def _flight_reference(pm, shape_s, k1, c1, g, t0, X0):
    """The coupled flight with a pressed linear stop (k1, c1 at the point ``shape_s`` on its wall
    +g; k1 = c1 = 0: none) and base motion: M_sq̈ + (C + c1φφᵀ)q̇ + (K + k1φφᵀ)q = P cos θ +
    Q sin θ + k1·g·φ, P = F + K·X_b, Q = −CΩ·X_b per mode, from SciPy's ``expm``."""
    Mi = _inverse_mass(pm)
    Ks = np.diag(pm[:, P_K]) + k1 * np.outer(shape_s, shape_s)
    Cs = np.diag(pm[:, P_C]) + c1 * np.outer(shape_s, shape_s)
    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-Mi @ Ks, -Mi @ Cs]])
    P = pm[:, P_F0] + pm[:, P_K] * pm[:, P_XB]
    Q = -pm[:, P_C] * W * pm[:, P_XB]
    Xhat = np.linalg.solve(1j * W * np.eye(6) - A, np.concatenate([np.zeros(3), Mi @ (P - 1j * Q)]))
    Xs = np.concatenate([np.linalg.solve(Ks, k1 * g * shape_s), np.zeros(3)])

    def particular(t):
        return (Xhat * np.exp(1j * (W * t + PHASE))).real + Xs

    return lambda tau: expm(A * tau) @ (X0 - particular(t0)) + particular(t0 + tau)


@pytest.mark.parametrize("case", ["forced and base motion", "short", "a pressed stop"])
def test_a_stuck_flights_ledger_is_the_quadrature_of_its_power(case):
    """The coupled flight's closed-form ledger (:func:`_modal_ledger._held_ledger`) against QUADPACK's
    adaptive quadrature of the same integrands along the matrix exponential's flight: the modal
    forces' work Σᵢ Fᵢcos θ·q̇ᵢ − (Kᵢ(qᵢ − Γᵢx_b) + Cᵢ(q̇ᵢ − Γᵢẋ_b))Γᵢẋ_b, the modes'
    dissipation Σᵢ Cᵢ(q̇ᵢ − Γᵢẋ_b)² and a pressed stop's c₁(φₛᵀq̇)², each to 1e-12 of the
    integral of its absolute value (QUADPACK's requested 1e-12; measured 3e-14 at most)."""
    pm = _parameters((0.01, 0.02, 0.03))
    shape_s, k1, c1, g, tau = np.array([0.2, 0.9, -0.5]), 0.0, 0.0, 0.0, 1.3 * 2 * math.pi / W
    if case != "a pressed stop":
        pm[:, P_XB] = (0.4e-3, -0.2e-3, 0.1e-3)  # Γᵢ·X_b
    if case == "short":
        tau = 2e-4
    if case == "a pressed stop":
        k1, c1, g, tau = 3e4, 12.0, -2e-3, 0.7 * 2 * math.pi / W
    e = np.zeros(0)
    nothing = np.zeros(0, dtype=np.int64)
    stops = (shape_s[None, :], np.array([k1]), np.array([c1]), np.array([g]), np.array([1]),
             np.array([0])) if k1 else (np.zeros((0, 3)), e, e, e, nothing, nothing)  # fmt: skip
    Sphi, sk, sc, sg, contact, srig = stops
    cfg = _modal_flight._config(
        pm, SHAPE, MASS, np.array([1]), Sphi, sk, sc, sg, contact, srig, 0.0
    )
    assert not cfg[6]
    t0 = 0.83
    rng = np.random.default_rng(3)
    q0, v0 = rng.normal(size=3) * 1e-3, rng.normal(size=3) * 1e-2
    flight = _flight_reference(pm, shape_s, k1, c1, g, t0, np.concatenate([q0, v0]))

    def integrands(s):
        X = flight(s)
        q, v = X[:3], X[3:]
        th = W * (t0 + s) + PHASE
        xg, vg = pm[:, P_XB] * math.cos(th), -pm[:, P_XB] * W * math.sin(th)
        rel = v - vg
        power = pm[:, P_F0] * math.cos(th) * v - (pm[:, P_K] * (q - xg) + pm[:, P_C] * rel) * vg
        return np.array([power.sum(), (pm[:, P_C] * rel * rel).sum(), c1 * (shape_s @ v) ** 2])

    want, scale = np.zeros(3), np.zeros(3)
    for j in range(3):
        want[j] = quad(
            lambda s, j=j: integrands(s)[j], 0.0, tau, limit=400, epsabs=0, epsrel=1e-12
        )[0]
        scale[j] = quad(lambda s, j=j: abs(integrands(s)[j]), 0.0, tau, limit=400, epsrel=1e-8)[0]
    ledger = np.zeros(4)
    _modal_ledger._held_ledger(pm, cfg, t0, q0, v0, tau, ledger, Sphi, sc, contact)
    got = ledger[[0, 1, 3]]
    assert np.all(np.abs(got - want) <= 1e-12 * scale + 1e-300)
    if k1:
        assert want[2] > 0.0
