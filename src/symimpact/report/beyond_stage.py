"""Report stage "beyond": what the paper does not show.

- Accuracy map: the error of the perturbation (Eq. 31), Hertz (Eq. 34) and linear (Eq. 35)
  contact durations against the numerical truth (the Hertz law integrated with the main mass on
  its spring) over mass ratio m/M, approach speed v0 and main stiffness K.
- Lindstedt order study: the frequency of the Duffing equation (Eq. 14) to first, second and third
  order (Eq. 19 and beyond) against numerical integration, over ε·α²/ω0².
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import ellipk

from ..free.contact import contact_duration, numerical_contact
from ..generated import closed_forms, lindstedt
from ..model.system import ImpactSystem
from .document import Figure, Section, Table
from .figures import pyplot, save

K_HZ = 1000.0  # N/m^1.5
MAP_K = (100.0, 1000.0, 10000.0)  # N/m
LEVELS = (1.0, 5.0, 10.0)  # per cent
#: Bands of the accuracy map: cividis (readable with any colour vision), dark to light =
#: within 1 %, 5 %, 10 %, beyond.
BAND_COLOURS = ["#00204d", "#575d6d", "#a59c74", "#ffea46"]


def _stroke(width: float, colour: str):
    """A line's outline, so that it is seen on any band of the map."""
    from matplotlib import patheffects

    return [patheffects.withStroke(linewidth=width, foreground=colour)]


HALO = _stroke(3, "w")  # a black line's white halo
OUTLINE = _stroke(2.5, "k")  # a white line's black outline, seen on the light bands
STEPS = 1 + len(MAP_K)


def section(folder: Path, quick: bool, tick: Any, earlier: Any = ()) -> Section:
    """Build the stage: write its figures into ``folder`` and return its section (``earlier``:
    the sections built before it, unused here)."""
    s = Section("beyond", "Beyond the paper: accuracy map and Lindstedt order study")
    _accuracy_map(s, folder, 8 if quick else 32, tick)
    _lindstedt(s, folder, 12 if quick else 60)
    tick()
    return s


def accuracy_errors(m_ratio: np.ndarray, v0: np.ndarray, K: float) -> dict[str, np.ndarray]:
    """Relative errors [%] of each method's contact duration against the numerical truth, on the
    grid m/M × v0 (M = 1 kg, c1 = 0, K_Hz = 1000 N/m^1.5 with its fits), and the truth [s]."""
    out = {k: np.empty((len(m_ratio), len(v0))) for k in ("perturbation", "hertz", "linear")}
    out["truth"] = np.empty((len(m_ratio), len(v0)))
    out["penetration"] = np.empty((len(m_ratio), len(v0)))
    for i, q in enumerate(m_ratio):
        s = ImpactSystem(M=1.0, K=K, m=float(q), gap=0.009, C=0.0, k_hz=K_HZ, c1=0.0)
        truth = np.asarray(numerical_contact(s, v0, law="hertz").duration)
        out["truth"][i] = truth
        out["perturbation"][i] = contact_duration(s, v0, "perturbation").value
        out["hertz"][i] = contact_duration(s, v0, "hertz").value
        out["linear"][i] = contact_duration(s, v0, "linear").value
        out["penetration"][i] = closed_forms.hertz_max_penetration(s.m, s.M, K_HZ, v0)
        for k in ("perturbation", "hertz", "linear"):
            out[k][i] = 100 * (out[k][i] - truth) / truth
    return out


def accurate_by_cancellation(err: np.ndarray, levels: tuple[float, ...] = LEVELS) -> np.ndarray:
    """Cells of a signed-error grid [%] that are within a tolerance only because the error
    passes through zero there: a cell in the band (previous level, level] counts when its
    connected region of {|err| ≤ level} (8-neighbours) holds errors of both signs. A formula's
    regime of validity, where the error shrinks towards a limit, has one sign throughout."""
    from scipy import ndimage

    out = np.zeros(err.shape, dtype=bool)
    below = -1.0  # the first band includes an error of exactly 0
    for level in levels:
        regions, n = ndimage.label(np.abs(err) <= level, structure=np.ones((3, 3)))
        if n:
            ids = np.arange(1, n + 1)
            both = (np.asarray(ndimage.maximum(err, regions, ids)) > 0) & (
                np.asarray(ndimage.minimum(err, regions, ids)) < 0
            )
            out |= np.isin(regions, ids[both]) & (np.abs(err) > below)
        below = level
    return out


