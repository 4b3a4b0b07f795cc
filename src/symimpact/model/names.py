"""The names a parameter map sweeps (:mod:`symimpact.maps.points`), here with no import, so that
the command line's help lists them without loading the maps."""

from __future__ import annotations

#: The initial state and the run's length: x0 [m], ẋ0 [m/s], y0 [m], ẏ0 [m/s], t_end [s].
INITIAL = ("x0", "xdot0", "y0", "ydot0", "t_end")
#: The system's parameters (Table 2 and Eq. 1–9; :class:`~symimpact.model.system.ImpactSystem`).
SYSTEM_PARAMETERS = ("M", "K", "C", "zeta", "m", "gap", "a", "b", "k_hz", "k1", "c1")
#: Every input a map can sweep: initial conditions, system parameters and the mass ratio m/M.
SWEEPABLE = INITIAL + SYSTEM_PARAMETERS + ("mass_ratio",)
