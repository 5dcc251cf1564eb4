"""The drop-in OCIO config (configs/thinfilm): names, roles, validation by OCIO and by
``ociocheck`` (PyPI build and, when installed, Debian's OCIO 2.1 build), processors
and agreement with the package's own transforms."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import object_colours
from evaluation.truth import colour_science_RGB_to_XYZ, log_decoding
from evaluation.views import COMMITTED_CONFIG, decode_display
from ocio_thinfilm import config, registry
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.lut import ocio_ops, view_transforms
from ocio_thinfilm.lut.options import MapOptions

ROOT = Path(__file__).resolve().parents[1]
OCIO21_CHECK = Path("/usr/bin/ociocheck")  # Debian opencolorio-tools (OCIO 2.1)

ROLES = (
    "scene_linear",
    "data",
    "default",
    "color_picking",
    "texture_paint",
    "matte_paint",
    "compositing_log",
    "color_timing",
    "aces_interchange",
    "cie_xyz_d65_interchange",
    "default_byte",
    "default_float",
    "default_sequencer",
)
#: Every colour space the registry names must be in the config (a new one included).
SPACES = (
    (registry.REFERENCE,)
    + registry.SCENE_LINEAR_SPACES
    + registry.ENCODED_SPACES
    + (registry.RAW_SPACE, registry.TEXTURE_SPACE)
    + registry.THIN_FILM_SPACES
    + tuple(d.colorspace for d in registry.ALL_DISPLAY_LIST)
)


@pytest.fixture(scope="module")
def ocio():
    import PyOpenColorIO

    return PyOpenColorIO


def test_profile_version_and_validation(cfg):
    assert COMMITTED_CONFIG.read_text().startswith("ocio_profile_version: 2.1\n")
    assert (cfg.getMajorVersion(), cfg.getMinorVersion()) == (2, 1)
    cfg.validate()


def test_generate_config_in_memory_validates():
    import PyOpenColorIO as ocio

    c = config.generate_config(config.config_data(inline=True))
    c.validate()
    c.getProcessor(
        "CIE-XYZ-D65", "sRGB", "Constant-Lightness Clip", ocio.TRANSFORM_DIR_FORWARD
    ).getDefaultCPUProcessor()


def test_roles(cfg):
    roles = dict(cfg.getRoles())
    for role in ROLES:
        assert role in roles, role
        assert cfg.getColorSpace(roles[role]) is not None
    assert roles["cie_xyz_d65_interchange"] == "CIE-XYZ-D65"
    assert roles["aces_interchange"] == "ACES2065-1"
    assert roles["scene_linear"] == "Linear Rec.709 (sRGB)"
    assert cfg.getColorSpace(roles["data"]).isData()


def test_colour_spaces_displays_views(cfg):
    names = list(cfg.getColorSpaceNames())
    for name in SPACES:
        assert name in names, name
    assert list(cfg.getDisplays()) == list(registry.ALL_DISPLAYS)
    for display in cfg.getDisplays():
        assert list(cfg.getViews(display)) == list(registry.VIEWS)


def test_file_rules_present(cfg):
    rules = cfg.getFileRules()
    assert rules.getNumEntries() >= 2

    def space(path):
        return cfg.getColorSpace(cfg.getColorSpaceFromFilepath(path)[0]).getName()

    assert space("render.exr") == "Linear Rec.709 (sRGB)"
    assert space("texture.PNG") == "sRGB - Texture"
    assert space("notes.txt") == "Linear Rec.709 (sRGB)"


def test_every_processor_builds(cfg, ocio):
    for display in cfg.getDisplays():
        for view in cfg.getViews(display):
            cfg.getProcessor(
                "Thin Film Phase-Change Thickness", display, view, ocio.TRANSFORM_DIR_FORWARD
            ).getDefaultCPUProcessor()
    for name in cfg.getColorSpaceNames():
        cfg.getProcessor(name, "CIE-XYZ-D65").getDefaultCPUProcessor()


def _run_check(tool):
    result = subprocess.run(
        [str(tool), "--iconfig", str(COMMITTED_CONFIG)], capture_output=True, text=True, timeout=120
    )
    text = result.stdout + result.stderr
    return result.returncode, text


def test_ociocheck_pypi():
    tool = shutil.which("ociocheck")
    if tool is None:
        pytest.skip("ociocheck (PyPI opencolorio) not on PATH")
    code, text = _run_check(tool)
    assert code == 0, text
    assert re.search(r"Validation:? passed", text), text
    assert "ERROR" not in text.upper().replace("ERRORS: 0", ""), text


@pytest.mark.skipif(
    not OCIO21_CHECK.exists(),
    reason="Debian opencolorio-tools (OCIO 2.1) not installed: apt-get install opencolorio-tools",
)
def test_ociocheck_ocio21():
    code, text = _run_check(OCIO21_CHECK)
    assert code == 0, text
    assert "passed" in text and "ERROR" not in text.upper(), text


@pytest.mark.skipif(
    not Path("/usr/bin/ociochecklut").exists(),
    reason="Debian opencolorio-tools (OCIO 2.1) not installed",
)
def test_ocio21_reads_every_config_lut():
    for path in sorted((COMMITTED_CONFIG.parent / "luts").glob("*.clf")):
        result = subprocess.run(
            ["/usr/bin/ociochecklut", str(path), "0.3", "0.3", "0.3"],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert result.returncode == 0, result.stdout + result.stderr
        values = [float(v) for v in result.stdout.split()[-3:]]
        assert np.all(np.isfinite(values))


def test_clf_metadata(ocio):
    for path in sorted((COMMITTED_CONFIG.parent / "luts").glob("*.clf")):
        text = path.read_text()
        assert 'id="urn:aswf:ocio:transformId:1.0:OCIO-ThinFilm:' in text, path.name
        for tag in ("Description", "InputDescriptor", "OutputDescriptor"):
            assert f"<{tag}>" in text, (path.name, tag)
        assert not re.search(r"20\d\d-\d\d-\d\d", text)  # no timestamps


def test_thin_film_spaces_through_config(cfg):
    t = np.linspace(0.0, 3.0, 3001)
    px = np.repeat(t[:, None], 3, 1).astype(np.float32)
    cpu = cfg.getProcessor(
        "Thin Film Phase-Change Thickness", "CIE-XYZ-D65"
    ).getDefaultCPUProcessor()
    out = px.copy()
    cpu.applyRGB(out)
    direct = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    assert colorimetry.delta_E2000(out.astype(np.float64), direct).max() <= 0.05
    cos = np.linspace(0, 1, 501)
    px = np.repeat(cos[:, None], 3, 1).astype(np.float32)
    cfg.getProcessor(
        "Thin Film Morpho Iridescence", "CIE-XYZ-D65"
    ).getDefaultCPUProcessor().applyRGB(px)
    direct = colorimetry.morpho_XYZ(np.degrees(np.arccos(cos)))
    assert colorimetry.delta_E2000(px.astype(np.float64), direct).max() <= 0.05


def test_config_views_equal_package_view_transforms(cfg, ocio):
    X = object_colours(n_random=500)[::3]
    for display in registry.DISPLAYS:
        for view in registry.VIEWS:
            out = X.astype(np.float32).copy()
            cfg.getProcessor(
                "CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD
            ).getDefaultCPUProcessor().applyRGB(out)
            ref = ocio_ops.apply(view_transforms.view_transform(display, view), X)
            # 3e-4 of code, or 1e-7 of display light: a pure power (BT.1886, gamma 2.6)
            # magnifies differences near black (file vs in-memory LUT ops: one Rec.2020
            # compression pixel at 2.3e-4 = a linear 1e-9, one Rec.1886 Rec.709 clip
            # pixel at 7.9e-4 = a linear 3.5e-8)
            light = np.abs(decode_display(out, display) - decode_display(ref, display))
            far = (np.abs(out - ref) > 3e-4) & (light > 1e-7)
            assert not far.any(), f"{display} / {view}: {out[far]} vs {ref[far]}"


def _hdr_nits(display, code):
    """An HDR display's code values -> absolute display light, cd/m2 (colour-science's
    ST 2084 EOTF, or the BT.2100 HLG EOTF for a 1000 cd/m2 peak, black at 0)."""
    import colour

    code = np.asarray(code, dtype=np.float64)
    if registry.as_display(display).transfer == "PQ":
        return colour.models.eotf_ST2084(code)
    return colour.models.eotf_BT2100_HLG(code, L_B=0.0, L_W=1000.0)


def test_scene_linear_white_is_display_white(cfg, ocio):
    """Scene-linear 1.0 is the display white on SDR displays and the BT.2408 reference
    white (203 cd/m2) on HDR ones; far above white is the white, resp. the 1000 cd/m2
    peak white."""
    for display in cfg.getDisplays():
        hdr = registry.as_display(display).hdr
        for view in registry.VIEWS[:3]:
            px = np.ones((1, 3), np.float32)
            cfg.getProcessor(
                "Linear Rec.709 (sRGB)", display, view, ocio.TRANSFORM_DIR_FORWARD
            ).getDefaultCPUProcessor().applyRGB(px)
            if hdr:  # 0.25/255 of an sRGB code at white is 2.3e-3 of its light
                np.testing.assert_allclose(_hdr_nits(display, px), 203.0, rtol=2.5e-3)
            else:
                np.testing.assert_allclose(px, 1.0, atol=0.25 / 255)  # clip: see test_tables
            px = np.full((1, 3), 4.0 * (5.0 if hdr else 1.0), np.float32)  # above white
            cfg.getProcessor(
                "Linear Rec.709 (sRGB)", display, view, ocio.TRANSFORM_DIR_FORWARD
            ).getDefaultCPUProcessor().applyRGB(px)
            if hdr:
                np.testing.assert_allclose(_hdr_nits(display, px), 1000.0, rtol=1e-3)
            elif view == "Constant-Lightness Clip":
                np.testing.assert_allclose(px, 1.0, atol=1e-4)


def test_acescct_round_trip(cfg):
    """Pinned: ACEScct's published code values (S-2016-001) of three ACEScg values; every
    encoded space, ACEScct included, is checked against colour-science below."""
    cpu = cfg.getProcessor("ACEScg", "ACEScct").getDefaultCPUProcessor()
    px = np.array([[0.18, 0.18, 0.18], [0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], np.float32)
    cpu.applyRGB(px)
    np.testing.assert_allclose(px[0], 0.4135884, atol=1e-5)  # ACEScct of 18 % grey
    np.testing.assert_allclose(px[1], 0.0729055, atol=1e-5)
    np.testing.assert_allclose(px[2], 0.5547945, atol=1e-5)


BLENDER = shutil.which("blender")


@pytest.mark.skipif(BLENDER is None, reason="Debian blender (OCIO 2.1) not installed")
def test_blender_loads_config_without_colour_management_errors(tmp_path):
    script = tmp_path / "probe.py"
    script.write_text(
        "import bpy\n"
        "s = bpy.context.scene\n"
        f"for d in {registry.ALL_DISPLAYS!r}:\n"
        "    s.display_settings.display_device = d\n"
        f"    for v in {tuple(registry.VIEWS)!r}:\n"
        "        s.view_settings.view_transform = v\n"
        "        print('SET', s.display_settings.display_device, '/', "
        "s.view_settings.view_transform)\n"
        "img = bpy.data.images.new('t', 4, 1, float_buffer=True)\n"
        "img.colorspace_settings.name = 'Thin Film Phase-Change Thickness'\n"
        "print('IMAGE', img.colorspace_settings.name)\n"
    )
    env = {"OCIO": str(COMMITTED_CONFIG), "PATH": "/usr/bin:/bin", "HOME": str(tmp_path)}
    result = subprocess.run(
        [BLENDER, "-b", "--factory-startup", "--python", str(script)],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )
    text = result.stdout + result.stderr
    assert "Color management: Error" not in text, text
    for display in registry.ALL_DISPLAYS:
        for view in registry.VIEWS:
            assert f"SET {display} / {view}" in text, text
    assert "IMAGE Thin Film Phase-Change Thickness" in text, text


# --------------------------------------------------------------------------- #
# The encoded (log) input spaces against colour-science's own decodings and gamuts
# --------------------------------------------------------------------------- #
#: The relative tolerance of OCIO's float32 CPU processor against colour-science's
#: decoding of each log curve and its gamut (the independent truths of
#: evaluation/truth.py, not the registry's own names of them): OCIO's log/exp
#: are approximations good to ~1e-5; measured max 3.1e-6 (DaVinci Intermediate) ..
#: 2.9e-5 (V-Log; 1.9e-5 S-Log3 .. 6.7e-5 DaVinci Intermediate, LogC4 relative to the
#: components alone). Relative to the larger of 1 and the magnitude of the terms each
#: XYZ component sums (:func:`_term_scale`: a float dot product's error bound), which is
#: the component's own magnitude unless its terms cancel: Z of REDWideGamutRGB at
#: Log3G10's high codes (linear up to 184) sums +-50 to 0.5, where float32 decoding
#: errors of 1e-6 in the terms are 1.8e-4 of Z.
ENCODED_RTOL = 1.5e-4


def _colour_science_matrix(encoded):
    """colour-science's RGB -> CIE-XYZ-D65 of the encoded space's gamut (Bradford to D65
    where its white differs), as a matrix."""
    return colour_science_RGB_to_XYZ(encoded.gamut.name)


def _colour_science_linear(codes, encoded):
    """Code values of ``encoded`` -> linear RGB by colour-science's decoding of the curve."""
    return log_decoding(codes, encoded.curve)


