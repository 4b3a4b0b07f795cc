"""What the paper prints, kept as the printed strings, and how a result of ours compares with one.

The paper prints rounded (and sometimes truncated) decimals.  :func:`compare` says whether our
value rounds (half up) or truncates to the printed digits, and gives the relative deviation.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal

#: Table 1 (M = 1 kg, K = 1000 N/m, Ż0 = 7.5 cm/s): m → Hertz, T_CD, linear [s] and the errors [%].
TABLE1 = {
    "0.15": {"hertz": "0.1509", "perturbation": "0.1407", "linear": "0.1024",
             "error_perturbation": "6.76", "error_linear": "32.14"},
    "0.20": {"hertz": "0.1664", "perturbation": "0.1656", "linear": "0.1157",
             "error_perturbation": "0.48", "error_linear": "30.47"},
    "0.25": {"hertz": "0.1790", "perturbation": "0.1885", "linear": "0.1268",
             "error_perturbation": "5.31", "error_linear": "29.16"},
}  # fmt: skip

#: Table 3: d [mm] → class, N_tot, N_eff, effectiveness, DI [µm].
TABLE3 = {
    "6": ("out of range", "41", "14", "0.52", "43.85"),
    "7": ("in range", "24", "13", "1.18", "64.56"),
    "9": ("in range", "19", "11", "1.38", "71.05"),
    "15": ("in range", "12", "7", "1.40", "82.40"),
    "20": ("in range", "19", "10", "1.11", "43.55"),
    "25": ("in range", "9", "6", "2.00", "88.72"),
    "32": ("in range", "12", "6", "1.00", "61.60"),
    "34": ("in range", "10", "6", "1.50", "75.32"),
    "35": ("out of range", "12", "5", "0.71", "14.98"),
}

#: Table 2 as printed (the units are part of the printed value).
TABLE2 = {
    "M": "1 kg",
    "K": "100 N/cm",
    "a": "0.1553 N/cm^3",
    "m": "0.25 kg",
    "c1": "5 N s/cm",
    "b": "0.8360 N/cm",
    "xdot0": "5 mm/s",
}

#: Other printed numbers: fit (Sect. 3, Fig. 2, Table 2), gap range (Fig. 5), DI at 9 mm (Fig. 4).
FIT = {"a": "0.1553", "b": "0.8360", "k1": "122.7"}  # N/cm³, N/cm, N/m
GAP_RANGE = {"d_min": "6.49", "d_max": "34.43"}  # mm
DI_FIG4 = "71.05"  # µm
FIG3_CAPTION = {"m": "0.25 kg", "a": "0.1553 N/cm^3", "b": "0.8360 N/cm", "c1": "1 N s/cm"}


@dataclass(frozen=True)
class Comparison:
    """Our value against a printed one (both in the printed unit)."""

    ours: float
    printed: str
    rounds: bool  # ours rounded half-up to the printed digits equals the printed value
    truncates: bool  # ours truncated to the printed digits equals the printed value
    deviation: float  # (ours − printed)/printed [1]

    @property
    def verdict(self) -> str:
        """'= (rounded)', '= (truncated)' or the signed deviation in percent."""
        if self.rounds:
            return "= (rounded)"
        if self.truncates:
            return "= (truncated)"
        return f"{100 * self.deviation:+.2f} %"


def compare(ours: float, printed: str) -> Comparison:
    """Compare ``ours`` with the ``printed`` decimal string at the printed number of digits."""
    p = Decimal(printed)
    exp = p.as_tuple().exponent
    q = Decimal(1).scaleb(exp)
    o = Decimal(repr(float(ours)))
    return Comparison(
        ours=float(ours),
        printed=printed,
        rounds=o.quantize(q, rounding=ROUND_HALF_UP) == p,
        truncates=o.quantize(q, rounding=ROUND_DOWN) == p,
        deviation=float((o - p) / p) if p != 0 else float("inf"),
    )