def _accuracy_map(s: Section, folder: Path, n: int, tick: Any) -> None:
    m_ratio = np.geomspace(0.02, 1.0, n)
    v0 = np.geomspace(0.01, 1.0, n)
    plt = pyplot()
    fig, axes = plt.subplots(3, len(MAP_K), figsize=(12, 10), sharex=True, sharey=True)
    rows = []
    methods = (
        ("perturbation", "perturbation, Eq. 31 (derived, B/A impact root)"),
        ("hertz", "Hertz, Eq. 34"),
        ("linear", "linear, Eq. 35"),
    )
    for j, K in enumerate(MAP_K):
        err = accuracy_errors(m_ratio, v0, K)
        for i, (key, label) in enumerate(methods):
            ax = axes[i, j]
            size = np.abs(err[key])
            cs = ax.contourf(
                v0,
                m_ratio,
                size,
                levels=[0, *LEVELS, max(100.0, float(np.max(size)) + 1)],
                colors=BAND_COLOURS,
            )
            chance = accurate_by_cancellation(err[key])
            if chance.any():
                with plt.rc_context({"hatch.color": "w", "hatch.linewidth": 0.8}):
                    ax.contourf(v0, m_ratio, chance.astype(float), levels=[0.5, 1.5],
                                colors="none", hatches=["////"])  # fmt: skip
            if (err[key] > 0).any() and (err[key] < 0).any():
                ax.contour(
                    v0,
                    m_ratio,
                    err[key],
                    levels=[0.0],
                    colors="w",
                    linewidths=1.2,
                    path_effects=OUTLINE,
                )
            ax.contour(v0, m_ratio, err["penetration"], levels=[0.02], colors="k",
                       linewidths=1.0, linestyles="--", path_effects=HALO)  # fmt: skip
            ax.set_xscale("log")
            ax.set_yscale("log")
            if i == 0:
                ax.set_title(f"K = {K:g} N/m", fontsize=10)
            if j == 0:
                ax.set_ylabel(f"{label.split(',')[0]}\nm/M")
            if i == 2:
                ax.set_xlabel("approach speed v0 [m/s]")
            for lev in LEVELS:
                within = size <= lev
                rows.append([key, K, lev, 100 * float(np.mean(within)),
                             100 * float(np.mean(within & chance))])  # fmt: skip
            rows.append([key, K, "max", float(np.max(size)), None])
        tick()
    fig.colorbar(cs, ax=axes, ticks=[0, *LEVELS], label="|error| vs numerical truth [%]")
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    with plt.rc_context({"hatch.color": "w"}):
        fig.legend(
            [Line2D([], [], color="k", lw=1.0, ls="--", path_effects=HALO),
             Line2D([], [], color="w", lw=1.2, path_effects=OUTLINE),
             Patch(facecolor=BAND_COLOURS[1], hatch="////")],
            ["Hertz penetration = 2 cm (the fits' range; extrapolated to its right)",
             "error changes sign", "within a tolerance only where the error changes sign"],
            loc="upper center", fontsize=9, frameon=False, ncol=2,
        )  # fmt: skip
    save(fig, folder, "accuracy_map", tight=False)
    s.blocks += [
        Figure(
            "accuracy_map",
            "Accuracy map of the contact-duration formulas",
            "Colour: |T − T_truth|/T_truth with T_truth the contact phase of the Hertz law "
            "K_Hz = 1000 N/m^1.5 integrated with the main mass (M = 1 kg) on its spring K "
            "(c1 = 0). Bands, dark to light (cividis, readable with any colour vision): within "
            "1 %, 5 %, 10 % and beyond. The solid white line is where the error changes sign; "
            "hatched cells are within their band only because of that crossing (their connected "
            "region within the band's tolerance holds errors of both signs), not because the "
            "formula holds there — the table counts them apart. The dashed black line (white "
            "halo) is where the Hertz penetration reaches 2 cm, the range of the cubic and linear fits (to its right the "
            f"fits are extrapolated). Grid {n}×{n} per panel, log-spaced.",
        ),
        Table(
            "accuracy_map_summary",
            "Share of the grid within each tolerance",
            [
                "method",
                "K [N/m]",
                "tolerance [%]",
                "share of grid [%] (or max error)",
                "of it where the error changes sign [%]",
            ],
            rows,
            [None, ".0f", None, ".1f", ".1f"],
            note="Eq. 34 is exact for two free bodies; its error here is the effect of the "
            "main spring, which grows with K and with the contact duration (small v0, large m).",
        ),
    ]


