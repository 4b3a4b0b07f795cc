"""The compiled fixed-point loops of Eq. 31 (generated/fixed_points.py) against mpmath.

300 random physical points (the ranges the derivation declares).  The iteration kernel is checked
against the same iteration run in 30-digit mpmath from the board's own start and map; the Newton
kernel against ``mpmath.findroot`` of the board's residual h(T) = T²·D(T) − π², a different
algorithm.  Where the iteration of Eq. 31 does not converge the kernel must say so (its step
count reaches the cap), never return an unconverged number as converged.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from symimpact.generated import fixed_points, multiple_scales

from symimpact.errors import ConvergenceError, ParameterError
from symimpact.free.contact import perturbation_duration, perturbation_durations

RTOL = 1e-13
N_POINTS = 300


def _points(fp, rng, n=N_POINTS):
    cols = []
    for a in fp.args:
        u = rng.random(n)
        if a.log:
            cols.append(np.exp(np.log(a.low) + u * (np.log(a.high) - np.log(a.low))))
        else:
            cols.append(a.low + u * (a.high - a.low))
    return np.array(cols).T


def _declared(boards, name):
    return next(f for f in boards["multiple_scales"].fixed_points if f.name == name)


@pytest.mark.parametrize("name", ["contact_duration", "contact_duration_printed"])
def test_iteration_kernel_equals_the_mpmath_iteration(boards, name):
    fp = _declared(boards, name)
    symbols = [a.symbol for a in fp.args]
    start = sp.lambdify(symbols, fp.start, "mpmath")
    step = sp.lambdify([fp.iterate, *symbols], fp.step, "mpmath")
    pts = _points(fp, np.random.default_rng(31))
    value, steps = getattr(fixed_points, name)(*pts.T)
    assert value.shape == steps.shape == (N_POINTS,)
    converged_mp = 0
    with mp.workdps(30):
        for p, v, k in zip(pts, value, steps, strict=True):
            args = [mp.mpf(float(x)) for x in p]
            T = start(*args)
            for _ in range(400):
                T_next = step(T, *args)
                if abs(T_next - T) < mp.mpf(10) ** -25 * abs(T_next):
                    break
                T = T_next
            else:  # mpmath's iteration does not settle either: the kernel must hit its cap
                assert k == fp.max_iter, (p, v, k)
                continue
            converged_mp += 1
            if k < fp.max_iter:
                assert abs(v - T_next) <= RTOL * abs(T_next), (p, v, T_next)
    scalar = getattr(fixed_points, f"{name}_scalar")
    for p, v, k in zip(pts[:20], value[:20], steps[:20], strict=True):
        assert scalar(*map(float, p)) == (v, k)  # the float twin is the same loop
    assert converged_mp >= 0.8 * N_POINTS


def test_newton_kernel_equals_findroot_of_the_residual(boards):
    fp = _declared(boards, "contact_duration_newton")
    b = boards["multiple_scales"].values
    lam = sp.Symbol("lambda", positive=True)  # λ → its derived value in B/A (Eq. 21)
    symbols = [a.symbol for a in fp.args]
    ratio = next(a.symbol for a in fp.args if a.name == "ba")
    amp = {s.name: s for s in b["lambda"].free_symbols}
    lam_ba = sp.simplify(b["lambda"].subs(amp["B"], ratio * amp["A"]))  # B = (B/A)·A
    h = b["contact_duration_residual"].subs(lam, lam_ba)
    assert h.free_symbols <= {fp.iterate, *symbols}
    residual = sp.lambdify([fp.iterate, *symbols], h, "mpmath")
    pts = _points(fp, np.random.default_rng(32))
    value, steps = fixed_points.contact_duration_newton(*pts.T)
    assert (steps < fp.max_iter).mean() >= 0.99, "Newton converges almost everywhere"
    plain, plain_steps = fixed_points.contact_duration(*pts.T)
    with mp.workdps(30):
        for p, v, k in zip(pts, value, steps, strict=True):
            if k >= fp.max_iter:
                continue
            args = [mp.mpf(float(x)) for x in p]
            root = mp.findroot(lambda T, args=args: residual(T, *args), mp.mpf(float(v)))
            assert abs(v - root) <= RTOL * root, (p, v, root)
    # Eq. 31 can have several positive fixed points (h has up to three positive roots when
    # c₁ > 0, because T⁴·exp(−cT) rises and falls): there the iteration settles on a stable one
    # and Newton on the one it reaches from the c₁ = 0 value.  Compare where the root is unique.
    h_np = sp.lambdify([fp.iterate, *symbols], h, "numpy")
    grid = np.geomspace(1e-5, 1e3, 4000)
    single = np.array(
        [np.count_nonzero(np.diff(np.sign(h_np(grid, *p)))) == 1 for p in pts], dtype=bool
    )
    assert single.mean() > 0.97
    ok = (plain_steps < 100) & (steps < 100) & single
    np.testing.assert_allclose(value[ok], plain[ok], rtol=RTOL, atol=0)
    assert np.mean(steps[ok]) < np.mean(plain_steps[ok]) / 2  # and in far fewer steps


def test_kernels_broadcast_scalar_1d_2d():
    m = np.array([0.15, 0.2, 0.25])
    v0 = np.array([[0.01], [0.075], [0.5]])
    for kernel in (fixed_points.contact_duration, fixed_points.contact_duration_newton):
        grid, steps = kernel(m, 155300.0, 83.6, 2.0, v0, -4.0)
        assert grid.shape == steps.shape == (3, 3)
        for i in range(3):
            row, _ = kernel(m, 155300.0, 83.6, 2.0, v0[i, 0], -4.0)
            np.testing.assert_array_equal(row, grid[i])
            for j in range(3):
                one, k = kernel(m[j], 155300.0, 83.6, 2.0, v0[i, 0], -4.0)
                assert np.ndim(one) == 0 and one == grid[i, j] and k == steps[i, j]


def test_runtime_wrapper_matches_the_history_iteration_and_reports_failures():
    v0 = np.array([0.02, 0.075, 0.3])
    ref = perturbation_duration(0.25, 155300.0, 83.6, 5.0, v0, -4.0)
    for method in ("iteration", "newton"):
        got = perturbation_durations(0.25, 155300.0, 83.6, 5.0, v0, -4.0, method=method)
        np.testing.assert_allclose(got, ref.value, rtol=RTOL, atol=0)
    for v in v0:  # the same stopping rule: the same number of steps (±1 for the last ulp)
        one = perturbation_duration(0.25, 155300.0, 83.6, 5.0, v, -4.0)
        _, k = fixed_points.contact_duration(0.25, 155300.0, 83.6, 5.0, v, -4.0)
        assert abs(int(k) - one.iterations) <= 1
    # strong nonlinearity: Eq. 31's iteration oscillates; Newton finds the fixed point
    with pytest.raises(ConvergenceError, match="last iterates") as err:
        perturbation_durations(0.25, 1.553e9, 83.6, 0.0, 1.0, -0.1, method="iteration")
    last = err.value.history
    assert len(last) == 6 and abs(last[-1] - last[-3]) < abs(last[-1] - last[-2])  # 2-cycle
    T = perturbation_durations(0.25, 1.553e9, 83.6, 0.0, 1.0, -0.1, method="newton")
    step = float(multiple_scales.contact_duration_map(T, 0.25, 1.553e9, 83.6, 0.0, 1.0, -0.1))
    assert step == pytest.approx(T, rel=1e-13)  # it is a fixed point of Eq. 31
    # values that would overflow Eq. 31 to a non-finite T are refused at the door
    with pytest.raises(ParameterError, match=r"v0: 1e\+200 m/s lies outside the magnitudes"):
        perturbation_durations(0.25, 1e300, 83.6, 0.0, 1e200, -4.0)
    with pytest.raises(ParameterError, match="ba: B/A in"):
        perturbation_durations(0.25, 1.0, 83.6, 0.0, 1.0, 0.5)
    with pytest.raises(ParameterError, match="method"):
        perturbation_durations(0.25, 1.0, 83.6, 0.0, 1.0, -1, method="secant")


@pytest.mark.parametrize(
    "name", ["contact_duration", "contact_duration_newton", "contact_duration_printed"]
)
@pytest.mark.parametrize(("tol", "max_iter"), [(1e-14, 100), (1e-6, 3), (0.0, 7), (np.nan, 100)])
def test_lanes_give_the_scalar_loops_bits(boards, name, tol, max_iter):
    """Arguments of one shape go through the lane-interleaved loop: every element takes the
    scalar loop's steps, so value and step count equal the generalised ufunc's bit for bit —
    over the declared ranges and beyond them (B/A in (0, 1) makes the start imaginary: NaN), at
    a length that is not a multiple of LANES, with a 2-D shape, and with odd tol and max_iter."""
    (fp,) = [f for b in boards.values() for f in b.fixed_points if f.name == name]
    rng = np.random.default_rng(20261122)
    n = 3 * fixed_points.LANES * 97 + 5
    cols = []
    for a in fp.args:
        u = rng.random(n)
        lo, hi = (a.low / 10, a.high * 10) if a.log else (a.low - 1, a.high + 1)
        cols.append(np.exp(np.log(lo) + u * np.log(hi / lo)) if a.log else lo + u * (hi - lo))
    kernel = getattr(fixed_points, name)
    gufunc = getattr(fixed_points, f"_{name}_gufunc")
    value, steps = kernel(*cols, tol=tol, max_iter=max_iter)
    with np.errstate(all="ignore"):  # the ufunc reports the NaN it makes; the lanes do not
        ref_value, ref_steps = gufunc(*cols, float(tol), int(max_iter))
    assert np.isnan(value).any() and np.isfinite(value).any()  # both kinds of element met
    np.testing.assert_array_equal(value, ref_value)  # NaN where NaN, else the same bits
    np.testing.assert_array_equal(steps, ref_steps)
    square = [c[: 40 * 40].reshape(40, 40) for c in cols]
    v2, s2 = kernel(*square, tol=tol, max_iter=max_iter)
    assert v2.shape == (40, 40)
    np.testing.assert_array_equal(v2, ref_value[:1600].reshape(40, 40))
    np.testing.assert_array_equal(s2, ref_steps[:1600].reshape(40, 40))


def test_where_newton_and_the_iteration_part(boards):
    """Every figure of the docs paragraph "Where Newton and the iteration reach different fixed
    points" (docs/kernels.md), recomputed from the same 2·10⁶ seeded points; the paragraph must
    state these figures (two counts within 20 points, below)."""
    import re
    from pathlib import Path

    fp = _declared(boards, "contact_duration")
    n = 2_000_000
    pts = _points(fp, np.random.default_rng(20261122), n).T
    m, a, b, c1, zdot0, _ = pts
    t_it, s_it = fixed_points.contact_duration(*pts)
    t_nt, s_nt = fixed_points.contact_duration_newton(*pts)
    both = (s_it < fp.max_iter) & (s_nt < fp.max_iter)
    part = both & (np.abs(t_it - t_nt) > 1e-9 * t_it)
    kappa = 3 * a * zdot0**2 * (t_it / np.pi) ** 2 / (4 * b)
    damping = c1 * t_it / m
    residual = max(
        float(np.max(np.abs(multiple_scales.contact_duration_map(t, *pts) - t)[part] / t[part]))
        for t in (t_it, t_nt)
    )
    ratio = t_nt[part] / t_it[part]
    assert np.all(ratio < 1)  # Newton's is the shorter one at every such point
    floor = lambda x, d: np.floor(x * 10**d) / 10**d  # noqa: E731 (bounds stated downwards)
    ceil = lambda x, d: np.ceil(x * 10**d) / 10**d  # noqa: E731
    figures = [
        f"{n:,} points",
        "seed 20261122",
        f"({100 * part.sum() / both.sum():.2f} %)",
        f"within {ceil(residual * 1e15, 1):.1f}e-15 of itself",
        f"κ = 3a·Ż₀²·(T/π)²/(4b) ≥ {floor(kappa[part].min(), 0):.0f}",
        f"the median κ is {np.median(kappa[both]):.2g}",
        f"c₁·T/m ≥ {floor(damping[part].min(), 2):.2f}",
        f"{floor(ratio.min(), 3):.3f} to {ceil(ratio.max(), 2):.2f} times",
        f"(κ ≥ {floor(kappa[part].min(), 0):.0f} with c₁·T/m ≥ {floor(damping[part].min(), 2):.2f})",
    ]
    doc = Path(__file__).resolve().parents[1] / "docs" / "kernels.md"
    text = re.sub(r"\s+", " ", doc.read_text())
    missing = [f for f in figures if f not in text]
    assert not missing, missing
    # The two counts are stated as one CPU gave them: points whose iteration ends on its last
    # allowed step flip with the last bit of libm's pow and sqrt (3 of the 2·10⁶ points between an
    # Intel Xeon and an AMD EPYC). They must hold within 1e-5 of the points (20).
    stated = re.search(r"converge at ([\d,]+) of the points\. They differ at ([\d,]+) of", text)
    assert stated, "the paragraph no longer states the two counts"
    for count, computed in zip(stated.groups(), (both.sum(), part.sum()), strict=True):
        assert abs(int(count.replace(",", "")) - int(computed)) <= 1e-5 * n, (count, computed)


def test_the_kernel_page_example_runs_on_the_impact_mode():
    """docs/kernels.md's code block, run as printed: its B/A is the impact mode's, the mode of
    the linear two-mass system (main spring K, contact b) with the larger |B/A|, from NumPy's
    eigenvectors; and its loop ends on a fixed point of Eq. 31 (issue 35, item 8: the page called
    the out-of-phase root the impact mode where the in-phase root is)."""
    import re
    from pathlib import Path

    import scipy.linalg

    page = (Path(__file__).resolve().parents[1] / "docs" / "kernels.md").read_text()
    (block,) = [b for b in re.findall(r"```python\n(.*?)```", page, flags=re.S) if "ratio =" in b]
    ns: dict = {}
    exec(block, ns)
    M, K, m, b = ns["M"], ns["K"], ns["m"], ns["b"]
    _, vectors = scipy.linalg.eigh([[K + b, -b], [-b, b]], np.diag([M, m]))
    ratios = vectors[1] / vectors[0]  # B/A of each mode
    assert ns["ratio"] == pytest.approx(max(ratios, key=abs), rel=1e-12)
    assert ns["ratio"] > 1  # the in-phase root: the contact is softer than the main spring
    T = ns["T"]
    step = ns["ms"].contact_duration_map(T, m, ns["a"], b, ns["c1"], ns["v0"], ns["ratio"])
    assert step == pytest.approx(T, rel=1e-12)
