"""The ``report`` sub-command: ``report --quick`` into a temporary folder, end to end,
plus the peers implemented in ``report/peers.py`` checked against independent facts."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import numpy as np
import pytest

from evaluation import report
from ocio_thinfilm.cli.main import main
from ocio_thinfilm.colour import clip, colorimetry

SECTIONS = [
    "## Machine",
    "### 1a. Spectral step",
    "### 1b. 1D table size and spacing",
    "### 1c. 3D LUT size, domain/shaper and interpolation",
    "### 1d. Analytic per-pixel evaluation vs LUT application",
    "### 2a. Gamut mapping peers",
    "### 2b. Exact band-limited integration vs the Belcour & Barla Gaussian fits",
    "### 2c. Closed form vs colour-science's transfer-matrix method",
    "## 3. Stability on stiff and extreme cases",
    "## 4. Throughput against the physical limit",
]


@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    assert main(["report", "--quick", "--no-progress", "--out", str(out)]) == 0
    return out


def test_quick_report_writes_markdown_plots_and_json(quick_report):
    md = (quick_report / "report.md").read_text(encoding="utf-8")
    for heading in SECTIONS:
        assert heading in md, heading
    assert "Skipped" not in md
    # Every referenced figure exists and is a PNG.
    figures = [line.split("](")[1].rstrip(")") for line in md.splitlines() if line.startswith("![")]
    for name in [
        "knob_spectral_step.png",
        "knob_table1d.png",
        "knob_lut3d.png",
        "knob_apply.png",
        "peers_gamut_spectrum.png",
        "peers_gaussian_fit.png",
        "throughput.png",
    ]:
        assert name in figures
    for name in figures:
        data = (quick_report / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000, name
    results = json.loads((quick_report / "report.json").read_text())
    machine = results["machine"]
    assert machine["cpu"] and machine["logical_cpus"] >= 1 and machine["OpenColorIO"]
    assert "cpu" in md and "OpenColorIO" in md


def test_quick_report_numbers_are_measured_and_sane(quick_report):
    r = json.loads((quick_report / "report.json").read_text())
    rows = r["spectral_step"]["rows"]
    fine = min(x["step"] for x in rows)
    coarse = max(x["step"] for x in rows)
    by = {(x["step"], x["band_limited"]): x for x in rows}
    # Finer steps are more accurate, and cost more.
    assert by[(fine, True)]["all"]["max"] < by[(coarse, True)]["all"]["max"]
    assert by[(fine, True)]["us_per_colour"] > by[(coarse, True)]["us_per_colour"]
    # The peers: the constant-lightness clip keeps L*, the clamp does not.
    for name, m in r["gamut"]["metrics"].items():
        assert m["constant-lightness clip"]["dL_max"] < 1e-6, name
        assert m["constant-lightness clip"]["left_out_of_gamut"] == 0.0
    assert all(v > 0 for v in r["gamut"]["throughput_Mpix_s"].values())
    assert r["throughput"]["copy_Mpix_s"]["numpy 1 thread"] > 0


def test_quick_report_stability_rows_are_backed_by_tests(quick_report):
    r = json.loads((quick_report / "report.json").read_text())
    source = (Path(__file__).parent / "test_stability.py").read_text()
    names = {n.name for n in ast.walk(ast.parse(source)) if isinstance(n, ast.FunctionDef)}
    for row in r["stability"]:
        assert row["test"] in names, row
        assert row["case"] and row["expected"] and row["observed"]


def test_quick_report_headline_is_built_from_its_json_facts(quick_report):
    """The headline is the formatting of ``report.json["headline"]`` (facts stored by
    each section under explicit ids), nothing else."""
    from evaluation.report.headline import LINES, headline_lines

    r = json.loads((quick_report / "report.json").read_text())
    md = (quick_report / "report.md").read_text(encoding="utf-8")
    headline = md.split("## Headline\n\n", 1)[1].split("\n\n", 1)[0].split("\n")
    assert set(r["headline"]) == set(LINES)
    assert all(r["headline"].values())  # every section has its facts in quick mode
    assert headline_lines(r["headline"]) == headline
    assert len(headline) == len(LINES) + 1  # the gamut section gives two lines


def test_report_bad_out_is_a_usage_error(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["report", "--quick", "--out", str(blocker / "sub")]) == 2
    err = capsys.readouterr().err
    assert "not writable" in err and len(err.strip().splitlines()) == 1


def test_quick_report_never_replaces_a_full_report(tmp_path, capsys):
    """A folder whose report.json is a full report (no "quick": true, as the committed
    reports/report.json) is refused for --quick: exit 2, one line, nothing changed."""
    full = tmp_path / "reports"
    full.mkdir()
    (full / "report.json").write_text(json.dumps({"headline": {}}))
    (full / "report.md").write_text("the full report")
    before = {p.name: p.read_bytes() for p in full.iterdir()}
    assert main(["report", "--quick", "--no-progress", "--out", str(full)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("ocio-thinfilm: --out:") or "--out:" in err, err
    assert "holds a full report" in err and len(err.splitlines()) == 1
    assert {p.name: p.read_bytes() for p in full.iterdir()} == before


def test_quick_report_records_that_it_is_quick(quick_report):
    assert json.loads((quick_report / "report.json").read_text())["quick"] is True


def test_quick_report_defaults_to_its_own_folder():
    from ocio_thinfilm.cli import report as report_cli

    assert report_cli.QUICK_OUT == "reports/quick"
    ignored = Path(".gitignore").read_text(encoding="utf-8").splitlines()
    assert "/reports/quick/" in ignored


def test_belcour_barla_fit_is_normalised_and_tracks_the_exact_integral():
    # S(0, 0) = (1, 1, 1): the fit's equal-energy white.
    assert np.allclose(report.belcour_barla_sensitivity(0.0), 1.0, atol=2e-3)
    # A thin film in the fit vs exact integration (illuminant E): close, not equal.
    t = np.array([100.0, 200.0, 300.0])
    exact = colorimetry.film_XYZ(t, step=1.0, illuminant="E")
    fit = report.belcour_barla_film_XYZ(t)
    assert np.abs(fit - exact).max() < 0.05
    # Thick films: both tend to half the white.
    assert np.allclose(report.belcour_barla_film_XYZ(1e5), 0.5, atol=1e-3)


def test_oklch_gamut_map_follows_css_color_4():
    import colour

    M = colorimetry.matrix_XYZ_to_RGB("sRGB")
    Minv = np.linalg.inv(M)
    rng = np.random.default_rng(2)
    inside = rng.uniform(0.0, 1.0, (200, 3))
    assert np.array_equal(report.oklch_gamut_map_RGB(inside), inside)  # in gamut: unchanged
    xyz = colorimetry.spectral_locus_XYZ(0.3, np.arange(420.0, 681.0, 10.0))
    rgb = xyz @ M.T
    out = report.oklch_gamut_map_RGB(rgb)
    assert np.all(out >= 0) and np.all(out <= 1)  # the result is clipped into gamut
    lab0 = colour.XYZ_to_Oklab(xyz)
    lab1 = colour.XYZ_to_Oklab(out @ Minv.T)
    # CSS Color 4 returns clip(current) within JND 0.02 of a colour of the same L and h:
    # the lightness moves by at most that JND (plus the search's epsilon).
    # (Origins with L >= 1 -- deep blue at this Y -- become white, per the spec.)
    mid = lab0[:, 0] < 1.0
    assert mid.sum() > 10
    assert np.abs(lab1[mid, 0] - lab0[mid, 0]).max() < 0.02 + 1e-3
    assert np.allclose(out[~mid], 1.0)
    # White and black at the ends of L.
    assert np.allclose(report.oklch_gamut_map_RGB(np.array([3.0, 2.5, 2.8])), 1.0)
    assert np.allclose(report.oklch_gamut_map_RGB(np.array([-0.1, -0.2, -0.1])), 0.0)
    # Compared with a clamp, it keeps more of the lightness on the spectrum.
    lab_c = colour.XYZ_to_Oklab(clip.clamp_RGB(rgb) @ Minv.T)
    assert np.abs(lab1[mid, 0] - lab0[mid, 0]).mean() < np.abs(lab_c[mid, 0] - lab0[mid, 0]).mean()


def test_readme_headline_is_the_committed_reports():
    """The README quotes the headline of reports/report.md verbatim (no number typed
    by hand): the lines between its markers are the report's headline lines."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    report = (root / "reports" / "report.md").read_text()
    headline = report.split("## Headline\n\n", 1)[1].split("\n\n", 1)[0].strip().split("\n")
    readme = (root / "README.md").read_text()
    quoted = (
        readme.split("<!-- report:headline:begin -->\n", 1)[1]
        .split("\n<!-- report:headline:end -->", 1)[0]
        .split("\n")
    )
    assert quoted == [line for line in headline if not line.startswith("- Machine:")]


def test_report_outside_a_checkout_says_in_one_line_what_to_run(tmp_path, monkeypatch, capsys):
    """Installed from a wheel, ``evaluation`` is not importable: the command prints one
    line saying the report runs from a checkout, exit 2 (no ImportError traceback)."""
    import sys

    from ocio_thinfilm.cli import report as report_cli

    # None in sys.modules: ``import evaluation`` fails as where it is not installed
    monkeypatch.setitem(sys.modules, "evaluation", None)
    monkeypatch.setitem(sys.modules, "evaluation.report", None)
    assert main(["report", "--quick", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and report_cli.NEEDS_CHECKOUT in err[0], err
    assert "checkout" in err[0] and ".[report]" in err[0], err
    assert not (tmp_path / "out").exists()
