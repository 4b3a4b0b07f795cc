"""One run of a map: the system of a point (its swept inputs set on the base system) simulated,
and the row it gives: the figures of Sect. 4 and the energy ledger, with its gap class."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..model.names import INITIAL
from ..model.system import ImpactSystem

#: Output columns of a map row, in table order (after ``run`` and the swept inputs).
OUTPUTS = (
    "n_impacts",
    "n_effective",
    "effectiveness",
    "damping_inclination",
    "zeta_eq",
    "energy_initial",
    "energy_dissipated",
    "energy_dissipated_contact",
    "energy_residual",
    "class",
)


def gap_class(n_impacts: int, n_effective: int) -> str:
    """``in range``, ``out of range`` or ``no impact`` by the criterion of this module."""
    if n_impacts == 0:
        return "no impact"
    return "in range" if n_effective >= n_impacts - n_effective else "out of range"


@dataclass(frozen=True)
class _Base:
    system: ImpactSystem
    initial: tuple[tuple[str, float], ...]
    contact: str | None


def _point_system(base: _Base, names: tuple[str, ...], values: Sequence[float]):
    initial = dict(base.initial)
    changes: dict[str, float] = {}
    ratio = None
    for n, v in zip(names, values, strict=True):
        if n in INITIAL:
            initial[n] = float(v)
        elif n == "mass_ratio":
            ratio = float(v)
        else:
            changes[n] = float(v)
    if ratio is not None:
        if not ratio > 0:
            raise ParameterError("mass_ratio", f"must be positive, got {ratio:g}")
        changes["m"] = ratio * changes.get("M", base.system.M)
    system = base.system.with_(**changes) if changes else base.system
    return system, initial


def run_point(base: _Base, names: tuple[str, ...], values: Sequence[float]) -> dict[str, Any]:
    """The table row (without ``run``) of one map point."""
    from ..free.simulation import simulate

    system, initial = _point_system(base, names, values)
    res = simulate(system, contact=base.contact, **initial)
    e = res.energy
    row: dict[str, Any] = dict(zip(names, (float(v) for v in values), strict=True))
    row.update(
        n_impacts=res.n_impacts,
        n_effective=res.n_effective,
        effectiveness=res.effectiveness,
        damping_inclination=res.damping_inclination,
        zeta_eq=res.zeta_eq,
        energy_initial=e["initial"],
        energy_dissipated=e["dissipated_C"] + e["dissipated_c1"],
        energy_dissipated_contact=e["dissipated_c1"],
        energy_residual=e["residual"],
    )
    row["class"] = gap_class(res.n_impacts, res.n_effective)
    return row


def _system_columns(base: _Base, names: tuple[str, ...], values: np.ndarray) -> dict:
    """Each point's system parameters [SI] as columns, by the rules of
    :meth:`ImpactSystem.with_` (the swept value, else the base's; ``mass_ratio`` sets m = ratio·M;
    a swept ``zeta`` sets C = 2ζ√(KM); a and b fitted to K_Hz are fitted again to a swept
    ``k_hz``), with the same floating-point operations, so that each column holds the bits the
    point's own :class:`ImpactSystem` would."""
    from ..generated import contact_fits

    s = base.system
    n = values.shape[0]
    swept = {name: values[:, j].astype(float) for j, name in enumerate(names)}

    def column(name: str, default: float | None) -> np.ndarray:
        if name in swept:
            return swept[name]
        return np.full(n, np.nan if default is None else float(default))

    col = {name: column(name, getattr(s, name)) for name in ("M", "K", "gap", "c1", "k_hz")}
    col["m"] = swept["mass_ratio"] * col["M"] if "mass_ratio" in swept else column("m", s.m)
    if "C" in swept:
        col["C"] = swept["C"]
    elif "zeta" in swept:
        col["C"] = 2.0 * swept["zeta"] * np.sqrt(col["K"] * col["M"])
    else:
        col["C"] = np.full(n, s.C)
    refit = "k_hz" in swept and not ({"a", "b"} & set(swept)) and s._fitted_a_b()
    fit_k1 = "k_hz" in swept and "k1" not in swept and s.k1 is None

    def fitted(fit) -> np.ndarray:  # one scalar call per distinct K_Hz, as __post_init__ makes
        unique, where = np.unique(swept["k_hz"], return_inverse=True)
        return np.array([float(fit(v, s.delta_max)) for v in unique])[where]

    col["a"] = fitted(contact_fits.cubic_fit_a) if refit else column("a", s.a)
    col["b"] = fitted(contact_fits.cubic_fit_b) if refit else column("b", s.b)
    col["k1"] = fitted(contact_fits.linear_fit_k1) if fit_k1 else column("k1", s.k1)
    return col


