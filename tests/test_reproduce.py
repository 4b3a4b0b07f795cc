"""`symimpact reproduce`: the report's numbers against independent computations, its files, and
its folder behaviour (atomic, refuses to overwrite, --force)."""

from __future__ import annotations

import csv
import math
import os
import struct
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.free.reference import reference_impacts
from symimpact.report import beyond_stage, contact_stage, paper, reproduce, vibration_stage
from symimpact.report.document import Figure, Table

#: The progress bars of the fixture's report, in the order they were opened.
_BARS: list[_Bar] = []


class _Bar:
    """Records a stage's progress bar: its total and every update."""

    def __init__(self, total, desc, **_):
        self.total, self.desc, self.updates = total, desc, []
        _BARS.append(self)

    def update(self, n=1):
        self.updates.append(n)

    def close(self):
        pass


#: What each of the fixture's figures' legends cover (figure name → labels), found as it was saved.
_COVERED: dict[str, list[str]] = {}


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    from symimpact.report import figures

    out = tmp_path_factory.mktemp("rep") / "report"
    _BARS.clear()
    _COVERED.clear()
    savefig = figures.atomic_savefig

    def recorded(fig, path, **kw):
        _COVERED[Path(path).stem] = figures.covered_by_legend(fig)
        return savefig(fig, path, **kw)

    with pytest.MonkeyPatch.context() as mp_:
        mp_.setattr("symimpact.report.tqdm", _Bar)
        mp_.setattr(figures, "atomic_savefig", recorded)
        path, sections = reproduce(out, quick=True, progress=True, command="pytest")
    return path, {s.key: s for s in sections}


def test_every_stage_reaches_its_planned_steps_and_the_design_map_moves_per_design(report):
    from symimpact.report import forced_stage

    assert [b.desc.split(" ")[0] for b in _BARS] == ["contact", "free", "beyond", "forced", "loads"]
    for bar in _BARS:
        assert sum(bar.updates) == bar.total, bar.desc
    forced = _BARS[-2]
    designs = len(forced_stage._design_gaps(True)) * len(forced_stage.MASS_RATIOS_QUICK)
    assert forced.total == 1 + 2 * len(forced_stage.GAPS_MM) + designs
    # one update per design or per group of designs finished together, never one for the map
    assert len([n for n in forced.updates if n > 0]) >= 1 + 2 * len(forced_stage.GAPS_MM) + 2
    assert forced_stage.steps(False) > forced_stage.steps(True)


