"""The ``render`` command and the paper's scenes (ocio_thinfilm.render.frames / .scenes).

Reference images: ``tests/reference/<scene>.png`` are 64x64 renders (seed 0, sRGB,
Constant-Lightness Clip) compared with OpenImageIO's ``idiff``:

    idiff -warn 0.004 -fail 0.02 -failpercent 1 -hardfail 0.25 reference new

i.e. a pixel differing by more than 0.02 (5 of 255 code values) in any channel
counts as failing; the test fails if more than 1 % of the pixels fail or any pixel
differs by more than 0.25. Differences up to one code value (0.004) are only a
warning. That tolerates last-bit differences of float32 maths between CPUs around
the 8-bit rounding, but catches any real change of the scenes, the tables or the
views. Regenerate after an intended change with ``python tests/test_render.py``.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from evaluation.truth import HDR_CICP
from ocio_thinfilm import cache, registry
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.io import read_image
from ocio_thinfilm.lut import ocio_ops, view_transforms
from ocio_thinfilm.lut.options import MapOptions
from ocio_thinfilm.render import frames as render
from ocio_thinfilm.render import processors, scenes

REFERENCE = Path(__file__).parent / "reference"
REF_SIZE = "64"
IDIFF_THRESHOLDS = ["-warn", "0.004", "-fail", "0.02", "-failpercent", "1", "-hardfail", "0.25"]
ROOT = Path(__file__).resolve().parent.parent


def _env():
    env = dict(os.environ)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    return env


def _channels(path) -> dict:
    """EXR channels by name (OpenEXR stores the channels sorted by name)."""
    import OpenImageIO as oiio

    names = oiio.ImageInput.open(str(path)).spec().channelnames
    pixels = read_image(path)
    return {n: pixels[..., i] for i, n in enumerate(names)}


def _cli(capsys, *argv):
    code = cli.main(["render", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.fixture(scope="module")
def stills(tmp_path_factory):
    """All four scenes at 48x40, rendered once for the module."""
    out = tmp_path_factory.mktemp("stills")
    assert cli.main(["render", "all", "--size", "48x40", "--out", str(out), "--quiet"]) == 0
    return out


# --------------------------------------------------------------------------- #
# Command line
# --------------------------------------------------------------------------- #
def test_writes_an_exr_and_a_png_per_scene(stills):
    names = sorted(p.name for p in stills.iterdir())
    assert names == sorted(f"{s}.{ext}" for s in scenes.SCENES for ext in ("exr", "png"))
    for s in scenes.SCENES:
        png = read_image(stills / f"{s}.png")
        assert png.shape == (40, 48, 3)
        assert png.max() > 0.2  # not a black frame


def test_output_is_byte_identical_for_the_same_command(stills, tmp_path):
    assert cli.main(["render", "all", "--size", "48x40", "--out", str(tmp_path), "--quiet"]) == 0
    for p in stills.iterdir():
        assert (tmp_path / p.name).read_bytes() == p.read_bytes(), p.name


def test_seed_changes_the_noise_but_not_the_spectrum(stills, tmp_path):
    assert (
        cli.main(
            ["render", "all", "--size", "48x40", "--out", str(tmp_path), "--seed", "5", "--quiet"]
        )
        == 0
    )
    assert (tmp_path / "spectrum.png").read_bytes() == (stills / "spectrum.png").read_bytes()
    for s in ("oil", "soap", "morpho"):
        assert not np.array_equal(
            read_image(tmp_path / f"{s}.exr"), read_image(stills / f"{s}.exr")
        ), s


@pytest.mark.parametrize(
    "argv, message",
    [
        (["nosuch"], "invalid choice"),
        (["oil", "--size", "0"], "--size"),
        (["oil", "--size", "-5"], "--size"),
        (["oil", "--size", "64x0"], "--size"),
        (["oil", "--size", "100000"], "--size"),
        (["oil", "--size", "5000x5000"], "--size"),
        (["oil", "--size", "big"], "--size"),
        (["oil", "--frames", "3-1"], "--frames"),
        (["oil", "--frames", "0-2"], "--frames"),
        (["oil", "--frames", "1-x"], "--frames"),
        (["oil", "--seed", "-1"], "--seed"),
        (["oil", "--display", "CRT"], "--display"),
        (["oil", "--view", "Filmic"], "--view"),
    ],
)
def test_bad_input_is_one_line_exit_2_and_writes_nothing(capsys, tmp_path, argv, message):
    out = tmp_path / "out"
    code, stdout, stderr = _cli(capsys, *argv, "--out", str(out))
    assert code == 2
    assert stderr.count("\n") == 1 and stderr.startswith("ocio-thinfilm render: error:")
    assert message in stderr
    assert not out.exists()


def test_unwritable_output_is_one_line_exit_2(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    code, _, stderr = _cli(capsys, "oil", "--size", "16", "--out", str(blocker / "sub"))
    assert code == 2 and stderr.count("\n") == 1 and "not writable" in stderr
    assert blocker.read_text() == "not a directory"


def test_failed_write_leaves_no_partial_files(capsys, tmp_path, monkeypatch):
    from ocio_thinfilm import io

    real = io.write_image

    def failing(path, *args, **kwargs):
        if str(path).endswith(".png"):
            raise OSError("disk full (simulated)")
        return real(path, *args, **kwargs)

    monkeypatch.setattr(render, "write_image", failing)
    code, _, stderr = _cli(capsys, "soap", "--size", "16", "--out", str(tmp_path))
    assert code == 2 and "disk full" in stderr
    # The EXR is complete or absent; no temporary files are left behind.
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]
    for p in tmp_path.glob("*.exr"):
        assert read_image(p).shape == (16, 16, 5)


# --------------------------------------------------------------------------- #
# Pictures: through the tables and the views
# --------------------------------------------------------------------------- #
def test_exr_is_scene_linear_xyz_with_aovs_and_documented(stills):
    import OpenImageIO as oiio

    for name, aovs in (
        ("spectrum", ["angle", "thickness", "wavelength"]),
        ("oil", ["angle", "thickness"]),
        ("soap", ["angle", "thickness"]),
        ("morpho", ["angle", "cos_theta"]),
    ):
        spec = oiio.ImageInput.open(str(stills / f"{name}.exr")).spec()
        assert list(spec.channelnames[:3]) == ["R", "G", "B"]
        assert sorted(spec.channelnames[3:]) == sorted(aovs)
        assert "CIE XYZ" in spec.getattribute("ocio_thinfilm:colorspace")
        for aov in aovs:
            assert spec.getattribute(f"ocio_thinfilm:aov:{aov}")
    morpho = oiio.ImageInput.open(str(stills / "morpho.exr")).spec()
    assert morpho.getattribute("ocio_thinfilm:exposure") == scenes.MorphoScene.EXPOSURE


def test_png_is_the_exr_through_the_chosen_view(stills):
    exr = read_image(stills / "oil.exr")
    png = read_image(stills / "oil.png")
    view = view_transforms.view_transform("sRGB", render.DEFAULT_VIEW)
    expected = np.clip(ocio_ops.apply(view, exr[..., :3]), 0, 1)
    # Half-float EXR and 8-bit PNG: within a couple of code values.
    assert np.abs(expected - png).max() < 3 / 255


@pytest.mark.parametrize("display", registry.DISPLAYS)
def test_png_is_tagged_with_its_display(tmp_path, display):
    """Every SDR display: a display with cICP code points of its own (``png_cicp``,
    where OpenImageIO has no interop ID) gets that chunk; any other reads back, by
    OpenImageIO, as its interop ID's encoding and primaries (``srgb_p3d65`` for
    ``srgb_p3d65_display``)."""
    import OpenImageIO as oiio

    from evaluation.views import COMMITTED_CONFIG

    argv = ["render", "morpho", "--size", "16", "--display", display, "--out", str(tmp_path)]
    assert cli.main([*argv, "--config", str(COMMITTED_CONFIG), "--quiet"]) == 0
    entry = registry.as_display(display)
    if entry.png_cicp is not None:
        chunks = _png_chunks(tmp_path / "morpho.png")
        assert [tuple(d) for k, d in chunks if k == "cICP"] == [entry.png_cicp]
        return
    spec = oiio.ImageInput.open(str(tmp_path / "morpho.png")).spec()
    tag = entry.png_colorspace.removesuffix("_display")
    assert spec.getattribute("oiio:ColorSpace").startswith(tag)


def test_spectrum_film_strip_is_the_exact_film_colour(stills):
    """The film strips come through the film table's OCIO transform: compare the EXR
    with direct spectral integration at the thickness AOV."""
    ch = _channels(stills / "spectrum.exr")
    t = ch["thickness"]
    strip = t > 0.05
    exact = colorimetry.film_XYZ(t[strip].astype(np.float64) * 1000.0, "phase-change")
    got = np.stack([ch["R"], ch["G"], ch["B"]], axis=-1)[strip]
    assert np.abs(got - exact).max() < 0.01  # half-float EXR, LUT interpolation
    wl = ch["wavelength"]
    assert 379 < wl[wl > 0].min() < 390 and 690 < wl.max() < 701


def test_spectrum_shows_four_views_side_by_side(tmp_path):
    picture, rgb = render.render_scene("spectrum", (480, 320))
    assert [r[2] for r in picture.regions] == list(scenes.SpectrumScene.VIEWS)
    captions = [label[2] for label in picture.labels]
    assert [c for c in captions if c in scenes.SpectrumScene.VIEWS] == list(
        scenes.SpectrumScene.VIEWS
    )
    assert captions.count("spectrum") == captions.count("film") == captions.count("morpho") == 4
    # The same XYZ in each panel, different display colours: the views differ.
    panels = [rgb[60:300, x0:x1] for x0, x1, _ in picture.regions]
    w = min(t.shape[1] for t in panels)
    for a, b in zip(panels[:-1], panels[1:], strict=True):
        assert not np.allclose(a[:, :w], b[:, :w], atol=0.02)


@pytest.mark.parametrize("panel", [0, 1])
def test_constant_lightness_views_keep_the_luminance_of_the_spectrum(panel):
    picture, rgb = render.render_scene("spectrum", (240, 160), view="Channel Clamp")
    import colour

    x0, x1, view = picture.regions[panel]
    assert view == ("Constant-Lightness Clip", "Constant-Lightness Compress")[panel]
    wl = picture.aovs["wavelength"][:, x0:x1]
    mask = wl > 0
    Y_scene = picture.xyz[..., 1][:, x0:x1][mask]
    lin = colour.cctf_decoding(rgb[:, x0:x1][mask].astype(np.float64), function="sRGB")
    Y_shown = colorimetry.RGB_to_XYZ(lin, "sRGB")[:, 1]
    assert np.abs(Y_shown - Y_scene).max() < 0.02


def test_soap_is_black_at_the_top_and_coloured_below():
    picture, rgb = render.render_scene("soap", (128, 128))
    t = picture.aovs["thickness"]
    inside = t > 0
    rows = np.nonzero(inside.any(axis=1))[0]
    top = picture.aovs["thickness"][rows[0] : rows[0] + 6]
    assert np.median(top) < 0.03  # the black film: t' under ~30 nm
    band = t[90:110][inside[90:110]]
    assert band.mean() > 0.5
    assert picture.aovs["angle"].max() > 70  # grazing at the silhouette


def test_oil_view_angle_and_thickness():
    picture, _ = render.render_scene("oil", (96, 96))
    angle, t = picture.aovs["angle"], picture.aovs["thickness"]
    # Camera looking down at the road at an angle: steeper towards the bottom.
    assert angle[0].mean() > angle[-1].mean() + 10
    assert 0 < angle.min() and angle.max() < 90
    # Eq. 13: thickest in the middle, negligible at the borders.
    assert t[40:56, 40:56].mean() > 0.4 and t[:4].max() < 0.05


def test_morpho_is_blue_and_darkens_with_angle():
    picture, _ = render.render_scene("morpho", (128, 128))
    xyz, angle = picture.xyz, picture.aovs["angle"]
    facing, oblique = angle < 10, (angle > 30) & (angle < 45)
    assert facing.any() and oblique.any()
    x = xyz[..., 0] / xyz.sum(axis=-1)
    assert x[facing].mean() < 0.2  # blue-violet chromaticity
    assert xyz[..., 1][facing].mean() > 3 * xyz[..., 1][oblique].mean()


# --------------------------------------------------------------------------- #
# Only the declared tables and views become processors; the config is the source
# --------------------------------------------------------------------------- #
def _built(scene, *, display="sRGB", view="Constant-Lightness Clip"):
    """(tables and clip LUTs computed, processors created from the config) by one render
    of ``scene`` in a process whose caches are emptied first."""
    cache.clear()
    procs = processors.ConfigProcessors()
    render.render_scene(scene, (16, 16), display=display, view=view, config=procs)
    return cache.entries("ocio_thinfilm.lut."), procs.created


def test_morpho_uses_only_its_table_and_the_displays_view():
    # The tables and the clip come from the baked config's files: nothing is computed.
    built, created = _built("morpho", display="Display P3")
    assert built == {}
    assert sorted(created) == sorted(
        ["colorspace:Thin Film Morpho Iridescence", "view:Display P3/Constant-Lightness Clip"]
    )


def test_a_scene_uses_only_the_view_it_shows():
    assert _built("oil", view="Channel Clamp") == (
        {},
        ["colorspace:Thin Film Phase-Change Thickness", "view:sRGB/Channel Clamp"],
    )


def test_spectrum_uses_both_tables_and_its_four_views():
    built, created = _built("spectrum", display="Rec.2020")
    assert built == {}
    assert sorted(created) == sorted(
        ["colorspace:Thin Film Phase-Change Thickness", "colorspace:Thin Film Morpho Iridescence"]
        + [
            f"view:Rec.2020/{v}"
            for v in (
                "Constant-Lightness Clip",
                "Constant-Lightness Compress",
                "Channel Clamp",
                "ACES Gamut Compression",
            )
        ]
    )


def _modified_config(tmp_path, *, film=None, view=None):
    """The baked config copied to ``tmp_path`` with the phase-change film space's
    transform and/or the sRGB Channel Clamp view transform replaced."""
    import PyOpenColorIO as ocio

    src = ROOT / "configs" / "thinfilm"
    shutil.copytree(src / "luts", tmp_path / "luts")
    cfg = ocio.Config.CreateFromFile(str(src / "config.ocio"))
    if film is not None:
        cs = cfg.getColorSpace("Thin Film Phase-Change Thickness")
        cs.setTransform(film, ocio.COLORSPACE_DIR_TO_REFERENCE)
        cfg.addColorSpace(cs)
    if view is not None:
        vt = cfg.getViewTransform("Channel Clamp - sRGB")
        vt.setTransform(view, ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
        cfg.addViewTransform(vt)
    path = tmp_path / "config.ocio"
    path.write_text(cfg.serialize())
    return path


def test_render_goes_through_the_configs_thin_film_space(tmp_path):
    import PyOpenColorIO as ocio

    scale = (0.2, 0.3, 0.4)
    m = [0.0] * 16
    m[0], m[5], m[10], m[15] = *scale, 1.0
    config = _modified_config(tmp_path / "cfg", film=ocio.MatrixTransform(m))
    out = tmp_path / "out"
    assert (
        cli.main(
            [
                "render",
                "spectrum",
                "--size",
                "96x64",
                "--config",
                str(config),
                "--out",
                str(out),
                "--quiet",
            ]
        )
        == 0
    )
    ch = _channels(out / "spectrum.exr")
    strip = ch["thickness"] > 0.05
    got = np.stack([ch["R"], ch["G"], ch["B"]], axis=-1)[strip]
    expected = ch["thickness"][strip][:, None] * np.array(scale)
    assert np.abs(got - expected).max() < 2e-3  # half floats
    # the Morpho strips still hold the (unchanged) Morpho table's colours
    morpho = ch["angle"] > 1.0
    assert np.stack([ch["R"], ch["G"], ch["B"]], axis=-1)[morpho][:, 2].max() > 0.1


def test_render_goes_through_the_configs_view(tmp_path, colour):
    import PyOpenColorIO as ocio

    half = ocio.MatrixTransform([0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1])
    config = _modified_config(tmp_path / "cfg", view=half)
    out, plain = tmp_path / "out", tmp_path / "plain"
    for directory, extra in ((out, ["--config", str(config)]), (plain, [])):
        assert (
            cli.main(
                [
                    "render",
                    "oil",
                    "--size",
                    "48",
                    "--view",
                    "Channel Clamp",
                    "--out",
                    str(directory),
                    "--quiet",
                    *extra,
                ]
            )
            == 0
        )
    xyz = read_image(out / "oil.exr")[..., :3].astype(np.float64)
    srgb = colour.RGB_COLOURSPACES["sRGB"]
    linear = np.clip(colour.XYZ_to_RGB(0.5 * xyz, srgb, apply_cctf_encoding=False), 0, 1)
    expected = colour.cctf_encoding(linear, function="sRGB")
    png, before = read_image(out / "oil.png"), read_image(plain / "oil.png")
    assert np.abs(png - expected).max() < 2.5 / 255
    assert np.abs(before - expected).max() > 10 / 255  # the change shows


def test_config_option_reaches_frame_children(tmp_path):
    import PyOpenColorIO as ocio

    zero = ocio.MatrixTransform([0.0] * 15 + [1.0])
    config = _modified_config(tmp_path / "cfg", view=zero)
    out = tmp_path / "out"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "ocio_thinfilm",
            "render",
            "oil",
            "--frames",
            "1-2",
            "--size",
            "16",
            "--view",
            "Channel Clamp",
            "--config",
            str(config),
            "--out",
            str(out),
            "--quiet",
            "--jobs",
            "2",
        ],
        check=True,
        env=_env(),
    )
    for frame in (1, 2):
        assert read_image(out / f"oil.{frame:04d}.png").max() == 0.0


def test_missing_default_config_is_baked_first(tmp_path, monkeypatch):
    from ocio_thinfilm.export import bake as bake_module

    baked = []
    real_bake = bake_module.bake

    def small_bake(out, **kwargs):
        baked.append(Path(out))
        return real_bake(out, options=MapOptions(clip_size=9))

    monkeypatch.setattr(processors, "DEFAULT_CONFIG", tmp_path / "thinfilm" / "config.ocio")
    monkeypatch.setattr(bake_module, "bake", small_bake)
    assert (
        cli.main(["render", "morpho", "--size", "16", "--out", str(tmp_path / "out"), "--quiet"])
        == 0
    )
    assert baked == [tmp_path / "thinfilm"]
    assert (tmp_path / "thinfilm" / "config.ocio").is_file()
    assert (tmp_path / "out" / "morpho.png").is_file()


@pytest.mark.parametrize(
    "argv, message",
    [
        (["--config", "no/such/config.ocio"], "--config no/such/config.ocio: no such config file"),
        (
            ["--view", "Channel Clamp", "--config", "{removed}"],
            "--view 'Channel Clamp': the config's display sRGB has Raw",
        ),
        (["--display", "CRT", "--config", "{removed}"], "--display 'CRT': the config has sRGB"),
    ],
)
def test_config_errors_are_one_line_exit_2(capsys, tmp_path, argv, message):
    import PyOpenColorIO as ocio

    config = _modified_config(tmp_path / "cfg")
    cfg = ocio.Config.CreateFromFile(str(config))
    cfg.clearDisplays()
    cfg.addDisplayView("sRGB", "Raw", "Raw", "")
    cfg.setActiveViews("")
    config.write_text(cfg.serialize())
    argv = [a.replace("{removed}", str(config)) for a in argv]
    code, _, err = _cli(capsys, "oil", "--size", "16", "--out", str(tmp_path / "out"), *argv)
    assert code == 2 and message in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out" / "oil.png").exists()


def test_the_library_names_config_display_and_view(tmp_path):
    """The same mistakes through the library name its parameters, not the options."""
    with pytest.raises(ValueError, match=r"^config no/such\.ocio: no such config file$"):
        processors.ConfigProcessors("no/such.ocio")
    config = _modified_config(tmp_path / "cfg")
    procs = processors.ConfigProcessors(config)
    with pytest.raises(ValueError, match=r"^display 'CRT': the config has "):
        procs.check_display_view("CRT", "Raw")
    with pytest.raises(ValueError, match=r"^view 'Nope': the config's display sRGB has "):
        procs.check_display_view("sRGB", "Nope")


# --------------------------------------------------------------------------- #
# Frames
# --------------------------------------------------------------------------- #
def test_frame_range_one_process_per_frame(tmp_path):
    subprocess.run(
        [
            sys.executable,
            "-m",
            "ocio_thinfilm",
            "render",
            "morpho",
            "--frames",
            "2-3",
            "--size",
            "24",
            "--out",
            str(tmp_path),
            "--quiet",
            "--jobs",
            "2",
        ],
        check=True,
        env=_env(),
    )
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["morpho.0002.exr", "morpho.0002.png", "morpho.0003.exr", "morpho.0003.png"]
    # Frames are independent: frame 3 alone (in this process) gives the same bytes.
    alone = tmp_path / "alone"
    assert (
        cli.main(
            ["render", "morpho", "--frames", "3-3", "--size", "24", "--out", str(alone), "--quiet"]
        )
        == 0
    )
    assert (alone / "morpho.0003.png").read_bytes() == (tmp_path / "morpho.0003.png").read_bytes()
    assert (alone / "morpho.0003.exr").read_bytes() == (tmp_path / "morpho.0003.exr").read_bytes()


@pytest.mark.parametrize(
    "name, aov", [("oil", "thickness"), ("soap", "thickness"), ("morpho", "angle")]
)
def test_animated_parameters_change_with_the_frame(name, aov):
    a, _ = render.render_scene(name, (48, 48), frame=1)
    b, _ = render.render_scene(name, (48, 48), frame=12)
    assert not np.allclose(a.aovs[aov], b.aovs[aov])
    if name == "oil":  # the slick spreads: thinner in the middle
        assert b.aovs[aov][20:28, 20:28].mean() < a.aovs[aov][20:28, 20:28].mean()
    if name == "soap":  # the film drains: more black film
        assert (b.aovs[aov] < 0.03).sum() > (a.aovs[aov] < 0.03).sum()


def test_spectrum_ignores_the_frame():
    a, _ = render.render_scene("spectrum", (48, 48), frame=1)
    b, _ = render.render_scene("spectrum", (48, 48), frame=7)
    assert np.array_equal(a.xyz, b.xyz)


# --------------------------------------------------------------------------- #
# Reference images
# --------------------------------------------------------------------------- #
@pytest.fixture(scope="module")
def reference_renders(tmp_path_factory):
    out = tmp_path_factory.mktemp("reference")
    assert cli.main(["render", "all", "--size", REF_SIZE, "--out", str(out), "--quiet"]) == 0
    return out


@pytest.mark.skipif(shutil.which("idiff") is None, reason="OpenImageIO's idiff not on PATH")
@pytest.mark.parametrize("name", list(scenes.SCENES))
def test_matches_the_reference_image(reference_renders, name):
    ref = REFERENCE / f"{name}.png"
    new = reference_renders / f"{name}.png"
    result = subprocess.run(
        ["idiff", *IDIFF_THRESHOLDS, str(ref), str(new)], capture_output=True, text=True
    )
    assert result.returncode in (0, 1), result.stdout + result.stderr  # 0 pass, 1 warn


def _regenerate() -> None:
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        assert cli.main(["render", "all", "--size", REF_SIZE, "--out", tmp, "--quiet"]) == 0
        REFERENCE.mkdir(exist_ok=True)
        for name in scenes.SCENES:
            shutil.copyfile(Path(tmp) / f"{name}.png", REFERENCE / f"{name}.png")
            print(f"wrote {REFERENCE / f'{name}.png'}")


if __name__ == "__main__":
    _regenerate()


def test_documented_render_timings_come_from_the_benchmark(load_benchmark, marked):
    """docs/render.md's timing table is what benchmarks/bench_render.py renders from
    reports/bench_render.json (no figure typed by hand), and that run created only the
    processors each scene shows and computed no table."""
    bench = load_benchmark("bench_render")
    result = json.loads((ROOT / "reports" / "bench_render.json").read_text())
    doc = (ROOT / "docs" / "render.md").read_text()
    table = marked(doc, bench.BEGIN, bench.END)
    assert table == bench.timings_markdown(result)
    assert [r["scene"] for r in result["scenes"]] == list(scenes.SCENES)
    for r in result["scenes"]:
        assert r["computed"] == []
        spaces = {
            f"colorspace:{processors.table_colorspace(t)}"
            for t in scenes.get_scene(r["scene"]).tables
        }
        assert spaces <= set(r["processors"])
        assert "view:sRGB/Constant-Lightness Clip" in r["processors"]


@pytest.mark.parametrize(
    "base",
    ["ocio://studio-config-v1.0.0_aces-v1.3_ocio-v2.1", "ocio://studio-config-latest"],
    ids=["aces1.3", "latest"],
)
def test_render_through_a_merged_aces_config(tmp_path, capsys, base):
    """``--config`` takes a studio's ACES config merged with ``bake --into``: it has no
    CIE-XYZ-D65 colour space, so the render reaches XYZ through its
    cie_xyz_d65_interchange role. The EXR equals the package config's render, the PNG
    through the merged sRGB display's clip view is within one code value of it (and
    untagged: that display is not the registry's), and a view the merged display lacks
    is one line naming it."""
    from ocio_thinfilm.export import merged

    config = merged.bake_into(base, tmp_path / "studio")
    ours, theirs = tmp_path / "ours", tmp_path / "theirs"
    assert cli.main(["render", "oil", "--size", "64", "--out", str(ours), "--quiet"]) == 0
    assert (
        cli.main(
            [
                "render",
                "oil",
                "--size",
                "64",
                "--config",
                str(config),
                "--display",
                "sRGB - Display",
                "--out",
                str(theirs),
                "--quiet",
            ]
        )
        == 0
    )
    a, b = _channels(ours / "oil.exr"), _channels(theirs / "oil.exr")
    for c in "RGB":
        np.testing.assert_allclose(b[c], a[c], rtol=2e-3, atol=1e-5)
    png_a, png_b = read_image(ours / "oil.png"), read_image(theirs / "oil.png")
    assert np.abs(png_a - png_b).max() <= 1.0 / 255 + 1e-6
    head_a, head_b = ((d / "oil.png").read_bytes()[:256] for d in (ours, theirs))
    assert b"sRGB" in head_a and b"sRGB" not in head_b  # PNG's sRGB chunk
    capsys.readouterr()
    code, _, err = _cli(
        capsys,
        "spectrum",
        "--size",
        "32",
        "--config",
        str(config),
        "--display",
        "sRGB - Display",
        "--out",
        str(theirs),
    )
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Channel Clamp" in err


def _png_chunks(path):
    """(type, data) of every chunk of a PNG file, read with the PNG layout (length,
    type, data, CRC), not with OpenImageIO."""
    import struct

    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    out, i = [], 8
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i : i + 8])
        out.append((kind.decode("ascii"), data[i + 8 : i + 8 + n]))
        i += 12 + n
    return out


@pytest.mark.parametrize("display, cicp", sorted(HDR_CICP.items()))
def test_hdr_png_is_16_bit_with_its_cicp_chunk(tmp_path, display, cicp):
    """render --display on an HDR display: a 16-bit PNG whose cICP chunk holds the
    ITU-T H.273 code points (BT.2020 = 9 / P3-D65 = 12 primaries, PQ = 16 / HLG = 18,
    RGB matrix 0, full range 1), no sRGB/gAMA chunk claiming otherwise; its pixels
    are the EXR through the view (to 16-bit rounding and the half-float EXR); the EXR
    is as for SDR displays."""
    assert (
        cli.main(
            [
                "render",
                "oil",
                "--size",
                "24x16",
                "--display",
                display,
                "--out",
                str(tmp_path),
                "--quiet",
            ]
        )
        == 0
    )
    chunks = _png_chunks(tmp_path / "oil.png")
    kinds = [k for k, _ in chunks]
    assert tuple(chunks[0][1][8:9]) == (16,)  # IHDR bit depth
    assert [tuple(d) for k, d in chunks if k == "cICP"] == [cicp]
    assert kinds.index("cICP") < kinds.index("IDAT")
    assert not {"sRGB", "gAMA", "iCCP"} & set(kinds)
    exr = read_image(tmp_path / "oil.exr")
    png = read_image(tmp_path / "oil.png")
    expected = np.clip(
        ocio_ops.apply(view_transforms.view_transform(display, render.DEFAULT_VIEW), exr[..., :3]),
        0,
        1,
    )
    assert np.abs(expected - png).max() < 2 / 1023


def _has_x265():
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        return False
    out = subprocess.run([ffmpeg, "-hide_banner", "-encoders"], capture_output=True, text=True)
    return "libx265" in out.stdout


@pytest.mark.skipif(not _has_x265(), reason="ffmpeg with libx265 not installed")
def test_hdr_png_encodes_to_hdr10_with_ffmpeg(tmp_path):
    """docs/hdr.md's ffmpeg command: the PQ PNGs of render become a BT.2020 / ST 2084
    stream whose decoded codes are the PNG's (to 10-bit 4:2:0 coding), tagged as such."""
    # morpho: saturated blues, where a wrong (BT.601) matrix shifts the mean by 0.04
    assert (
        cli.main(
            [
                "render",
                "morpho",
                "--size",
                "64x48",
                "--display",
                "Rec.2100-PQ",
                "--out",
                str(tmp_path),
                "--quiet",
            ]
        )
        == 0
    )
    ffmpeg, mp4 = shutil.which("ffmpeg"), tmp_path / "out.mp4"
    subprocess.run(
        [
            ffmpeg,
            "-v",
            "error",
            "-i",
            str(tmp_path / "morpho.png"),
            "-vf",
            "scale=out_color_matrix=bt2020:out_range=tv",
            "-pix_fmt",
            "yuv420p10le",
            "-c:v",
            "libx265",
            "-x265-params",
            "hdr10=1:max-cll=1000,400:crf=4:log-level=error",
            "-color_primaries",
            "bt2020",
            "-color_trc",
            "smpte2084",
            "-colorspace",
            "bt2020nc",
            "-color_range",
            "tv",
            str(mp4),
        ],
        check=True,
        timeout=120,
    )
    probe = subprocess.run(
        [
            shutil.which("ffprobe"),
            "-v",
            "error",
            "-show_entries",
            "stream=color_space,color_transfer,color_primaries",
            "-of",
            "compact",
            str(mp4),
        ],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "color_transfer=smpte2084" in probe.stdout and "primaries=bt2020" in probe.stdout
    back = subprocess.run(
        [
            ffmpeg,
            "-v",
            "error",
            "-i",
            str(mp4),
            "-frames:v",
            "1",
            "-vf",
            "scale=in_color_matrix=bt2020:in_range=tv",
            "-pix_fmt",
            "rgb48le",
            "-f",
            "rawvideo",
            "-",
        ],
        capture_output=True,
        check=True,
    ).stdout
    decoded = np.frombuffer(back, "<u2").reshape(-1, 3) / 65535.0
    png = read_image(tmp_path / "morpho.png").reshape(-1, 3)
    # 4:2:0 chroma at this size blurs edges (median |diff| 0.014); the mean carries no
    # matrix shift: measured 3e-4 (without the scale filter, BT.601: 0.038)
    assert np.abs((decoded - png).mean(axis=0)).max() < 5e-3
