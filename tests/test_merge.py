"""``bake --into`` an ACES built-in config, named transforms, ``.ocioz``.

Expected values come from outside the merge code: the project's own committed config
(through oiiotool), colour-science's ACES2065-1 matrix, the analytic clip and the
spectral integration, and the unmerged base config itself.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import object_colours, spectral_colours
from evaluation.views import apply_processor
from ocio_thinfilm import config, registry
from ocio_thinfilm.cli.main import main
from ocio_thinfilm.colour import clip, colorimetry, compress
from ocio_thinfilm.config import merge
from ocio_thinfilm.export import bake
from ocio_thinfilm.export import merged as export_merged
from ocio_thinfilm.lut.options import MapOptions

ocio = pytest.importorskip("PyOpenColorIO")

ROOT = Path(__file__).resolve().parents[1]
PROJECT = ROOT / "configs" / "thinfilm" / "config.ocio"
OCIO21_CHECK = Path("/usr/bin/ociocheck")
BASE21 = "ocio://studio-config-v1.0.0_aces-v1.3_ocio-v2.1"
LATEST = "ocio://studio-config-latest"
#: The SDR displays with sRGB / Rec.709, P3-D65 or Rec.2020 primaries and D65 white or
#: with P3 primaries and DCI white (the cinema projector), by their published names
#: (P3-D60 has ACES white: no project display), and the HDR displays
#: BT.2100 PQ / HLG and P3-D65 PQ (not Display P3 HDR, Apple's extended sRGB curve).
_HDR = {
    "Rec.2100-HLG - Display": "Rec.2100-HLG",
    "Rec.2100-PQ - Display": "Rec.2100-PQ",
    "ST2084-P3-D65 - Display": "P3-D65 PQ",
}
EXPECTED = {
    BASE21: {
        "sRGB - Display": "sRGB",
        "Rec.1886 Rec.709 - Display": "sRGB",
        "Rec.1886 Rec.2020 - Display": "Rec.2020",
        "P3-D65 - Display": "Display P3",
        "P3-DCI - Display": "P3-DCI",
        **_HDR,
    },
    LATEST: {
        "sRGB - Display": "sRGB",
        "Display P3 - Display": "Display P3",
        "Gamma 2.2 Rec.709 - Display": "sRGB",
        "Gamma 2.6 P3-D65 - Display": "Display P3",
        "Rec.1886 Rec.709 - Display": "sRGB",
        **_HDR,
    },
}
#: (merged display, project display) pairs with the same encoding, for oiiotool.
SAME_ENCODING = {
    BASE21: [
        ("sRGB - Display", "sRGB"),
        ("Rec.1886 Rec.709 - Display", "Rec.1886 Rec.709"),
        ("Rec.1886 Rec.2020 - Display", "Rec.2020"),
        ("P3-DCI - Display", "P3-DCI"),
        *_HDR.items(),
    ],
    LATEST: [
        ("sRGB - Display", "sRGB"),
        ("Display P3 - Display", "Display P3"),
        ("Rec.1886 Rec.709 - Display", "Rec.1886 Rec.709"),
        *_HDR.items(),
    ],
}


#: What ``bake --into`` printed, per base config (filled by the ``merged`` fixture).
PRINTED = {}


@pytest.fixture(scope="module", params=[BASE21, LATEST], ids=["aces1.3-ocio2.1", "latest"])
def merged(request, tmp_path_factory):
    import contextlib
    import io

    out = tmp_path_factory.mktemp("merged") / "config"
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        assert main(["bake", "--into", request.param, "--out", str(out), "--quiet"]) == 0
    PRINTED[request.param] = printed.getvalue()
    path = out / "config.ocio"
    return request.param, path, ocio.Config.CreateFromFile(str(path))


def test_merged_validates_and_keeps_profile(merged):
    uri, path, cfg = merged
    base = ocio.Config.CreateFromFile(uri)
    cfg.validate()
    assert (cfg.getMajorVersion(), cfg.getMinorVersion()) == (
        base.getMajorVersion(),
        base.getMinorVersion(),
    )
    assert path.read_text().startswith(
        f"ocio_profile_version: {base.getMajorVersion()}.{base.getMinorVersion()}\n"
    )


def _ociocheck(tool, path):
    result = subprocess.run(
        [str(tool), "--iconfig", str(path)], capture_output=True, text=True, timeout=120
    )
    return result.returncode, result.stdout + result.stderr


def test_merged_passes_ociocheck_pypi(merged):
    uri, path, _ = merged
    tool = shutil.which("ociocheck")
    if tool is None:
        pytest.skip("ociocheck (PyPI opencolorio) not on PATH")
    code, text = _ociocheck(tool, path)
    assert code == 0, text
    assert re.search(r"Validation:? passed", text), text
    # no error, and no warning the base config does not have itself
    _, base_text = _ociocheck(tool, uri)
    assert "ERROR" not in text, text
    assert text.count("WARNING") == base_text.count("WARNING"), text


def test_merged_21_passes_debian_ociocheck(merged):
    uri, path, _ = merged
    if uri != BASE21:
        pytest.skip("Debian's OCIO 2.1 reads profile 2.1 configs only")
    if not OCIO21_CHECK.exists():
        pytest.skip(
            "Debian opencolorio-tools (OCIO 2.1) not installed: apt-get install opencolorio-tools"
        )
    code, text = _ociocheck(OCIO21_CHECK, path)
    assert code == 0 and "passed" in text and "ERROR" not in text.upper(), text


def test_merged_contents(merged):
    uri, path, cfg = merged
    base = ocio.Config.CreateFromFile(uri)
    spaces = set(cfg.getColorSpaceNames()) - set(base.getColorSpaceNames())
    assert spaces == set(registry.THIN_FILM_SPACES)
    for display in base.getDisplays():
        added = [v for v in cfg.getViews(display) if v not in base.getViews(display)]
        if display in EXPECTED[uri]:
            assert added[:2] == ["Constant-Lightness Clip", "Constant-Lightness Compress"]
            assert "ACES Gamut Compression" in added
            assert (
                cfg.getDisplayViewTransformName(display, added[0])
                == f"Constant-Lightness Clip - {EXPECTED[uri][display]}"
            )
            # views appended, the base's own views first and unchanged in order
            assert list(cfg.getViews(display))[: len(base.getViews(display))] == list(
                base.getViews(display)
            )
        else:
            assert added == [], display
    assert "Constant-Lightness Clip" in list(cfg.getActiveViews())
    assert list(cfg.getActiveDisplays()) == list(base.getActiveDisplays())
    assert dict(cfg.getRoles()) == dict(base.getRoles())
    gamuts = {registry.as_display(d).gamut.name for d in EXPECTED[uri].values()}
    nts = set(cfg.getNamedTransformNames()) - set(base.getNamedTransformNames())
    assert nts == (
        {
            f"Constant-Lightness {v} - {g} (display-linear)"
            for g in gamuts
            for v in ("Clip", "Compress")
        }
        | {f"{s} to CIE-XYZ-D65" for s in registry.THIN_FILM_SPACES}
    )
    luts = {p.name for p in (path.parent / "luts").iterdir()}
    assert len(luts) == 3 + 4 * len(gamuts)  # tables; per gamut the clip's 2 and 2 squeezes


def _write_exr(path, pixels):
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(np.ascontiguousarray(pixels, np.float32).reshape(1, -1, 3))
    assert buf.write(str(path)), buf.geterror()


def _read_exr(path):
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(str(path))
    return buf.get_pixels(oiio.FLOAT).reshape(-1, 3).astype(np.float64)


def _oiiotool(cfg_path, src, space, display, view, out):
    tool = shutil.which("oiiotool")
    if tool is None:
        pytest.skip("oiiotool (PyPI openimageio) not on PATH")
    result = subprocess.run(
        [
            tool,
            "--colorconfig",
            str(cfg_path),
            str(src),
            "--iscolorspace",
            space,
            "--ociodisplay",
            display,
            view,
            "-d",
            "float",
            "-o",
            str(out),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    if "not able to load that config version" in result.stderr + result.stdout:
        # PyPI OpenImageIO bundles an older OCIO (2.5) than PyPI OCIO (2.6): apply the
        # view with PyOpenColorIO's CPU processor, which is what oiiotool runs
        cfg = ocio.Config.CreateFromFile(str(cfg_path))
        proc = cfg.getProcessor(space, display, view, ocio.TRANSFORM_DIR_FORWARD)
        return apply_processor(proc, _read_exr(src)).astype(np.float64)
    assert result.returncode == 0, result.stdout + result.stderr
    return _read_exr(out)


def test_oiiotool_clip_view_matches_project_config(merged, tmp_path, colour):
    """The merged clip view equals the project config's, through oiiotool: on the SDR
    displays for colours up to white, on the HDR ones (the base's built-in PQ / HLG
    display spaces, 100 cd/m2 per unit, against the project's 203 cd/m2 convention)
    for the same colours scaled by 1000 / 203 into the HDR range."""
    uri, path, _ = merged
    if not PROJECT.exists():
        pytest.skip("configs/thinfilm not baked")
    X = np.vstack([object_colours(n_random=300)[::2], spectral_colours(max_Y=0.6, levels=8)])
    # ACES2065-1 from colour-science (Bradford D65 -> ACES white), not from our code
    D65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    files = {}
    for hdr, scale in ((False, 1.0), (True, 1000.0 / 203.0)):
        xyz, ap0 = tmp_path / f"xyz{int(hdr)}.exr", tmp_path / f"ap0{int(hdr)}.exr"
        _write_exr(xyz, X * scale)
        _write_exr(
            ap0,
            colour.XYZ_to_RGB(
                X * scale, "ACES2065-1", illuminant=D65, chromatic_adaptation_transform="Bradford"
            ),
        )
        files[hdr] = (xyz, ap0)
    for display, ours in SAME_ENCODING[uri]:
        xyz, ap0 = files[registry.as_display(ours).hdr]
        expected = _oiiotool(
            PROJECT, xyz, "CIE-XYZ-D65", ours, "Constant-Lightness Clip", tmp_path / "e.exr"
        )
        for src, space in ((xyz, "cie_xyz_d65_interchange"), (ap0, "ACES2065-1")):
            got = _oiiotool(
                path, src, space, display, "Constant-Lightness Clip", tmp_path / "g.exr"
            )
            diff = np.abs(got - expected).max()
            print(f"{uri} {display} from {space}: max |code difference| {diff:.2e}")
            assert diff <= 1.0 / 255.0, (display, space, diff)


def test_base_views_and_spaces_unchanged(merged):
    uri, _, cfg = merged
    base = ocio.Config.CreateFromFile(uri)
    rng = np.random.default_rng(3)
    px = np.vstack([rng.uniform(-0.2, 4.0, (2000, 3)), np.eye(3), np.zeros((1, 3))])
    src = dict(base.getRoles())["aces_interchange"]
    for display in base.getDisplays():
        for view in base.getViews(display):
            a = apply_processor(
                base.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD), px
            )
            b = apply_processor(
                cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD), px
            )
            assert a.tobytes() == b.tobytes(), (display, view)
    for name in base.getColorSpaceNames():
        a = apply_processor(base.getProcessor(src, name), px)
        b = apply_processor(cfg.getProcessor(src, name), px)
        assert a.tobytes() == b.tobytes(), name


def _check_clip_named_transform(cfg, display, kind="Clip"):
    rng = np.random.default_rng(5)
    M = colorimetry.matrix_XYZ_to_RGB(display)
    inside = rng.uniform(0.0, 1.0, (500, 3))
    X = object_colours(n_random=200)
    rgb = X @ M.T
    nt = f"Constant-Lightness {kind} - {display} (display-linear)"
    proc = cfg.getProcessor(nt, ocio.TRANSFORM_DIR_FORWARD)
    analytic = clip.clip_RGB if kind == "Clip" else compress.compress_RGB
    if kind == "Clip":  # in-gamut colours unchanged
        np.testing.assert_allclose(apply_processor(proc, inside), inside, atol=2e-3)
    else:  # the compression moves those near the boundary: within its accuracy target
        got = apply_processor(proc, inside).astype(np.float64)
        dE = colorimetry.delta_E2000(
            colorimetry.RGB_to_XYZ(got, display),
            colorimetry.RGB_to_XYZ(analytic(inside, display), display),
        )
        assert dE.max() <= 1.5, dE.max()
    out = apply_processor(proc, rgb).astype(np.float64)
    assert out.min() >= -1e-6 and out.max() <= 1.0 + 1e-4
    ref = analytic(rgb, display)
    Y = np.linalg.inv(M)[1]
    below = rgb @ Y < 0.95
    assert np.abs(out @ Y - rgb @ Y)[below].max() < 2e-3  # luminance kept
    assert np.median(np.abs(out - ref).max(axis=1)) < 2e-3


def _check_table_named_transforms(cfg):
    t = np.linspace(0.0, 3.0, 601)
    px = np.repeat(t[:, None], 3, 1)
    out = apply_processor(
        cfg.getProcessor(
            "Thin Film Phase-Change Thickness to CIE-XYZ-D65", ocio.TRANSFORM_DIR_FORWARD
        ),
        px,
    )
    direct = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    assert colorimetry.delta_E2000(out.astype(np.float64), direct).max() <= 0.05
    cos = np.linspace(0.0, 1.0, 101)
    out = apply_processor(
        cfg.getProcessor("Thin Film Morpho Iridescence to CIE-XYZ-D65", ocio.TRANSFORM_DIR_FORWARD),
        np.repeat(cos[:, None], 3, 1),
    )
    direct = colorimetry.morpho_XYZ(np.degrees(np.arccos(cos)))
    assert colorimetry.delta_E2000(out.astype(np.float64), direct).max() <= 0.05


def test_named_transforms_in_merged_config(merged):
    uri, _, cfg = merged
    for display in {registry.as_display(d).gamut.name for d in EXPECTED[uri].values()}:
        _check_clip_named_transform(cfg, display)
        _check_clip_named_transform(cfg, display, "Compress")
    _check_table_named_transforms(cfg)


def test_named_transforms_in_project_config():
    cfg = config.generate_config(config.config_data(inline=True))
    for display in clip.DISPLAYS:
        _check_clip_named_transform(cfg, display)
        _check_clip_named_transform(cfg, display, "Compress")
    _check_table_named_transforms(cfg)


def test_thin_film_space_in_merged_config_reaches_xyz(merged):
    uri, _, cfg = merged
    t = np.linspace(0.0, 2.0, 201)
    out = apply_processor(
        cfg.getProcessor("Thin Film Phase-Change Thickness", "cie_xyz_d65_interchange"),
        np.repeat(t[:, None], 3, 1),
    )
    direct = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    assert colorimetry.delta_E2000(out.astype(np.float64), direct).max() <= 0.05


def test_file_rules_name_colour_spaces():
    cfg = config.generate_config(config.config_data(inline=True))
    rules = cfg.getFileRules()
    roles = dict(cfg.getRoles())
    for i in range(rules.getNumEntries()):
        name = rules.getColorSpace(i)
        assert name not in roles, name
        assert cfg.getColorSpace(name).getName() == name
    assert cfg.getColorSpaceFromFilepath("render.exr")[0] == "Linear Rec.709 (sRGB)"


def test_ocioz_gives_the_folders_output(tmp_path):
    folder = tmp_path / "folder"
    folder.mkdir()
    bake.write_config(folder, options=MapOptions(clip_size=9))
    archive = export_merged.bake_archive(
        tmp_path / "thinfilm.ocioz", options=MapOptions(clip_size=9)
    )
    a = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    b = ocio.Config.CreateFromFile(str(archive))
    b.validate()
    rng = np.random.default_rng(9)
    px = rng.uniform(-0.1, 1.5, (500, 3))
    for display in a.getDisplays():
        for view in a.getViews(display):
            pa = a.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
            pb = b.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
            assert apply_processor(pa, px).tobytes() == apply_processor(pb, px).tobytes()
    for name in a.getNamedTransformNames():
        assert (
            apply_processor(a.getProcessor(name, ocio.TRANSFORM_DIR_FORWARD), px).tobytes()
            == apply_processor(b.getProcessor(name, ocio.TRANSFORM_DIR_FORWARD), px).tobytes()
        )
    for name in registry.THIN_FILM_SPACES:
        assert (
            apply_processor(a.getProcessor(name, "CIE-XYZ-D65"), px).tobytes()
            == apply_processor(b.getProcessor(name, "CIE-XYZ-D65"), px).tobytes()
        )


def test_into_refuses_config_without_interchange_or_display(tmp_path, capsys):
    raw = ocio.Config.CreateRaw()
    raw.setVersion(2, 1)
    (tmp_path / "raw.ocio").write_text(raw.serialize())
    code = main(
        ["bake", "--into", str(tmp_path / "raw.ocio"), "--out", str(tmp_path / "a"), "--quiet"]
    )
    err = capsys.readouterr().err
    assert code == 2 and "cie_xyz_d65_interchange" in err and len(err.splitlines()) == 1
    raw.setRole("cie_xyz_d65_interchange", "raw")  # scene-referred, no view transform
    (tmp_path / "role.ocio").write_text(raw.serialize())
    code = main(
        ["bake", "--into", str(tmp_path / "role.ocio"), "--out", str(tmp_path / "b"), "--quiet"]
    )
    err = capsys.readouterr().err
    assert code == 2 and len(err.splitlines()) == 1, err
    # an ACES config whose only display is P3-D60 (ACES white): nothing to add to
    dci = ocio.Config.CreateFromFile(BASE21)
    dci.clearDisplays()
    dci.addDisplayView(
        "P3-D60 - Display", "Un-tone-mapped", "Un-tone-mapped", "P3-D60 - Display", "", "", ""
    )
    dci.setActiveDisplays("")
    dci.setActiveViews("")
    dci.validate()
    (tmp_path / "dci.ocio").write_text(dci.serialize())
    code = main(
        ["bake", "--into", str(tmp_path / "dci.ocio"), "--out", str(tmp_path / "c"), "--quiet"]
    )
    err = capsys.readouterr().err
    assert code == 2 and "no SDR display" in err and len(err.splitlines()) == 1, err
    assert not any((tmp_path / d).exists() for d in "abc")


def test_a_missing_base_is_named_source_by_the_library_and_into_by_the_cli(tmp_path, capsys):
    missing = tmp_path / "no" / "such.ocio"
    with pytest.raises(ValueError, match=r"^source .*such\.ocio: no such config file"):
        export_merged.bake_into(missing, tmp_path / "a")
    assert main(["bake", "--into", str(missing), "--out", str(tmp_path / "a"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert (
        err == f"ocio-thinfilm bake: error: --into {missing}: no such config file (or ocio:// URI)"
    ), err
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(ValueError, match=r"^out .*file: not a directory"):
        export_merged.bake_into(BASE21, blocker)
    assert blocker.read_text() == "x" and not (tmp_path / "a").exists()


def test_bake_into_says_which_ocio_reads_the_result(merged, tmp_path):
    """``bake --into`` prints the merged config's profile and the oldest OCIO that reads
    it; OpenImageIO 3.2's oiiotool (OCIO 2.5) refuses the config exactly when the line
    says so."""
    base, path, cfg = merged
    major, minor = cfg.getMajorVersion(), cfg.getMinorVersion()
    line = PRINTED[base].splitlines()[-1]
    assert line == merge.profile_readers(cfg)
    assert line.startswith(f"profile {major}.{minor}: read by OCIO {major}.{minor} and newer")
    oiiotool = shutil.which("oiiotool")
    if oiiotool is None:
        pytest.skip("oiiotool not installed")
    version = subprocess.run([oiiotool, "--version"], capture_output=True, text=True).stdout
    if not version.startswith("3.2."):
        pytest.skip(f"oiiotool {version.strip()} is not OpenImageIO 3.2 (OCIO 2.5)")
    run = subprocess.run(
        [
            oiiotool,
            "--pattern",
            "constant:color=0.5,0.5,0.5",
            "4x4",
            "3",
            "--colorconfig",
            str(path),
            "--colorconvert",
            "sRGB - Display",
            "sRGB - Display",
            "-o",
            str(tmp_path / "o.exr"),
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    refused = "not able to load that config version" in run.stdout + run.stderr
    assert refused == ("OpenImageIO 3.2's oiiotool" in line)
    assert refused == ((major, minor) > (2, 5))


def test_docs_table_of_builtin_configs_matches_ocio():
    """docs/studio.md's table of the built-in ACES configs: each studio config with its
    profile as OCIO reports it, and the hosts of ``merge.HOST_OCIO`` that read it."""
    text = (Path(__file__).resolve().parents[1] / "docs" / "studio.md").read_text()
    block = text.split("<!-- builtin-configs:begin -->", 1)[1]
    rows = block.split("<!-- builtin-configs:end -->")[0].strip().splitlines()[2:]
    studio = [
        item[0]
        for item in ocio.BuiltinConfigRegistry().getBuiltinConfigs()
        if item[0].startswith("studio-config-")
    ]
    assert len(rows) == len(studio)
    for row, name in zip(rows, sorted(studio), strict=True):
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[0].startswith(f"`{name}`")
        cfg = ocio.Config.CreateFromFile("ocio://" + name)
        profile = (cfg.getMajorVersion(), cfg.getMinorVersion())
        assert cells[1] == f"{profile[0]}.{profile[1]}"
        readers = [host for host, v in merge.HOST_OCIO if v >= profile]
        if len(readers) == len(merge.HOST_OCIO):
            assert cells[2] == "every host below"
        elif not readers:
            assert cells[2] == f"OCIO {profile[0]}.{profile[1]} only"
        else:
            for host, v in merge.HOST_OCIO:
                assert (f"(OCIO {v[0]}.{v[1]})" in cells[2]) == (v >= profile), (name, host)
