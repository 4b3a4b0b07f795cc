"""Issue 82: the restitution identified from single impacts, with its uncertainty.

Checked against what does not share the fit's code: the closed form of a regression through the
origin and its t-interval (the constant law is linear in e), Thornton's formula typed from his
paper and evaluated in mpmath (noise-free data give back the yield speed), central differences
(the Jacobians), the interval's coverage over many noisy data sets, and the free fall
(drop heights)."""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest
from scipy import stats

from symimpact.cli import main
from symimpact.identify import Impacts, fall_speed, fit_restitution, read_impacts, restitution
from symimpact.identify.impacts import _jacobian


def _thornton_mp(v_y: float, w: float) -> float:
    """Thornton (1997), e of an elastic–perfectly-plastic sphere above first yield, typed from
    the paper in mpmath: e = √(6√3/5)·√(1 − r²/6)·[r/(r + 2√(6/5 − r²/5))]^¼, r = v_y/w."""
    if w <= v_y:
        return 1.0
    r = mpmath.mpf(v_y) / mpmath.mpf(w)
    e = (mpmath.sqrt(6 * mpmath.sqrt(3) / 5) * mpmath.sqrt(1 - r**2 / 6)
         * (r / (r + 2 * mpmath.sqrt(mpmath.mpf(6) / 5 - r**2 / 5))) ** mpmath.mpf(0.25))  # fmt: skip
    return float(e)


def _write(path, header, rows) -> str:
    path.write_text(header + "\n" + "\n".join(f"{float(a)!r},{float(b)!r}" for a, b in rows) + "\n")
    return str(path)


def test_constant_e_is_the_regression_through_the_origin_with_its_t_interval():
    """e = Σwv/Σw², se = √(s²/Σw²), and the profile interval of a model linear in e is exactly
    e ± t₀.₉₇₅(n−1)·se (1e-9: the interval's ends are roots found to 1e-14 of a quadratic)."""
    rng = np.random.default_rng(11)
    w = rng.uniform(0.1, 3.0, 17)
    v = 0.83 * w + rng.normal(0.0, 0.02, w.size)
    got = fit_restitution(Impacts(w, v), "constant")
    e = float(w @ v / (w @ w))
    s2 = float(((v - e * w) ** 2).sum()) / (w.size - 1)
    se = math.sqrt(s2 / float(w @ w))
    t = stats.t.ppf(0.975, w.size - 1)
    p = got.parameters["e"]
    assert p.value == pytest.approx(e, rel=1e-12)
    assert p.stderr == pytest.approx(se, rel=1e-9)
    assert p.ci95[0] == pytest.approx(e - t * se, rel=1e-9)
    assert p.ci95[1] == pytest.approx(e + t * se, rel=1e-9)
    assert got.dof == w.size - 1 and not got.warnings


@pytest.mark.parametrize("v_y", [0.004, 0.05, 0.7])
def test_noise_free_impacts_give_back_thorntons_yield_speed(v_y):
    """Rebound speeds from Thornton's formula in mpmath, impacts from below the yield speed to
    100 times it: the fitted v_y is the one that made them (1e-9: the derived kernel and the
    typed formula agree to ~1e-15, and the optimum of an exact fit is found to xtol 1e-15)."""
    w = np.geomspace(0.3 * v_y, 100 * v_y, 20)
    v = np.array([wi * _thornton_mp(v_y, wi) for wi in w])
    got = fit_restitution(Impacts(w, v), "thornton")
    assert got.parameters["yield_speed"].value == pytest.approx(v_y, rel=1e-9)
    assert got.residual_rms < 1e-12 * w.max()


@pytest.mark.parametrize("law, theta", [("thornton", [0.03]), ("power", [0.03, 0.3]),
                                        ("constant", [0.7])])  # fmt: skip