def _initial_columns(base: _Base, names: tuple[str, ...], values: np.ndarray) -> np.ndarray:
    """(n, 5): x0, ẋ0, y0, ẏ0, t_end of each point [SI]."""
    initial = dict(base.initial)
    out = np.empty((values.shape[0], len(INITIAL)))
    for k, name in enumerate(INITIAL):
        out[:, k] = values[:, names.index(name)] if name in names else initial[name]
    return out


def _law(base: _Base) -> int:
    from ..free import _stepper

    return _stepper.LAWS[base.contact or base.system.contact]


def _packed(base: _Base, names: tuple[str, ...], values: np.ndarray) -> np.ndarray:
    """(n, N_PARAMS): the stepper's parameter vector of each point (as :func:`_stepper.pack`;
    the tolerances are set per run by :func:`_batch.prepare`)."""
    from ..free import _stepper as st
    from ..free.contact import amplitude_ratio

    col = _system_columns(base, names, values)
    P = np.zeros((values.shape[0], st.N_PARAMS))
    for index, name in (
        (st.P_M, "M"),
        (st.P_K, "K"),
        (st.P_C, "C"),
        (st.P_m, "m"),
        (st.P_a, "a"),
        (st.P_b, "b"),
        (st.P_khz, "k_hz"),
        (st.P_k1, "k1"),
        (st.P_c1, "c1"),
    ):
        P[:, index] = np.nan_to_num(col[name], nan=0.0)  # a missing a, b, K_Hz or k1 packs as 0
    P[:, st.P_h] = 0.5 * col["gap"]
    if _law(base) == st.PERTURBATION:  # B/A of each distinct system, as simulate finds it
        key = P[:, [st.P_M, st.P_K, st.P_m, st.P_a, st.P_b]]
        _, first, where = np.unique(key, axis=0, return_index=True, return_inverse=True)
        ratios = [
            float(amplitude_ratio(_point_system(base, names, values[i])[0], ba="impact"))
            for i in first
        ]
        P[:, st.P_ba] = np.asarray(ratios)[where.reshape(-1)]
    return P


def _refused(base: _Base, names: tuple[str, ...], values: np.ndarray) -> np.ndarray:
    """Indices of the points that a check combining several inputs refuses (the ones made on
    each value alone are :func:`engine._validate`'s): damping at or above critical, C and ζ
    that disagree, more than ``MAX_PERIODS`` periods, abs(y0 − x0) beyond d/2."""
    from ..free.simulation import MAX_PERIODS

    col = _system_columns(base, names, values)
    init = _initial_columns(base, names, values)
    with np.errstate(all="ignore"):
        critical = 2.0 * np.sqrt(col["K"] * col["M"])
        bad = ~(col["C"] < critical)
        if "C" in names and "zeta" in names:
            zeta = values[:, names.index("zeta")]
            bad |= ~np.isclose(col["C"], 2 * zeta * np.sqrt(col["K"] * col["M"]), rtol=1e-9, atol=0)
        periods = init[:, 4] * np.sqrt(col["K"] / col["M"]) / (2 * math.pi)
        bad |= periods > MAX_PERIODS
        bad |= np.abs(init[:, 2] - init[:, 0]) > 0.5 * col["gap"] * (1 + 1e-12)
    return np.flatnonzero(bad)


