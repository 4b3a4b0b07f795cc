"""Issue 82: e, ζ and the clearance identified from a free decay with impacts.

The records are made by a brute force that shares nothing with the package's engine: SciPy's
DOP853 (rtol 1e-12) with each impact a terminal event and Newton's law applied there
(tests/helpers.flights_with_impacts).  From a noise-free record the fit gives back the
parameters that made it; from a record without an impact it says what it cannot tell."""

from __future__ import annotations

import json

import numpy as np
import pytest
from helpers import flights_with_impacts

from symimpact.cli import main
from symimpact.identify.decay import Decay, fit_decay
from symimpact.model.system import ImpactSystem

#: The rig: M 1 kg, K 1000 N/m (f_n 5.03 Hz), ζ 1 %, a 50 g ball in 10 mm, e 0.6, tapped to
#: 0.3 m/s (amplitude 9.5 mm: 20 impacts in 1.5 s).
M, K, m, ZETA, GAP, E, V0 = 1.0, 1000.0, 0.05, 0.01, 0.010, 0.6, 0.3


def _record(n: int, dt: float, v0: float = V0, quantity: str = "displacement") -> Decay:
    c = 2 * ZETA * np.sqrt(K * M)

    def rhs(_, w):
        return [w[1], -(K * w[0] + c * w[1]) / M, w[3], 0.0]

    marks = list(dt * np.arange(n))
    _, _, out = flights_with_impacts(rhs, [0.0, v0, 0.0, 0.0], 0.0, marks[-1] + 1e-9,
                                        GAP / 2, E, M, m, marks=marks)  # fmt: skip
    values = {"displacement": out[:, 0], "velocity": out[:, 1],
              "acceleration": -(K * out[:, 0] + c * out[:, 1]) / M}[quantity]  # fmt: skip
    return Decay(values, dt, quantity)


def _rig(**changes) -> ImpactSystem:
    """The rig as the fit is told it: M, K, m; ζ and d wrong on purpose (fitted)."""
    return ImpactSystem(M=M, K=K, m=m, gap=changes.get("gap", 0.03),
                        zeta=changes.get("zeta", 0.05), k_hz=1000.0)  # fmt: skip


def test_a_noise_free_decay_gives_back_the_rig():
    """e, ζ, d and the tap's speed to 1e-7 (the record is exact to ~1e-12 and the fit's
    optimum is where its residual vanishes; 1e-7 is the Jacobian's differences' accuracy, which
    bounds how closely the optimiser is asked to land), the tap's x₀ to 1e-9 m."""
    result, response = fit_decay(_rig(), _record(1000, 1e-3))
    got = result.values()
    assert got["e"] == pytest.approx(E, rel=1e-7)
    assert got["zeta"] == pytest.approx(ZETA, rel=1e-7)
    assert got["gap"] == pytest.approx(GAP, rel=1e-7)
    assert got["xdot0"] == pytest.approx(V0, rel=1e-7)
    assert abs(got["x0"]) < 1e-9
    assert response.impact_times.size > 10 and result.residual_rms < 1e-9


@pytest.mark.slow
def test_an_acceleration_record_gives_back_the_rig():
    """The same from an accelerometer's record (the absolute acceleration between impacts),
    ζ and e fitted with the clearance known."""
    result, _ = fit_decay(_rig(gap=GAP), _record(1000, 1e-3, quantity="acceleration"),
                          fitted=("e", "zeta"))  # fmt: skip
    assert result.values()["e"] == pytest.approx(E, rel=1e-7)
    assert result.values()["zeta"] == pytest.approx(ZETA, rel=1e-7)


def test_a_decay_without_impacts_says_what_it_cannot_tell():
    """Tapped to 0.1 m/s the primary moves 3.2 mm, inside half the clearance: no impact, so e
    is not determined and d only bounded from below; ζ is still found."""
    result, response = fit_decay(_rig(), _record(600, 2e-3, v0=0.1))
    assert response.impact_times.size == 0
    assert result.values()["zeta"] == pytest.approx(ZETA, rel=1e-6)
    assert any("no impact" in w for w in result.warnings)


def test_the_command_fits_and_writes_the_rig(tmp_path, capsys):
    """identify decay --json --out: a CSV in mm, the JSON's parameters, and the system file's
    M, K, m, ζ, d, e, which a simulation reads back."""
    data = _record(600, 2e-3)
    csv = tmp_path / "decay.csv"
    csv.write_text("time [s],displacement [mm]\n" + "".join(
        f"{t!r},{x * 1e3!r}\n" for t, x in zip(data.times.tolist(), data.values.tolist(),
                                               strict=True)))  # fmt: skip
    out = tmp_path / "rig.toml"
    code = main(["identify", "decay", str(csv), "--M", "1 kg", "--fn", "5.0329212 Hz", "--m",
                 "50 g", "--json", "--out", str(out)])  # fmt: skip
    got = json.loads(capsys.readouterr().out)
    assert code == 0
    assert got["parameters"]["gap"]["value"] == pytest.approx(GAP, rel=1e-6)
    assert got["system"]["e"] == pytest.approx(E, rel=1e-6)
    from symimpact.cli.common import read_uncertainty

    assert read_uncertainty(out)["names"] == ["e", "zeta", "gap"]  # for frf --propagate
    code = main(["simulate", "--system", str(out), "--contact", "rigid", "--force", "1 N",
                 "--omega", "30", "--periods", "3", "--json"])  # fmt: skip
    sim = json.loads(capsys.readouterr().out)
    assert code == 0 and sim["e"] == pytest.approx(E, rel=1e-6)
    assert sim["system"]["gap"] == pytest.approx(GAP, rel=1e-6)


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--K", "1000", "--m", "0.05"], "M: the rig's M is needed"),
        (["--M", "1", "--K", "1000", "--m", "0.05", "--fit", "e,mass"], "fit: 'mass'"),
        (["--M", "1", "--K", "1000", "--m", "0.05", "--fit", "zeta"], "gap: give the clearance"),
    ],
)
def test_bad_decay_input_is_refused_in_one_line(tmp_path, capsys, argv, words):
    csv = tmp_path / "decay.csv"
    csv.write_text("time [s],displacement [mm]\n" + "".join(f"{k * 1e-3!r},1.0\n"
                                                             for k in range(20)))  # fmt: skip
    code = main(["identify", "decay", str(csv), *argv])
    err = capsys.readouterr().err
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1