def _colour_science_XYZ(codes, encoded):
    """Code values of ``encoded`` -> CIE-XYZ-D65 by colour-science: the curve's decoding,
    then the gamut's RGB -> XYZ."""
    return _colour_science_linear(codes, encoded) @ _colour_science_matrix(encoded).T


def _term_scale(codes, encoded):
    """The larger of 1 and ``sum_j |M_ij linear_j|`` per XYZ component: what float32
    errors of the terms a component sums are relative to."""
    M = np.abs(_colour_science_matrix(encoded))
    return np.maximum(1.0, np.abs(_colour_science_linear(codes, encoded)) @ M.T)


@pytest.fixture(scope="module")
def fresh_cfg():
    """The config as ``bake`` makes it (its LUTs inline, small: the encoded spaces need none)."""
    small = MapOptions(clip_size=9, film_size=16, morpho_size=16)
    data = config.config_data(inline=True, options=small)
    return config.generate_config(data)


@pytest.mark.parametrize("encoded", registry.ENCODED_LIST, ids=lambda e: e.name)
def test_encoded_spaces_are_colour_sciences_curves_and_gamuts(fresh_cfg, encoded):
    """The config's colour space (CPU processor to CIE-XYZ-D65) of every encoded space is
    colour-science's decoding of its curve and its gamut's matrix, codes 0..1."""
    cfg = fresh_cfg
    assert cfg.getColorSpace(encoded.name).getFamily() == encoded.family
    rng = np.random.default_rng(5)
    codes = np.concatenate([rng.uniform(0.0, 1.0, (20000, 3)), np.eye(3), np.zeros((1, 3))])
    px = codes.astype(np.float32)
    cfg.getProcessor(encoded.name, registry.REFERENCE).getDefaultCPUProcessor().applyRGB(px)
    codes = codes.astype(np.float32).astype(np.float64)
    truth = _colour_science_XYZ(codes, encoded)
    err = np.abs(px - truth) / np.maximum(np.abs(truth), _term_scale(codes, encoded))
    per_component = (np.abs(px - truth) / np.maximum(1.0, np.abs(truth))).max()
    print(f"{encoded.name}: max relative error {err.max():.3g} ({per_component:.3g} of |XYZ|)")
    assert err.max() <= ENCODED_RTOL


