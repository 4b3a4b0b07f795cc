"""Parameter maps: the tidy table, executors (serial, processes, a 2-worker Dask LocalCluster)
giving identical rows, resumable files, parameter sets, the heat map and the command line."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.free.simulation import equivalent_damping_ratio, simulate
from symimpact.maps import OUTPUTS, parameter_map, read_map, read_sets
from symimpact.model.system import ImpactSystem
from symimpact.report.plots import plot_map

BASE = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GRID = {"gap": "6 mm:30 mm:4 mm", "mass_ratio": [0.1, 0.25, 0.4]}
KW = {"xdot0": 0.5, "t_end": 12.0, "progress": False}


@pytest.fixture(scope="module")
def serial_table():
    return parameter_map(BASE, GRID, executor="serial", **KW)


def test_rows_are_the_simulations_of_their_points(serial_table):
    t = serial_table
    assert list(t.columns) == ["run", "gap", "mass_ratio", *OUTPUTS]
    assert len(t) == 7 * 3 and list(t["run"]) == list(range(21))
    # first input varies slowest
    assert list(t["gap"][:3]) == [0.006] * 3 and list(t["mass_ratio"][:3]) == [0.1, 0.25, 0.4]
    for i in (0, 7, 20):
        row = t.iloc[i]
        res = simulate(BASE.with_(gap=row["gap"], m=row["mass_ratio"] * BASE.M), 0, 0.5, 0, 0, 12)
        assert row["n_impacts"] == res.n_impacts and row["n_effective"] == res.n_effective
        assert row["damping_inclination"] == res.damping_inclination
        dissipated = res.energy["dissipated_C"] + res.energy["dissipated_c1"]
        assert row["energy_dissipated"] == dissipated
        assert row["energy_initial"] == pytest.approx(0.5 * BASE.M * 0.5**2, rel=1e-15)
    # balance: initial = final + dissipated + residual, residual small
    assert (t["energy_residual"].abs() < 1e-9 * t["energy_initial"]).all()
    # no NaN: undefined values are <NA>
    for c in OUTPUTS[2:-1]:
        assert not np.isnan(t[c].dropna().to_numpy(float)).any()


def test_equivalent_damping_ratio_is_zeta_for_a_linear_oscillator():
    # gap far larger than the motion: no impact, x = A e^(-ζωt) sin(ω_d t); ζ_eq must equal ζ
    for zeta in (0.001, 0.02, 0.1):
        s = ImpactSystem(M=2.0, K=300.0, zeta=zeta, m=0.1, gap=1.0, a=1.0, b=1.0)
        res = simulate(s, 0, 0.3, 0, 0, 4.0)
        assert res.n_impacts == 0
        assert res.zeta_eq == pytest.approx(zeta, rel=1e-7)
    # only the upper envelope counts: a lower maximum before a higher one is ignored
    peaks = np.array([[0.0, 1.0], [0.5, 0.2], [1.0, math.exp(-1.0)], [2.0, math.exp(-2.0)]])
    assert equivalent_damping_ratio(peaks, 1.0) == pytest.approx(1.0, rel=1e-12)
    assert equivalent_damping_ratio(peaks[:1], 1.0) is None


def test_process_and_dask_executors_give_identical_rows(serial_table):
    distributed = pytest.importorskip("distributed")
    procs = parameter_map(BASE, GRID, executor="processes", workers=2, chunk_size=2, **KW)
    pd.testing.assert_frame_equal(procs, serial_table, check_exact=True)
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        assert len(client.scheduler_info()["workers"]) == 2
        via_client = parameter_map(BASE, GRID, client=client, chunk_size=3, **KW)
        via_address = parameter_map(BASE, GRID, scheduler=cluster.scheduler_address, **KW)
    pd.testing.assert_frame_equal(via_client, serial_table, check_exact=True)
    pd.testing.assert_frame_equal(via_address, serial_table, check_exact=True)


class _Stop(Exception):
    pass


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_interrupted_map_resumes_and_computes_only_the_missing_runs(tmp_path, serial_table, suffix):
    out = tmp_path / f"map{suffix}"
    seen = []

    def stop_after_three_chunks(done, total):
        seen.append(done)
        if len(seen) == 3:
            raise _Stop

    with pytest.raises(_Stop):
        parameter_map(
            BASE,
            GRID,
            executor="serial",
            chunk_size=2,
            out=out,
            **{**KW, "progress": stop_after_three_chunks},
        )
    assert not out.exists()  # nothing under the output's name until the map is complete
    partial = tmp_path / f".map{suffix}.partial"
    assert len(list(partial.glob("chunk-*"))) == 3
    # another map into the same file is refused instead of mixed in
    with pytest.raises(ParameterError, match="other inputs") as err:
        parameter_map(BASE, {"gap": "6 mm:30 mm:4 mm"}, executor="serial", out=out, **KW)
    assert err.value.parameter == "out"

    counts = []
    resumed = parameter_map(
        BASE,
        GRID,
        executor="serial",
        chunk_size=2,
        out=out,
        **{**KW, "progress": lambda d, t: counts.append(d)},
    )
    assert counts[0] == 6 + 2  # started from the six saved runs
    assert counts[-1] == 21 and len(counts) == math.ceil(15 / 2)
    pd.testing.assert_frame_equal(resumed, serial_table, check_exact=True)
    pd.testing.assert_frame_equal(read_map(out), serial_table, check_exact=True)
    assert not partial.exists()
    with pytest.raises(ParameterError, match="exists"):
        parameter_map(BASE, GRID, executor="serial", out=out, **KW)
    again = parameter_map(BASE, GRID, executor="serial", out=out, force=True, **KW)
    pd.testing.assert_frame_equal(again, serial_table, check_exact=True)


def test_parameter_sets_from_csv_with_units(tmp_path):
    f = tmp_path / "sets.csv"
    f.write_text("gap [mm],c1,xdot0\n9,5 N s/m,50 cm/s\n15,2.5,0.25\n")
    pts = read_sets(f)
    assert pts.names == ("gap", "c1", "xdot0")
    np.testing.assert_array_equal(pts.values, [[0.009, 5.0, 0.5], [0.015, 2.5, 0.25]])
    t = parameter_map(BASE, sets=f, executor="serial", t_end=5.0, progress=False)
    res = simulate(BASE.with_(gap=0.015, c1=2.5), 0, 0.25, 0, 0, 5.0)
    assert t.loc[1, "n_impacts"] == res.n_impacts
    assert t.loc[1, "damping_inclination"] == res.damping_inclination
    bad = tmp_path / "bad.csv"
    bad.write_text("gap,colour\n1,2\n")
    with pytest.raises(ParameterError, match="colour: cannot be swept"):
        read_sets(bad)
    bad.write_text("gap\n5 kg\n")
    with pytest.raises(ParameterError, match="line 2"):
        read_sets(bad)


def test_heat_map_marks_the_optimum_of_each_row(serial_table, tmp_path):
    png = tmp_path / "heat.png"
    opt = plot_map(serial_table, "gap", "mass_ratio", "damping_inclination", png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    di = serial_table.astype({"damping_inclination": "float64"})
    for ratio, gap, value in opt["rows"]:
        sub = di[di["mass_ratio"] == ratio]
        best = sub.loc[sub["damping_inclination"].idxmax()]
        assert (gap, value) == (best["gap"], best["damping_inclination"])
    top = di.loc[di["damping_inclination"].idxmax()]
    assert (opt["gap"], opt["mass_ratio"]) == (top["gap"], top["mass_ratio"])
    with pytest.raises(ParameterError, match="not a swept input"):
        plot_map(serial_table, "gap", "n_impacts", "damping_inclination", png)


def test_cli_map_writes_table_and_heat_map(tmp_path, capsys):
    out, png = tmp_path / "m.csv", tmp_path / "h.png"
    argv = [
        "map", "--M", "1 kg", "--K", "100 N/m", "--C", "1 N s/m", "--m", "0.25 kg",
        "--c1", "5 N s/m", "--k-hz", "1000", "--xdot0", "0.5 m/s", "--t-end", "12 s",
        "--vary", "gap=6 mm:30 mm:4 mm", "--vary", "mass_ratio=0.1,0.25,0.4",
        "--executor", "serial", "--quiet", "--out", str(out), "--plot", str(png),
    ]  # fmt: skip
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert "max damping_inclination" in text and png.exists()
    got = read_map(out)
    ref = parameter_map(
        ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0,
                     a=155300.0, b=83.6),
        GRID, executor="serial", **KW,
    )  # fmt: skip
    pd.testing.assert_frame_equal(got, ref, check_exact=True)


@pytest.mark.parametrize(
    "argv, message",
    [
        (["map", "--vary", "gap=6 mm:30 mm:0 mm"], "gap: range step must be positive"),
        (["map", "--vary", "colour=1,2"], "colour: cannot be swept"),
        (["map", "--vary", "gap"], "vary: 'gap' must be NAME=RANGE"),
        (["map", "--vary", "gap=1,2", "--vary", "gap=3"], "gap: is swept twice"),
        (["map", "--vary", "m=0.1", "--vary", "mass_ratio=0.2"], "mass_ratio: sweep m or"),
        (["map", "--vary", "gap=5 kg"], "gap: '5 kg' has dimension"),
        (["map", "--vary", "gap=9 mm", "--out", "/nonexistent/x.csv"], "out: folder"),
        (["map", "--vary", "gap=9 mm", "--out", "x.txt"], "out: 'x.txt' must end in"),
        (["map", "--vary", "gap=9 mm", "--sets", "s.csv"], "sets: give one of"),
        (["map", "--sets", "/nonexistent.csv"], "sets: cannot read"),
        (["map", "--vary", "mass_ratio=-0.1"], "mass_ratio: must be positive"),
        (["map", "--vary", "gap=9 mm,1 mm", "--y0", "4 mm"], "y0: |y0 − x0|"),
    ],
)
def test_cli_map_bad_input_exits_2_with_one_line(argv, message, capsys):
    assert main([*argv, "--quiet", "--executor", "serial"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err, err


def test_progress_bar_ends_on_the_last_run(capsys):
    """tqdm draws at most every 0.1 s, so a fast map's last drawn state was an early count (the
    issue saw 69 %); the bar now draws its final count and leaves that line."""
    parameter_map(BASE, {"gap": "6 mm:30 mm:2 mm"}, executor="serial", xdot0=0.5, t_end=2.0)
    drawn = [s for s in capsys.readouterr().err.replace("\r", "\n").splitlines() if "%" in s]
    assert drawn and "100%" in drawn[-1] and "13/13" in drawn[-1]


def _field(outlier: float | None) -> pd.DataFrame:
    """DI [m] on a 6 × 4 grid, smooth (1.5–1.9 mm, largest at the grid's middle), with one cell
    replaced by ``outlier`` (the issue's map: 2290 µm among neighbours near 1700 µm)."""
    rows = []
    for j, ratio in enumerate((0.1, 0.2, 0.3, 0.4)):
        for i, gap in enumerate(np.arange(6, 18, 2) * 1e-3):
            di = 1.9e-3 - 2e-5 * (i - 3) ** 2 - 3e-5 * (j - 2) ** 2
            if outlier is not None and (i, j) == (1, 1):
                di = outlier
            rows.append({"gap": gap, "mass_ratio": ratio, "damping_inclination": di})
    return pd.DataFrame(rows)


def test_an_isolated_best_cell_is_marked(tmp_path):
    """The star of the heat map stands for a design its neighbourhood confirms: a lone outlier
    (2290 µm where its best neighbour gives 1880 µm, a jump of 59 % of the map's range) is
    marked isolated with that neighbour's value; the smooth field's peak (its neighbours within
    2e-5 m, 7 % of the range) is not."""
    png = tmp_path / "heat.png"
    opt = plot_map(_field(2.29e-3), "gap", "mass_ratio", "damping_inclination", png)
    assert (opt["gap"], opt["mass_ratio"], opt["damping_inclination"]) == (8e-3, 0.2, 2.29e-3)
    assert opt["isolated"] and opt["neighbour_best"] == pytest.approx(1.88e-3)
    opt = plot_map(_field(None), "gap", "mass_ratio", "damping_inclination", png)
    assert (opt["gap"], opt["mass_ratio"]) == (pytest.approx(12e-3), 0.3)
    assert not opt["isolated"]
    assert opt["neighbour_best"] == pytest.approx(1.9e-3 - 2e-5)
