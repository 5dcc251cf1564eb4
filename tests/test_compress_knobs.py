"""The Constant-Lightness Compress view baked with other knobs (threshold, limit).

``bake`` and ``export view`` take ``--compress-threshold`` / ``--compress-limit`` (the
library ``compress_threshold`` / ``compress_limit``). The baked view, applied by OCIO's
CPU processor, is held against the analytic map with those knobs
(``colour.compress.compress_XYZ(XYZ, display, threshold, limit)``, itself checked
against an independent ray-marching reference in ``tests/test_compress.py``), with the
accuracy targets of the defaults; bad knobs are refused before anything is written.
The figures of docs/compress.md and of the command line's warning are those of
``benchmarks/bench_compress_knobs.py``.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import gamut_map_sets, half_way_colours
from evaluation.views import decode_display
from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.colour import colorimetry, compress
from ocio_thinfilm.lut import compress_lut
from ocio_thinfilm.lut.options import MapOptions

ocio = pytest.importorskip("PyOpenColorIO")

ROOT = Path(__file__).resolve().parents[1]
VIEW = "Constant-Lightness Compress"
#: A pair inside the tested range, far enough from the defaults that a view baked with
#: the defaults misses it by far.
KNOBS = (0.6, 1.5)
KNOB_ARGS = ["--compress-threshold", "0.6", "--compress-limit", "1.5"]


def _apply_file(path, XYZ):
    """A LUT file applied by OCIO's FileTransform (CPU, float32) to CIE XYZ."""
    t = ocio.FileTransform(str(path))
    proc = ocio.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor()
    px = np.ascontiguousarray(np.asarray(XYZ, dtype=np.float32)).copy()
    proc.applyRGB(px)
    return px


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """``ocio-thinfilm export view`` of CIE-XYZ-D65 -> sRGB / Constant-Lightness Compress
    with the knobs :data:`KNOBS`, as ``.ctf`` (the exact chain, LUTs inline): the file,
    the exit code and stderr."""
    import contextlib
    import io

    out = tmp_path_factory.mktemp("view") / "compress.ctf"
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = cli.main(
            ["export", "view", "--from", "CIE-XYZ-D65", "--display", "sRGB", "--view", VIEW]
            + KNOB_ARGS
            + ["--out", str(out)]
        )
    return out, code, err.getvalue()


def test_export_view_takes_the_knobs(exported):
    """The exported view is the analytic map with the knobs, within the defaults'
    targets (dE2000 p99 <= 0.5, max <= 1.5, |dY| <= 1e-3 on the clip's test sets) --
    the tested range's claim for 0.6 / 1.5 on sRGB -- and misses the defaults' map by
    far (it would pass that instead if the knobs were ignored)."""
    path, code, err = exported
    assert code == 0 and err == ""  # inside the tested range: no warning
    text = path.read_text()
    assert "threshold 0.6, limit 1.5" in text and "threshold 0.8" not in text
    M = colorimetry.matrix_XYZ_to_RGB("sRGB")
    to_xyz = np.linalg.inv(M)
    off_defaults = []
    for name, XYZ in gamut_map_sets().items():
        got = decode_display(_apply_file(path, XYZ), "sRGB") @ to_xyz.T
        truth = compress.compress_XYZ(XYZ, "sRGB", *KNOBS)
        de = colorimetry.delta_E2000(truth, got)
        dY = np.abs(got[:, 1] - truth[:, 1]).max()
        print(f"{name}: dE2000 p99 {np.percentile(de, 99):.2f} max {de.max():.2f} |dY| {dY:.1e}")
        assert np.percentile(de, 99) <= 0.5 and de.max() <= 1.5 and dY <= 1e-3, name
        defaults = colorimetry.delta_E2000(compress.compress_XYZ(XYZ, "sRGB"), got)
        off_defaults.append(np.percentile(defaults, 99))
    assert min(off_defaults) > 1.5, off_defaults  # measured 2.1-2.2


