"""The model: what the user describes, validated and in SI units, before anything moves.

- :mod:`.units` — quantities with units at the boundary, turned into SI floats;
- :mod:`.checks` — the public functions' arguments checked as the command line checks its options;
- :mod:`.display` — the unit each quantity is shown in to people;
- :mod:`.beams`, :mod:`.modal` — a primary from a beam's modes (Step 14) or a finite-element
  model's (Step 15), referred to the damper's point;
- :mod:`.system` — :class:`~.system.ImpactSystem`, the paper's system (Table 2 and Eq. 1–9);
- :mod:`.structure` — a primary of several modes with named points (a beam, modal data or a
  finite-element model), its receptances and the mass an impact meets at each point;
- :mod:`.materials` — the materials table (E, ν, ρ, yield strength, each with its source);
- :mod:`.hunt_crossley` — one impact under the Hunt–Crossley law (Step 11): e from χ and back;
- :mod:`.derived_contact` — the contact (K_Hz, e, χ, c1) from materials and geometry (Step 13).

Nothing here imports :mod:`symimpact.free`, :mod:`symimpact.forced` or what follows them.
"""