OCIO_2_1_BAKER = Path("/usr/bin/ociobakelut")


@pytest.mark.skipif(not OCIO_2_1_BAKER.exists(), reason="Debian's OCIO 2.1 tools not installed")
def test_encoded_spaces_load_and_decode_in_ocio_2_1(tmp_path):
    """The encoded spaces as the config writes them, read by OCIO 2.1 (Debian's
    opencolorio-tools, the OCIO of Blender 3.4): a 9^3 table of each space to
    CIE-XYZ-D65 baked by its ociobakelut is colour-science's decoding."""
    import PyOpenColorIO as ocio

    from ocio_thinfilm.config import spaces

    cfg = ocio.Config.CreateRaw()
    cfg.setMajorVersion(2)
    cfg.setMinorVersion(1)
    for data in spaces.scene_colorspaces():
        if data["name"] != "Raw":
            cfg.addColorSpace(config.colorspace_factory(**data))
    cfg.setRole("reference", registry.REFERENCE)
    cfg.setRole("scene_linear", registry.REFERENCE)
    path = tmp_path / "config.ocio"
    path.write_text(cfg.serialize())
    check = subprocess.run(
        [str(OCIO_2_1_BAKER.with_name("ociocheck")), "--iconfig", str(path)],
        capture_output=True,
        text=True,
    )
    if "Library Version: 2.1." not in check.stdout:
        pytest.skip("the OCIO tools in /usr/bin are not OCIO 2.1")
    assert check.returncode == 0 and "passed" in check.stdout, check.stdout + check.stderr
    size = 9
    u = np.linspace(0.0, 1.0, size)
    codes = np.stack(np.meshgrid(u, u, u, indexing="ij"), axis=-1).transpose(2, 1, 0, 3)
    codes = codes.reshape(-1, 3)  # red fastest, as a .cube lists its nodes
    for encoded in registry.ENCODED_LIST:
        out = tmp_path / "table.cube"
        result = subprocess.run(
            [
                str(OCIO_2_1_BAKER),
                "--iconfig",
                str(path),
                "--inputspace",
                encoded.name,
                "--outputspace",
                registry.REFERENCE,
                "--format",
                "resolve_cube",
                "--cubesize",
                str(size),
                str(out),
            ],
            capture_output=True,
            text=True,
        )
        assert result.returncode == 0, result.stderr
        rows = [line.split() for line in out.read_text().splitlines()]
        table = np.array([[float(v) for v in r] for r in rows if len(r) == 3 and "_" not in r[0]])
        truth = _colour_science_XYZ(codes, encoded)
        err = np.abs(table - truth) / np.maximum(np.abs(truth), _term_scale(codes, encoded))
        print(f"{encoded.name} (OCIO 2.1): max relative error {err.max():.3g}")
        assert err.max() <= ENCODED_RTOL