def test_export_view_leaves_colours_below_the_threshold_alone(exported):
    """Colours at most 0.375 of the way to the boundary (0.625 of the threshold 0.6, as
    half-way is of 0.8) move by dE2000 <= 0.1 and at most 2.5e-4 (2 % of the distance at
    >= 0.01) beyond the input along the ray, as with the defaults."""
    path, _, _ = exported
    rgb, Y, _ = half_way_colours("sRGB", reach=0.625 * KNOBS[0])
    np.testing.assert_array_equal(compress.compress_RGB(rgb, "sRGB", *KNOBS), rgb)
    XYZ = colorimetry.RGB_to_XYZ(rgb, "sRGB")
    got = decode_display(_apply_file(path, XYZ), "sRGB")
    de = colorimetry.delta_E2000(XYZ, colorimetry.RGB_to_XYZ(got, "sRGB"))
    v = rgb - Y[:, None]
    dist = np.linalg.norm(v, axis=1)
    beyond = ((got - Y[:, None]) * v).sum(axis=1) / dist - dist
    far = dist >= 0.01
    print(f"below the threshold: dE2000 max {de.max():.3f}, beyond {beyond.max():.1e}")
    assert de.max() <= 0.1
    assert beyond.max() <= 2.5e-4 and (beyond[far] / dist[far]).max() <= 0.02


def test_bake_takes_the_knobs(tmp_path, capsys):
    """``bake --compress-threshold 0.6 --compress-limit 1.5``: every display's Compress
    view (SDR and HDR) and named transform, and every compression LUT file, state the
    knobs; the sRGB view read from the written files is the analytic map with them."""
    out = tmp_path / "cfg"
    assert cli.main(["bake", "--out", str(out), "--quiet", *KNOB_ARGS]) == 0
    assert "warning" not in capsys.readouterr().err
    cfg = ocio.Config.CreateFromFile(str(out / "config.ocio"))
    for display in cfg.getDisplays():
        vt = cfg.getViewTransform(cfg.getDisplayViewTransformName(display, VIEW))
        assert "beyond 0.6 of the distance" in vt.getDescription(), display
        assert "so that 1.5 boundary distances" in vt.getDescription(), display
    named = [n for n in cfg.getNamedTransformNames() if n.startswith(VIEW)]
    assert len(named) == len(registry.GAMUT_DISPLAY_LIST)  # one per gamut
    for name in named:
        assert "(threshold 0.6, limit 1.5)" in cfg.getNamedTransform(name).getDescription()
    files = sorted((out / "luts").glob("ConstantLightnessCompress*.clf"))
    assert len(files) == 2 * len(registry.GAMUT_DISPLAY_LIST)
    for path in files:
        assert "(threshold 0.6, limit 1.5)" in path.read_text()
    XYZ = gamut_map_sets()["ap0"]
    proc = cfg.getProcessor("CIE-XYZ-D65", "sRGB", VIEW, ocio.TRANSFORM_DIR_FORWARD)
    px = np.ascontiguousarray(XYZ, dtype=np.float32).copy()
    proc.getDefaultCPUProcessor().applyRGB(px)
    got = colorimetry.RGB_to_XYZ(decode_display(px, "sRGB"), "sRGB")
    de = colorimetry.delta_E2000(compress.compress_XYZ(XYZ, "sRGB", *KNOBS), got)
    assert np.percentile(de, 99) <= 0.5 and de.max() <= 1.5


def test_merge_takes_the_knobs():
    """``bake --into``'s merged config (in memory) states the knobs in its Compress views
    and compression LUTs."""
    from ocio_thinfilm.config import merge

    base = merge.load_base("ocio://studio-config-latest")
    cfg, luts, _ = merge.merge_config(base, options=MapOptions(*KNOBS))
    described = [
        cfg.getViewTransform(n).getDescription()
        for n in cfg.getViewTransformNames()
        if n.startswith(VIEW)
    ]
    assert described and all("beyond 0.6 of the distance" in d for d in described)
    soft = [t for name, t in luts.items() if name.startswith("ConstantLightnessCompress")]
    assert soft and all("(threshold 0.6, limit 1.5)" in str(t.getFormatMetadata()) for t in soft)