RIG = ["--M", "1", "--K", "1000", "--m", "0.05"]


@pytest.mark.parametrize(
    "rows, words",
    [
        ("time,displacement\n0,1\n0.001,2\n", "unit in brackets"),
        ("time [s],displacement [mm]\n0,1\n0.002,2\n0.001,3\n", "time must increase"),
        ("time [s],displacement [mm]\n0,1\n0.001,2\n0.001,3\n", "time must increase"),
        ("time [s],displacement [mm]\n0,1\n0.001,nan\n0.002,3\n", "not finite"),
        ("time [s],displacement [mm]\n" + "".join(f"{k * 1e-3!r},1\n" for k in (0, 1, 2, 4, 5, 6,
                                                                               7, 8, 9)),
         "equally spaced"),
        ("time [s],displacement [N]\n" + "".join(f"{k * 1e-3!r},1\n" for k in range(9)),
         "not a displacement"),
        ("time [s],displacement [mm]\n" + "".join(f"{k * 0.02!r},1\n" for k in range(40)),
         "9.93 times a natural period"),
    ],
)  # fmt: skip
def test_a_bad_record_is_refused_in_one_line(tmp_path, capsys, rows, words):
    """Missing units, unsorted or repeated times, NaN, a gap, a value that is not a motion, and
    a sampling too coarse for the impacts (20 ms against the 199 ms natural period)."""
    csv = tmp_path / "decay.csv"
    csv.write_text(rows)
    code = main(["identify", "decay", str(csv), *RIG])
    err = capsys.readouterr().err
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1


def test_thorntons_yield_speed_from_a_decay():
    """Impacts by Thornton's e(v) (typed from his paper, in mpmath, tests/test_identify_impacts)
    with v_y = 20 mm/s: the fit of the law's one parameter gives it back, with ζ and d (1e-7,
    as above)."""
    from test_identify_impacts import _thornton_mp

    from symimpact.forced.contact_law import MaterialRestitution

    c = 2 * ZETA * np.sqrt(K * M)

    def rhs(_, w):
        return [w[1], -(K * w[0] + c * w[1]) / M, w[3], 0.0]

    dt, n = 1e-3, 1000
    marks = list(dt * np.arange(n))
    _, _, out = flights_with_impacts(rhs, [0.0, V0, 0.0, 0.0], 0.0, marks[-1] + 1e-9, GAP / 2,
                                     lambda w: _thornton_mp(0.02, w), M, m, marks=marks)  # fmt: skip
    result, _ = fit_decay(_rig(), Decay(out[:, 0], dt, "displacement"),
                                 e=MaterialRestitution(0.1))  # fmt: skip
    got = result.values()
    assert set(got) == {"yield_speed", "zeta", "gap", "x0", "xdot0"}
    assert got["yield_speed"] == pytest.approx(0.02, rel=1e-7)
    assert got["zeta"] == pytest.approx(ZETA, rel=1e-7)
    assert got["gap"] == pytest.approx(GAP, rel=1e-7)


def test_a_fit_that_leaves_the_record_is_said_to():
    """The detector of a fitted motion that has left its record: white noise alone raises it
    at no period (probability 1.5e-8 a period, whatever the seed); an oscillation at the
    natural frequency from t = 1 s, 10 deviations of the noise's estimate over a period's 198
    samples, is caught in the period that holds t = 1 s (95 % of it after the onset)."""
    from symimpact.identify.decay import departure

    rng = np.random.default_rng(7)
    dt, w = 1e-3, np.sqrt(K / M)
    period = 2 * np.pi / w / dt
    t = dt * np.arange(4000)
    noise = rng.normal(0.0, 1e-5, t.size)
    assert departure(noise, dt, period, w, 0.01) is None
    drift = np.where(t >= 1.0, 10 * 1e-5 * np.sqrt(2 / int(period)) * np.sin(w * t), 0.0)
    at = departure(noise + drift, dt, period, w, 0.01)
    assert at is not None and 1.0 - period * dt < at <= 1.0


def test_until_fits_the_first_seconds(tmp_path, capsys):
    data = _record(600, 2e-3)
    csv = tmp_path / "decay.csv"
    csv.write_text("time [s],displacement [m]\n" + "".join(
        f"{t!r},{x!r}\n" for t, x in zip(data.times.tolist(), data.values.tolist(),
                                         strict=True)))  # fmt: skip
    code = main(["identify", "decay", str(csv), "--M", "1", "--K", "1000", "--m", "0.05",
                 "--until", "0.6 s", "--json"])  # fmt: skip
    got = json.loads(capsys.readouterr().out)
    assert code == 0 and got["data"]["samples"] == 301
    assert got["parameters"]["e"]["value"] == pytest.approx(E, rel=1e-6)