def test_the_jacobians_are_the_differences_of_the_rebound_speeds(law, theta):
    """∂(w·e)/∂θ against central differences (rel. step 1e-6: truncation ~1e-12, rounding
    ~1e-10 of the speed; 1e-7 leaves room for both), at speeds on both sides of v_y."""
    w = np.geomspace(0.01, 2.0, 15)
    jac = _jacobian(law, np.array(theta), w)
    for k in range(len(theta)):
        h = 1e-6 * theta[k]
        up, dn = list(theta), list(theta)
        up[k] += h
        dn[k] -= h
        diff = (w * restitution(law, up, w) - w * restitution(law, dn, w)) / (2 * h)
        assert np.allclose(jac[:, k], diff, rtol=1e-7, atol=1e-7 * np.abs(diff).max())


def test_the_95_percent_intervals_cover_the_truth_about_95_percent_of_the_time():
    """120 noisy data sets of Thornton's law (σ 5 mm/s on the rebound speed): the profile
    interval holds the true v_y in 95 % of them, up to the binomial spread.  Expected 114 of
    120, standard deviation 2.4; the bounds 104 and 120 are 4 deviations out (a false alarm
    about once in 30 000 runs, whatever the seed)."""
    rng = np.random.default_rng(20261206)
    w = np.geomspace(0.05, 3.0, 15)
    clean = w * restitution("thornton", [0.02], w)
    hits = 0
    for _ in range(120):
        got = fit_restitution(Impacts(w, clean + rng.normal(0, 0.005, w.size)), "thornton")
        lo, hi = got.parameters["yield_speed"].ci95
        hits += lo <= 0.02 <= hi
    assert 104 <= hits <= 120


def test_drop_heights_are_free_fall_speeds(tmp_path):
    """√(2gh): 1 m of free fall is 4.42869 m/s (g = 9.80665 m/s²); a ball dropped from 1000 mm
    that rises to 810 mm has e = √0.81 = 0.9."""
    assert fall_speed(1.0) == pytest.approx(4.428690551, rel=1e-9)
    rows = [(h, 0.81 * h) for h in (100.0, 250.0, 500.0, 1000.0)]
    data = read_impacts(
        _write(tmp_path / "drops.csv", "drop height [mm],rebound height [mm]", rows)
    )
    assert data.given == "height"
    assert data.v_in[-1] == pytest.approx(4.428690551, rel=1e-9)
    assert fit_restitution(data, "constant").parameters["e"].value == pytest.approx(0.9, rel=1e-12)


def test_a_yield_speed_above_every_impact_is_said_to_be_undetermined():
    """Every impact elastic (e = 1, and noise that only adds: the law cannot exceed 1, so any v_y
    above the fastest impact fits best): the data bound v_y from below only, which a warning
    says; its interval is open above."""
    rng = np.random.default_rng(5)
    w = np.linspace(0.1, 1.0, 12)
    got = fit_restitution(Impacts(w, w * (1 + np.abs(rng.normal(0, 1e-3, w.size)))), "thornton")
    assert got.parameters["yield_speed"].ci95[1] is None
    assert any("yield_speed" in text for text in got.warnings)


def test_one_speed_cannot_separate_the_power_laws_two_parameters():
    """Impacts all at one speed determine e there, not v_y and α apart: a warning says so."""
    rng = np.random.default_rng(6)
    w = np.full(10, 1.0)
    got = fit_restitution(Impacts(w, 0.7 + rng.normal(0, 0.01, w.size)), "power")
    assert any("not determined" in t or "correlated" in t for t in got.warnings)