# --- files -----------------------------------------------------------------------------------------
def _png_size(path: Path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    assert data[12:16] == b"IHDR"
    return struct.unpack(">II", data[16:24])


def test_every_figure_is_a_valid_nonempty_png(report):
    import matplotlib.image

    path, sections = report
    figures = [b for s in sections.values() for b in s.blocks if isinstance(b, Figure)]
    names = {f.name for f in figures}
    assert {"fig2_force_laws", "fig3a_amplitude_ratio", "fig3b_iterations", "fig4_response_9mm",
            "fig5_relative_motion", "fig6_six_gaps", "fig7_gap_sweep", "accuracy_map",
            "lindstedt_orders", "gap_classes", "forced_frc", "forced_frc_compliant",
            "forced_design_map", "loads_random_psd", "loads_shock_srs"} <= names  # fmt: skip
    for f in figures:
        png = path / f"{f.name}.png"
        w, h = _png_size(png)
        assert w > 300 and h > 200
        img = matplotlib.image.imread(png)
        assert img.shape[:2] == (h, w)
        assert float(np.std(img[..., :3])) > 0.01  # not a blank canvas


def test_no_legend_covers_data(report):
    """Every figure's legends sit on blank space or outside the axes (issue 35, item 8: the
    legends of Fig. 5 and Fig. 7 covered curves and markers)."""
    assert len(_COVERED) >= 12, sorted(_COVERED)
    assert {name: labels for name, labels in _COVERED.items() if labels} == {}


def test_covered_by_legend_sees_a_line_under_the_legend():
    """The check itself, on figures whose answer is known: a level line through a corner legend
    and a marker under it are covered; the same legend beside the axes covers nothing."""
    from symimpact.report.figures import covered_by_legend, pyplot
    from symimpact.report.plots import legend_beside

    plt = pyplot()
    x = np.linspace(0.0, 1.0, 50)
    fig, ax = plt.subplots()
    ax.plot(x, x**8, label="low curve")
    ax.axhline(0.97, label="level")
    ax.plot([0.03], [0.9], "ko", label="point")
    ax.legend(loc="upper left")
    assert covered_by_legend(fig) == ["level", "point"]
    ax.get_legend().remove()
    legend_beside(ax)
    fig.tight_layout()
    assert covered_by_legend(fig) == []
    plt.close(fig)


def test_every_table_has_its_csv_with_full_precision(report):
    path, sections = report
    tables = [b for s in sections.values() for b in s.blocks if isinstance(b, Table)]
    assert {"table1", "table3", "table3_as_stated", "table2_readings", "fit_coefficients",
            "gap_range", "gap_intervals", "accuracy_map_summary", "lindstedt_orders"} <= {
        t.name for t in tables}  # fmt: skip
    for t in tables:
        with open(path / f"{t.name}.csv", newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        assert rows[0] == t.columns
        assert len(rows) == len(t.rows) + 1
        for raw, row in zip(t.rows, rows[1:], strict=True):
            for v, text in zip(raw, row, strict=True):
                if isinstance(v, float):
                    assert float(text) == v  # round-trip exact
                    # and the shortest such decimal: no float noise (0.1, not 0.10000000000000001)
                    assert text == repr(float(v))


def test_html_and_markdown_carry_version_command_and_every_figure(report):
    from symimpact import __version__

    path, sections = report
    page = (path / "index.html").read_text(encoding="utf-8")
    md = (path / "report.md").read_text(encoding="utf-8")
    for text in (page, md):
        assert f"symimpact {__version__}" in text
        assert "pytest" in text
        for s in sections.values():
            for f in s.figures():
                assert f"{f.name}.png" in text
    assert "<script" not in page and "http://" not in page and "https://" not in page
    assert not [p for p in path.parent.iterdir() if p.name.startswith(".report.")]


# --- Table 1 and the fit against independent computations ------------------------------------------
def _row(table: Table, m: float, method: str) -> list:
    for r in table.rows:
        if r[0] == m and r[1].startswith(method):
            return r
    raise KeyError((m, method))


def _hertz_mp(m, M, k_hz, v0):
    """Eq. 34 with the exact constant, in mpmath (not the generated kernel)."""
    mp.mp.dps = 30
    c = 4 * mp.sqrt(mp.pi) * mp.gamma(mp.mpf(2) / 5) / (5 * mp.gamma(mp.mpf(9) / 10))
    kstar = (mp.mpf(m) + M) / (mp.mpf(m) * M)
    return float(c * (5 / (4 * kstar * k_hz)) ** (mp.mpf(2) / 5) / mp.mpf(v0) ** (mp.mpf(1) / 5))


def _fit_lstsq():
    d = np.linspace(0, 0.02, 21)
    f = 1000.0 * d**1.5
    (a, b), *_ = np.linalg.lstsq(np.c_[d**3, d], f, rcond=None)
    k1 = float(d @ f / (d @ d))
    return a, b, k1


def _contact_ivp(m, M, K, force, v0):
    """Contact phase by solve_ivp: main mass at rest at x = 0 on its spring, δ(0) = 0, δ̇ = v0."""

    def rhs(t, u):
        x, xd, d, dd = u
        f = force(max(d, 0.0))
        xdd = (f - K * x) / M
        return [xd, xdd, dd, -f / m - xdd]

    def end(t, u):
        return u[2]

    end.terminal, end.direction = True, -1
    sol = solve_ivp(rhs, (0, 10), [0, 0, 0, v0], method="DOP853", rtol=1e-12, atol=1e-15,
                    events=end, first_step=1e-7)  # fmt: skip
    return float(sol.t_events[0][0])


def test_table1_against_closed_forms_and_integration(report):
    _, sections = report
    t1 = sections["contact"].table("table1")
    a, b, k1 = _fit_lstsq()
    for m in contact_stage.TABLE1_M:
        hertz = _row(t1, m, "Hertz, Eq. 34")
        assert hertz[2] == pytest.approx(_hertz_mp(m, 1.0, 1000.0, 0.075), rel=1e-13)
        mu = m / (1 + m)
        lin = _row(t1, m, "linear, Eq. 35")
        assert lin[2] == pytest.approx(math.pi * math.sqrt(mu / k1), rel=1e-12)
        truth = _row(t1, m, "numerical, Hertz law, main mass on K")
        ivp = _contact_ivp(m, 1.0, 1000.0, lambda d: 1000.0 * d**1.5, 0.075)
        assert truth[2] == pytest.approx(ivp, rel=1e-8)
        assert truth[6] == 0.0
        # the derived Eq. 31 with B/A = −M/m is the free-body contact of the cubic law
        derived = _row(t1, m, "perturbation Eq. 31 derived, B/A = −M/m")
        free_cubic = _contact_ivp(m, 1.0, 0.0, lambda d: a * d**3 + b * d, 0.075)
        assert derived[2] == pytest.approx(free_cubic, rel=2e-4)
        # every printed Hertz and linear value equals ours at the printed digits
        for r in (hertz, lin):
            assert r[4].startswith("=")
        # errors are recomputed from the columns they name
        assert hertz[5] == pytest.approx(100 * abs(hertz[2] - hertz[3]) / hertz[3])
        assert lin[6] == pytest.approx(100 * abs(lin[2] - ivp) / ivp, rel=1e-6)


def test_fit_coefficients_against_lstsq(report):
    _, sections = report
    fit = sections["contact"].table("fit_coefficients")
    a, b, k1 = _fit_lstsq()
    assert fit.cell(0, "ours") == pytest.approx(a * 1e-6, rel=1e-10)
    assert fit.cell(1, "ours") == pytest.approx(b * 1e-2, rel=1e-10)
    assert fit.cell(2, "ours") == pytest.approx(k1, rel=1e-10)
    assert all(v == "= (rounded)" for v in fit.column("ours vs paper"))


# --- Table 2 and Table 3 -----------------------------------------------------------------------------
def test_table2_as_printed_gives_no_impact_and_the_amplitude_bound(report):
    _, sections = report
    t = sections["vibration"].table("table3_as_stated")
    assert t.column("N_tot ours") == [0] * 9
    bound = 0.005 / 100.0 * 1e3  # Ẋ0/ω_n in mm
    assert max(t.column("max x [mm]")) <= bound
    assert min(t.column("d/2 [mm]")) > 10 * bound


def test_reading_choice_is_the_minimum_of_the_stated_misfit(report):
    _, sections = report
    ranking = sections["vibration"].table("table2_readings")
    scores = [r for r in ranking.column("misfit") if r is not None]
    assert scores == sorted(scores) and len(scores) == 12
    assert ranking.rows[0][5] == "chosen"
    assert [r[5] for r in ranking.rows].count("as printed") == 1
    # recompute the chosen reading's misfit from fresh simulations
    chosen = vibration_stage.Reading(*ranking.rows[0][:3])
    runs = [(float(d), chosen.run(float(d))) for d in paper.TABLE3]
    assert vibration_stage.misfit(runs) == pytest.approx(ranking.rows[0][3], rel=1e-12)


def test_table3_impacts_against_the_solve_ivp_reference(report):
    _, sections = report
    t3 = sections["vibration"].table("table3")
    ranking = sections["vibration"].table("table2_readings")
    chosen = vibration_stage.Reading(*ranking.rows[0][:3])
    for d in (9.0, 25.0):
        s = chosen.system(d)
        xdot0 = float(chosen.run(d).initial_state[1])
        ref = reference_impacts(s, 0.0, xdot0, 0.0, 0.0, vibration_stage.T_PRIME_END / s.omega_n)
        row = t3.rows[list(paper.TABLE3).index(f"{d:g}")]
        assert row[3] == len(ref)
        assert row[5] == sum(1 for r in ref if r["xdot"] * r["ydot"] < 0)
        assert row[4] == int(paper.TABLE3[f"{d:g}"][1])  # the paper's value sits beside ours


def test_zeta_eq_below_the_primarys_own_is_explained_by_energy_given_back(report):
    """The ζ_eq table: the primary alone's ζ_eq is its own ζ (every maximum of a linear
    oscillator lies on e^(−ζω_n t): exact to rounding), every gap where ζ_eq < ζ has a rise of
    the maxima, and a rise is energy a contact gave back: the independent solve_ivp reference
    (scipy's DOP853 with its own contact events) has a contact between the two maxima."""
    _, sections = report
    table = sections["vibration"].table("zeta_eq_gap")
    ranking = sections["vibration"].table("table2_readings")
    chosen = vibration_stage.Reading(*ranking.rows[0][:3])
    zeta = chosen.system(9.0).zeta
    assert chosen.alone().zeta_eq == pytest.approx(zeta, rel=1e-9)
    below = [r for r in table.rows if r[1] < zeta]
    assert below and all(r[2] > 0 for r in below)
    d = below[0][0]
    run = chosen.run(d)
    pk = run.peaks
    k = int(np.flatnonzero(pk[1:, 1] > pk[:-1, 1])[0])
    s = chosen.system(d)
    ref = reference_impacts(s, 0.0, float(run.initial_state[1]), 0.0, 0.0,
                            vibration_stage.T_PRIME_END / s.omega_n)  # fmt: skip
    assert any(r["t"] < pk[k + 1, 0] and r.get("t_off", math.inf) > pk[k, 0] for r in ref)


# --- beyond the paper ------------------------------------------------------------------------------
def test_forced_section_restitution_peaks_and_best_clearance(report):
    """The forced-response section: its e is the restitution of a linear contact (k1 of the
    paper's fit, c1 of the chosen reading), written here from the damped oscillator,
    exp(−ζπ/√(1 − ζ²)) with ζ = c1/(2√(k1·μ)); each gap's peak is at least the largest swept
    amplitude less the sweeps' transient (1e-4); the best clearance of each mass ratio is the
    smallest peak of the design map's CSV for that ratio."""
    path, sections = report
    forced = sections["forced"]
    text = " ".join(b for b in forced.blocks if isinstance(b, str))
    reading = sections["vibration"].facts["reading"]
    system = reading.system(9.0)
    mu = system.m * system.M / (system.m + system.M)
    k1 = float(paper.FIT["k1"])
    zeta = system.c1 / (2 * math.sqrt(k1 * mu))
    e = math.exp(-zeta * math.pi / math.sqrt(1 - zeta * zeta))
    assert f"e = {e:.4f}" in text
    peaks = next(b for b in forced.blocks if isinstance(b, Table) and b.name == "forced_peaks")
    for row in peaks.rows:
        peak, swept = row[2], row[5]
        assert peak >= swept * (1 - 1e-4)
        assert row[7] == pytest.approx(peak / row[6], rel=1e-12)
        traced, periodic = (int(x) for x in row[8].split(" of "))  # the coverage, "k of n"
        assert 0 <= traced <= periodic and row[9] >= 0
    compliant = next(b for b in forced.blocks
                     if isinstance(b, Table) and b.name == "forced_compliant_peaks")  # fmt: skip
    rigid = {row[0]: row[2] for row in peaks.rows}
    assert [row[0] for row in compliant.rows] == list(rigid)
    for gap_mm, _, peak, _, _, rigid_peak, ratio in compliant.rows:
        assert rigid_peak == rigid[gap_mm] and ratio == pytest.approx(peak / rigid_peak, rel=1e-12)
    with open(path / "forced_design_map.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    best = next(b for b in forced.blocks
                if isinstance(b, Table) and b.name == "forced_best_clearance")  # fmt: skip
    assert best.rows
    for ratio, gap_mm, peak_mm, *_ in best.rows:
        mine = [r for r in rows if float(r["m/M"]) == ratio]
        least = min(mine, key=lambda r: float(r["peak [mm]"]))
        assert float(least["d [mm]"]) == pytest.approx(gap_mm, rel=1e-12)
        assert float(least["peak [mm]"]) == pytest.approx(peak_mm, rel=1e-12)


def test_lindstedt_truth_matches_the_elliptic_integral_and_orders_improve():
    for x in (1e-3, 0.1, 1.0, 3.0):
        num = beyond_stage.duffing_frequency_numerical(1.0, x, 1.0)
        ell = beyond_stage.duffing_frequency_elliptic(1.0, x, 1.0)
        assert num == pytest.approx(ell, rel=1e-10)
    # against an mpmath elliptic integral as a third, independent value
    mp.mp.dps = 30
    k2 = mp.mpf("0.5") / (2 * (1 + mp.mpf("0.5")))
    exact = mp.pi * mp.sqrt(1 + mp.mpf("0.5")) / (2 * mp.ellipk(k2))
    assert beyond_stage.duffing_frequency_numerical(1.0, 0.5, 1.0) == pytest.approx(
        float(exact), rel=1e-10
    )
    err = beyond_stage.lindstedt_errors(np.array([0.01, 0.1]))
    for j in range(2):
        assert err["order1"][j] > err["order2"][j] > err["order3"][j]
    # leading error of order 1 is the ε² term of the series: 21/256 (εα²)²
    assert err["order1"][0] == pytest.approx(21 / 256 * 1e-4, rel=2e-2)


def test_accuracy_by_cancellation_is_a_sign_change_not_a_regime():
    """A grid whose error crosses zero along a line: its small-error stripe is accurate by
    cancellation; an error that shrinks towards a corner with one sign is a regime; the two side
    by side are told apart (issue 35, item 8: the accuracy map counted the stripes as accuracy)."""
    x, y = np.meshgrid(np.linspace(0.0, 1.0, 41), np.linspace(0.0, 1.0, 41))
    crossing = 40.0 * (x - 0.5125)  # [%]: zero between grid lines, at x = 0.5125
    chance = beyond_stage.accurate_by_cancellation(crossing)
    assert np.array_equal(chance, np.abs(crossing) <= 10.0)
    regime = 30.0 * (x + y)  # [%]: one sign, small towards the corner (0, 0)
    assert not beyond_stage.accurate_by_cancellation(regime).any()
    both = np.where(y < 0.5, regime, crossing)
    chance = beyond_stage.accurate_by_cancellation(both)
    assert not chance[y < 0.3].any()  # the regime's corner, away from the crossing
    assert chance[(y > 0.6) & (np.abs(crossing) <= 10.0)].all()


def test_accuracy_map_hertz_is_exact_without_spring_and_linear_matches_closed_form():
    q = np.array([0.05, 0.5])
    v0 = np.array([0.02, 0.3])
    err = beyond_stage.accuracy_errors(q, v0, 1e-9)
    assert np.max(np.abs(err["hertz"])) < 1e-6  # Eq. 34 is exact for two free bodies (percent)
    for i, m in enumerate(q):
        for j, v in enumerate(v0):
            assert err["truth"][i, j] == pytest.approx(_hertz_mp(m, 1.0, 1000.0, v), rel=1e-8)


# --- paper comparison rules ------------------------------------------------------------------------
@pytest.mark.parametrize(
    "ours, printed, rounds, truncates",
    [(0.16646, "0.1664", False, True), (0.15092, "0.1509", True, True),
     (0.14159, "0.1407", False, False), (122.691, "122.7", True, False),
     (0.83595, "0.8360", True, False)],
)  # fmt: skip
def test_compare_knows_rounding_from_truncation(ours, printed, rounds, truncates):
    c = paper.compare(ours, printed)
    assert (c.rounds, c.truncates) == (rounds, truncates)
    assert c.deviation == pytest.approx((ours - float(printed)) / float(printed))


# --- folder behaviour ------------------------------------------------------------------------------
@pytest.mark.slow  # a quick report (70 s on CI's 2 cores): in the slow set
def test_refuses_a_nonempty_folder_and_force_replaces_only_its_own(tmp_path, capsys):
    """Issue 16, item 5: --force removed any non-empty folder (a thesis.tex went with it); now it
    replaces only a folder symimpact wrote (it holds the .symimpact-output marker).  The folder
    symimpact wrote before is written by the staging every output folder goes through
    (:func:`symimpact.io.staged_folder`, which a report's run uses); one report is then run, with
    --force, over it (a second report, 70 s of CI's slow set, wrote the same folder)."""
    from symimpact.io import staged_folder

    out = tmp_path / "rep"
    out.mkdir()
    (out / "thesis.tex").write_text("x")
    for extra in ([], ["--force"]):
        assert main(["reproduce", str(out), "--quick", "--quiet", *extra]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "out" in err and "Traceback" not in err
        assert (out / "thesis.tex").exists()
    assert "not written by symimpact" in err
    mine = tmp_path / "mine"
    with staged_folder(mine) as staged:
        (staged / "index.html").write_text("an earlier report")
    (mine / "extra.txt").write_text("x")
    assert main(["reproduce", str(mine), "--quick", "--quiet", "--force"]) == 0
    assert not (mine / "extra.txt").exists() and (mine / "index.html").exists()
    assert "an earlier report" not in (mine / "index.html").read_text(encoding="utf-8")
    assert (mine / ".symimpact-output").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine", "rep"]  # no leftovers


def test_leftovers_of_killed_runs_are_removed_and_links_refused(tmp_path):
    from symimpact.io import staged_folder

    dead = tmp_path / ".rep.partial-999999999-abc"  # no process has this pid
    dead.mkdir()
    live = tmp_path / f".rep.partial-{os.getpid()}-abc"  # a run still going
    live.mkdir()
    with staged_folder(tmp_path / "rep") as tmp:
        (tmp / "a.txt").write_text("a")
    assert not dead.exists() and live.exists()
    (tmp_path / "link").symlink_to(tmp_path / "rep")
    with pytest.raises(ParameterError, match="symbolic link"):
        with staged_folder(tmp_path / "link", force=True):
            pass


def test_interrupted_run_leaves_no_report(tmp_path, monkeypatch):
    out = tmp_path / "rep"

    def boom(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(beyond_stage, "section", boom)
    with pytest.raises(KeyboardInterrupt):
        reproduce(out, quick=True, progress=False)
    assert list(tmp_path.iterdir()) == []


def test_output_under_a_missing_folder_is_a_parameter_error(tmp_path):
    with pytest.raises(ParameterError) as exc:
        reproduce(tmp_path / "no" / "such" / "rep", quick=True, progress=False)
    assert exc.value.parameter == "out"


def test_long_tables_are_links_and_the_paper_is_cited_by_title(report):
    """Issue 17, item 8: the gap sweep behind Fig. 7 (hundreds of rows in the full report) is its
    CSV link with a summary; the report cites the paper by its title, not by a path."""
    path, sections = report
    t = sections["vibration"].table("fig7_gap_sweep")
    assert t.link_only and "gaps in range" in t.note
    md = (path / "report.md").read_text(encoding="utf-8")
    assert f"{len(t.rows)} rows, in the CSV file." in md
    assert "| d [mm] | N_tot | N_eff | effectiveness | DI [µm] | class |" not in md
    assert "shared/paper" not in md and "Free vibration analysis of nonlinear resilient" in md
    assert "shared/paper" not in (path / "index.html").read_text(encoding="utf-8")


def test_without_a_folder_it_says_what_it_would_write_and_stops(tmp_path, capsys, monkeypatch):
    """`symimpact reproduce` alone starts no run (issue 35 item 6): it prints the stages and
    exits 2 naming `out`; nothing is written in the working folder."""
    monkeypatch.chdir(tmp_path)
    assert main(["reproduce"]) == 2
    out, err = capsys.readouterr()
    assert "1. contact" in out and "4. forced" in out
    assert err.startswith("symimpact reproduce: error: out:") and "--quick" in err
    assert list(tmp_path.iterdir()) == []
