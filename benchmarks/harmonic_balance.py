"""The frequency-response curve by harmonic balance beside the exact one (issue 83's speed
case): the README's primary (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 50 g, d 20 mm, F0 2 N) with
the default linear contact (k₁ fitted to K_Hz 1000 N/m^1.5, c₁ 5 N s/m) over 200 frequencies of
25–40 rad/s, H = 15 (N = 60).

Three figures, each a median of five runs on one core: the exact curve (shooting and
continuation, no multi-start, no sweeps: the baseline, measured in the same run), the balance's
curve seeded by it (:func:`symimpact.forced.orbits.hb_frf.hb_frequency_response`; target 5 s)
and the comparison table (:func:`symimpact.forced.orbits.hb_frf.compare`, with the ladder of
harmonics up to 128; target 1 min).  The two curves are not of the same accuracy: the exact
one's orbits hold to 1e-10, the balance's at H = 15 are a few per cent off, which the table
states; the baseline is the cost of what the balance approximates.  Prints figures, asserts
nothing.  Run from the checkout: python -m benchmarks.harmonic_balance
"""

from __future__ import annotations

import numpy as np

from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.frf import frequency_response
from symimpact.forced.orbits.hb_frf import compare, hb_frequency_response
from symimpact.model.system import ImpactSystem

from .timing import timed

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, k_hz=1000.0, c1=5.0,
                      contact="linear")  # fmt: skip
FORCING, CONTACT = Forcing(F0=2.0, omega=25.0), CompliantContact("linear")
BAND = np.linspace(25.0, 40.0, 200)


def main() -> None:
    exact = timed(lambda: frequency_response(SYSTEM, FORCING, CONTACT, BAND, sweeps=False,
                                             multistart=0, workers=1))  # fmt: skip
    ex = exact.out
    hb = timed(lambda: hb_frequency_response(SYSTEM, FORCING, CONTACT, ex, harmonics=15))
    table = timed(lambda: compare(SYSTEM, FORCING, CONTACT, ex, hb.out, harmonics=15))
    points = sum(len(b.points) for b in hb.out.branches)
    print(f"README primary, default linear contact (k1 {SYSTEM.k1:.4g} N/m, c1 5 N s/m), "
          f"200 frequencies of 25-40 rad/s, H = 15, N = 60")  # fmt: skip
    print(f"  exact curve (baseline): {exact.s()}, {len(ex.branches)} branch(es), "
          f"{sum(len(b.points) for b in ex.branches)} orbits")  # fmt: skip
    print(f"  balance's curve: {hb.s()} (target 5 s), {len(hb.out.branches)} branch(es), "
          f"{points} orbits; {hb.median / exact.median:.2f} of the baseline")  # fmt: skip
    print(f"  comparison table: {table.s()} (target 60 s)")
    for r in table.out.branches:
        need = ", ".join(f"{100 * float(k):g} %: {v if v is not None else '> 128'}"
                         for k, v in r.harmonics_for.items())  # fmt: skip
        err = "none balanced" if r.hb_error is None else f"{100 * r.hb_error:.3g} %"
        print(f"    exact branch {r.branch}: largest error {err}, harmonics needed: {need}, "
              f"{len(r.missed)} of {r.compared} orbits with no balanced orbit near")  # fmt: skip


if __name__ == "__main__":
    main()
