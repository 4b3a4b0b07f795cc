"""Units for people: the unit each quantity is shown in, and values converted to it.

SI inside the package, in JSON and in CSV files (whose headers carry the SI unit:
``gap [m]``).  Text output, printed tables and plot axes show each quantity in an engineering
unit chosen for it (:data:`DISPLAY_UNITS`: mm for gaps and displacements, µm for the damping
inclination DI, ms for contact durations…), with the unit in every header and label.  A user may
choose another unit per quantity (:func:`set_display_unit`, ``--show NAME=UNIT`` on the command
line).
"""

from __future__ import annotations

from decimal import Decimal
from typing import Any

from ..errors import ParameterError
from .units import SI_UNITS, _factor

#: SI units of the outputs of a simulation or map (inputs: :data:`symimpact.model.units.SI_UNITS`).
OUTPUT_SI_UNITS = {
    "n_impacts": "dimensionless",
    "n_effective": "dimensionless",
    "effectiveness": "dimensionless",
    "damping_inclination": "m",
    "zeta_eq": "dimensionless",
    "energy_initial": "J",
    "energy_dissipated": "J",
    "energy_dissipated_contact": "J",
    "energy_residual": "J",
    "t": "s",
    "x": "m",
    "y": "m",
    "z": "m",
    "xdot": "m/s",
    "ydot": "m/s",
    "duration": "s",
    "amplitude": "m",
    # the responses of a curve (symimpact.forced.responses), as frf's JSON and CSV name them
    "relative_displacement": "m",
    "acceleration": "m/s^2",
    "force": "N",
    "transmissibility": "dimensionless",
    "impacts_per_period": "dimensionless",
    "impact_events_per_period": "dimensionless",
    "period_multiple": "dimensionless",
    "branch": "dimensionless",
    "omega": "rad/s",
    "peak_amplitude": "m",
    "peak_omega": "rad/s",
    "baseline_peak": "m",
    "baseline_omega": "rad/s",
    "worst_peak": "m",
    "tolerance": "m",  # a refined best clearance's (design)
    "nominal_peak": "m",
    "worst_e": "dimensionless",
    "e": "dimensionless",
    # random, shock and sweep-sine (symimpact.cli.loads)
    "frequency": "Hz",
    "displacement_psd": "m^2/Hz",
    "baseline_displacement_psd": "m^2/Hz",
    "srs": "m/s^2",
    "baseline_srs": "m/s^2",
    "envelope": "m",
    "baseline_envelope": "m",
    "direction": "dimensionless",
    # an ensemble's rows (symimpact.maps.ensemble)
    "realisation": "dimensionless",
    "rms_displacement": "m",
    "rms_velocity": "m/s",
    "rms_acceleration": "m/s^2",
    "rms_base_force": "N",
    "baseline_rms_displacement": "m",
    "baseline_rms_velocity": "m/s",
    "baseline_rms_acceleration": "m/s^2",
    "baseline_rms_base_force": "N",
    "impacts": "dimensionless",
    # identification (symimpact.identify): a restitution law's parameters, the measured speeds
    # of single impacts, and a fit's residual in the record's own quantity
    "yield_speed": "m/s",
    "alpha": "dimensionless",
    "rebound_speed": "m/s",
    "residual_displacement": "m",
    "residual_velocity": "m/s",
    "residual_acceleration": "m/s^2",
}

#: A design row's keys that hold a peak of the primary's response, and their names when the
#: design measures another response than the displacement (``design --response``; ``{key}``:
#: the response's JSON name, e.g. ``peak_force``).
DESIGN_PEAK_NAMES = {"peak_amplitude": "peak_{key}", "baseline_peak": "baseline_{key}",
                     "peak_e_minus": "peak_{key}_e_minus", "peak_e_plus": "peak_{key}_e_plus",
                     "worst_peak": "worst_{key}", "nominal_peak": "nominal_{key}"}  # fmt: skip
OUTPUT_SI_UNITS.update({
    name.format(key=key): OUTPUT_SI_UNITS[key]
    for key in ("relative_displacement", "acceleration", "force", "transmissibility")
    for name in DESIGN_PEAK_NAMES.values()
})  # fmt: skip