def test_the_command_line_hands_the_knobs_to_every_bake(tmp_path, monkeypatch, capsys):
    """Plain bake, ``--into`` and ``.ocioz`` get the knobs (the library is stubbed: what
    each path writes is tested above and in tests/test_export.py)."""
    from ocio_thinfilm.export import bake as bake_module
    from ocio_thinfilm.export import merged

    calls = []

    def stub(name):
        def record(*args, **kwargs):
            calls.append((name, *kwargs["options"].knobs()))
            return Path(tmp_path / "x")

        return record

    monkeypatch.setattr(bake_module, "bake", stub("bake"))
    monkeypatch.setattr(merged, "bake_into", stub("into"))
    monkeypatch.setattr(merged, "bake_archive", stub("ocioz"))
    monkeypatch.setattr(merged.merge, "profile_readers", lambda cfg: "")
    monkeypatch.setattr(ocio.Config, "CreateFromFile", lambda path: None)
    for extra in (
        [],
        ["--into", "ocio://studio-config-latest", "--out", str(tmp_path / "m")],
        ["--out", str(tmp_path / "t.ocioz")],
    ):
        assert cli.main(["bake", *extra, *KNOB_ARGS, "--quiet"]) == 0
    assert calls == [("bake", 0.6, 1.5), ("into", 0.6, 1.5), ("ocioz", 0.6, 1.5)]


