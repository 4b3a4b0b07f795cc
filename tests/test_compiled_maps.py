"""The compiled map path: a chunk of points run in one compiled loop gives, point by point, the
bits of the per-point path (each point's own ImpactSystem through ``simulate``), for every kind of
swept input and every contact path; combinations of inputs are refused as the per-point path
refuses them; the compiled figures (DI, ζ_eq) agree with NumPy's least squares."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.errors import MethodNotApplicable, ParameterError
from symimpact.free.simulation import damping_inclination, equivalent_damping_ratio
from symimpact.maps import parameter_map
from symimpact.maps.points import as_points
from symimpact.maps.runs import _Base, _chunk_rows, run_point
from symimpact.model.system import ImpactSystem

FITTED = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GIVEN = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, a=2e5, b=300.0, k1=400.0)
INITIAL = (("x0", 0.0), ("xdot0", 0.5), ("y0", 0.0), ("ydot0", 0.0), ("t_end", 3.0))

CASES = [
    # (base system, contact path, grid): every kind of swept input, every contact path
    (FITTED, None, {"gap": [0.004, 0.009, 0.03], "mass_ratio": [0.05, 0.3], "c1": [0.0, 5.0]}),
    (FITTED, None, {"k_hz": [300.0, 1000.0, 5000.0], "M": [0.5, 2.0]}),  # a, b refitted
    (FITTED, None, {"zeta": [0.0, 0.01, 0.3], "K": [50.0, 400.0]}),  # C = 2ζ√(KM)
    (FITTED, None, {"C": [0.0, 2.0], "m": [0.1, 0.5]}),
    (GIVEN, None, {"a": [0.0, 1e6], "b": [100.0, 900.0]}),
    (GIVEN, "linear", {"k1": [50.0, 4000.0], "gap": [0.005, 0.02]}),
    (FITTED, "hertz", {"k_hz": [200.0, 3000.0], "c1": [0.5, 20.0]}),
    (FITTED, "perturbation", {"M": [0.5, 1.0, 3.0], "gap": [0.006, 0.012]}),
    # initial conditions: a run that never touches, one that starts in contact, end times
    (FITTED, None, {"xdot0": [0.0, 0.01, 0.5, 2.0], "y0": [-0.0045, 0.0, 0.002]}),
    (FITTED, None, {"x0": [-0.003, 0.004], "ydot0": [-0.3, 0.4], "t_end": [0.05, 1.0, 6.0]}),
]


@pytest.mark.parametrize("system, contact, grid", CASES)
def test_a_compiled_chunk_gives_the_bits_of_the_per_point_path(system, contact, grid):
    points = as_points(grid, None)
    base = _Base(system, INITIAL, contact)
    runs = list(range(len(points)))
    rows = _chunk_rows(base, points.names, runs, points.values)
    for run, values, row in zip(runs, points.values, rows, strict=True):
        expected = {"run": run, **run_point(base, points.names, values)}
        assert row == expected, (run, dict(zip(points.names, values, strict=True)))


def test_a_map_refuses_a_combination_as_the_per_point_path_does():
    # each value alone is valid; together K = 1 N/m and C = 5 N s/m exceed critical damping
    with pytest.raises(ParameterError, match=r"^C: damping ratio"):
        parameter_map(FITTED, {"K": [100.0, 1.0], "C": [0.5, 5.0]}, progress=False)
    # y0 within d/2 of one gap but not of the other
    with pytest.raises(ParameterError, match=r"^y0: "):
        parameter_map(FITTED, {"gap": [0.02, 0.004], "y0": [0.0, 0.005]}, progress=False)
    # 1e7 periods of the main mass: K/M large and t_end long together
    with pytest.raises(ParameterError, match=r"^t_end: "):
        parameter_map(
            FITTED, {"K": [100.0, 1e12], "t_end": [1.0, 100.0]}, executor="serial", progress=False
        )


def test_a_run_failing_in_the_loop_raises_the_per_point_error():
    # a cubic term far beyond b: Eq. 31 has no fixed point at the second point; the chunk
    # raises simulate's error for that point, not a row
    base = _Base(GIVEN, INITIAL, "perturbation")
    values = np.array([[1e8], [1e12]])
    assert len(_chunk_rows(base, ("a",), [0], values[:1])) == 1
    with pytest.raises(MethodNotApplicable, match=r"Eq\. 31 has no converging fixed point"):
        _chunk_rows(base, ("a",), [0, 1], values)


def _polyfit_slope(t, y):
    return np.polyfit(t, y, 1)[0]


@pytest.mark.parametrize("seed", range(20))
def test_compiled_figures_agree_with_numpy_least_squares(seed):
    """DI and ζ_eq by centred sums against np.polyfit (an SVD least-squares solve).  Both are
    backward stable.  Their rounding errors in the slope are bounded by a few ULPs times
    Σ|t−t̄||y−ȳ| / Σ(t−t̄)², enlarged by max|t| / (max t − min t) (centring t at a late time
    loses those digits of t − t̄); 100 such units bound the difference with a wide margin."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(4, 40))
    t = np.cumsum(rng.uniform(0.05, 0.5, n)) + rng.uniform(0, 100)
    x = rng.uniform(1e-6, 1e-1) * np.exp(-rng.uniform(0, 3) * (t - t[0])) * rng.uniform(0.5, 1, n)
    peaks = np.column_stack([t, x])
    omega_n = rng.uniform(1.0, 300.0)
    di = damping_inclination(peaks, omega_n)
    expected = abs(_polyfit_slope(t[:4] * omega_n, x[:4]))
    assert abs(di - expected) <= 100 * np.finfo(float).eps * _scale(t[:4] * omega_n, x[:4])
    later = np.maximum.accumulate(x[::-1])[::-1]
    keep = np.append(x[:-1] > later[1:], True)
    zeta = equivalent_damping_ratio(peaks, omega_n)
    expected = -_polyfit_slope(t[keep], np.log(x[keep])) / omega_n
    if keep.sum() < 2:
        assert zeta is None
    else:
        bound = _scale(t[keep], np.log(x[keep])) / omega_n
        assert abs(zeta - expected) <= 100 * np.finfo(float).eps * bound