def duffing_frequency_numerical(omega0: float, epsilon: float, alpha: float) -> float:
    """Angular frequency [rad/s] of ẍ + ω0²x + εx³ = 0 from x(0) = α, ẋ(0) = 0, by integrating a
    quarter period (DOP853, rtol 1e-12) to the first zero of x: ω = 2π/(4·t_quarter)."""

    def rhs(t, u):
        return [u[1], -(omega0**2) * u[0] - epsilon * u[0] ** 3]

    def zero(t, u):
        return u[0]

    zero.terminal = True
    zero.direction = -1
    t_max = 10 * 2 * math.pi / omega0
    sol = solve_ivp(rhs, (0.0, t_max), [alpha, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=zero)  # fmt: skip
    tq = float(sol.t_events[0][0])
    return 2 * math.pi / (4 * tq)


def duffing_frequency_elliptic(omega0: float, epsilon: float, alpha: float) -> float:
    """The exact frequency (complete elliptic integral K(k), k² = εα²/(2(ω0² + εα²)))."""
    w2 = omega0**2 + epsilon * alpha**2
    k2 = epsilon * alpha**2 / (2 * w2)
    return math.pi * math.sqrt(w2) / (2 * float(ellipk(k2)))


def lindstedt_errors(x: np.ndarray) -> dict[str, np.ndarray]:
    """Relative frequency errors [1] of orders 1–3 against integration, at ε·α²/ω0² = ``x``
    (ω0 = 1 rad/s, α = 1 m); also the numerical and elliptic frequencies."""
    num = np.array([duffing_frequency_numerical(1.0, float(e), 1.0) for e in x])
    ell = np.array([duffing_frequency_elliptic(1.0, float(e), 1.0) for e in x])
    out = {"numerical": num, "elliptic": ell}
    for order in (1, 2, 3):
        w = getattr(lindstedt, f"duffing_frequency_order{order}")(1.0, x, 1.0)
        out[f"order{order}"] = np.abs(w - num) / num
    return out


def _lindstedt(s: Section, folder: Path, n: int) -> None:
    x = np.geomspace(1e-3, 3.0, n)
    err = lindstedt_errors(x)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for order in (1, 2, 3):
        ax.loglog(x, err[f"order{order}"], "o-", ms=3, label=f"order {order}")
    ax.loglog(x, np.maximum(np.abs(err["numerical"] - err["elliptic"]) / err["elliptic"], 1e-17),
              "k:", lw=0.8, label="integration vs elliptic integral")  # fmt: skip
    for p in (2, 3, 4):
        ax.loglog(x, 0.1 * x**p, color="grey", lw=0.5, ls="--")
    ax.set_xlabel("ε·α²/ω0²")
    ax.set_ylabel("relative frequency error")
    ax.legend(fontsize=8)
    save(fig, folder, "lindstedt_orders")
    rows = []
    for target in (1e-2, 1e-4, 1e-6):
        row: list[Any] = [target]
        for order in (1, 2, 3):
            ok = err[f"order{order}"] <= target
            # largest ε·α² up to which every grid point is within the target
            bad = np.nonzero(~ok)[0]
            row.append(float(x[bad[0] - 1]) if bad.size and bad[0] > 0 else
                       (float(x[-1]) if not bad.size else None))  # fmt: skip
        rows.append(row)
    slopes = []
    for o in (1, 2, 3):  # fit where the error is above the integration floor and still small
        e = err[f"order{o}"]
        sel = (e > 1e-10) & (x < 0.1)
        slopes.append(float(np.polyfit(np.log(x[sel]), np.log(e[sel]), 1)[0]))
    s.blocks += [
        Figure(
            "lindstedt_orders",
            "Lindstedt–Poincaré frequency, orders 1–3, against integration",
            "ẍ + ω0²x + εx³ = 0 from x(0) = α, ẋ(0) = 0 (Eq. 14 with the exact turning-point "
            "amplitude); the truth is a quarter period integrated with DOP853 (rtol 1e-12). The "
            "dotted line shows that integration agrees with the elliptic-integral closed form. "
            "Grey dashes: slopes 2, 3, 4. Fitted slopes for ε·α² < 0.1 (errors above 1e-10): "
            + ", ".join(f"order {o}: {sl:.2f}" for o, sl in zip((1, 2, 3), slopes, strict=True))
            + " (an order-n expansion errs like (εα²)^(n+1)).",
        ),
        Table(
            "lindstedt_orders",
            "Largest ε·α²/ω0² of the grid up to which each order stays within a tolerance",
            ["tolerance", "order 1", "order 2", "order 3"],
            rows,
            [".0e", ".3g", ".3g", ".3g"],
            note="The paper uses order 1 (Eq. 19–20).",
        ),
    ]
