"""Periodic orbits of the forced primary and of structures, and the curves built on them.

Closed forms (Eq. F3, the linearised and slow-flow approximations), shooting on the stroboscopic
map with Floquet multipliers, pseudo-arclength continuation with its bifurcations, the
multi-start coverage of a band, the located peaks, the frequency-response curve and the rigid
limit of compliant contacts; a structure's orbits and branches.
"""
