"""The closed-form orbit's amplitude slopes in the clearance d and the restitution e (Eq. F3
differentiated: the generated derivatives of the phase residual and of X, V at a fixed phase,
carried to the extreme of x by the flight's derivatives) against central differences of the whole
closed-form solution, recomputed from scratch at d ± h and e ± h.

Tolerance: the central difference's truncation is ~h² relative (1e-12 at h = 1e-6); its rounding
is eps·A·κ/h with κ the amplitude's sensitivity to rounding in the solution (the phase from
atan2/arccos, the refined extreme: measured 1e-10 relative on these cases).  So 1e-7 relative to
the slope, plus an absolute floor for slopes near zero: eps·A/h ≈ 1e-11 m per unit e (and per unit
d/d), times a safety factor of 100.
"""

from __future__ import annotations

import dataclasses

import pytest

from symimpact.forced import Forcing, periodic_orbits
from symimpact.model.system import ImpactSystem

#: The README's forced system (the compliant fields only satisfy the system's checks: the closed
#: form is the rigid law).
SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
#: A heavy damper in a narrow box: its extremes sit at the impacts (x = ±X), not between them.
HEAVY = dataclasses.replace(SYSTEM, m=0.5, gap=0.01)
E = 0.6
H = 1e-6


def _amplitude(system, forcing, e, phase):
    """The amplitude of the closed-form orbit nearest in impact phase to ``phase``."""
    orbits = periodic_orbits(system, forcing, e)
    return min(orbits, key=lambda o: abs(o.impact_phase - phase)).amplitude


def _cases():
    for system, omegas in (
        (SYSTEM, (24.0, 28.0, 33.0, 36.0, 40.0)),
        (HEAVY, (20.0, 44.0)),
    ):
        for omega in omegas:
            forcing = Forcing(F0=2.0, X_b=0.0, omega=omega)
            for k, o in enumerate(periodic_orbits(system, forcing, E)):
                where = "at-impact" if _at_impact(o) else "between-impacts"
                yield pytest.param(system, forcing, o, id=f"m{system.m}-{omega}-{k}-{where}")


def _at_impact(orbit) -> bool:
    """Whether the orbit's extreme of x is at an impact (x = ±X there)."""
    return abs(abs(orbit.X) - orbit.amplitude) <= 1e-15 * orbit.amplitude


def test_both_kinds_of_extreme_are_covered():
    kinds = {_at_impact(p.values[2]) for p in _cases()}
    assert kinds == {True, False}


@pytest.mark.parametrize(("system", "forcing", "orbit"), list(_cases()))
def test_slopes_equal_central_differences(system, forcing, orbit):
    gap = system.gap
    d_gap = (
        _amplitude(dataclasses.replace(system, gap=gap * (1 + H)), forcing, E, orbit.impact_phase)
        - _amplitude(dataclasses.replace(system, gap=gap * (1 - H)), forcing, E, orbit.impact_phase)
    ) / (2 * H * gap)
    d_e = (
        _amplitude(system, forcing, E + H, orbit.impact_phase)
        - _amplitude(system, forcing, E - H, orbit.impact_phase)
    ) / (2 * H)
    floor = 100 * 2.2e-16 * orbit.amplitude / H
    assert orbit.amplitude_slope_gap == pytest.approx(d_gap, rel=1e-7, abs=floor / gap)
    assert orbit.amplitude_slope_e == pytest.approx(d_e, rel=1e-7, abs=floor)


def test_the_cli_prints_the_slopes(capsys):
    from symimpact.cli import main

    argv = ["periodic", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
            "--force", "2 N", "--omega", "36", "--contact", "rigid", "--e", "0.6"]  # fmt: skip
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert "∂A/∂d [1]  ∂A/∂e [mm]" in text
    o = periodic_orbits(SYSTEM, Forcing(F0=2.0, X_b=0.0, omega=36.0), E)[0]
    assert f"{o.amplitude_slope_gap:9.4g}" in text
    assert main([*argv, "--json"]) == 0
    assert '"amplitude_slope_e"' in capsys.readouterr().out