def _scale(t, y):
    """The size of the slope's rounding errors per ULP (see the test above)."""
    dt, dy = t - t.mean(), y - y.mean()
    offset = 1.0 + np.max(np.abs(t)) / (np.max(t) - np.min(t))
    return float(np.sum(np.abs(dt * dy)) / np.sum(dt * dt) * offset)


def test_figures_are_undefined_below_their_count():
    peaks = np.array([[0.1, 0.01], [0.2, 0.009], [0.3, 0.008]])
    assert damping_inclination(peaks, 10.0) is None
    assert damping_inclination(peaks, 10.0, count=2) == pytest.approx(0.01 / 10.0, rel=1e-12)
    assert equivalent_damping_ratio(peaks[:1], 10.0) is None
    assert math.isfinite(equivalent_damping_ratio(peaks, 10.0))


def test_cached_machine_code_is_dropped_when_a_compiled_source_changes(tmp_path, monkeypatch):
    """numba keys a cache to its own file only; the stepper keeps a digest of every source that
    is compiled into it and drops its cached code (and _batch's) when the digest changes."""
    from symimpact.free import _stepper as st

    monkeypatch.setattr(st.run._cache, "_cache_path", str(tmp_path))
    names = ["_stepper.run-9.py311.nbi", "_stepper.run-9.py311.1.nbc", "_batch.run_many-3.nbi"]
    other = tmp_path / "contact.kernel-1.py311.nbi"  # another module's cache: kept

    def make():
        for n in names:
            (tmp_path / n).write_bytes(b"stale")
        other.write_bytes(b"kept")

    make()
    st._forget_stale_compilations()  # no digest yet: everything of the stepper goes
    assert sorted(f.name for f in tmp_path.iterdir()) == [
        other.name,
        "symimpact-compiled-sources-_stepper.sha256",
    ]
    make()
    st._forget_stale_compilations()  # same sources: the cache stays
    assert all((tmp_path / n).exists() for n in names)
    stamp = tmp_path / "symimpact-compiled-sources-_stepper.sha256"
    stamp.write_text("0" * 64)  # as after an edit of a source
    st._forget_stale_compilations()
    assert not any((tmp_path / n).exists() for n in names) and other.exists()