def test_warning_outside_the_tested_range(tmp_path, monkeypatch, capsys):
    """Knobs outside the tested range: one warning line on stderr with the figures
    measured there, and the command goes on; inside it, none."""
    from ocio_thinfilm.export import view as view_module

    monkeypatch.setattr(view_module, "export_view", lambda *a, **k: [tmp_path / "x.cube"])
    argv = ["export", "view", "--from", "ACEScct", "--display", "sRGB", "--view", VIEW]
    assert cli.main(argv + ["--compress-threshold", "0.95", "--compress-limit", "1.05"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith("ocio-thinfilm export view: warning: threshold 0.95 / limit 1.05")
    p99, worst = compress_lut.MEASURED_KNOBS[0.95, 1.05][:2]
    assert f"measured there, 0.95 / 1.05: p99 {p99:.2f} / max {worst:.2f}" in err[0]
    assert cli.main(argv + KNOB_ARGS) == 0
    assert capsys.readouterr().err == ""


BAD = [
    (["--compress-threshold", "0"], "--compress-threshold"),
    (["--compress-threshold", "-0.2"], "--compress-threshold"),
    (["--compress-threshold", "1"], "--compress-threshold"),
    (["--compress-threshold", "1.2", "--compress-limit", "1.1"], "--compress-threshold"),
    (["--compress-threshold", "nan"], "--compress-threshold"),
    (["--compress-threshold", "inf"], "--compress-threshold"),
    (["--compress-threshold", "abc"], "--compress-threshold"),
    (["--compress-limit", "1"], "--compress-limit"),
    (["--compress-limit", "0.9"], "--compress-limit"),
    (["--compress-limit", "nan"], "--compress-limit"),
    (["--compress-limit", "inf"], "--compress-limit"),
]


@pytest.mark.parametrize("command", ["bake", "view", "ocioz"])
@pytest.mark.parametrize("knobs, option", BAD, ids=[" ".join(k) for k, _ in BAD])
def test_bad_knobs_one_line_exit_2_nothing_written(
    command, knobs, option, tmp_path, capsys, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    argv = {
        "bake": ["bake", "--out", str(tmp_path / "out" / "cfg"), "--quiet"],
        "ocioz": ["bake", "--out", str(tmp_path / "out" / "t.ocioz"), "--quiet"],
        "view": ["export", "view", "--from", "ACEScct", "--display", "sRGB", "--view", VIEW]
        + ["--out", str(tmp_path / "out" / "x.cube")],
    }[command]
    assert cli.main(argv + knobs) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and ": error: " + option in err, err
    assert list(tmp_path.rglob("*")) == []


@pytest.mark.parametrize(
    "argv, needle",
    [
        (
            ["export", "film", "--compress-threshold", "0.6"],
            "export film: error: unrecognized arguments: --compress-threshold 0.6",
        ),
        (
            ["export", "view", "--from", "ACEScct", "--display", "sRGB"]
            + ["--view", "Constant-Lightness Clip", "--compress-limit", "1.5"],
            "--compress-limit applies to 'export view|shader --view",
        ),
        (
            ["export", "shader", "--lang", "glsl", "--display", "sRGB"]
            + ["--view", "Constant-Lightness Clip", "--compress-threshold", "0.6"],
            "--compress-threshold applies to 'export view|shader --view",
        ),
    ],
)
def test_knobs_refused_where_there_is_no_compression(argv, needle, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert cli.main(argv + ["--out", str(tmp_path / "x.cube")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err, err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(compress_threshold=0.0), "compress_threshold"),
        (dict(compress_threshold=1.0), "compress_threshold"),
        (dict(compress_threshold=float("nan")), "compress_threshold"),
        (dict(compress_limit=1.0), "compress_limit"),
        (dict(compress_limit=float("inf")), "compress_limit"),
        (dict(compress_threshold=0.99, compress_limit=0.99), "compress_limit"),
    ],
)
def test_library_refuses_bad_knobs_naming_the_parameter(kwargs, parameter, tmp_path):
    """The knobs are checked once, where the options object is made (before any bake,
    merge, export or config is begun); every function after the ``lut`` stage takes that
    object, keyword-only, and no other spelling of the knobs."""
    import inspect

    from ocio_thinfilm import config
    from ocio_thinfilm.export import bake as bake_module
    from ocio_thinfilm.export import merged
    from ocio_thinfilm.export.view import export_view, view_config

    with pytest.raises(ParameterError) as raised:
        MapOptions(**kwargs)
    assert str(raised.value).startswith(parameter + " must be"), raised.value
    assert raised.value.parameter == parameter
    with pytest.raises(TypeError, match="^compress_limit must be a number"):
        MapOptions(compress_limit="1.5")  # type: ignore[arg-type]
    functions = [
        bake_module.bake,
        merged.bake_archive,
        merged.bake_into,
        export_view,
        view_config,
        config.config_data,
        config.compress_luts,
    ]
    for function in functions:
        parameters = inspect.signature(function).parameters
        assert parameters["options"].kind is inspect.Parameter.KEYWORD_ONLY, function
        assert not set(parameters) & {"compress_threshold", "compress_limit"}, function
    with pytest.raises(TypeError, match="^options must be a MapOptions"):
        config.compress_luts(options=(0.6, 1.5))  # type: ignore[arg-type]
    assert list(tmp_path.iterdir()) == []


def test_documented_knob_figures_come_from_the_benchmark(load_benchmark, marked):
    """docs/compress.md's knob tables and the warning's figures
    (``compress_lut.MEASURED_KNOBS``) are what benchmarks/bench_compress_knobs.py made
    (reports/bench_compress_knobs.json), and every measured pair inside the tested range
    meets every target."""
    bench = load_benchmark("bench_compress_knobs")
    result = json.loads((ROOT / "reports" / "bench_compress_knobs.json").read_text())
    doc = (ROOT / "docs" / "compress.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.knobs_markdown(result)
    assert bench.measured_knobs(result) == {
        k: tuple(v) for k, v in compress_lut.MEASURED_KNOBS.items()
    }
    assert tuple(result["tested_threshold"]) == compress_lut.TESTED_THRESHOLD
    assert tuple(result["tested_limit"]) == compress_lut.TESTED_LIMIT
    inside = [r for r in result["rows"] if compress_lut.knobs_tested(r["threshold"], r["limit"])]
    assert len(inside) >= 20
    assert [(r["threshold"], r["limit"], r["fails"]) for r in inside if r["fails"]] == []
    (t_lo, t_hi), (l_lo, l_hi) = compress_lut.TESTED_THRESHOLD, compress_lut.TESTED_LIMIT
    corners = {(r["threshold"], r["limit"]) for r in inside}
    assert {(t_lo, l_lo), (t_lo, l_hi), (t_hi, l_lo), (t_hi, l_hi)} <= corners