def _cli(capsys, *argv) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_the_command_writes_a_system_file_every_command_reads(tmp_path, capsys):
    """identify impacts --json --out: the JSON of the issue, and a system file whose e a forced
    simulation runs (Thornton's law with the fitted yield speed); a typed --e wins over it."""
    w = np.geomspace(0.05, 3.0, 12)
    v = np.array([wi * _thornton_mp(0.02, wi) for wi in w])
    csv = _write(tmp_path / "impacts.csv", "approach speed [mm/s],rebound speed [mm/s]",
                 zip(w * 1e3, v * 1e3, strict=True))  # fmt: skip
    out = tmp_path / "ball.toml"
    code, text, _ = _cli(capsys, "identify", "impacts", csv, "--law", "thornton", "--json",
                         "--out", str(out))  # fmt: skip
    assert code == 0
    got = json.loads(text)
    assert set(got) >= {"parameters", "correlation", "residual_rms", "warnings", "system"}
    assert got["parameters"]["yield_speed"]["value"] == pytest.approx(0.02, rel=1e-9)
    system = ["--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--gap", "20 mm",
              "--force", "2 N", "--omega", "34", "--contact", "rigid", "--periods", "3"]  # fmt: skip
    code, text, _ = _cli(capsys, "simulate", "--system", str(out), *system, "--json")
    assert code == 0
    assert json.loads(text)["e"]["yield_speed"] == pytest.approx(0.02, rel=1e-9)
    code, text, _ = _cli(capsys, "simulate", "--system", str(out), *system, "--e", "0.5", "--json")
    assert code == 0 and json.loads(text)["e"] == 0.5


def test_the_yield_speed_is_typed_with_its_unit(capsys):
    """--e 'thornton 20 mm/s' is Thornton's law with v_y = 0.02 m/s."""
    code, text, _ = _cli(capsys, "simulate", "--M", "1", "--K", "1000", "--m", "0.05", "--gap",
                         "20 mm", "--force", "2 N", "--omega", "34", "--contact", "rigid",
                         "--e", "thornton 20 mm/s", "--periods", "2", "--json")  # fmt: skip
    assert code == 0 and json.loads(text)["e"] == {"e": "material", "yield_speed": 0.02}


@pytest.mark.parametrize(
    "header, rows, argv, words",
    [
        ("approach speed [m/s],rebound speed [m/s]", [(1.0, 0.8), (-1.0, 0.5)], [],
         "impacts: approach speeds"),
        ("approach speed [m/s],rebound height [mm]", [(1.0, 0.8), (2.0, 0.5)], [],
         "as speeds or both as heights"),
        ("approach speed [m/s],rebound speed [m/s]", [(1.0, 0.8), (2.0, 1.5)],
         ["--law", "power", "--out", "x.toml"], "out: the engines run"),
        ("approach speed [N],rebound speed [N]", [(1.0, 0.8), (2.0, 1.5)], [],
         "neither a speed nor a height"),
        ("approach speed [m/s],rebound speed [m/s]", [(1.0, 0.8)], [], "impacts: needs"),
    ],
)  # fmt: skip
def test_bad_impacts_are_refused_in_one_line(tmp_path, capsys, monkeypatch, header, rows, argv,
                                              words):  # fmt: skip
    monkeypatch.chdir(tmp_path)
    csv = _write(tmp_path / "impacts.csv", header, rows)
    code, _, err = _cli(capsys, "identify", "impacts", csv, *argv)
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1


def test_a_system_file_with_a_key_no_command_takes_is_refused(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text("zeta = 0.01\nfoo = 1\n")
    code, _, err = _cli(capsys, "simulate", "--system", str(bad))
    assert code == 2 and "system: 'foo'" in err


def test_the_guides_example_prints_what_the_guide_shows(tmp_path, capsys, monkeypatch):
    """docs/guide.md's identification example: its CSV, its command, its printed text, as
    written there."""
    import shlex
    from pathlib import Path

    guide = (Path(__file__).resolve().parents[1] / "docs" / "guide.md").read_text()
    section = guide.split("## Identification from measurements", 1)[1]
    blocks = [b.split("```", 1)[0] for b in section.split("```text\n")[1:]]
    (tmp_path / "drops.csv").write_text(blocks[0])
    command = section.split("```bash\n", 1)[1].split("```", 1)[0].replace("\\\n", " ")
    monkeypatch.chdir(tmp_path)
    code, out, _ = _cli(capsys, *shlex.split(command)[1:])
    assert code == 0
    assert out.strip().splitlines() == blocks[1].strip().splitlines()
    assert (tmp_path / "drops.png").stat().st_size > 10_000
    assert 'e = "thornton 0.0486' in (tmp_path / "ball.toml").read_text()