def _check_points(base: _Base, names: tuple[str, ...], values: np.ndarray) -> None:
    """Refuse the map, naming the input, if any point's combination of inputs is refused (the
    first such point is set up as its own run, which raises the one-line reason)."""
    for i in _refused(base, names, values)[:1]:
        run_point(base, names, values[i])


def _chunk_rows(base: _Base, names: tuple[str, ...], runs: list[int], values: np.ndarray):
    """The rows of a chunk of points, run in one compiled loop (:func:`_batch.run_many`); each
    row holds the bits :func:`run_point` gives for the same point."""
    from .. import _interrupt
    from ..free import _batch
    from ..free import _stepper as st
    from ..free.simulation import MAX_IMPACTS, REST, RTOL, effectiveness

    values = np.asarray(values, dtype=float).reshape(len(runs), len(names))
    P = _packed(base, names, values)
    init = _initial_columns(base, names, values)
    out = np.empty((len(runs), _batch.N_ROW))
    _interrupt.call(
        _batch.run_many,
        _law(base),
        P,
        np.ascontiguousarray(init[:, :4]),
        np.ascontiguousarray(init[:, 4]),
        RTOL,  # simulate's defaults
        REST,
        MAX_IMPACTS,
        out,
    )
    rows = []
    for k, (run, vals) in enumerate(zip(runs, values, strict=True)):
        r = out[k]
        if r[_batch.R_STATUS] not in (st.OK, st.AT_REST):
            run_point(base, names, vals)  # raises simulate's error for this point
            raise RuntimeError(f"run {run}: the stepper failed (status {r[0]:g})")
        n_imp, n_eff = int(r[_batch.R_N_IMPACTS]), int(r[_batch.R_N_EFFECTIVE])
        row: dict[str, Any] = {"run": int(run)}
        row.update(zip(names, (float(v) for v in vals), strict=True))
        row.update(
            n_impacts=n_imp,
            n_effective=n_eff,
            effectiveness=effectiveness(n_imp, n_eff),
            damping_inclination=_number(r[_batch.R_DI]),
            zeta_eq=_number(r[_batch.R_ZETA]),
            energy_initial=float(r[_batch.R_E_INITIAL]),
            energy_dissipated=float(r[_batch.R_DISS_C] + r[_batch.R_DISS_C1]),
            energy_dissipated_contact=float(r[_batch.R_DISS_C1]),
            energy_residual=float(r[_batch.R_RESIDUAL]),
        )
        row["class"] = gap_class(n_imp, n_eff)
        rows.append(row)
    return rows


def _number(v: float) -> float | None:
    return None if math.isnan(v) else float(v)


def _run_chunk(payload: tuple[_Base, tuple[str, ...], list[int], np.ndarray]):
    """The rows of one chunk of a map (what every executor runs)."""
    base, names, runs, values = payload
    return _chunk_rows(base, names, runs, values)


def _first_point(payload: tuple) -> tuple:
    """A chunk (base, names, runs, values) cut to its first point: the warm-up before local
    workers fork (:func:`symimpact._pool.spread`)."""
    base, names, runs, values = payload
    return base, names, runs[:1], values[:1]


_run_chunk.warm_payload = _first_point  # type: ignore[attr-defined]


def _run_chunk_per_point(payload: tuple[_Base, tuple[str, ...], list[int], np.ndarray]):
    """The same rows, one :func:`run_point` (ImpactSystem, then ``simulate``) per point: the
    path the compiled loop replaced, kept as the reference of the tests and the baseline of
    ``benchmarks.map_throughput``."""
    base, names, runs, values = payload
    return [
        {"run": int(run), **run_point(base, names, v)} for run, v in zip(runs, values, strict=True)
    ]
