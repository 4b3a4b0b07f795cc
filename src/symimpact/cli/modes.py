"""``symimpact modes``: a finite-element model's first modes at the damper's degree of freedom
(issue 36: each mode's mass and stiffness there, the primary a damper at that point sees), or a
structure file's modes at its named points with the mass an impact meets at each."""

from __future__ import annotations

import math
from typing import Any

from .common import add_output, emit


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "modes",
        help="a finite-element model's first modes at the damper's DOF: mass, stiffness, "
        "frequency, and how much of the DOF's static flexibility they hold",
    )
    p.add_argument("--structure", metavar="FILE",
                   help="a structure file (JSON or TOML: a beam, modal data or a finite-element "
                   "model, with named points): its modes' frequencies, damping ratios and shapes "
                   "at each point, and the mass an impact meets at each point")  # fmt: skip
    p.add_argument("--fe", metavar="FILE", help="one .npz file holding arrays K [N/m] and M [kg]")
    p.add_argument("--stiffness", metavar="FILE",
                   help="the stiffness matrix K [N/m] (.mtx, .npy, .csv or a scipy sparse .npz)")  # fmt: skip
    p.add_argument("--mass", metavar="FILE", help="the mass matrix M [kg], as --stiffness")
    p.add_argument("--dof", type=int, metavar="J",
                   help="the damper's degree of freedom: a 0-based row of K and M (needed with "
                   "--fe or --stiffness and --mass)")  # fmt: skip
    p.add_argument("--modes", type=int, default=4, metavar="N", help="modes to list (default 4)")
    p.add_argument("--influence", metavar="R",
                   help="each DOF's displacement when the supports move by one unit, repeated to "
                   "fill the DOFs ('1' for translations, '1,0' for a beam's (w, θ) pairs): lists "
                   "each mode's participation factor and share of the mass (Eq. F7)")  # fmt: skip
    add_output(p)


def run(ns) -> None:
    from ..errors import ParameterError
    from ..model.modal import fe_modes, read_matrices, static_flexibility

    if ns.structure is not None:
        if ns.fe is not None or ns.stiffness is not None or ns.mass is not None:
            raise ParameterError("structure", "give the model either as --structure or as "
                                              "--fe / --stiffness and --mass")  # fmt: skip
        return _structure(ns)
    if ns.dof is None:
        raise ParameterError("dof", "the damper's degree of freedom is needed with --fe or "
                                    "--stiffness and --mass")  # fmt: skip
    K, M = read_matrices(ns.fe, ns.stiffness, ns.mass)
    modes = fe_modes(K, M, ns.dof, ns.modes, ns.influence)
    exact = static_flexibility(K, ns.dof)
    summed = sum(1.0 / m.K for m in modes if not m.node)
    out = {"dof": ns.dof, "modes": [m.as_dict() for m in modes], "static_flexibility": exact,
           "static_flexibility_of_the_modes": summed}  # fmt: skip
    base = ns.influence is not None
    lines = [
        f"{'mode':>4}  {'f [Hz]':>11}  {'M at the DOF [kg]':>17}  {'K at the DOF [N/m]':>18}"
        + (f"  {'Γ at the DOF':>12}  {'mass share [%]':>14}" if base else ""),
        *(
            f"{m.number:>4}  {m.frequency:11.5g}  "
            + (f"{'node':>17}  {'node':>18}" if m.node else f"{m.M:17.6g}  {m.K:18.6g}")
            + (f"  {m.participation:12.6g}  {m.mass_share * 100:14.4g}" if base else "")
            for m in modes
        ),
        *([_moved(modes)] if base else []),
        f"static flexibility at DOF {ns.dof}: {exact * 1e3:.6g} mm/N; the sum over these "
        f"{len(modes)} modes, Σ1/K, {summed * 1e3:.6g} mm/N ({(1 - summed / exact) * 100:.3g} % "
        "short)",
    ]
    emit(ns, out, "\n".join(lines))


def _structure(ns) -> None:
    """The structure file's modes at its points (Step 15, Eq. F7) and each point's effective
    mass over them, 1/m_eff = Σ φᵢ(p)²/Mᵢ (Step 15, item 4)."""
    from ..model.structure import read_structure
    from ..model.structure_model import has_loads, read_model

    # a file with dampers and a force: its structure (the dampers do not change the modes)
    s = (
        read_model(ns.structure).structure
        if has_loads(ns.structure)
        else read_structure(ns.structure)
    )
    points = s.points
    masses = {p: s.effective_mass(p) for p in points}
    out = {"source": s.source, "points": list(points), "modes": [m.as_dict() for m in s.modes],
           "effective_mass": masses}  # fmt: skip
    width = max(12, *(len(p) + 4 for p in points))
    head = f"{'mode':>4}  {'f [Hz]':>11}  {'ζ':>7}  " + "  ".join(
        f"{'φ(' + p + ')/√M':>{width}}" for p in points
    )
    rows = [
        f"{m.number:>4}  {m.frequency:11.5g}  {m.zeta:7.4g}  "
        + "  ".join(f"{m.shape[p] / m.mass**0.5:{width}.5g}" for p in points)
        for m in s.modes
    ]
    tail = "mass an impact meets (over these modes): " + ", ".join(
        f"{p} {masses[p]:.5g} kg" if math.isfinite(masses[p]) else f"{p} (no mode moves it)"
        for p in points
    )
    shares = {p: s.flexibility_share(p) for p in points}
    out["flexibility_share"] = {p: (None if math.isnan(v) else v) for p, v in shares.items()}
    if s.flexibility:
        tail += "\nshare of each point's static flexibility these modes hold: " + ", ".join(
            f"{p} {shares[p] * 100:.4g} %" if not math.isnan(shares[p]) else f"{p} (held fixed)"
            for p in points
        )
    emit(
        ns,
        out,
        "\n".join(
            [
                f"{len(s.modes)} modes of the {s.source} model; shapes φ(p)/√M in 1/√kg (scaled to unit modal mass)",
                head,
                *rows,
                tail,
            ]
        ),
    )


def _moved(modes) -> str:
    """The share of the mass the listed modes move under base excitation, in words."""
    share = sum(m.mass_share for m in modes) * 100
    return f"these {len(modes)} modes move {share:.4g} % of the mass the supports carry"


#: The subcommands this module runs.
COMMANDS = {"modes": run}