#: The unit each quantity is shown in (quantities not listed: their SI unit).
DISPLAY_UNITS: dict[str, str] = {
    "gap": "mm",
    "x0": "mm",
    "y0": "mm",
    "x": "mm",
    "y": "mm",
    "z": "mm",
    "delta_max": "mm",
    "position": "mm",
    "damping_inclination": "µm",
    "duration": "ms",
    "amplitude": "mm",
    "peak_amplitude": "mm",
    "baseline_peak": "mm",
    "worst_peak": "mm",
    "nominal_peak": "mm",
    "energy_initial": "mJ",
    "energy_dissipated": "mJ",
    "energy_dissipated_contact": "mJ",
    "energy_residual": "mJ",
    "yield_speed": "mm/s",
    "rebound_speed": "mm/s",
    "residual_displacement": "µm",
    "residual_velocity": "mm/s",
}

_PRETTY = {"N*s/m": "N s/m", "N/m^1.5": "N/m^1.5", "N/m^3": "N/m³", "kg/m^3": "kg/m³",
           "m^2": "m²", "m^4": "m⁴"}  # fmt: skip


def si_unit(name: str) -> str:
    """The SI unit of quantity ``name`` (``"dimensionless"`` for pure numbers)."""
    return SI_UNITS.get(name) or OUTPUT_SI_UNITS.get(name, "dimensionless")


def display_unit(name: str) -> str:
    """The unit quantity ``name`` is shown in."""
    return DISPLAY_UNITS.get(name, si_unit(name))


def _bracket(unit: str) -> str:
    return "" if unit == "dimensionless" else f" [{_PRETTY.get(unit, unit)}]"


def label(name: str) -> str:
    """``name [unit]`` in the display unit (no brackets for a pure number): for text headers and
    plot axes."""
    return name + _bracket(display_unit(name))


def csv_header(name: str) -> str:
    """``name [SI unit]``: for CSV headers, whose values stay SI."""
    return name + _bracket(si_unit(name))


def shown(name: str, value: Any) -> Any:
    """``value`` [SI] of quantity ``name`` in its display unit (None stays None)."""
    if value is None:
        return None
    unit = display_unit(name)
    if unit == si_unit(name):
        return value
    kind, factor = _factor(unit, si_unit(name))
    return value / float(factor) if kind == "ok" else value


def omega_text(omega: Any, spec: str = ".6g") -> str:
    """``"75.398 rad/s"`` or ``"12 Hz"``: a frequency Ω [rad/s] in its display unit (Hz when the
    user gave the band or the frequency in Hz, or chose it with ``--show omega=UNIT``)."""
    return f"{shown('omega', omega):{spec}} {_PRETTY.get(display_unit('omega'), display_unit('omega'))}"


def impacts_text(impacts: float, events: float) -> str:
    """``"12 impacts per period"``, or with chatter ``"418 impacts per period (2 impact events:
    a chatter sequence counts once)"`` — the second number does not depend on how many impacts
    of a sequence the run resolved before jumping to their limit."""
    text = f"{impacts:.4g} impacts per period"
    if events != impacts:
        text += f" ({events:.4g} impact events: a chatter sequence counts once)"
    return text


def set_display_unit(name: str, unit: str) -> None:
    """Show quantity ``name`` in ``unit`` from now on (checked against its SI unit)."""
    kind, info = _factor(unit, si_unit(name))
    if kind != "ok" or info == Decimal(0):
        why = info if kind == "unit" else f"dimension {info}, expected units of {si_unit(name)}"
        raise ParameterError("show", f"{name} cannot be shown in {unit!r}: {why}")
    DISPLAY_UNITS[name] = unit


def parse_show(specs: list[str]) -> None:
    """Apply ``NAME=UNIT`` options (the command line's ``--show``)."""
    for spec in specs:
        name, sep, unit = spec.partition("=")
        if not sep or not name.strip() or not unit.strip():
            raise ParameterError("show", f"{spec!r} must be NAME=UNIT, e.g. gap=µm")
        set_display_unit(name.strip(), unit.strip())
